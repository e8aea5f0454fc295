@tool
extends RefCounted
## A plant's three parts of one level merged into one mesh that is drawn once per plant
## ([code]shaders/plant_whole.gdshader[/code] bends and stacks the parts; each vertex holds its
## part's index in UV2.x). Only parts drawn with the addon's plant material merge: surfaces of
## triangles, every one with a [code]shaders/plant_parts.gdshader[/code] material (a plain
## StandardMaterial3D becomes one: [code]plant_material.gd[/code]) or, when asked for, a
## ShaderMaterial of your own that fades, which is drawn by a copy whose shader bends the same way
## ([method PlantMaterial.bending]). Surfaces of equal settings become one surface of the merged mesh,
## so a plant of one material is one draw call per level. A mesh with another material could not
## place its parts, so such a plant is drawn part by part.

const PARTS_SHADER: Shader = preload("../shaders/plant_parts.gdshader")
const WHOLE_SHADER: Shader = preload("../shaders/plant_whole.gdshader")
const PlantMaterial: GDScript = preload("plant_material.gd")
const SurfaceTangents: GDScript = preload("surface_tangents.gd")
## The vertex arrays a merged surface keeps (the surfaces merged into it must all have the same).
const KEPT: Array[int] = [Mesh.ARRAY_VERTEX, Mesh.ARRAY_NORMAL, Mesh.ARRAY_TANGENT, Mesh.ARRAY_COLOR, Mesh.ARRAY_TEX_UV]


## Whether [param parts] (bottom, middle, head; null for an empty slot) can be merged: see the
## script's description ([param own_shaders]: whether ShaderMaterials of your own that fade may be).
static func can_merge(parts: Array[Mesh], own_shaders: bool = false) -> bool:
	return _mergeable(parts, own_shaders)


## The merged mesh of [param parts] (bottom, middle, head) for a plant whose parts' roots lie
## [param part_lengths] model units apart and whose leaves [param flutter] ([member SunflowerPlant.flutter]),
## or null when they cannot be merged ([method can_merge] with [param own_shaders]).
static func merge(
	parts: Array[Mesh], part_lengths: Vector3, flutter: float = 0.0, own_shaders: bool = false
) -> ArrayMesh:
	if not _mergeable(parts, own_shaders):
		return null
	# One group per distinct setting: the source material and the arrays merged so far.
	var groups: Array[Dictionary] = []
	for part: int in parts.size():
		if parts[part] == null:
			continue  # an empty slot
		for surface: int in parts[part].get_surface_count():
			var material: ShaderMaterial = parts[part].surface_get_material(surface) as ShaderMaterial
			var group: Dictionary = {}
			for candidate: Dictionary in groups:
				if _same_settings(candidate.material, material):
					group = candidate
					break
			if group.is_empty():
				group = {"material": material, "arrays": empty_arrays(), "present": []}
				groups.append(group)
			if not _append(group, SurfaceTangents.filled(parts[part].surface_get_arrays(surface)), part):
				return null
	var mesh: ArrayMesh = ArrayMesh.new()
	for group: Dictionary in groups:
		mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, _merged_arrays(group))
		var whole: ShaderMaterial = null
		if group.material.shader == PARTS_SHADER:
			whole = ShaderMaterial.new()
			whole.shader = WHOLE_SHADER
			for uniform: Dictionary in PARTS_SHADER.get_shader_uniform_list():
				whole.set_shader_parameter(uniform.name, group.material.get_shader_parameter(uniform.name))
		else:
			whole = PlantMaterial.bending(group.material)
		whole.set_shader_parameter(&"plant_part_lengths", part_lengths)
		whole.set_shader_parameter(&"plant_flutter", flutter)
		mesh.surface_set_material(mesh.get_surface_count() - 1, whole)
	return mesh


