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
## and 3 simplified from level 1 by the engine's mesh simplifier ([method ImporterMesh.generate_lods]),
## to about [constant LEVEL_SHARES] of its triangles where a surface keeps [constant AREA_KEPT] of its
## area; surfaces of cards ([constant CARD_TRIANGLES]) keep every card.

## The share of level 1's triangles each mesh level is simplified to when the scene has no variants.
const LEVEL_SHARES: Array[float] = [1.0, 0.5, 0.2]
## The vertex arrays a merged surface keeps; surfaces merge only with others that have the same.
const KEPT: Array[int] = [
	Mesh.ARRAY_VERTEX, Mesh.ARRAY_NORMAL, Mesh.ARRAY_TANGENT, Mesh.ARRAY_COLOR, Mesh.ARRAY_TEX_UV, Mesh.ARRAY_TEX_UV2
]
## The least share of a surface's area a simplified level keeps (thin branches lose some as their
## sides merge; a surface that would lose more keeps its triangles).
const AREA_KEPT: float = 0.8
## A surface of at most this many triangles per connected piece is of cards (leaves, blades): the
## simplifier would drop whole cards, and a crown that lost its leaves no longer looks like the
## plant, so such a surface keeps every card at every level.
const CARD_TRIANGLES: float = 4.0
## The engine importer's defaults for the simplifier's normal angles, degrees.
const NORMAL_MERGE_ANGLE: float = 60.0
const NORMAL_SPLIT_ANGLE: float = 25.0
const WholePlantMesh: GDScript = preload("whole_plant_mesh.gd")
const ScenePieces: GDScript = preload("scene_pieces.gd")


## The scene's three mesh levels as ArrayMeshes (null where the scene has nothing to draw), with
## [code]"generated"[/code] (whether levels 2 and 3 were simplified from level 1),
## [code]"triangles"[/code] (per level) and [code]"problems"[/code] (what was left out, and why).
static func levels_of(scene: PackedScene) -> Dictionary:
	var problems: PackedStringArray = []
	var root: Node = scene.instantiate() if scene else null
	if root == null:
		problems.append("the scene cannot be instantiated")
		return {"levels": [null, null, null], "generated": false, "triangles": [0, 0, 0], "problems": problems}
	var pieces: Array[Dictionary] = ScenePieces.of(root, problems)
	root.free()
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
		levels.append_array(_simplified(levels[0]))
	return {
		"levels": levels,
		"generated": not variants,
		"triangles": levels.map(func(mesh: Mesh) -> int: return triangle_count(mesh)),
		"problems": problems,
	}


## Why [param mesh] (a plant's merged level 1) makes no plant, or "" when it makes one: nothing, or
## nothing with area (every point at one place, or scaled to nothing).
static func refusal(mesh: Mesh) -> String:
	if mesh == null:
		return "has no visible MeshInstance3D, MultiMeshInstance3D or CSG shape with triangles to make a plant of"
	var area: float = 0.0
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		area += _area(arrays[Mesh.ARRAY_VERTEX], arrays[Mesh.ARRAY_INDEX])
	if not area > 1e-8:
		return "draws no triangle with area (every point at one place, or scaled to nothing): no plant to make of it"
	return ""


## Where [param mesh] (a plant's merged level 1) stands off its root, or "": wholly below it, or
## starting above it by more than its own height.
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
			var material: Material = piece.materials[surface]
			var format: Array = KEPT.map(func(kind: int) -> bool: return arrays[kind] != null)
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
		for k: int in KEPT.size():
			if group.format[k]:
				arrays[KEPT[k]] = group.arrays[KEPT[k]]
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


## Levels 2 and 3 of [param mesh]: its surfaces simplified to about [constant LEVEL_SHARES] of their
## triangles, keeping [constant AREA_KEPT] of their area; surfaces of cards, and those the simplifier
## cannot reduce so, keep their own triangles.
static func _simplified(mesh: ArrayMesh) -> Array:
	if mesh == null:
		return [null, null]
	var importer: ImporterMesh = ImporterMesh.new()
	for surface: int in mesh.get_surface_count():
		importer.add_surface(
			Mesh.PRIMITIVE_TRIANGLES, mesh.surface_get_arrays(surface), [], {}, mesh.surface_get_material(surface)
		)
	importer.generate_lods(NORMAL_MERGE_ANGLE, NORMAL_SPLIT_ANGLE, [])
	var out: Array = []
	for level: int in [1, 2]:
		var simplified: bool = false
		var simpler: ArrayMesh = ArrayMesh.new()
		for surface: int in importer.get_surface_count():
			var arrays: Array = importer.get_surface_arrays(surface)
			var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
			var best: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
			var wanted: float = best.size() * LEVEL_SHARES[level]
			var least_area: float = AREA_KEPT * _area(positions, best)
			var cards: bool = best.size() / 3.0 <= CARD_TRIANGLES * _pieces(best, positions.size())
			for lod: int in 0 if cards else importer.get_surface_lod_count(surface):
				var indices: PackedInt32Array = importer.get_surface_lod_indices(surface, lod)
				if (
					absf(indices.size() - wanted) < absf(best.size() - wanted)
					and _area(positions, indices) >= least_area
				):
					best = indices
			simplified = simplified or best != arrays[Mesh.ARRAY_INDEX]
			arrays[Mesh.ARRAY_INDEX] = best
			simpler.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
			simpler.surface_set_material(surface, importer.get_surface_material(surface))
		out.append(simpler if simplified else (out[-1] if level == 2 and out[-1] != mesh else mesh))
	return out


## The area of the triangles [param indices] make of [param positions].
static func _area(positions: PackedVector3Array, indices: PackedInt32Array) -> float:
	var area: float = 0.0
	for k: int in range(0, indices.size() - 2, 3):
		var a: Vector3 = positions[indices[k]]
		area += 0.5 * (positions[indices[k + 1]] - a).cross(positions[indices[k + 2]] - a).length()
	return area


## How many connected pieces the triangles [param indices] make of [param vertex_count] vertices.
static func _pieces(indices: PackedInt32Array, vertex_count: int) -> int:
	var parent: PackedInt32Array = range(vertex_count)
	var pieces: int = vertex_count
	for k: int in indices.size():
		var a: int = _root_of(parent, indices[k - k % 3])
		var b: int = _root_of(parent, indices[k])
		if a != b:
			parent[b] = a
			pieces -= 1
	var used: Dictionary = {}
	for index: int in indices:
		used[index] = true
	return pieces - (vertex_count - used.size())  # vertices no triangle uses are no piece


static func _root_of(parent: PackedInt32Array, vertex: int) -> int:
	while parent[vertex] != vertex:
		parent[vertex] = parent[parent[vertex]]
		vertex = parent[vertex]
	return vertex
