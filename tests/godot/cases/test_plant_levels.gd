extends TestCase
## A plant's generated mesh levels (plant_levels.gd, mesh_pieces.gd, plant_cover.gd): fewer triangles, the foliage
## cards thinned to fewer and bigger ones, the cover kept where each level begins; tall standing cards
## sliced so that they bend (card_slices.gd).

const Picture: GDScript = preload("res://runner/picture.gd")
const Stage: GDScript = preload("res://runner/stage.gd")
const Maps: GDScript = preload("res://runner/maps.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")
const ScenePlant: GDScript = preload("res://addons/sunflower_field/plant/scene_plant.gd")
const PlantLevels: GDScript = preload("res://addons/sunflower_field/plant/plant_levels.gd")
const MeshPieces: GDScript = preload("res://addons/sunflower_field/plant/mesh_pieces.gd")
const CardSlices: GDScript = preload("res://addons/sunflower_field/plant/card_slices.gd")
const PlantCover: GDScript = preload("res://addons/sunflower_field/plant/plant_cover.gd")
## The Sapling test plants (TEST_PLANTS in TEST_PLANT_FOLDER).
const ScenePlantTests: GDScript = preload("res://cases/test_scene_plant.gd")

var stage: Node3D


func after_each() -> void:
	if stage:
		stage.free()
		stage = null


## Generated levels thin a plant's foliage cards: mesh 2 draws at most 55 % and mesh 3 at most 30 %
## of mesh 1's triangles for each test plant of 1 000 or more (the maple, the bush, a curtain of
## twigs), a plant of a few dozen cards (the grass clump, a bush of 36 cards) thins too, and each
## level, seen alone from where it begins (45° above, no shadows), shows within ±10 % of the
## leaf-green pixels mesh 1 shows there, and covers 0.85 to 1.1 of the pixels it covers: the twigs
## the simplifier drops are not made up for by bigger leaves (grown to the cover of all, the maple's
## mesh 3 showed 1.37 times mesh 1's leaf green, a weeping willow's 2.2 times: far trees turned
## greener), but by the branches kept, thicker (or more of them): kept at their share as they came,
## the twig curtain's mesh 3 covered 0.70 (0.75 with more of them alone, at most 30 % of the
## plant), with 1.24 of its leaf green (the maple's 0.86); its like twigs kept in the order they were
## made, not spread round it, 0.85 of the cells (plant_cover.gd). The card bush, of
## positions and UVs alone, is drawn without the engine's warning of a mesh without tangents (23 of
## them before).
func test_generated_levels_thin_the_cards_and_keep_the_cover() -> void:
	var scenes: Dictionary = {"card_bush": _card_bush(), "twig_curtain": Scenes.twig_curtain(48)}
	for file: String in ScenePlantTests.TEST_PLANTS:
		scenes[file.get_basename()] = load(ScenePlantTests.TEST_PLANT_FOLDER.path_join(file)) as PackedScene
	var figures: PackedStringArray = []
	for plant_name: String in scenes:
		var plant: SunflowerPlant = SunflowerPlant.from_scene(scenes[plant_name])
		if not check(plant != null, "%s: a plant is made of the scene" % plant_name):
			continue
		var triangles: Array = [1, 2, 3].map(
			func(level: int) -> int: return ScenePlant.triangle_count(plant.get("mesh_level_%d" % level)[0])
		)
		var shares: Vector2 = Vector2(triangles[1], triangles[2]) / float(triangles[0])
		check(
			triangles[2] < triangles[1] and triangles[1] < triangles[0],
			"%s: each level has fewer triangles (%d / %d / %d)" % ([plant_name] + triangles)
		)
		if triangles[0] >= 1000:
			check(
				shares.x <= 0.55 and shares.y <= 0.30,
				(
					"%s: mesh 2 and 3 draw %.2f and %.2f of mesh 1's triangles, at most 0.55 and 0.30"
					% [plant_name, shares.x, shares.y]
				)
			)
		var staged: Stage = Stage.new(tree.root)
		stage = staged.root
		plant.yaw_range = 0.0
		var field: SunflowerField = staged.lone_plant(plant, Maps.filled(1, 1, "user://one_thinned_plant.field"))
		var camera: Camera3D = tree.root.get_camera_3d()
		var root: Vector3 = field.get_plant_info(0)["position"]
		var middle: Vector3 = root + Vector3(0.0, plant.height * 0.5, 0.0)
		var covers: PackedStringArray = []
		for level: int in [1, 2]:
			var begins: float = field.lod_distances[level - 1] * plant.lod_scale_used()
			camera.look_at_from_position(middle + Vector3(0.0, 1.0, 1.0).normalized() * begins, middle)
			var seen: Array[Vector3] = []  # pixels covered and leaf green, mesh 1's then the level's
			for drawn: int in [0, level]:
				field.force_lod = drawn
				field.advance(0.0)
				await frames(3)
				var image: Image = tree.root.get_viewport().get_texture().get_image()
				image.save_png(artifact_path("thinned_%s_mesh%d_at_mesh%d.png" % [plant_name, drawn + 1, level + 1]))
				seen.append(Picture.covered_green_light(image))
			var cover: float = seen[1].x / maxf(seen[0].x, 1.0)
			var green: float = seen[1].y / maxf(seen[0].y, 1.0)
			covers.append("%.2f / %.2f" % [green, cover])
			check(
				absf(green - 1.0) <= 0.1,
				(
					(
						"%s: mesh %d shows %.2f of mesh 1's leaf-green pixels (%d of %d) from %.1f m, where it begins;"
						+ " within ±10 %%"
					)
					% [plant_name, level + 1, green, seen[1].y, seen[0].y, begins]
				)
			)
			check(
				cover >= 0.85 and cover <= 1.1,
				(
					"%s: mesh %d covers %.2f of mesh 1's pixels (%d of %d) from %.1f m; 0.85–1.1"
					% [plant_name, level + 1, cover, seen[1].x, seen[0].x, begins]
				)
			)
		check(
			not warned("doesn't contain tangents"),
			"%s: its levels drawn without the engine's warning of a mesh without tangents" % plant_name
		)
		figures.append("%s %d / %d / %d, %s" % ([plant_name] + triangles + [", ".join(covers)]))
		stage.free()
		stage = null
	print(
		(
			(
				"     triangles at mesh 1 / 2 / 3, and the leaf green / cover of mesh 2, then 3, of mesh 1's where"
				+ " each begins: %s"
			)
			% "; ".join(figures)
		)
	)