## Empty vertex arrays by kind (position, normal, tangent, colour, UV, UV2, index), to append surfaces to.
static func empty_arrays() -> Dictionary:
	return {
		Mesh.ARRAY_VERTEX: PackedVector3Array(),
		Mesh.ARRAY_NORMAL: PackedVector3Array(),
		Mesh.ARRAY_TANGENT: PackedFloat32Array(),
		Mesh.ARRAY_COLOR: PackedColorArray(),
		Mesh.ARRAY_TEX_UV: PackedVector2Array(),
		Mesh.ARRAY_TEX_UV2: PackedVector2Array(),
		Mesh.ARRAY_INDEX: PackedInt32Array(),
	}


## Adds a part's surface [param arrays] to [param group], its vertices marked as part [param part];
## false when the surface has other vertex arrays than the group's first.
static func _append(group: Dictionary, arrays: Array, part: int) -> bool:
	var has: Array = KEPT.map(func(kind: int) -> bool: return arrays[kind] != null)
	if group.present.is_empty():
		group.present = has
	elif has != group.present:
		return false
	var merged: Dictionary = group.arrays
	var first: int = merged[Mesh.ARRAY_VERTEX].size()
	var count: int = arrays[Mesh.ARRAY_VERTEX].size()
	for kind: int in KEPT:
		if arrays[kind] != null:
			var values: Variant = merged[kind]  # packed arrays are values: appended, then stored back
			values.append_array(arrays[kind])
			merged[kind] = values
	var indices: PackedInt32Array = merged[Mesh.ARRAY_INDEX]
	if arrays[Mesh.ARRAY_INDEX] != null:
		for index: int in arrays[Mesh.ARRAY_INDEX]:
			indices.append(first + index)
	else:
		for index: int in count:
			indices.append(first + index)
	merged[Mesh.ARRAY_INDEX] = indices
	var uv2: PackedVector2Array = merged[Mesh.ARRAY_TEX_UV2]
	for k: int in count:
		uv2.append(Vector2(part, 0.0))
	merged[Mesh.ARRAY_TEX_UV2] = uv2
	return true


static func _merged_arrays(group: Dictionary) -> Array:
	var out: Array = []
	out.resize(Mesh.ARRAY_MAX)
	for kind: int in KEPT:
		out[kind] = group.arrays[kind] if group.present[KEPT.find(kind)] else null
	out[Mesh.ARRAY_TEX_UV2] = group.arrays[Mesh.ARRAY_TEX_UV2]
	out[Mesh.ARRAY_INDEX] = group.arrays[Mesh.ARRAY_INDEX]
	return out


## Whether [param parts] has a surface and every surface has a plant material (or, with
## [param own_shaders], one that [method PlantMaterial.can_bend]), is of triangles and has no blend
## shapes (empty slots hold none).
static func _mergeable(parts: Array[Mesh], own_shaders: bool) -> bool:
	if parts.size() != 3:
		return false
	if parts.all(func(mesh: Mesh) -> bool: return mesh == null or mesh.get_surface_count() == 0):
		return false
	for mesh: Mesh in parts:
		if mesh == null:
			continue
		for surface: int in mesh.get_surface_count():
			var material: ShaderMaterial = mesh.surface_get_material(surface) as ShaderMaterial
			if material == null:
				return false
			if material.shader != PARTS_SHADER and not (own_shaders and PlantMaterial.can_bend(material)):
				return false
			if (
				mesh is ArrayMesh
				and (mesh as ArrayMesh).surface_get_primitive_type(surface) != Mesh.PRIMITIVE_TRIANGLES
			):
				return false
			if mesh.surface_get_blend_shape_arrays(surface).size() > 0:
				return false
	return true


static func _same_settings(a: ShaderMaterial, b: ShaderMaterial) -> bool:
	if a.shader != b.shader:
		return false
	for uniform: Dictionary in a.shader.get_shader_uniform_list():
		if a.get_shader_parameter(uniform.name) != b.get_shader_parameter(uniform.name):
			return false
	return true
