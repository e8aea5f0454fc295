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
## area, or its smallest pieces dropped (twigs), the branches kept thickened where the level would
## cover less than [constant COVER_KEPT] of level 1, and its foliage cards thinned to fewer, bigger
## leaves ([code]mesh_pieces.gd[/code]). At every level, foliage cards that stand on the plant's base and
## span most of its height are cut into slices so that they bend ([code]card_slices.gd[/code]).

## The share of level 1's triangles each mesh level is simplified to when the scene has no variants.
const LEVEL_SHARES: Array[float] = [1.0, 0.5, 0.2]
## A plant of fewer triangles than this at level 1 is cheap wherever it is drawn as meshes (its
## levels of detail follow its size: a small plant's meshes end a few metres away): its levels keep
## [constant SMALL_PLANT_SHARES] of them, so that its few leaves or blades stay what they were.
const SMALL_PLANT: int = 1000
const SMALL_PLANT_SHARES: Array[float] = [1.0, 0.75, 0.5]
## The least share of a surface's area a simplified level keeps (thin branches lose some as their
## sides merge; a surface that would lose more keeps its triangles).
const AREA_KEPT: float = 0.8
## The least share of a surface of cards (leaves, blades) each mesh level keeps: the cards keep what
## makes the level [constant LEVEL_SHARES] of the whole, but no fewer than this share of them (a tree
## whose trunk the simplifier cannot thin keeps this much of its crown).
const LEAST_CARD_SHARES: Array[float] = [1.0, 0.25, 0.1]
## Card triangles above which the kept cards grow to the area of all instead of to the cover measured:
## measuring takes time in proportion to the cards (tests/godot/bench/levels_bench.gd, performance.md
## table 17: a plant of 20 000 card triangles made in 4.9 s of blades, 9.4 s of broad cut-out cards;
## of 40 000, 3.9 s unmeasured, 9.7 s and 18.2 s measured).
const COVER_CARD_TRIANGLES: int = 20_000
## Triangles of other surfaces (trunks, branches, twigs) above which a generated level's cover is not
## measured, its branches kept at [constant LEVEL_SHARES] as they come.
const COVER_BRANCH_TRIANGLES: int = 40_000
## The least share of level 1's cover (the whole plant's, [code]plant_cover.gd[/code]) a generated
## level keeps where the cover is measured: where its simplified branches lose more (a twiggy tree,
## whose twigs are most of what it covers: a Sapling weeping willow's mesh 3 covered 0.63 of mesh 1),
## the branches kept thicken (fewer, thicker twigs; up to [constant BRANCH_THICKENING]), and where
## that is not enough they keep more of their triangles, up to [constant LEVEL_MOST_SHARES] of the
## plant's.
const COVER_KEPT: float = 0.9
## The most of level 1's triangles a generated level of a plant of [constant SMALL_PLANT] or more
## draws when its branches keep more of theirs for the cover ([constant COVER_KEPT]).
const LEVEL_MOST_SHARES: Array[float] = [1.0, 0.55, 0.3]
## How far a generated level's branches may thicken ([constant COVER_KEPT]), in cells of
## [code]plant_cover.gd[/code] (a 64th of the plant's longest side: under a pixel at 640 × 360 where
## level 3 begins, about two at 1 920 × 1 080).
const BRANCH_THICKENING: Array[float] = [0.0, 0.5, 1.0]
## How much more of their triangles the branches keep at each step towards [constant COVER_KEPT].
const BRANCH_SHARE_STEP: float = 1.25
## Bisection steps that find how much the kept cards of a level grow (to within 8^(1 / 2^steps)).
const COVER_STEPS: int = 5
## The engine importer's defaults for the simplifier's normal angles, degrees.
const NORMAL_MERGE_ANGLE: float = 60.0
const NORMAL_SPLIT_ANGLE: float = 25.0
const WholePlantMesh: GDScript = preload("whole_plant_mesh.gd")
const ScenePieces: GDScript = preload("scene_pieces.gd")
const NodeSpace: GDScript = preload("node_space.gd")
const MeshPieces: GDScript = preload("mesh_pieces.gd")
const PlantCover: GDScript = preload("plant_cover.gd")
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
		levels.append_array(_simplified(levels[0]))
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
		area += _area(arrays[Mesh.ARRAY_VERTEX], arrays[Mesh.ARRAY_INDEX])
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