## Thinning keeps a stable share of the cards, fewer always among more, and grows them to the area
## of all: a standing blade (its foot on the base) grows only in width, keeping its foot and height;
## no card leaves the bounds given.
func test_foliage_cards_thin_to_fewer_of_the_same_area() -> void:
	var bush: Node = _card_bush().instantiate()
	var arrays: Array = (bush.get_node("Leaves").mesh as ArrayMesh).surface_get_arrays(0)
	bush.free()
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	for k: int in 12:  # blades standing on the base, 1 m tall
		var turn: float = TAU * k / 12.0
		var foot: Vector3 = Vector3(cos(turn), 0.0, sin(turn)) * 0.2
		var side: Vector3 = Vector3(-sin(turn), 0.0, cos(turn)) * 0.03
		var first: int = positions.size()
		positions.append_array(
			PackedVector3Array([foot - side, foot + side, foot + side + Vector3.UP, foot - side + Vector3.UP])
		)
		indices.append_array(PackedInt32Array([first, first + 1, first + 2, first, first + 2, first + 3]))
	var uvs: PackedVector2Array = arrays[Mesh.ARRAY_TEX_UV]
	uvs.resize(positions.size())
	arrays[Mesh.ARRAY_VERTEX] = positions
	arrays[Mesh.ARRAY_TEX_UV] = uvs
	arrays[Mesh.ARRAY_INDEX] = indices
	var cards: MeshPieces = MeshPieces.new(arrays)
	check(cards.are_cards(), "a surface of quads is of cards")
	check_eq(cards.count, 48, "48 cards")
	var wide: AABB = AABB(Vector3(-100, 0, -100), Vector3(200, 200, 200))
	var all_area: float = _area_of(arrays)
	var centres: Array = [_centres(arrays)]
	for share: float in [0.5, 0.2]:
		var thin: Array = cards.cards_thinned(share, cards.area_growth(share), wide)
		var count: int = MeshPieces.new(thin).count
		check_eq(count, roundi(share * 48), "%.1f of the cards kept" % share)
		check_near(_area_of(thin) / all_area, 1.0, 1e-3, "%.1f of the cards: the area of all" % share)
		centres.append(_centres(thin))
		check(
			_among(centres[-1], centres[-2]), "the cards kept at %.1f are among those kept at the share before" % share
		)
		# The blades are the cards about 0.2 m from the middle (the bush's leaves are 0.35 m or more).
		var blades: int = 0
		var standing: int = 0
		var kept: PackedVector3Array = thin[Mesh.ARRAY_VERTEX]
		for k: int in range(0, kept.size(), 4):
			var corners: Array = Array(kept.slice(k, k + 4))
			var middle: Vector3 = (
				corners.reduce(func(sum: Vector3, v: Vector3) -> Vector3: return sum + v, Vector3.ZERO) / 4.0
			)
			if Vector2(middle.x, middle.z).length() < 0.25:
				blades += 1
				var heights: Array = corners.map(func(v: Vector3) -> float: return v.y)
				standing += 1 if is_zero_approx(heights.min()) and is_equal_approx(heights.max(), 1.0) else 0
		check(blades > 0, "%.1f: blades kept" % share)
		check_eq(standing, blades, "%.1f: the kept blades keep their feet on the base and their 1 m" % share)
	var tight: AABB = AABB(Vector3(-0.5, 0.0, -0.5), Vector3(1.0, 1.0, 1.0))
	var clamped: PackedVector3Array = cards.cards_thinned(0.2, cards.area_growth(0.2), tight)[Mesh.ARRAY_VERTEX]
	check(
		Array(clamped).all(func(v: Vector3) -> bool: return tight.grow(1e-5).has_point(v)),
		"no grown card leaves the bounds"
	)
	var again: Array = cards.cards_thinned(0.5, cards.area_growth(0.5), wide)
	check_eq(
		again[Mesh.ARRAY_VERTEX],
		cards.cards_thinned(0.5, cards.area_growth(0.5), wide)[Mesh.ARRAY_VERTEX],
		"the same cards each time"
	)


