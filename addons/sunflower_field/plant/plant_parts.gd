@tool
extends RefCounted
## How a [SunflowerPlant]'s parts are drawn, behind the plant's methods of the same names: the copies
## of its part meshes the field draws (its plain StandardMaterial3D surfaces taken over by the plant
## material, its own ShaderMaterials made to fade) and the whole meshes merged from them, each made
## once and kept while what it was made from stays; whether its parts stack; the frame fitted to its
## level-1 meshes. One per plant (its caches); the functions without state are static.

const PartMeshes: GDScript = preload("part_meshes.gd")
const PlantMaterial: GDScript = preload("plant_material.gd")
const WholePlantMesh: GDScript = preload("whole_plant_mesh.gd")

## A plant's properties that hold its mesh levels' parts, level 1 first.
const LEVEL_PROPERTIES: Array[StringName] = [&"mesh_level_1", &"mesh_level_2", &"mesh_level_3"]

var _whole_meshes: Dictionary = {}  # level → [what it was merged from, the merged mesh]
var _field_meshes: Dictionary = {}  # a part mesh → the mesh the field draws it with


## The mesh the field's nodes draw a part of [param plant] with (see
## [method SunflowerPlant.mesh_for_field]).
func for_field(plant: SunflowerPlant, level: int, part: int) -> Mesh:
	var mesh: Mesh = plant.mesh_drawn(level, part)
	if not plant.use_plant_material or mesh == null:
		return mesh
	if not _field_meshes.has(mesh):
		if _field_meshes.size() >= PartMeshes.LEVELS * PartMeshes.PART_NAMES.size():
			_field_meshes.clear()  # parts were swapped: the copies of meshes no longer drawn go
		_field_meshes[mesh] = PlantMaterial.adopt_mesh(mesh)
	return _field_meshes[mesh]


## Whether the near levels draw [param plant] whole (see [method SunflowerPlant.drawn_whole]).
func drawn_whole(plant: SunflowerPlant) -> bool:
	if not plant.draw_whole:
		return false
	for level: int in PartMeshes.LEVELS:
		if not WholePlantMesh.can_merge(_drawn_parts(plant, level), plant.use_plant_material):
			return false
	return true


## The mesh [param plant] drawn whole is drawn with at [param level], or null (see
## [method SunflowerPlant.whole_mesh]).
func whole_mesh(plant: SunflowerPlant, level: int) -> Mesh:
	var parts: Array[Mesh] = _drawn_parts(plant, level)
	var lengths: Vector3 = plant.stacked_lengths()
	var source: Array = [parts, lengths, plant.flutter, plant.use_plant_material]
	var made: Array = _whole_meshes.get(level, [])
	if made.is_empty() or made[0] != source:
		made = [source, WholePlantMesh.merge(parts, lengths, plant.flutter, plant.use_plant_material)]
		_whole_meshes[level] = made
	return made[1]


## The parts of [param plant]'s mesh [param level] (0–2), as set.
static func level_parts(plant: SunflowerPlant, level: int) -> Array[Mesh]:
	return plant.get(LEVEL_PROPERTIES[level])


## [param meshes] made three slots long (bottom, middle, head): missing ones empty, extra ones gone.
static func three(meshes: Array[Mesh]) -> Array[Mesh]:
	var out: Array[Mesh] = meshes.duplicate()
	out.resize(PartMeshes.PART_NAMES.size())
	return out


## The mesh a part of [param plant] is drawn with (see [method SunflowerPlant.mesh_drawn]).
static func drawn(plant: SunflowerPlant, level: int, part: int) -> Mesh:
	for source: int in range(level, -1, -1):
		var meshes: Array[Mesh] = level_parts(plant, source)
		if meshes.any(func(mesh: Mesh) -> bool: return mesh != null):
			return meshes[part]
	return null


## The triangles of one plant at mesh [param level], its parts as drawn (see
## [method SunflowerPlant.triangle_count]).
static func triangles(plant: SunflowerPlant, level: int) -> int:
	var count: int = 0
	for part: int in PartMeshes.PART_NAMES.size():
		var mesh: Mesh = drawn(plant, level, part)
		if mesh:
			count += mesh.get_faces().size() / 3
	return count


## What keeps [param plant]'s parts from stacking (see [method SunflowerPlant.stacking_problems]).
static func stacking_problems(plant: SunflowerPlant) -> PackedStringArray:
	var problems: PackedStringArray = []
	if plant.mesh_level_1.all(func(mesh: Mesh) -> bool: return mesh == null):
		problems.append("SunflowerPlant '%s' has no mesh in mesh_level_1: its plants are not drawn near." % plant.name)
	for level: int in PartMeshes.LEVELS:
		var parts: Array[Mesh] = level_parts(plant, level)
		var top: int = -1
		for part: int in parts.size():
			if parts[part] != null:
				top = part
		for part: int in top:
			if parts[part] == null:
				problems.append(
					(
						"SunflowerPlant '%s': mesh_level_%d's %s slot is empty below its %s, which floats over the gap."
						% [plant.name, level + 1, PartMeshes.PART_NAMES[part], PartMeshes.PART_NAMES[top]]
					)
				)
	return problems


## Frames [param plant] from its level-1 parts as they stack (see [method SunflowerPlant.fit_to_meshes]).
static func fit(plant: SunflowerPlant) -> void:
	var lengths: Vector3 = plant.stacked_lengths()
	var points: PackedVector3Array = []
	var base: float = 0.0
	for part: int in PartMeshes.PART_NAMES.size():
		var mesh: Mesh = plant.mesh_level_1[part]
		if mesh:
			for point: Vector3 in mesh.get_faces():
				points.append(point + Vector3(0.0, base, 0.0))
		base += lengths[part]
	if points.is_empty():
		push_warning("SunflowerPlant.fit_to_meshes: '%s' has no level-1 mesh to fit to" % plant.name)
		return
	var top: float = 0.0
	var reach: float = 0.0
	for point: Vector3 in points:
		top = maxf(top, point.y)
		reach = maxf(reach, Vector2(point.x, point.z).length())
	top = maxf(top, 0.01)
	var farthest: float = 0.0
	for point: Vector3 in points:
		farthest = maxf(farthest, point.distance_to(Vector3(0.0, top * 0.5, 0.0)))
	if plant.mesh_level_1[1] == null and plant.mesh_level_1[2] == null:
		plant.part_lengths = Vector3(top, plant.part_lengths.y, plant.part_lengths.z)
	plant.height_units = top
	plant.impostor_width = maxf(2.0 * reach, 0.01)
	# Tilted about the root by θ, the middle moves 2·(top/2)·sin(θ/2): the sphere grows by that.
	var largest_bend: float = (SunflowerWind as Script).get_property_default_value(&"max_bend")
	plant.cull_radius_units = farthest + top * sin(0.5 * largest_bend)


func _drawn_parts(plant: SunflowerPlant, level: int) -> Array[Mesh]:
	var parts: Array[Mesh] = []
	for part: int in PartMeshes.PART_NAMES.size():
		parts.append(for_field(plant, level, part))
	return parts