## Levels 2 and 3 of [param mesh] ([code]mesh_pieces.gd[/code]): each surface of foliage cards keeps
## what makes the level [constant LEVEL_SHARES] of the whole mesh ([constant SMALL_PLANT_SHARES] for a
## small plant; at least [constant LEAST_CARD_SHARES]
## of its cards), grown until they cover what level 1's cards cover ([code]plant_cover.gd[/code]; to
## the area of all when there are more than [constant COVER_CARD_TRIANGLES] card triangles: not to the
## cover of all, which made up for the twigs the level dropped with leaves, a twiggy tree's far levels
## greener); any
## other surface is simplified to about [constant LEVEL_SHARES] of its triangles, by the engine's
## simplifier where that keeps [constant AREA_KEPT] of its area, else by dropping its smallest pieces
## (twigs, like ones spread round the plant), whichever keeps more area; where the level would cover
## less than [constant COVER_KEPT] of level 1 (where the cover is measured:
## [constant COVER_CARD_TRIANGLES], [constant COVER_BRANCH_TRIANGLES]), the kept branches keep more
## of their triangles (by [constant BRANCH_SHARE_STEP], up to [constant LEVEL_MOST_SHARES] of the
## plant) while even at their thickest ([constant BRANCH_THICKENING]) it would, then thicken as little
## as makes it cover that much ([method thickened]).
static func _simplified(mesh: ArrayMesh) -> Array:
	if mesh == null:
		return [null, null]
	var bounds: AABB = mesh.get_aabb()
	var importer: ImporterMesh = ImporterMesh.new()
	var pieces: Array[MeshPieces] = []
	var card_triangles: int = 0
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		importer.add_surface(Mesh.PRIMITIVE_TRIANGLES, arrays, [], {}, mesh.surface_get_material(surface))
		pieces.append(MeshPieces.new(arrays))
		card_triangles += pieces[-1].piece_of.size() if pieces[-1].are_cards() else 0
	var triangles: int = triangle_count(mesh)
	# The cover is measured where the plant is small enough for it to take a moment.
	var measured: bool = card_triangles <= COVER_CARD_TRIANGLES and triangles - card_triangles <= COVER_BRANCH_TRIANGLES
	var masks: Array[Dictionary] = []  # per surface: where its texture is cut out
	var leaves: Dictionary = PlantCover.empty(bounds)  # what level 1's cards cover
	for surface: int in mesh.get_surface_count() if measured else 0:
		masks.append(PlantCover.cut_out(mesh.surface_get_material(surface)))
		if pieces[surface].are_cards():
			PlantCover.draw(leaves, pieces[surface].arrays, masks[-1])
	var whole: Dictionary = PlantCover.copied(leaves)  # what level 1 covers
	for surface: int in mesh.get_surface_count() if measured else 0:
		if not pieces[surface].are_cards():
			PlantCover.draw(whole, pieces[surface].arrays, masks[surface])
	importer.generate_lods(NORMAL_MERGE_ANGLE, NORMAL_SPLIT_ANGLE, [])
	var shares: Array[float] = LEVEL_SHARES if triangles >= SMALL_PLANT else SMALL_PLANT_SHARES
	var measure_branches: bool = measured and card_triangles < triangles  # the level's cover, its branches'
	var out: Array = []
	for level: int in [1, 2]:
		var branch_share: float = shares[level]
		var branches: Array = _branches(importer, pieces, branch_share)
		var card_share: float = (
			clampf((shares[level] * triangles - branches[-1]) / card_triangles, LEAST_CARD_SHARES[level], shares[level])
			if card_triangles > 0
			else 1.0
		)
		var growth: float = (
			_cover_growth(pieces, masks, card_share, bounds, PlantCover.covered(leaves))
			if measured and card_triangles > 0
			else 1.0
		)
		var cards: Array = []  # per surface: its thinned cards, or null for a branch
		var cards_kept: int = 0
		var cards_cover: Dictionary = PlantCover.empty(bounds)
		for surface: int in pieces.size():
			cards.append(null)
			if pieces[surface].are_cards():
				var pieces_of: MeshPieces = pieces[surface]
				cards[-1] = pieces_of.cards_thinned(card_share, growth * pieces_of.area_growth(card_share), bounds)
				cards_kept += (cards[-1][Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3
				if measure_branches:
					PlantCover.draw(cards_cover, cards[-1], masks[surface])
		# Branches keep more of their triangles while the level, its branches at their thickest, covers
		# less than COVER_KEPT of level 1; then they thicken as little as makes it cover that much.
		var most: float = maxf(shares[level], LEVEL_MOST_SHARES[level]) * triangles
		var least_cover: float = COVER_KEPT * PlantCover.covered(whole)
		var thickest: float = BRANCH_THICKENING[level] * bounds.get_longest_axis_size() / PlantCover.CELLS
		while (
			measure_branches
			and branch_share < 1.0
			and _cover_with(cards_cover, branches, masks, thickest) < least_cover
		):
			branch_share = minf(1.0, branch_share * BRANCH_SHARE_STEP)
			var more: Array = _branches(importer, pieces, branch_share)
			if more[-1] + cards_kept > most:
				break
			branches = more
		var thickness: float = 0.0
		var thin_cover: int = _cover_with(cards_cover, branches, masks, 0.0) if measure_branches else 0
		# (Thickening that covers nothing more, as a ribbon's, moves it for nothing: it is left as it is.)
		if (
			measure_branches
			and thin_cover < least_cover
			and _cover_with(cards_cover, branches, masks, thickest) > thin_cover
		):
			var low: float = 0.0
			var high: float = thickest
			for step: int in COVER_STEPS:
				var middle: float = 0.5 * (low + high)
				if _cover_with(cards_cover, branches, masks, middle) < least_cover:
					low = middle
				else:
					high = middle
			thickness = high
		for surface: int in pieces.size():
			if cards[surface] == null:
				branches[surface] = thickened(branches[surface], thickness)
		var simpler: ArrayMesh = ArrayMesh.new()
		var simplified: bool = false
		for surface: int in importer.get_surface_count():
			var arrays: Array = cards[surface] if cards[surface] != null else branches[surface]
			simplified = simplified or arrays[Mesh.ARRAY_INDEX] != pieces[surface].arrays[Mesh.ARRAY_INDEX]
			simpler.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
			simpler.surface_set_material(surface, importer.get_surface_material(surface))
		out.append(simpler if simplified else (out[-1] if level == 2 and out[-1] != mesh else mesh))
	return out


## The cells [param cards_cover] and [param branches] (of [method _branches]) thickened by
## [param thickness] cover together, each surface cut out by its [param masks].
static func _cover_with(cards_cover: Dictionary, branches: Array, masks: Array[Dictionary], thickness: float) -> int:
	var cover: Dictionary = PlantCover.copied(cards_cover)
	for surface: int in branches.size() - 1:
		if branches[surface] != null:
			PlantCover.draw(cover, thickened(branches[surface], thickness), masks[surface])
	return PlantCover.covered(cover)


## [param arrays] with each vertex moved [param thickness] metres out along the surface's normal
## where it is (its vertices' normals there summed, or where it has none its triangles', each by its
## angle there, for the surface to stay closed): a twig of a centimetre thickened by one grows to
## three, a trunk of half a metre hardly changes.
static func thickened(arrays: Array, thickness: float) -> Array:
	if thickness <= 0.0:
		return arrays
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var outward: Dictionary = {}  # position: its vertices' normals summed
	if arrays[Mesh.ARRAY_NORMAL] != null:
		var normals: PackedVector3Array = arrays[Mesh.ARRAY_NORMAL]
		for vertex: int in positions.size():
			outward[positions[vertex]] = outward.get(positions[vertex], Vector3.ZERO) + normals[vertex]
	else:
		var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
		for k: int in range(0, indices.size() - 2, 3):
			var a: Vector3 = positions[indices[k]]
			# The engine's front faces wind clockwise: their normal is (c - a) × (b - a).
			var normal: Vector3 = (positions[indices[k + 2]] - a).cross(positions[indices[k + 1]] - a).normalized()
			for corner: int in 3:
				var at: Vector3 = positions[indices[k + corner]]
				var to_next: Vector3 = positions[indices[k + (corner + 1) % 3]] - at
				var to_last: Vector3 = positions[indices[k + (corner + 2) % 3]] - at
				# Weighed by the triangle's angle there: a face counts alike however it is cut.
				outward[at] = outward.get(at, Vector3.ZERO) + normal * to_next.angle_to(to_last)
	var moved: PackedVector3Array = positions.duplicate()
	for vertex: int in positions.size():
		var normal: Vector3 = outward.get(positions[vertex], Vector3.ZERO)
		if normal.length_squared() > 1e-12:
			moved[vertex] = positions[vertex] + normal.normalized() * thickness
	var out: Array = arrays.duplicate()
	out[Mesh.ARRAY_VERTEX] = moved
	return out


## The surfaces of [param importer] that are not cards, each simplified to about [param share] of its
## triangles ([method _simpler_surface]; null for a surface of cards), then the triangles they keep.
static func _branches(importer: ImporterMesh, pieces: Array[MeshPieces], share: float) -> Array:
	var out: Array = []
	var kept: int = 0
	for surface: int in importer.get_surface_count():
		if pieces[surface].are_cards():
			out.append(null)
			continue
		out.append(_simpler_surface(importer, surface, pieces[surface], share))
		kept += (out[-1][Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3
	out.append(kept)
	return out


## A surface (not of cards) of [param importer] with about [param share] of its triangles: of the
## engine's levels of detail that keep [constant AREA_KEPT] of its area and its biggest pieces, the
## one that keeps the most area at no more than a tenth above the share, else the nearest to it.
static func _simpler_surface(importer: ImporterMesh, surface: int, pieces: MeshPieces, share: float) -> Array:
	var arrays: Array = importer.get_surface_arrays(surface)
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var wanted: float = (arrays[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3.0 * share
	var least_area: float = AREA_KEPT * _area(positions, arrays[Mesh.ARRAY_INDEX])
	var candidates: Array[Array] = [arrays, pieces.biggest(share)]
	for lod: int in importer.get_surface_lod_count(surface):
		var indices: PackedInt32Array = importer.get_surface_lod_indices(surface, lod)
		if _area(positions, indices) >= least_area:
			var simpler: Array = arrays.duplicate()
			simpler[Mesh.ARRAY_INDEX] = indices
			candidates.append(simpler)
	var best: Array = arrays
	var best_area: float = -1.0
	for candidate: Array in candidates:
		var size: int = (candidate[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3
		var kept_area: float = _area(candidate[Mesh.ARRAY_VERTEX], candidate[Mesh.ARRAY_INDEX])
		if size <= 1.1 * wanted and kept_area > best_area:
			best = candidate
			best_area = kept_area
	if best_area < 0.0:
		for candidate: Array in candidates:
			var size: int = (candidate[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3
			if absf(size - wanted) < absf((best[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3 - wanted):
				best = candidate
	return best


## How much more than to their area the cards of [param pieces] kept at [param share] grow for the
## level to cover [param target] cells, each surface cut out by its [param masks]: found by bisection
## between a quarter and twice (less than once where the cards overlap less once fewer).
static func _cover_growth(
	pieces: Array[MeshPieces], masks: Array[Dictionary], share: float, bounds: AABB, target: int
) -> float:
	var low: float = 0.25
	var high: float = 2.0
	for step: int in COVER_STEPS:
		var middle: float = sqrt(low * high)
		var cover: Dictionary = PlantCover.empty(bounds)
		for surface: int in pieces.size():
			if pieces[surface].are_cards():
				var thin: Array = pieces[surface].cards_thinned(
					share, middle * pieces[surface].area_growth(share), bounds
				)
				PlantCover.draw(cover, thin, masks[surface])
		if PlantCover.covered(cover) < target:
			low = middle
		else:
			high = middle
	return sqrt(low * high)


## The area of the triangles [param indices] make of [param positions].
static func _area(positions: PackedVector3Array, indices: PackedInt32Array) -> float:
	var area: float = 0.0
	for k: int in range(0, indices.size() - 2, 3):
		var a: Vector3 = positions[indices[k]]
		area += 0.5 * (positions[indices[k + 1]] - a).cross(positions[indices[k + 2]] - a).length()
	return area