## Leaves that touch at a point — five to a stalk, as a Sapling Japanese maple's are, their corners
## there at one place or one shared vertex — are cards of their own: a piece is the triangles joined
## by edges, not by a point (joined by the point, each cluster was one piece of 10 triangles, the
## surface not of cards: the Japanese maple's levels were simplified as branches, covering 0.72 and
## 0.47 of mesh 1 where they begin; 0.97 and 0.98 as cards). Thinned, each kept leaf grows about its
## own centre: a shared corner is used once by each kept leaf, every kept leaf the same area.
func test_leaves_touching_at_a_point_are_cards_of_their_own() -> void:
	for shared: bool in [false, true]:
		var random: RandomNumberGenerator = RandomNumberGenerator.new()
		random.seed = 5
		var positions: PackedVector3Array = []
		var indices: PackedInt32Array = []
		for cluster: int in 40:
			var stalk: Vector3 = Vector3(random.randf_range(-1, 1), random.randf_range(1, 3), random.randf_range(-1, 1))
			var stalk_vertex: int = positions.size()
			if shared:
				positions.append(stalk)
			for leaf: int in 5:
				var out: Vector3 = Vector3.RIGHT.rotated(Vector3.UP, TAU * leaf / 5.0) * 0.2
				var side: Vector3 = out.cross(Vector3.UP) * 0.25
				var first: int = positions.size()
				positions.append_array(
					PackedVector3Array([stalk + out * 0.5 - side, stalk + out, stalk + out * 0.5 + side])
				)
				if not shared:
					positions.append(stalk)
				var at_stalk: int = stalk_vertex if shared else first + 3
				indices.append_array(PackedInt32Array([at_stalk, first, first + 1, at_stalk, first + 1, first + 2]))
		var arrays: Array = Scenes.surface_arrays(positions, indices)
		var what: String = "one shared vertex at the stalk" if shared else "corners at one place"
		var leaves: MeshPieces = MeshPieces.new(arrays)
		check_eq(leaves.count, 200, "%s: a card a leaf" % what)
		check(leaves.are_cards(), "%s: a surface of cards" % what)
		var thin: Array = leaves.cards_thinned(
			0.5, leaves.area_growth(0.5), AABB(Vector3(-9, -9, -9), Vector3(18, 18, 18))
		)
		var kept: MeshPieces = MeshPieces.new(thin)
		check_eq(kept.count, 100, "%s: half the leaves kept, none joined to another" % what)
		var areas: Array = Array(kept.area).map(func(area: float) -> float: return snappedf(area / kept.area[0], 1e-4))
		check(areas.all(func(ratio: float) -> bool: return ratio == 1.0), "%s: each kept leaf grown alike" % what)
		check_near(_area_of(thin) / _area_of(arrays), 1.0, 1e-3, "%s: the area of all" % what)


