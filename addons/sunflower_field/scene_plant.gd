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

static var _suffix: RegEx


## The scene's three mesh levels as ArrayMeshes (null where the scene has nothing to draw), with
## [code]"generated"[/code] (whether levels 2 and 3 were simplified from level 1),
## [code]"triangles"[/code] (per level) and [code]"problems"[/code] (what was left out, and why).
static func levels_of(scene: PackedScene) -> Dictionary:
	var problems: PackedStringArray = []
	var root: Node = scene.instantiate() if scene else null
	if root == null:
		problems.append("the scene cannot be instantiated")
		return {"levels": [null, null, null], "generated": false, "triangles": [0, 0, 0], "problems": problems}
	var pieces: Array[Dictionary] = []  # {node, transform, level (-1: every level)}
	_collect(root, Transform3D.IDENTITY, pieces, problems, true)
	var variants: bool = pieces.any(func(piece: Dictionary) -> bool: return piece.level >= 0)
	var levels: Array = []
	for level: int in 3 if variants else 1:
		var chosen: Array[Dictionary] = pieces.filter(
			func(piece: Dictionary) -> bool: return piece.level < 0 or piece.level == level
		)
		levels.append(_merge(chosen, problems))
	root.free()
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


## The level of detail a node's name marks (0, 1, 2 …), or -1 for none.
static func level_of_name(node_name: String) -> int:
	if _suffix == null:
		_suffix = RegEx.create_from_string("(?i)[_\\-. ]lod[_\\-]?(\\d+)$")
	var found: RegExMatch = _suffix.search(node_name)
	return found.get_string(1).to_int() if found else -1


static func _collect(
	node: Node, to_root: Transform3D, pieces: Array[Dictionary], problems: PackedStringArray, is_root: bool
) -> void:
	var here: Transform3D = to_root
	if node is Node3D:
		if not (node as Node3D).visible:
			return
		if not is_root:  # the plant's root stands at the scene root's origin
			here = to_root * (node as Node3D).transform
	if node is MeshInstance3D and (node as MeshInstance3D).mesh != null:
		var level: int = level_of_name(node.name)
		if level > 2:
			problems.append("%s: level of detail %d is past the three mesh levels; left out" % [node.name, level])
		else:
			pieces.append({"node": node, "transform": here, "level": level})
	for child: Node in node.get_children():
		_collect(child, here, pieces, problems, false)


## One mesh of [param pieces], surfaces of the same material and vertex format merged; null when
## they draw nothing.
static func _merge(pieces: Array[Dictionary], problems: PackedStringArray) -> ArrayMesh:
	var groups: Array[Dictionary] = []  # {material, format, arrays}
	for piece: Dictionary in pieces:
		var instance: MeshInstance3D = piece.node
		var mesh: Mesh = instance.mesh
		for surface: int in mesh.get_surface_count():
			if (
				mesh is ArrayMesh
				and (mesh as ArrayMesh).surface_get_primitive_type(surface) != Mesh.PRIMITIVE_TRIANGLES
			):
				problems.append("%s: surface %d is not made of triangles; left out" % [instance.name, surface])
				continue
			var arrays: Array = mesh.surface_get_arrays(surface)
			var material: Material = _material_shown(instance, surface)
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


## The material a MeshInstance3D shows on [param surface].
static func _material_shown(instance: MeshInstance3D, surface: int) -> Material:
	if instance.material_override:
		return instance.material_override
	var override: Material = instance.get_surface_override_material(surface)
	return override if override else instance.mesh.surface_get_material(surface)


## Appends a surface's [param arrays] to [param merged], its positions, normals and tangents moved
## by [param transform] into the plant's frame.
static func _append(merged: Dictionary, arrays: Array, transform: Transform3D) -> void:
	var first: int = (merged[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()
	var normal_basis: Basis = transform.basis.inverse().transposed()
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
