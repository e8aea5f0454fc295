@tool
extends RefCounted
## A plant's levels 2 and 3 generated from its level 1 (a scene without level-of-detail variants,
## [code]scene_plant.gd[/code]): its foliage cards thinned to fewer, bigger leaves that keep level 1's
## cover ([code]mesh_pieces.gd[/code], [code]plant_cover.gd[/code]); its other surfaces (trunks,
## branches) simplified by the engine's simplifier ([method ImporterMesh.generate_lods]) to about
## [constant LEVEL_SHARES] of their triangles where a surface keeps [constant AREA_KEPT] of its area,
## or their smallest pieces dropped (twigs), the branches kept thickened (fewer, thicker twigs) where
## the level would cover less than [constant COVER_KEPT] of level 1.

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
## Card triangles above which a plant's cover is measured in one view, not five: measuring takes time
## in proportion to the triangles and views (tests/godot/bench/levels_bench.gd, performance.md table
## 17: a plant of 20 000 card triangles made in 5.1 s of blades, 9.2 s of broad cut-out cards).
const COVER_CARD_TRIANGLES: int = 20_000
## Triangles of other surfaces (trunks, branches, twigs) above which a plant's cover is measured in
## one view, not five.
const COVER_BRANCH_TRIANGLES: int = 40_000
## Triangles up to which a plant over [constant COVER_CARD_TRIANGLES] or
## [constant COVER_BRANCH_TRIANGLES] has its cover measured in one view, 45° above (a Sapling pine of
## 153 178 triangles made in 3.4 s, 1.9 s unmeasured); above it, the kept cards grow to the area of
## all the cards and the branches are kept as they are simplified.
const COVER_ONE_VIEW_TRIANGLES: int = 200_000
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
const MeshPieces: GDScript = preload("mesh_pieces.gd")
const PlantCover: GDScript = preload("plant_cover.gd")


## Levels 2 and 3 of [param mesh], a plant's merged level 1 ([code]mesh_pieces.gd[/code]): each
## surface of foliage cards keeps what makes the level [constant LEVEL_SHARES] of the whole mesh
## ([constant SMALL_PLANT_SHARES] for a small plant; at least [constant LEAST_CARD_SHARES] of its
## cards), grown until they cover what level 1's cards cover ([code]plant_cover.gd[/code]; not to the
## cover of all, which made up for the twigs the level dropped with leaves, a twiggy tree's far
## levels greener); any other surface is simplified to about [constant LEVEL_SHARES] of its
## triangles, by the engine's simplifier where that keeps [constant AREA_KEPT] of its area, else by
## dropping its smallest pieces (twigs, like ones spread round the plant), whichever keeps more
## area; where the level would cover less than [constant COVER_KEPT] of level 1, the kept branches
## keep more of their triangles (by [constant BRANCH_SHARE_STEP], up to [constant LEVEL_MOST_SHARES]
## of the plant) while even at their thickest ([constant BRANCH_THICKENING]) it would, then thicken
## as little as makes it cover that much ([method thickened]). The cover is measured in five views,
## or in one above [constant COVER_CARD_TRIANGLES] or [constant COVER_BRANCH_TRIANGLES]; above
## [constant COVER_ONE_VIEW_TRIANGLES] it is not: the kept cards grow to the area of all.
static func generated(mesh: ArrayMesh) -> Array:
	if mesh == null:
		return [null, null]
	var bounds: AABB = mesh.get_aabb()
	var importer: ImporterMesh = ImporterMesh.new()
	var pieces: Array[MeshPieces] = []
	var card_triangles: int = 0
	var triangles: int = 0
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		importer.add_surface(Mesh.PRIMITIVE_TRIANGLES, arrays, [], {}, mesh.surface_get_material(surface))
		pieces.append(MeshPieces.new(arrays))
		card_triangles += pieces[-1].piece_of.size() if pieces[-1].are_cards() else 0
		triangles += pieces[-1].piece_of.size()
	# The cover is measured where it takes a moment: in five views, or in one (45° above).
	var all_views: bool = (
		card_triangles <= COVER_CARD_TRIANGLES and triangles - card_triangles <= COVER_BRANCH_TRIANGLES
	)
	var measured: bool = all_views or triangles <= COVER_ONE_VIEW_TRIANGLES
	var views: Array[Vector3] = PlantCover.VIEWS if all_views else ([PlantCover.VIEWS[3]] as Array[Vector3])
	var masks: Array[Dictionary] = []  # per surface: where its texture is cut out
	var leaves: Dictionary = PlantCover.empty(bounds, views)  # what level 1's cards cover
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
			_cover_growth(pieces, masks, card_share, bounds, PlantCover.covered(leaves), views)
			if measured and card_triangles > 0
			else 1.0
		)
		var cards: Array = []  # per surface: its thinned cards, or null for a branch
		var cards_kept: int = 0
		var cards_cover: Dictionary = PlantCover.empty(bounds, views)
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
		var thickest_cover: int = _cover_with(cards_cover, branches, masks, thickest) if measure_branches else 0
		while measure_branches and branch_share < 1.0 and thickest_cover < least_cover:
			branch_share = minf(1.0, branch_share * BRANCH_SHARE_STEP)
			var more: Array = _branches(importer, pieces, branch_share)
			if more[-1] + cards_kept > most:
				break
			branches = more
			thickest_cover = _cover_with(cards_cover, branches, masks, thickest)
		var thickness: float = 0.0
		var thin_cover: int = _cover_with(cards_cover, branches, masks, 0.0) if measure_branches else 0
		# (Thickening that covers nothing more, as a ribbon's, moves it for nothing: it is left as it is.)
		if measure_branches and thin_cover < least_cover and thickest_cover > thin_cover:
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
	var least_area: float = AREA_KEPT * area(positions, arrays[Mesh.ARRAY_INDEX])
	var candidates: Array[Array] = [arrays, pieces.biggest(share)]
	for lod: int in importer.get_surface_lod_count(surface):
		var indices: PackedInt32Array = importer.get_surface_lod_indices(surface, lod)
		if area(positions, indices) >= least_area:
			var simpler: Array = arrays.duplicate()
			simpler[Mesh.ARRAY_INDEX] = indices
			candidates.append(simpler)
	var best: Array = arrays
	var best_area: float = -1.0
	for candidate: Array in candidates:
		var size: int = (candidate[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 3
		var kept_area: float = area(candidate[Mesh.ARRAY_VERTEX], candidate[Mesh.ARRAY_INDEX])
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
	pieces: Array[MeshPieces], masks: Array[Dictionary], share: float, bounds: AABB, target: int, views: Array[Vector3]
) -> float:
	var low: float = 0.25
	var high: float = 2.0
	for step: int in COVER_STEPS:
		var middle: float = sqrt(low * high)
		var cover: Dictionary = PlantCover.empty(bounds, views)
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
static func area(positions: PackedVector3Array, indices: PackedInt32Array) -> float:
	var area: float = 0.0
	for k: int in range(0, indices.size() - 2, 3):
		var a: Vector3 = positions[indices[k]]
		area += 0.5 * (positions[indices[k + 1]] - a).cross(positions[indices[k + 2]] - a).length()
	return area