## A surface of branches thinned to its biggest pieces keeps the bigger first, and pieces of about
## one size spread round the plant (mesh_pieces.gd): of a trunk, 8 long twigs and 48 short ones all
## round it (10 triangles each), keeping 40 % keeps the trunk, the 8 long and 13 short twigs, 3 or 4
## in each quarter round the trunk (ordered by their area alone, which only rounding tells apart,
## 2 to 4).
func test_branches_keep_their_biggest_pieces_spread_round_the_plant() -> void:
	var positions: PackedVector3Array = []
	var indices: PackedInt32Array = []
	var strip: Callable = func(from: Vector3, to: Vector3, width: float) -> void:
		var first: int = positions.size()
		var along: Vector3 = (to - from).normalized()
		var across: Vector3 = along.cross(Vector3.UP if absf(along.y) < 0.9 else Vector3.FORWARD).normalized() * width
		for step: int in 6:
			var at: Vector3 = from.lerp(to, step / 5.0)
			positions.append_array(PackedVector3Array([at - across, at + across]))
		for step: int in 5:
			var k: int = first + 2 * step
			indices.append_array(PackedInt32Array([k, k + 2, k + 1, k + 1, k + 2, k + 3]))
	strip.call(Vector3.ZERO, Vector3(0, 3, 0), 0.2)
	for twig: int in 56:
		var out: Vector3 = Vector3.RIGHT.rotated(Vector3.UP, TAU * (twig / 8.0 if twig < 8 else (twig + 0.5) / 48.0))
		strip.call(Vector3(0, 2.5, 0) + out * 0.1, Vector3(0, 2.5, 0) + out * (1.1 if twig < 8 else 0.6), 0.02)
	var arrays: Array = Scenes.surface_arrays(positions, indices)
	var pieces: MeshPieces = MeshPieces.new(arrays)
	check_eq(pieces.count, 57, "a trunk and 56 twigs")
	var kept: MeshPieces = MeshPieces.new(pieces.biggest(0.4))
	check_eq(kept.count, 22, "40 % of the triangles: 22 pieces of 10")
	var long: int = 0
	var quarters: Array[int] = [0, 0, 0, 0]
	for piece: int in kept.count:
		var reach: Vector3 = kept.centre[piece] - Vector3(0, 2.5, 0)
		if kept.area[piece] > 0.5:
			continue  # the trunk
		if reach.length() > 0.4:
			long += 1
		else:
			quarters[posmod(floori(atan2(reach.z, reach.x) / (TAU / 4.0)), 4)] += 1
	check_eq(long, 8, "every long twig kept before a short one")
	check(
		quarters.all(func(count: int) -> bool: return count >= 3 and count <= 4),
		"the short twigs kept spread round the trunk, 3 or 4 a quarter: %s" % [quarters]
	)


