@tool
extends RefCounted
## A plant's mesh levels from a scene (a glTF, .blend or .tscn plant): every visible MeshInstance3D
## in it, placed by its node transforms relative to the scene's root and drawn with the materials
## it shows (the node's material override, else its surface overrides, else the mesh's own), merged
## into one mesh per level, surfaces of the same material and vertex format into one surface.
##
## Levels: nodes named with a level-of-detail suffix ([code]_LOD0[/code], [code]-lod1[/code],
## [code]_lod_2[/code], any case) are the variants of that level (0, 1 and 2 are mesh levels 1, 2
## and 3; a node without a suffix belongs to every level). A scene without variants gets levels 2
## and 3 generated from level 1 ([code]plant_levels.gd[/code]). At every level, foliage cards that
## stand on the plant's base and span most of its height are cut into slices so that they bend
## ([code]card_slices.gd[/code]).

const WholePlantMesh: GDScript = preload("whole_plant_mesh.gd")
const ScenePieces: GDScript = preload("scene_pieces.gd")
const NodeSpace: GDScript = preload("node_space.gd")
const MeshPieces: GDScript = preload("mesh_pieces.gd")
const PlantLevels: GDScript = preload("plant_levels.gd")
const CardSlices: GDScript = preload("card_slices.gd")
const SurfaceTangents: GDScript = preload("surface_tangents.gd")
const PlantMaterial: GDScript = preload("plant_material.gd")


## The scene's three mesh levels as ArrayMeshes (null where the scene has nothing to draw), with
## [code]"generated"[/code] (whether levels 2 and 3 were simplified from level 1),
## [code]"triangles"[/code] (per level), [code]"instance_parameters"[/code] (the instance shader
## parameters its nodes set) and [code]"problems"[/code] (what was left out, and why).
static func levels_of(scene: PackedScene) -> Dictionary:
	var problems: PackedStringArray = []
	var root: Node = scene.instantiate() if scene else null
	if root == null:
		problems.append("the scene cannot be instantiated")
		return {"levels": [null, null, null], "generated": false, "triangles": [0, 0, 0], "problems": problems}
	var pieces: Array[Dictionary] = ScenePieces.of(root, problems)
	root.free()
	NodeSpace.keep(pieces, problems)
	var parameters: Dictionary = _instance_parameters(pieces, problems)
	var variants: bool = pieces.any(func(piece: Dictionary) -> bool: return piece.level >= 0)
	var levels: Array = []
	for level: int in 3 if variants else 1:
		var chosen: Array[Dictionary] = pieces.filter(
			func(piece: Dictionary) -> bool: return piece.level < 0 or piece.level == level
		)
		levels.append(_merge(chosen, problems))
	if variants:
		for level: int in [1, 2]:
			if levels[level] == null:
				levels[level] = levels[level - 1]  # fewer variants than levels: the last repeats
	else:
		levels.append_array(PlantLevels.generated(levels[0]))
	problems.append_array(PlantMaterial.kept_materials(levels))
	var bounds: AABB = levels[0].get_aabb() if levels[0] != null else AABB()
	var bendable: Dictionary = {}  # a level's mesh -> it with its tall cards sliced (a mesh repeats)
	for level: int in levels.size():
		if levels[level] != null:
			if not bendable.has(levels[level]):
				bendable[levels[level]] = _tall_cards_sliced(levels[level], bounds)
			levels[level] = bendable[levels[level]]
	return {
		"levels": levels,
		"generated": not variants,
		"triangles": levels.map(func(mesh: Mesh) -> int: return triangle_count(mesh)),
		"instance_parameters": parameters,
		"problems": problems,
	}


## A plant of one part made from [param scene] (see [method SunflowerPlant.from_scene]), or null
## with an error; warnings name the scene.
static func plant_of(scene: PackedScene) -> SunflowerPlant:
	var source: String = scene.resource_path if scene and scene.resource_path else "(unsaved scene)"
	var made: Dictionary = levels_of(scene)
	for problem: String in made.problems:
		push_warning("SunflowerPlant.from_scene: %s: %s" % [source, problem])
	var refused: String = refusal(made.levels[0])
	if not refused.is_empty():
		push_error("SunflowerPlant.from_scene: %s %s" % [source, refused])
		return null
	var placement: String = placement_problem(made.levels[0])
	if not placement.is_empty():
		push_warning("SunflowerPlant.from_scene: %s: %s" % [source, placement])
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.name = source.get_file().get_basename() if scene.resource_path else "Plant"
	plant.mesh_level_1 = [made.levels[0], null, null]
	plant.mesh_level_2 = [made.levels[1], null, null]
	plant.mesh_level_3 = [made.levels[2], null, null]
	plant.instance_shader_parameters = made.instance_parameters
	plant.fit_to_meshes()
	plant.height = plant.part_lengths.x
	plant.middle_variation = 0.0  # a plant of one part has no middle to stretch
	return plant


