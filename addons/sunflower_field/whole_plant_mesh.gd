@tool
extends RefCounted
## A plant's three parts of one level merged into one mesh that is drawn once per plant
## ([code]shaders/plant_whole.gdshader[/code] bends and stacks the parts; each vertex holds its
## part's index in UV2.x). Only parts drawn with the addon's plant material merge: one or more
## surfaces of triangles, every one with a [code]shaders/plant_parts.gdshader[/code] material of the
## same settings. A mesh with another material could not place its parts, so such a plant is drawn
## part by part.

const PARTS_SHADER: Shader = preload("shaders/plant_parts.gdshader")
const WHOLE_SHADER: Shader = preload("shaders/plant_whole.gdshader")
## The vertex arrays a merged surface keeps (a part's surfaces must all have the same of these).
const KEPT: Array[int] = [Mesh.ARRAY_VERTEX, Mesh.ARRAY_NORMAL, Mesh.ARRAY_TANGENT, Mesh.ARRAY_COLOR, Mesh.ARRAY_TEX_UV]


## Whether [param parts] (bottom, middle, head) can be merged: see the script's description.
static func can_merge(parts: Array[Mesh]) -> bool:
	return _material_of(parts) != null


## The merged mesh of [param parts] (bottom, middle, head) for a plant whose parts' roots lie
## [param part_lengths] model units apart, or null when they cannot be merged ([method can_merge]).
static func merge(parts: Array[Mesh], part_lengths: Vector3) -> ArrayMesh:
	var source: ShaderMaterial = _material_of(parts)
	if source == null:
		return null
	var vertices: PackedVector3Array = PackedVector3Array()
	var normals: PackedVector3Array = PackedVector3Array()
	var tangents: PackedFloat32Array = PackedFloat32Array()
	var colours: PackedColorArray = PackedColorArray()
	var uvs: PackedVector2Array = PackedVector2Array()
	var uv2: PackedVector2Array = PackedVector2Array()
	var indices: PackedInt32Array = PackedInt32Array()
	var present: Array = []  # which of KEPT the first surface has; every other must have the same
	for part: int in parts.size():
		for surface: int in parts[part].get_surface_count():
			var arrays: Array = parts[part].surface_get_arrays(surface)
			var has: Array = KEPT.map(func(kind: int) -> bool: return arrays[kind] != null)
			if present.is_empty():
				present = has
			elif has != present:
				return null
			var first: int = vertices.size()
			var count: int = arrays[Mesh.ARRAY_VERTEX].size()
			vertices.append_array(arrays[Mesh.ARRAY_VERTEX])
			if arrays[Mesh.ARRAY_NORMAL] != null:
				normals.append_array(arrays[Mesh.ARRAY_NORMAL])
			if arrays[Mesh.ARRAY_TANGENT] != null:
				tangents.append_array(arrays[Mesh.ARRAY_TANGENT])
			if arrays[Mesh.ARRAY_COLOR] != null:
				colours.append_array(arrays[Mesh.ARRAY_COLOR])
			if arrays[Mesh.ARRAY_TEX_UV] != null:
				uvs.append_array(arrays[Mesh.ARRAY_TEX_UV])
			if arrays[Mesh.ARRAY_INDEX] != null:
				for index: int in arrays[Mesh.ARRAY_INDEX]:
					indices.append(first + index)
			else:
				for index: int in count:
					indices.append(first + index)
			for k: int in count:
				uv2.append(Vector2(part, 0.0))
	var merged: Array = []
	merged.resize(Mesh.ARRAY_MAX)
	merged[Mesh.ARRAY_VERTEX] = vertices
	merged[Mesh.ARRAY_NORMAL] = normals if present[KEPT.find(Mesh.ARRAY_NORMAL)] else null
	merged[Mesh.ARRAY_TANGENT] = tangents if present[KEPT.find(Mesh.ARRAY_TANGENT)] else null
	merged[Mesh.ARRAY_COLOR] = colours if present[KEPT.find(Mesh.ARRAY_COLOR)] else null
	merged[Mesh.ARRAY_TEX_UV] = uvs if present[KEPT.find(Mesh.ARRAY_TEX_UV)] else null
	merged[Mesh.ARRAY_TEX_UV2] = uv2
	merged[Mesh.ARRAY_INDEX] = indices
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, merged)
	var material: ShaderMaterial = ShaderMaterial.new()
	material.shader = WHOLE_SHADER
	for uniform: Dictionary in PARTS_SHADER.get_shader_uniform_list():
		material.set_shader_parameter(uniform.name, source.get_shader_parameter(uniform.name))
	material.set_shader_parameter(&"part_lengths", part_lengths)
	mesh.surface_set_material(0, material)
	return mesh


## The plant material all of [param parts]' surfaces share (equal settings), or null.
static func _material_of(parts: Array[Mesh]) -> ShaderMaterial:
	if parts.size() != 3:
		return null
	var found: ShaderMaterial = null
	for mesh: Mesh in parts:
		if mesh == null or mesh.get_surface_count() == 0:
			return null
		for surface: int in mesh.get_surface_count():
			var material: ShaderMaterial = mesh.surface_get_material(surface) as ShaderMaterial
			if material == null or material.shader != PARTS_SHADER:
				return null
			if (
				mesh is ArrayMesh
				and (mesh as ArrayMesh).surface_get_primitive_type(surface) != Mesh.PRIMITIVE_TRIANGLES
			):
				return null
			if mesh.surface_get_blend_shape_arrays(surface).size() > 0:
				return null
			if found == null:
				found = material
			elif not _same_settings(found, material):
				return null
	return found


static func _same_settings(a: ShaderMaterial, b: ShaderMaterial) -> bool:
	for uniform: Dictionary in PARTS_SHADER.get_shader_uniform_list():
		if a.get_shader_parameter(uniform.name) != b.get_shader_parameter(uniform.name):
			return false
	return true