## A level's branches thicken outwards (plant_levels.gd): a closed square tube thickened by 1 cm has
## every vertex 1 cm farther out along its corner's normal, whether the mesh has normals or they are
## its triangles' (the engine's front faces, wound clockwise); wound the other way round, the same
## tube's triangles face in, and it thins.
func test_branches_thicken_outwards() -> void:
	var positions: PackedVector3Array = []
	var indices: PackedInt32Array = []
	for ring: int in 2:
		for corner: int in 4:
			var turn: float = TAU * corner / 4.0
			positions.append(Vector3(cos(turn) * 0.1, ring * 1.0, sin(turn) * 0.1))
	for side: int in 4:
		var a: int = side
		var b: int = (side + 1) % 4
		indices.append_array(PackedInt32Array([a, b, b + 4, a, b + 4, a + 4]))
	var arrays: Array = Scenes.surface_arrays(positions, indices)
	var out_normals: PackedVector3Array = []
	for at: Vector3 in positions:
		out_normals.append(Vector3(at.x, 0.0, at.z).normalized())
	var with_normals: Array = arrays.duplicate()
	with_normals[Mesh.ARRAY_NORMAL] = out_normals
	var inside_out: Array = arrays.duplicate()
	inside_out[Mesh.ARRAY_INDEX] = PackedInt32Array(Array(indices).map(func(k: int) -> int: return k))
	for k: int in range(0, indices.size(), 3):
		inside_out[Mesh.ARRAY_INDEX][k + 1] = indices[k + 2]
		inside_out[Mesh.ARRAY_INDEX][k + 2] = indices[k + 1]
	for case: Array in [
		["normals", with_normals, 0.11], ["its triangles", arrays, 0.11], ["inside out", inside_out, 0.09]
	]:
		var thick: PackedVector3Array = PlantLevels.thickened(case[1], 0.01)[Mesh.ARRAY_VERTEX]
		var reach: Array = Array(thick).map(
			func(at: Vector3) -> float: return snappedf(Vector2(at.x, at.z).length(), 1e-4)
		)
		check(
			reach.all(func(r: float) -> bool: return is_equal_approx(r, case[2])),
			"%s: every corner at %.2f m: %s" % [case[0], case[2], reach]
		)