## The instance shader parameters the scene's nodes set, by name, for every part of the plant (the
## field draws all of a level with one node); a parameter two nodes set to different values is
## named in [param problems], the first node's value kept.
static func _instance_parameters(pieces: Array[Dictionary], problems: PackedStringArray) -> Dictionary:
	var parameters: Dictionary = {}
	var set_by: Dictionary = {}
	for piece: Dictionary in pieces:
		for parameter: String in piece.instance_parameters:
			var value: Variant = piece.instance_parameters[parameter]
			if not parameters.has(parameter):
				parameters[parameter] = value
				set_by[parameter] = piece.name
			elif parameters[parameter] != value:
				(
					problems
					. append(
						(
							"%s: its instance shader parameter '%s' is %s, but %s sets it to %s; the plant draws every part with %s's"
							% [
								piece.name,
								parameter,
								value,
								set_by[parameter],
								parameters[parameter],
								set_by[parameter]
							]
						)
					)
				)
	return parameters


## [param mesh] with the tall standing cards of its surfaces sliced so that they bend (level 1's
## [param bounds]; [code]card_slices.gd[/code]); itself when it has none.
static func _tall_cards_sliced(mesh: ArrayMesh, bounds: AABB) -> ArrayMesh:
	var sliced: ArrayMesh = ArrayMesh.new()
	var changed: bool = false
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		var cut: Array = CardSlices.sliced(arrays, bounds)
		changed = changed or cut != arrays
		sliced.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, cut)
		sliced.surface_set_material(surface, mesh.surface_get_material(surface))
	return sliced if changed else mesh


## Why [param mesh] (a plant's merged level 1) makes no plant, or "" when it makes one: nothing, or
## nothing with area (every point at one place, or scaled to nothing).
static func refusal(mesh: Mesh) -> String:
	if mesh == null:
		return "has no visible MeshInstance3D, MultiMeshInstance3D or CSG shape with triangles to make a plant of"
	var area: float = 0.0
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		area += PlantLevels.area(arrays[Mesh.ARRAY_VERTEX], arrays[Mesh.ARRAY_INDEX])
	if not area > 1e-8:
		return "draws no triangle with area (every point at one place, or scaled to nothing): no plant to make of it"
	return ""


## Where [param mesh] (a plant's merged level 1) stands off its root, or "": wholly below it, off to
## the side of it by more than half its own width, or starting above it by more than its own height.
static func placement_problem(mesh: Mesh) -> String:
	var box: AABB = mesh.get_aabb()
	if box.end.y <= 0.0:
		return (
			(
				"it stands wholly below its root (%.2f to %.2f m): its plants would be under the ground;"
				+ " move the scene's meshes up so that its base is at the root"
			)
			% [box.position.y, box.end.y]
		)
	var nearest: Vector2 = Vector2(clampf(0.0, box.position.x, box.end.x), clampf(0.0, box.position.z, box.end.z))
	if nearest.length() > 0.5 * maxf(box.size.x, box.size.z):
		return (
			(
				"it stands %.2f m from its root across the ground (its middle at x %.2f, z %.2f m), more than"
				+ " half its own width (%.2f m): its plants would stand off their cells, and their spacing"
				+ " follows its reach from the root; move the scene's meshes over the root"
			)
			% [nearest.length(), box.get_center().x, box.get_center().z, maxf(box.size.x, box.size.z)]
		)
	if box.position.y > box.size.y:
		return (
			(
				"it starts %.2f m above its root, more than its own height (%.2f m): its plants would float;"
				+ " move the scene's meshes down to the root"
			)
			% [box.position.y, box.size.y]
		)
	return ""


