@tool
extends RefCounted
## Tangents for a surface without normals. The engine gives every surface with normals a tangent
## (one at right angles to the normal when the mesh has none), but a surface of positions alone (a
## mesh made in code) has neither; the plant's shaders bend [code]TANGENT[/code] with the rest of a
## vertex ([code]shaders/plant_bend.gdshaderinc[/code]), so the engine warned at every draw of a plant
## mesh made of one ("requires tangents with a mesh that doesn't contain tangents"). The plant meshes
## the addon makes from yours give such a surface a unit tangent at right angles to its normal (to
## (0, 0, 1) where it has none); no normals are added (it is lit as in your scene). Your own meshes are
## not changed.


## [param arrays] (a triangle surface's, as [method Mesh.surface_get_arrays] gives them) with a tangent
## for each vertex; the same arrays when they have tangents.
static func filled(arrays: Array) -> Array:
	if arrays[Mesh.ARRAY_TANGENT] != null:
		return arrays
	var out: Array = arrays.duplicate()
	var normals: Variant = arrays[Mesh.ARRAY_NORMAL]
	var tangents: PackedFloat32Array = PackedFloat32Array()
	tangents.resize((arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size() * 4)
	for k: int in tangents.size() / 4:
		var normal: Vector3 = (normals as PackedVector3Array)[k] if normals != null else Vector3.BACK
		var across: Vector3 = normal.cross(Vector3.UP if absf(normal.y) < 0.9 else Vector3.RIGHT)
		across = across.normalized() if across.length_squared() > 0.0 else Vector3.RIGHT
		tangents[4 * k] = across.x
		tangents[4 * k + 1] = across.y
		tangents[4 * k + 2] = across.z
		tangents[4 * k + 3] = 1.0
	out[Mesh.ARRAY_TANGENT] = tangents
	return out