## Cards standing on the base and spanning most of the plant are sliced so that they bend: each of
## their triangles within one slice of the height, the area, the cards and their facing kept; a leaf
## off the base, and a short blade, left as they are.
func test_tall_standing_cards_are_sliced_and_stay_whole() -> void:
	var positions: PackedVector3Array = []
	var indices: PackedInt32Array = []
	var corners: Array[PackedVector3Array] = [
		PackedVector3Array([Vector3(0, 0, 0), Vector3(0.1, 0, 0), Vector3(0.1, 1, 0.2), Vector3(0, 1, 0.2)]),  # a blade
		PackedVector3Array([Vector3(1, 0, 0), Vector3(1.1, 0, 0), Vector3(1.1, 0.3, 0), Vector3(1, 0.3, 0)]),  # short
		PackedVector3Array([Vector3(2, 0.3, 0), Vector3(2.2, 0.3, 0), Vector3(2.2, 0.9, 0), Vector3(2, 0.9, 0)]),  # a leaf
	]
	for card: PackedVector3Array in corners:
		var first: int = positions.size()
		positions.append_array(card)
		indices.append_array(PackedInt32Array([first, first + 1, first + 2, first, first + 2, first + 3]))
	var arrays: Array = Scenes.surface_arrays(positions, indices)
	var uvs: PackedVector2Array = []
	for vertex: Vector3 in positions:
		uvs.append(Vector2(vertex.x, vertex.y))
	arrays[Mesh.ARRAY_TEX_UV] = uvs
	var bounds: AABB = AABB(Vector3(0, 0, 0), Vector3(2.2, 1, 0.2))
	var sliced: Array = CardSlices.sliced(arrays, bounds)
	var out: PackedVector3Array = sliced[Mesh.ARRAY_VERTEX]
	var out_indices: PackedInt32Array = sliced[Mesh.ARRAY_INDEX]
	var slice: float = 1.0 / CardSlices.SLICES
	var blade: int = 0
	var facing_kept: bool = true
	var uv_kept: bool = true
	for k: int in range(0, out_indices.size(), 3):
		var a: Vector3 = out[out_indices[k]]
		var b: Vector3 = out[out_indices[k + 1]]
		var c: Vector3 = out[out_indices[k + 2]]
		if maxf(a.x, maxf(b.x, c.x)) < 0.5:
			blade += 1
			check(
				maxf(a.y, maxf(b.y, c.y)) - minf(a.y, minf(b.y, c.y)) <= slice + 1e-5,
				"a blade's triangle within a slice"
			)
			facing_kept = facing_kept and (b - a).cross(c - a).dot(Vector3(0, -0.2, 1)) > 0.0
		for vertex: int in [out_indices[k], out_indices[k + 1], out_indices[k + 2]]:
			var uv: Vector2 = (sliced[Mesh.ARRAY_TEX_UV] as PackedVector2Array)[vertex]
			uv_kept = uv_kept and uv.is_equal_approx(Vector2(out[vertex].x, out[vertex].y))
	check(blade >= 2 * CardSlices.SLICES, "the blade is cut into its slices (%d triangles)" % blade)
	check(facing_kept, "its triangles face as it did")
	check(uv_kept, "the cut vertices' texture coordinates interpolated")
	check_eq(out_indices.size() / 3 - blade, 4, "the short blade and the leaf as they were")
	check_near(_area_of(sliced), _area_of(arrays), 1e-4, "the area kept")
	check_eq(MeshPieces.new(sliced).count, 3, "three cards still, each in one piece")
	check_eq(
		CardSlices.sliced(arrays, AABB(Vector3(0, 0, 0), Vector3(2.2, 3, 0.2))),
		arrays,
		"no card spans a plant three times as tall"
	)


## A plant of more cards than the cover is measured for in five views (PlantLevels.COVER_CARD_TRIANGLES)
## still thins, its kept cards grown to the cover measured in one view, 45° above (up to
## PlantLevels.COVER_ONE_VIEW_TRIANGLES): about 0.95 of the area of all the cards, as for 3 900 such
## cards measured in five views (grown to the area of all, as they were before, a Sapling pine's mesh
## 3 showed 1.15 times mesh 1's leaf green; measured in one view, 1.06).
func test_a_plant_of_many_cards_keeps_their_cover() -> void:
	var random: RandomNumberGenerator = RandomNumberGenerator.new()
	random.seed = 60
	var positions: PackedVector3Array = []
	var indices: PackedInt32Array = []
	var cards: int = PlantLevels.COVER_CARD_TRIANGLES / 2 + 100  # just over the limit
	for card: int in cards:
		var centre: Vector3 = Vector3(
			random.randf_range(-1.5, 1.5), random.randf_range(0.5, 3.5), random.randf_range(-1.5, 1.5)
		)
		var across: Vector3 = Vector3(random.randf_range(-1, 1), 0.0, random.randf_range(-1, 1)).normalized() * 0.05
		var first: int = positions.size()
		positions.append_array(
			PackedVector3Array(
				[
					centre - across - Vector3.UP * 0.05,
					centre + across - Vector3.UP * 0.05,
					centre + across + Vector3.UP * 0.05,
					centre - across + Vector3.UP * 0.05
				]
			)
		)
		indices.append_array(PackedInt32Array([first, first + 1, first + 2, first, first + 2, first + 3]))
	var arrays: Array = Scenes.surface_arrays(positions, indices)
	var scene: PackedScene = _leaves_scene("Crown", arrays, null)
	var started: int = Time.get_ticks_msec()
	var plant: SunflowerPlant = SunflowerPlant.from_scene(scene)
	print("     %d cards (%d triangles): the plant made in %d ms" % [cards, 2 * cards, Time.get_ticks_msec() - started])
	if not check(plant != null, "a plant"):
		return
	var all_area: float = _area_of((plant.mesh_level_1[0] as ArrayMesh).surface_get_arrays(0))
	for level: int in [2, 3]:
		var thinned: Array = (plant.get("mesh_level_%d" % level)[0] as ArrayMesh).surface_get_arrays(0)
		var share: float = (thinned[Mesh.ARRAY_INDEX] as PackedInt32Array).size() / 6.0 / cards
		check_near(share, PlantLevels.LEVEL_SHARES[level - 1], 0.01, "mesh %d keeps its share of the cards" % level)
		var area: float = _area_of(thinned) / all_area
		check(area > 0.9 and area < 0.98, "mesh %d: grown to the cover, under the area of all (%.3f)" % [level, area])