## The triangles [param mesh] draws (0 for null).
static func triangle_count(mesh: Mesh) -> int:
	if mesh == null:
		return 0
	var count: int = 0
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		var indices: Variant = arrays[Mesh.ARRAY_INDEX]
		count += (indices.size() if indices != null else (arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()) / 3
	return count


## One mesh of [param pieces] ([code]scene_pieces.gd[/code]), surfaces of the same material and
## vertex format merged; null when they draw nothing. A surface that is not of triangles, or whose
## positions are not all finite, is left out and named in [param problems].
static func _merge(pieces: Array[Dictionary], problems: PackedStringArray) -> ArrayMesh:
	var groups: Array[Dictionary] = []  # {material, format, arrays}
	for piece: Dictionary in pieces:
		var mesh: Mesh = piece.mesh
		for surface: int in mesh.get_surface_count():
			if (
				mesh is ArrayMesh
				and (mesh as ArrayMesh).surface_get_primitive_type(surface) != Mesh.PRIMITIVE_TRIANGLES
			):
				problems.append("%s: surface %d is not made of triangles; left out" % [piece.name, surface])
				continue
			var arrays: Array = mesh.surface_get_arrays(surface)
			if not (piece.weights as PackedFloat32Array).is_empty():
				arrays = ScenePieces.blended(
					arrays, (mesh as ArrayMesh).surface_get_blend_shape_arrays(surface), piece.weights
				)
			var unplaced: int = _non_finite(arrays[Mesh.ARRAY_VERTEX])
			if unplaced > 0:
				problems.append(
					(
						"%s: surface %d has %d vertex positions that are not finite numbers; left out"
						% [piece.name, surface, unplaced]
					)
				)
				continue
			arrays = SurfaceTangents.filled(arrays)
			var material: Material = piece.materials[surface]
			var format: Array = MeshPieces.VERTEX_ARRAYS.map(func(kind: int) -> bool: return arrays[kind] != null)
			var group: Dictionary = {}
			for candidate: Dictionary in groups:
				if candidate.material == material and candidate.format == format:
					group = candidate
			if group.is_empty():
				group = {"material": material, "format": format, "arrays": WholePlantMesh.empty_arrays()}
				groups.append(group)
			_append(group.arrays, arrays, piece.transform)
	if groups.is_empty():
		return null
	var merged: ArrayMesh = ArrayMesh.new()
	for group: Dictionary in groups:
		var arrays: Array = []
		arrays.resize(Mesh.ARRAY_MAX)
		for k: int in MeshPieces.VERTEX_ARRAYS.size():  # the arrays kept, each group of one format
			if group.format[k]:
				arrays[MeshPieces.VERTEX_ARRAYS[k]] = group.arrays[MeshPieces.VERTEX_ARRAYS[k]]
		arrays[Mesh.ARRAY_INDEX] = group.arrays[Mesh.ARRAY_INDEX]
		merged.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
		merged.surface_set_material(merged.get_surface_count() - 1, group.material)
	return merged


## How many of [param positions] are not finite.
static func _non_finite(positions: PackedVector3Array) -> int:
	var count: int = 0
	for position: Vector3 in positions:
		if not position.is_finite():
			count += 1
	return count


## Appends a surface's [param arrays] to [param merged], its positions, normals and tangents moved
## by [param transform] into the plant's frame.
static func _append(merged: Dictionary, arrays: Array, transform: Transform3D) -> void:
	var first: int = (merged[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()
	# A transform that scales to nothing draws nothing; its normals are kept as they are.
	var degenerate: bool = is_zero_approx(transform.basis.determinant())
	var normal_basis: Basis = Basis.IDENTITY if degenerate else transform.basis.inverse().transposed()
	var positions: PackedVector3Array = merged[Mesh.ARRAY_VERTEX]
	for position: Vector3 in arrays[Mesh.ARRAY_VERTEX]:
		positions.append(transform * position)
	merged[Mesh.ARRAY_VERTEX] = positions
	if arrays[Mesh.ARRAY_NORMAL] != null:
		var normals: PackedVector3Array = merged[Mesh.ARRAY_NORMAL]
		for normal: Vector3 in arrays[Mesh.ARRAY_NORMAL]:
			normals.append((normal_basis * normal).normalized())
		merged[Mesh.ARRAY_NORMAL] = normals
	if arrays[Mesh.ARRAY_TANGENT] != null:
		var tangents: PackedFloat32Array = merged[Mesh.ARRAY_TANGENT]
		var source: PackedFloat32Array = arrays[Mesh.ARRAY_TANGENT]
		for k: int in range(0, source.size(), 4):
			var turned: Vector3 = (transform.basis * Vector3(source[k], source[k + 1], source[k + 2])).normalized()
			# A mirroring transform flips the bitangent's side.
			var side: float = source[k + 3] * signf(transform.basis.determinant())
			tangents.append_array(PackedFloat32Array([turned.x, turned.y, turned.z, side]))
		merged[Mesh.ARRAY_TANGENT] = tangents
	for kind: int in [Mesh.ARRAY_COLOR, Mesh.ARRAY_TEX_UV, Mesh.ARRAY_TEX_UV2]:
		if arrays[kind] != null:
			var values: Variant = merged[kind]  # packed arrays are values: appended, then stored back
			values.append_array(arrays[kind])
			merged[kind] = values
	var indices: PackedInt32Array = merged[Mesh.ARRAY_INDEX]
	var source_indices: Variant = arrays[Mesh.ARRAY_INDEX]
	if source_indices == null:
		source_indices = range((arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size())
	var mirrored: bool = transform.basis.determinant() < 0.0
	for k: int in range(0, source_indices.size(), 3):
		# A mirroring transform turns the triangles' winding: keep their front faces in front.
		(
			indices
			. append_array(
				PackedInt32Array(
					[
						first + source_indices[k],
						first + source_indices[k + (1 if not mirrored else 2)],
						first + source_indices[k + (2 if not mirrored else 1)],
					]
				)
			)
		)
	merged[Mesh.ARRAY_INDEX] = indices