## What a card covers is counted cell by cell (plant_cover.gd): in a 1 m cube's grids of 64 cells a
## side, a half-metre square card facing the first view covers the 32 × 32 cells whose centres it
## holds, there and nowhere it is seen edge-on; half of it (one triangle, either winding) covers the
## cells on its side of the diagonal; cut out by its texture's right half, its left half's cells
## (u below a half: z below 0.5, the first view's columns 32 to 47). A StandardMaterial3D's UV1
## scale and offset move where the texture is read (a leaf atlas, a glTF texture transform): scaled
## by a half, the card reads the opaque half only; offset by a half too, the clear half only.
func test_a_cards_cover_is_counted_cell_by_cell() -> void:
	var bounds: AABB = AABB(Vector3.ZERO, Vector3.ONE)
	var square: PackedVector3Array = [
		Vector3(0.5, 0.25, 0.25), Vector3(0.5, 0.25, 0.75), Vector3(0.5, 0.75, 0.75), Vector3(0.5, 0.75, 0.25)
	]
	var uvs: PackedVector2Array = [Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)]
	var quad: PackedInt32Array = [0, 1, 2, 0, 2, 3]
	var halves: Image = Image.create(2, 1, false, Image.FORMAT_RGBA8)
	halves.set_pixel(0, 0, Color(0.2, 0.5, 0.1, 1.0))
	halves.set_pixel(1, 0, Color(0.2, 0.5, 0.1, 0.0))
	var cases: Array[Array] = [  # what, indices, mask, the cells covered in the first view
		["a square", quad, {}, 32 * 32],
		["a triangle", PackedInt32Array([0, 1, 2]), {}, 32 * 33 / 2],
		["a triangle wound the other way", PackedInt32Array([0, 2, 1]), {}, 32 * 33 / 2],
		["a square cut out", quad, {"size": Vector2i(2, 1), "opaque": PackedByteArray([1, 0])}, 16 * 32],
		["a square reading its texture's left half", quad, PlantCover.cut_out(_cut_by(halves, 0.0)), 32 * 32],
		["a square reading its texture's right half", quad, PlantCover.cut_out(_cut_by(halves, 0.5)), 0],
	]
	for case: Array in cases:
		var arrays: Array = Scenes.surface_arrays(square, case[1] as PackedInt32Array)
		arrays[Mesh.ARRAY_TEX_UV] = uvs
		var cover: Dictionary = PlantCover.empty(bounds)
		PlantCover.draw(cover, arrays, case[2])
		var seen: Array[int] = []
		for grid: PackedByteArray in cover.grids:
			seen.append(grid.count(1))
		check_eq(seen[0], case[3], "%s: the cells facing it" % case[0])
		check_eq(seen.slice(1, 4), [0, 0, 0], "%s: none where it is seen edge-on" % case[0])
		if case[3] > 0:
			check(seen[4] > case[3] / 2 and seen[4] < case[3], "%s: fewer at 45° (%d)" % [case[0], seen[4]])
		if case[3] == 16 * 32:
			var columns: Vector2i = Vector2i(64, 0)
			for cell: int in (cover.grids[0] as PackedByteArray).size():
				if cover.grids[0][cell]:
					columns = Vector2i(
						mini(columns.x, cell % cover.sides[0].x), maxi(columns.y, cell % cover.sides[0].x)
					)
			check_eq(columns, Vector2i(32, 47), "%s: the cells of its texture's opaque half" % case[0])


## A cut-out material of [param texture] read at UV1 scaled by a half across, offset by [param offset].
func _cut_by(texture: Image, offset: float) -> StandardMaterial3D:
	var material: StandardMaterial3D = StandardMaterial3D.new()
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	material.albedo_texture = ImageTexture.create_from_image(texture)
	material.uv1_scale = Vector3(0.5, 1.0, 1.0)
	material.uv1_offset = Vector3(offset, 0.0, 0.0)
	return material


## Whether every point of [param points] is (about) one of [param others].
func _among(points: Array, others: Array) -> bool:
	for point: Vector3 in points:
		if not others.any(func(other: Vector3) -> bool: return other.is_equal_approx(point)):
			return false
	return true


func _area_of(arrays: Array) -> float:
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	var area: float = 0.0
	for k: int in range(0, indices.size(), 3):
		var a: Vector3 = positions[indices[k]]
		area += 0.5 * (positions[indices[k + 1]] - a).cross(positions[indices[k + 2]] - a).length()
	return area


## The centre of each card of [param arrays] (their four corners' mean; cards of four corners).
func _centres(arrays: Array) -> Array:
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var out: Array = []
	for k: int in range(0, positions.size(), 4):
		out.append((positions[k] + positions[k + 1] + positions[k + 2] + positions[k + 3]) / 4.0)
	return out


## A bush of 36 alpha-cut cards and nothing else: 6 rings of 6 leaves, each ring higher and narrower.
func _card_bush() -> PackedScene:
	var positions: PackedVector3Array = []
	var uvs: PackedVector2Array = []
	var indices: PackedInt32Array = []
	for ring: int in 6:
		for k: int in 6:
			var turn: float = TAU * (k + 0.5 * ring) / 6.0
			var out: Vector3 = Vector3(cos(turn), 0.0, sin(turn))
			var side: Vector3 = Vector3(-out.z, 0.0, out.x) * 0.25
			var foot: Vector3 = out * (0.6 - 0.08 * ring) + Vector3.UP * (0.15 * ring)
			var tip: Vector3 = foot + out * 0.3 + Vector3.UP * 0.35
			var first: int = positions.size()
			positions.append_array(PackedVector3Array([foot - side, foot + side, tip + side, tip - side]))
			uvs.append_array(PackedVector2Array([Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)]))
			indices.append_array(PackedInt32Array([first, first + 1, first + 2, first, first + 2, first + 3]))
	var arrays: Array = Scenes.surface_arrays(positions, indices)
	arrays[Mesh.ARRAY_TEX_UV] = uvs
	return _leaves_scene("CardBush", arrays, Scenes.holed_leaves())


## A plant scene [param root_name] of one node, "Leaves", drawing a mesh of [param arrays] with
## [param material] as its override (none when null).
func _leaves_scene(root_name: String, arrays: Array, material: Material) -> PackedScene:
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	var root: Node3D = Node3D.new()
	root.name = root_name
	var leaves: MeshInstance3D = MeshInstance3D.new()
	leaves.name = "Leaves"
	leaves.mesh = mesh
	leaves.material_override = material
	root.add_child(leaves)
	return Scenes.packed(root)
