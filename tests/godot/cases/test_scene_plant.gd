extends TestCase
## A plant from a scene (SunflowerPlant.from_scene): a tree as an asset pack ships it (a trunk with a
## material override, a crown node moved, turned and scaled holding alpha-cut leaves in a surface
## override) becomes one mesh per level, placed and drawn as the scene shows it, framed from its
## bounds; its level-of-detail variants are its mesh levels, or levels 2 and 3 are simplified; no
## sunflower part in it; a lone plant at each mesh level looks like the scene drawn plainly.

const Picture: GDScript = preload("res://runner/picture.gd")
const Stage: GDScript = preload("res://runner/stage.gd")
const Maps: GDScript = preload("res://runner/maps.gd")
const Dressing: GDScript = preload("res://runner/dressing.gd")
const ScenePlant: GDScript = preload("res://addons/sunflower_field/plant/scene_plant.gd")
const ScenePieces: GDScript = preload("res://addons/sunflower_field/plant/scene_pieces.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")
const ImpostorBaker: GDScript = preload("res://addons/sunflower_field/plant/impostor_baker.gd")
const CROWN_PLACE: Vector3 = Vector3(0.5, 3.0, 0.0)
const CROWN_SCALE: float = 1.5
## Where the one-plant maps of these tests say they were read from.
const ONE_PLANT_MAP: String = "user://one_scene_plant.field"
## The directions around a lone plant its impostor's cover is counted from (45° above, evenly around).
const LONE_COVER_TURNS: int = 8
## Plants made by Blender's Sapling Tree Gen (assets/test_plants/make_test_plants.py).
const TEST_PLANT_FOLDER: String = "res://test_plants"
const TEST_PLANTS: PackedStringArray = ["maple_tree.glb", "bottlebrush_bush.glb", "grass_clump.glb"]
## The test plants whose near plants cast from their meshes at every level (SunflowerPlant.impostor_shadows
## off) for the SSIM at 45°: it credits a speck of shade only where the all-mesh-1 picture has one on
## the same pixel, and the maple's impostors' specks fall elsewhere (0.741 with them, 0.736 with no
## shadow from the impostors, 0.821 from their meshes).
const MESH_SHADOWS: PackedStringArray = ["maple_tree"]
## Their 45° view is drawn again with their impostor shadows on, and its shade compared with the
## meshes' shadows' eighth by eighth: the mean brightness within this share, and the contrast of
## SHADE_BLOCK-pixel blocks (the dappling) within [constant SHADE_CONTRAST_WITHIN] (the maple: within
## 1.9 % and 2 %; with no shadow from the impostors, up to 7 % brighter and 26 % less contrast).
const SHADE_BRIGHTNESS_WITHIN: float = 0.02
const SHADE_CONTRAST_WITHIN: float = 0.1
const SHADE_BLOCK: int = 5
## The impostors' brightness is compared over where they are drawn grown by this many pixels each
## way: the region they alone make holds none of the sky the meshes show between their leaves (a
## sparse crown's impostor pixels are other pixels than its meshes', as many), so it read the maple's
## far field from 40 m outside as 0.885 of the meshes' brightness where, grown by 2, it is 1.05.
const BRIGHTNESS_GROWTH: int = 2
## How far the camera moves to the side for the field test's ceiling: two pictures of the same meshes.
const CEILING_SHIFT: float = 0.05
## The least SSIM of a generated level whose foliage cards are thinned against the scene drawn
## plainly, alone, where the level begins (measured: 0.85–0.93 at mesh 2, 0.77–0.87 at mesh 3).
const THINNED_LEAST_SSIM: float = 0.7
## The least SSIM of a field of a plant with thinned levels against all its plants at mesh 1, at
## head height (measured: 0.85–0.95).
const THINNED_FIELD_LEAST_SSIM: float = 0.8
## The least SSIM of a field 25 m up at 45° against all its plants at mesh 1, anti-aliased: 0.85, or
## for a thin plant, where its meshes' own pictures [constant CEILING_SHIFT] apart score less (the
## maple's far leaves are specks of less than a pixel, which fall on other pixels in any two
## pictures), within this of theirs (measured: maple 0.821 against its meshes' own 0.813).
const FIELD_SSIM_BELOW_CEILING: float = 0.02
## The field test's pictures are drawn this many times as wide and high as the window and box-filtered
## back (anti-aliased); a thin plant's ([member SunflowerPlant.impostor_thin_from]) at 45°
## [constant THIN_FIELD_SAMPLES_A_SIDE] times, as the sunflower's aerial views (test_fidelity): at
## twice, the maple's meshes were 0.654 alike to themselves moved 5 cm, at 4 times 0.812 (the bush's,
## not thin, 0.899 at twice; the environment's FIELD_THIN_SAMPLES=8 draws it 8 times: 0.855 against
## the meshes' own 0.886).
const FIELD_SAMPLES_A_SIDE: int = 2
const THIN_FIELD_SAMPLES_A_SIDE: int = 4
## The test plants made and baked once a run ([method _baked_test_plant]), by file.
static var baked_plants: Dictionary = {}

var stage: Node3D


func after_each() -> void:
	if stage:
		stage.free()
		stage = null


## A tree scene: "Trunk" (a cylinder with a bark material override), "Crown" (moved, turned a quarter
## about z, scaled 1.5) holding "Leaves" (a cone with an alpha-cut leaf material as its surface
## override). With [param variants] the leaves come as Leaves_LOD0 / _LOD1 / _LOD2 of fewer sides.
func _tree_scene(variants: bool = false) -> PackedScene:
	var root: Node3D = Node3D.new()
	root.name = "Tree"
	var trunk: MeshInstance3D = MeshInstance3D.new()
	trunk.name = "Trunk"
	var cylinder: CylinderMesh = CylinderMesh.new()
	cylinder.top_radius = 0.12
	cylinder.bottom_radius = 0.18
	cylinder.height = 3.0
	trunk.mesh = cylinder
	trunk.position = Vector3(0.0, 1.5, 0.0)
	trunk.material_override = _bark()
	root.add_child(trunk)
	var crown: Node3D = Node3D.new()
	crown.name = "Crown"
	crown.position = CROWN_PLACE
	crown.rotation_degrees = Vector3(0.0, 0.0, 90.0)
	crown.scale = Vector3.ONE * CROWN_SCALE
	root.add_child(crown)
	var sides: Array[int] = [48]
	if variants:
		sides.append_array([12, 5])
	for k: int in sides.size():
		var leaves: MeshInstance3D = MeshInstance3D.new()
		leaves.name = "Leaves_LOD%d" % k if variants else "Leaves"
		var cone: CylinderMesh = CylinderMesh.new()
		cone.top_radius = 0.0
		cone.bottom_radius = 1.0
		cone.height = 2.0
		cone.radial_segments = sides[k]
		cone.rings = 8 if k == 0 else 1
		leaves.mesh = cone
		leaves.set_surface_override_material(0, Scenes.holed_leaves())
		crown.add_child(leaves)
	return Scenes.packed(root)


func _bark() -> StandardMaterial3D:
	var bark: StandardMaterial3D = StandardMaterial3D.new()
	bark.albedo_color = Color(0.35, 0.22, 0.12)
	return bark


## The bounds the scene's meshes cover in the root's frame, as the engine places them.
func _scene_bounds(packed: PackedScene) -> AABB:
	var root: Node3D = packed.instantiate() as Node3D
	var bounds: AABB = AABB()
	var first: bool = true
	for node: Node in root.find_children("*", "MeshInstance3D", true, false):
		var instance: MeshInstance3D = node as MeshInstance3D
		if instance.name.contains("LOD") and not instance.name.ends_with("0"):
			continue
		var to_root: Transform3D = Transform3D.IDENTITY
		var walk: Node = instance
		while walk != root:
			to_root = (walk as Node3D).transform * to_root
			walk = walk.get_parent()
		var box: AABB = to_root * instance.mesh.get_aabb()
		bounds = box if first else bounds.merge(box)
		first = false
	root.free()
	return bounds


func test_a_scene_of_several_meshes_becomes_a_plant_of_one_part_per_level() -> void:
	var packed: PackedScene = _tree_scene()
	var plant: SunflowerPlant = SunflowerPlant.from_scene(packed)
	if not check(plant != null, "a plant is made of the scene"):
		return
	var level_1: Mesh = plant.get_part_mesh(0, 0)
	check(level_1 != null and plant.get_part_mesh(0, 1) == null and plant.get_part_mesh(0, 2) == null, "one part")
	# Placed by the node transforms: the merged mesh covers what the engine draws.
	var expected: AABB = _scene_bounds(packed)
	var merged: AABB = level_1.get_aabb()
	check(
		merged.position.is_equal_approx(expected.position) and merged.end.is_equal_approx(expected.end),
		"the merged mesh covers the scene's bounds (%s against %s)" % [merged, expected]
	)
	# Drawn with what the nodes show: the bark override and the leaves' surface override, one surface each.
	check_eq(level_1.get_surface_count(), 2, "a surface per material")
	var bark: bool = false
	var cut_leaves: bool = false
	for surface: int in level_1.get_surface_count():
		var material: StandardMaterial3D = level_1.surface_get_material(surface) as StandardMaterial3D
		bark = bark or (material != null and material.albedo_color == Color(0.35, 0.22, 0.12))
		cut_leaves = (
			cut_leaves or (material != null and material.transparency == BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR)
		)
	check(bark, "the trunk's material override")
	check(cut_leaves, "the leaves' surface override, alpha-cut")
	# Framed from its bounds, as tall as the scene models it.
	check_near(plant.height, expected.end.y, 1e-3, "the plant is as tall as the scene")
	check_near(plant.part_lengths.x, expected.end.y, 1e-3, "its one part spans it")
	check_near(plant.height_units, expected.end.y, 1e-3, "the impostors frame its height")
	var reach: float = maxf(maxf(-expected.position.x, expected.end.x), maxf(-expected.position.z, expected.end.z))
	check(
		plant.impostor_width >= 2.0 * reach - 1e-3 and plant.impostor_width <= 2.0 * reach * sqrt(2.0),
		"and its reach (%.2f for %.2f)" % [plant.impostor_width, reach]
	)
	check(plant.cull_radius_units >= 0.5 * expected.end.y, "the culling sphere holds it")
	check(plant.stacking_problems().is_empty(), "it stacks")
	# No variants: levels 2 and 3 simplified from level 1.
	var triangles: Array = [1, 2, 3].map(
		func(level: int) -> int: return ScenePlant.triangle_count(plant.get("mesh_level_%d" % level)[0])
	)
	print("     tree from a scene: %d / %d / %d triangles at mesh 1 / 2 / 3 (2 and 3 simplified)" % triangles)
	check(triangles[1] < triangles[0] and triangles[2] < triangles[1], "simplified levels have fewer triangles")
	check(triangles[2] > 0, "and still draw the plant")
	# Its variants, where the scene has them: Leaves_LOD1 at mesh 2 (with the trunk, which has none).
	var variant_scene: PackedScene = _tree_scene(true)
	var with_variants: SunflowerPlant = SunflowerPlant.from_scene(variant_scene)
	var parts: Node = variant_scene.instantiate()
	var trunk: int = ScenePlant.triangle_count(parts.get_node("Trunk").mesh)
	for level: int in 3:
		var variant: int = ScenePlant.triangle_count(parts.get_node("Crown/Leaves_LOD%d" % level).mesh)
		check_eq(
			ScenePlant.triangle_count(with_variants.get_part_mesh(level, 0)),
			trunk + variant,
			"mesh %d is the trunk and Leaves_LOD%d" % [level + 1, level]
		)
	parts.free()
	check_eq(ScenePieces.level_of_name("Pine-lod2"), 2, "a '-lod2' suffix")
	check_eq(ScenePieces.level_of_name("Pine"), -1, "no suffix")
	# A field of it draws its meshes and nothing of the sunflower.
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = Maps.filled(1, 1, ONE_PLANT_MAP)
	tree.root.add_child(field)
	field.finish_build()
	var sunflower: Array = []
	for level: int in 3:
		sunflower.append(SunflowerPlant.default_plant().whole_mesh(level))
		sunflower.append_array(SunflowerPlant.default_plant().get("mesh_level_%d" % (level + 1)))
	var drawn: Array[Mesh] = []
	for node: Node in field.find_children("*", "MultiMeshInstance3D", true, false):
		var mesh: Mesh = (node as MultiMeshInstance3D).multimesh.mesh
		if mesh:
			drawn.append(mesh)
	check(not drawn.is_empty(), "the field draws the plant")
	check(drawn.all(func(m: Mesh) -> bool: return not sunflower.has(m)), "no sunflower mesh in any node")
	field.free()


## Each plant type switches levels at the field's distances times its size over the sunflower's 2 m:
## in a field of a row of Sapling maples (8.7 m), sunflowers and grass clumps (0.9 m), plants the same
## distance away are at finer levels the larger their type; lod_scale overrides it.
func test_lod_distances_follow_each_plant_types_size() -> void:
	var maple: SunflowerPlant = SunflowerPlant.from_scene(load(TEST_PLANT_FOLDER.path_join("maple_tree.glb")))
	var grass: SunflowerPlant = SunflowerPlant.from_scene(load(TEST_PLANT_FOLDER.path_join("grass_clump.glb")))
	check_near(SunflowerPlant.default_plant().lod_scale_used(), 1.0, 1e-3, "the sunflower keeps the field's distances")
	check(maple.lod_scale_used() > 4.0, "a maple's are over 4× as far (%.2f)" % maple.lod_scale_used())
	check(grass.lod_scale_used() < 0.6, "a grass clump's under 0.6× (%.2f)" % grass.lod_scale_used())
	var map: SunflowerFieldMap = SunflowerFieldMap.new()
	map.source_path = "user://three_sizes.field"
	map.text = (("80 3\n%s\n%s\n%s\n" % ["t".repeat(80), "*".repeat(80), "g".repeat(80)]).to_utf8_buffer())
	var observer: Node3D = Node3D.new()
	observer.name = "Observer"
	observer.position = Vector3(0.0, 1.6, 0.75)
	var field: SunflowerField = SunflowerField.new()
	field.legend = {"t": maple, "g": grass}
	tree.root.add_child(observer)
	field.observer = NodePath("../Observer")
	tree.root.add_child(field)
	field.map = map
	field.wind_power = 0.0
	field.finish_build()
	for i: int in 20:
		field.advance(0.3)
	var distances: PackedFloat32Array = field.lod_distances
	var rows: Array[SunflowerPlant] = [maple, SunflowerPlant.default_plant(), grass]
	var checked: int = 0
	for i: int in field.get_plant_count():
		var info: Dictionary = field.get_plant_info(i)
		var position: Vector3 = info["position"]
		var row: int = clampi(int(position.z / field.cell_size), 0, 2)
		var scale: float = rows[row].lod_scale_used()
		var distance: float = Vector2(position.x, position.z).distance_to(Vector2(0.0, 0.75)) / scale
		var expected: int = distances.size()
		for level: int in distances.size():
			if distance < distances[level]:
				expected = level
				break
		var near_switch: bool = Array(distances).any(func(d: float) -> bool: return absf(distance - d) < 1.5)
		if not near_switch and expected <= SunflowerField.Lod.MESH_3:
			checked += 1
			check_eq(info["lod"], expected, "row %d, %.1f m scaled: level %d" % [row, distance, expected])
	check(checked > 40, "plants of all three types checked (%d)" % checked)
	maple.lod_scale = 1.0
	check_near(maple.lod_scale_used(), 1.0, 1e-6, "lod_scale overrides the size")
	maple.lod_scale = NAN
	check_eq(maple.lod_scale, 1.0, "a NaN scale is refused")
	check(warned("SunflowerPlant.lod_scale: nan"), "with a warning naming the property")
	field.free()
	observer.free()


func test_a_scene_with_nothing_to_draw_is_an_error_naming_it() -> void:
	var empty: PackedScene = PackedScene.new()
	var root: Node3D = Node3D.new()
	empty.pack(root)
	root.free()
	allow_error("has no visible MeshInstance3D, MultiMeshInstance3D or CSG shape")
	check(SunflowerPlant.from_scene(empty) == null, "no plant of a scene without meshes")


## Each test plant alone (the tree scene built here and the three Sapling plants of
## assets/test_plants) at each mesh level against the same scene drawn plainly by the engine (its
## full meshes), in calm air, seen 20° up through a 50° lens from as near as that level is drawn (mesh
## 1 from half its first switch distance, mesh 2 from that switch, mesh 3 from the next, each
## scaled by the plant's size): alike where the plant is (SSIM ≥ 0.95 over its box on screen), and
## nothing of the sunflower's yellow.
func test_a_lone_scene_plant_looks_like_its_scene_drawn_plainly() -> void:
	var scenes: Dictionary = {"built": _tree_scene()}
	for file: String in TEST_PLANTS:
		scenes[file.get_basename()] = load(TEST_PLANT_FOLDER.path_join(file)) as PackedScene
	for plant_name: String in scenes:
		stage = Stage.new(tree.root).root
		await _compare_lone_plant(plant_name, scenes[plant_name])
		stage.free()
		stage = null


func _compare_lone_plant(plant_name: String, packed: PackedScene) -> void:
	var plant: SunflowerPlant = SunflowerPlant.from_scene(packed)
	if not check(plant != null, "%s: a plant is made of the scene" % plant_name):
		return
	plant.yaw_range = 0.0
	var shown: Array[Node3D] = Scenes.plant_beside_its_scene(stage, plant, packed)
	var field: SunflowerField = shown[0] as SunflowerField
	var plain: Node3D = shown[1]
	var root: Vector3 = plain.position
	var camera: Camera3D = Camera3D.new()
	stage.add_child(camera)
	camera.fov = 50.0
	camera.make_current()
	var middle: Vector3 = root + Vector3(0.0, plant.height * 0.5, 0.0)
	var nearest: Array[float] = [0.5 * field.lod_distances[0], field.lod_distances[0], field.lod_distances[1]]
	var scores: PackedStringArray = []
	for level: int in 3:
		var distance: float = nearest[level] * plant.lod_scale_used()
		camera.look_at_from_position(middle + Vector3(0.3, 0.36, 0.9).normalized() * distance, middle)
		var box: Rect2i = _box_on_screen(camera, root, plant)
		var picture: Picture = Picture.new(box.size.x, box.size.y)
		var pictures: Array[PackedFloat32Array] = []
		for drawn: Node3D in [plain, field]:
			plain.visible = drawn == plain
			field.visible = drawn == field
			field.force_lod = level
			field.advance(0.0)
			await frames(4)
			var image: Image = tree.root.get_viewport().get_texture().get_image()
			var way: String = "plain" if drawn == plain else "field"
			image.save_png(artifact_path("scene_plant_%s_mesh_%d_%s.png" % [plant_name, level + 1, way]))
			pictures.append(picture.luminance(image.get_region(box)))
			if drawn == field:
				check_eq(_yellow_pixels(image), 0, "%s: no sunflower yellow at mesh %d" % [plant_name, level + 1])
		var similarity: float = picture.ssim(pictures[1], pictures[0])
		scores.append("%.3f" % similarity)
		# Thinned cards are other leaves than the scene's, as many pixels (test_plant_levels checks the
		# cover): what is left to check is that the level still draws the plant there.
		var least: float = THINNED_LEAST_SSIM if level > 0 and plant_name + ".glb" in TEST_PLANTS else 0.95
		check(
			similarity >= least,
			(
				"%s: mesh %d looks like the scene drawn plainly (SSIM %.3f, at least %.2f)"
				% [plant_name, level + 1, similarity, least]
			)
		)
	var triangles: Array = [1, 2, 3].map(
		func(level: int) -> int: return ScenePlant.triangle_count(plant.get("mesh_level_%d" % level)[0])
	)
	print(
		(
			"     %s (%.2f m, %d / %d / %d triangles) against its scene drawn plainly, SSIM at mesh 1 / 2 / 3: %s"
			% ([plant_name, plant.height] + triangles + [" / ".join(scores)])
		)
	)


## The rectangle of the screen that holds [param plant] standing at [param root], a tenth more each
## way, within the viewport.
func _box_on_screen(camera: Camera3D, root: Vector3, plant: SunflowerPlant) -> Rect2i:
	var half: float = 0.5 * plant.impostor_width * plant.height / plant.height_units
	var box: Rect2 = Rect2(camera.unproject_position(root), Vector2.ZERO)
	for corner: int in 8:
		var offset: Vector3 = Vector3(
			half if corner & 1 else -half, plant.height if corner & 2 else 0.0, half if corner & 4 else -half
		)
		box = box.expand(camera.unproject_position(root + offset))
	box = box.grow(0.1 * maxf(box.size.x, box.size.y))
	var screen: Rect2i = Rect2i(Vector2i.ZERO, tree.root.get_viewport().get_texture().get_size())
	return Rect2i(box.position.floor(), box.size.ceil()).intersection(screen)


## A plant of one part bends with its height: a 10 m pole in wind 6, seen from the side, has its top
## moved by the wind while a point 1 m up stays under a twentieth of that (a rigid lean about the root
## would move it a tenth as far as the top); the same when the pole is
## drawn with a ShaderMaterial of its own (the field draws a copy that bends: PlantMaterial.bending),
## whose own "wind" (a shift it makes outside a field) the field's bend takes the place of, and when
## it is one card of two triangles (its cards are sliced so that they bend: card_slices.gd).
## Each Sapling test plant's impostors, baked: every one of the atlas' views holds its plant and
## touches no neighbour (its square's edge is clear all round: the frame from its bounds holds it from
## every side and elevation), and no view shows the sunflower's yellow.
func test_each_test_plants_impostor_views_are_framed() -> void:
	for file: String in TEST_PLANTS:
		var plant: SunflowerPlant = await _baked_test_plant(file)
		if not check(plant != null, "%s: baked" % file):
			continue
		var views: Image = plant.impostor_views.get_image()
		views.clear_mipmaps()
		views.convert(Image.FORMAT_RGBA8)
		# A thin plant's views are kept as drawn, SUPERSAMPLE times as fine (ImpostorBaker._read_views).
		var finer: int = ImpostorBaker.SUPERSAMPLE if plant.impostor_thin_from >= 0.0 else 1
		var cell: int = ImpostorBaker.CELL_PIXELS * finer
		check_eq(views.get_size(), SunflowerPlant.ATLAS_VIEWS * cell, "%s: %d pixels a view" % [file, cell])
		views.save_png(artifact_path("scene_plant_%s_views.png" % file.get_basename()))
		var touching: PackedStringArray = []
		var empty: int = 0
		for row: int in SunflowerPlant.ATLAS_VIEWS.y:
			for column: int in SunflowerPlant.ATLAS_VIEWS.x:
				var square: Image = views.get_region(Rect2i(column * cell, row * cell, cell, cell))
				if square.get_used_rect().size == Vector2i.ZERO:
					empty += 1
				elif not Rect2i(1, 1, cell - 2, cell - 2).encloses(square.get_used_rect()):
					touching.append("%d,%d" % [column, row])
		check(touching.is_empty(), "%s: views touching their square's edge: %s" % [file, ", ".join(touching)])
		check_eq(empty, 0, "%s: every view shows the plant" % file)
		check_eq(_yellow_pixels(views), 0, "%s: no sunflower yellow in its views" % file)


## Each test plant's impostor, alone, against its mesh 1 at the same view (45° above, on black, no
## ground, calm, unshadowed, from [constant LONE_COVER_TURNS] directions around it), close up (a
## quarter of the way to where its impostors begin), where they begin and twice as far. Where they
## begin and twice as far, the pixels it covers and its leaf green ones are 0.85–1.15 of the mesh's.
## Close up, the brightness of its pixels is 0.90–1.10 of the mesh's. Its thin leaves'
## cover is kept by the bake (supersampled: a pixel's alpha is the share covered), the alpha cut
## measured per mip level (SunflowerPlant.impostor_alpha_cuts) and, for a plant thin from near (the
## maple: SunflowerPlant.impostor_thin_from), the hashed test there. Drawn at twice the window's
## width and height (a far tree is a few hundred pixels at 640 × 360), or as many times as the
## environment's LONE_SCALE says (a finer screen: at 6, 3 840 × 2 160).
func test_each_test_plants_lone_impostor_covers_what_its_mesh_covers() -> void:
	var figures: PackedStringArray = []
	var window: Vector2i = tree.root.size
	tree.root.size = window * (int(OS.get_environment("LONE_SCALE")) if OS.has_environment("LONE_SCALE") else 2)
	await RenderingServer.frame_post_draw
	var drawn: Vector2i = tree.root.get_visible_rect().size
	for file: String in TEST_PLANTS:
		var plant: SunflowerPlant = await _baked_test_plant(file)
		if not check(plant != null, "%s: baked" % file):
			continue
		var staged: Stage = Stage.new(tree.root)
		stage = staged.root
		var field: SunflowerField = staged.lone_plant(plant, Maps.filled(1, 1, ONE_PLANT_MAP))
		var camera: Camera3D = tree.root.get_camera_3d()
		var root: Vector3 = field.get_plant_info(0)["position"]
		var middle: Vector3 = root + Vector3(0.0, plant.height * 0.5, 0.0)
		var begins: float = field.lod_distances[2] * plant.lod_scale_used()
		var parts: PackedStringArray = []
		for distance: float in [0.25 * begins, begins, 2.0 * begins]:
			var seen: Array[Vector3] = [Vector3.ZERO, Vector3.ZERO]  # (covered, leaf green, light) per way
			for way: int in 2:
				field.force_lod = SunflowerField.Lod.MESH_1 if way == 0 else SunflowerField.Lod.SPRITE
				field.advance(0.0)
				await frames(2)  # the level drawn; then a frame a view
				for turn: int in LONE_COVER_TURNS:
					var angle: float = TAU * turn / LONE_COVER_TURNS
					var towards: Vector3 = Vector3(sin(angle), 1.0, cos(angle)).normalized()
					camera.look_at_from_position(middle + towards * distance, middle)
					await frames(1)
					var image: Image = tree.root.get_viewport().get_texture().get_image()
					seen[way] += Picture.covered_green_light(_about_plant(image, camera, plant, distance))
					if turn == 0:
						image.save_png(
							artifact_path(
								(
									"lone_cover_%s_%dm_%s.png"
									% [file.get_basename(), roundi(distance), "mesh1" if way == 0 else "impostor"]
								)
							)
						)
			var ratio: Vector3 = seen[1] / seen[0].max(Vector3.ONE)
			var what: String = "%s at %.0f m" % [file.get_basename(), distance]
			if distance < begins:
				# Close up (where impostors are not drawn, but a player could force them): as bright as
				# the mesh, 0.90–1.10 (the bake reading textures two mip levels coarser made the bush and
				# the grass 1.11 and 1.12: ImpostorBaker.TEXTURE_MIP_BIAS). The cover is reported only:
				# a thin tree's near impostor is not hashed (docs/plants.md).
				var brightness: float = ratio.z / ratio.x
				parts.append("close up (%.0f m) brightness %.2f, cover %.2f" % [distance, brightness, ratio.x])
				check(
					brightness >= 0.90 and brightness <= 1.10,
					"%s: the impostor is %.2f as bright as its mesh, 0.90–1.10" % [what, brightness]
				)
				continue
			parts.append("%.0f m cover %.2f, leaf green %.2f" % [distance, ratio.x, ratio.y])
			check(
				ratio.x >= 0.85 and ratio.x <= 1.15,
				(
					"%s: the impostor covers %.2f of its mesh's pixels (%d of %d), 0.85–1.15"
					% [what, ratio.x, seen[1].x, seen[0].x]
				)
			)
			check(
				ratio.y >= 0.85 and ratio.y <= 1.15,
				(
					"%s: the impostor's leaf green pixels are %.2f of its mesh's (%d of %d), 0.85–1.15"
					% [what, ratio.y, seen[1].y, seen[0].y]
				)
			)
		figures.append(
			"%s (thin from mip %.2f): %s" % [file.get_basename(), plant.impostor_thin_from, ", ".join(parts)]
		)
		stage.free()
		stage = null
	tree.root.size = window
	print("     lone impostor against its mesh 1 (45° above, %d × %d): %s" % [drawn.x, drawn.y, "; ".join(figures)])


## The maple's far impostor in motion, where its impostors begin (thin there: its alpha test hashed,
## each pixel's threshold fixed on the screen): seen from a camera moving past it (half a pixel a
## frame across the picture, 45° above) or circling it (a quarter of a degree a frame), its pixels
## change from frame to frame no more than its mesh's, whose leaves are smaller than a pixel (the
## mean change of the picture's luminance about the plant between frames, the impostor's against the
## mesh's, at most 1.2 each way).
func test_a_thin_plants_far_impostor_sparkles_no_more_than_its_mesh() -> void:
	var plant: SunflowerPlant = await _baked_test_plant("maple_tree.glb")
	if not check(plant != null, "baked"):
		return
	var window: Vector2i = tree.root.size
	tree.root.size = window * 2
	await RenderingServer.frame_post_draw
	var staged: Stage = Stage.new(tree.root)
	stage = staged.root
	var field: SunflowerField = staged.lone_plant(plant, Maps.filled(1, 1, ONE_PLANT_MAP))
	var camera: Camera3D = tree.root.get_camera_3d()
	var middle: Vector3 = field.get_plant_info(0)["position"] + Vector3(0.0, plant.height * 0.5, 0.0)
	var distance: float = field.lod_distances[2] * plant.lod_scale_used()
	var size: Vector2i = tree.root.get_visible_rect().size
	var side: int = (
		_about_plant(tree.root.get_viewport().get_texture().get_image(), camera, plant, distance).get_width()
	)
	var picture: Picture = Picture.new(side, side)
	# Metres a frame that move the plant half a pixel across the picture.
	var sideways: float = 0.5 * 2.0 * distance * tan(deg_to_rad(camera.fov * 0.5)) / size.y
	var towards: Vector3 = Vector3(0.0, 1.0, 1.0).normalized()
	var figures: PackedStringArray = []
	for motion: String in ["passing", "circling"]:
		var change: Array[float] = [0.0, 0.0]
		for way: int in 2:
			field.force_lod = SunflowerField.Lod.MESH_1 if way == 0 else SunflowerField.Lod.SPRITE
			field.advance(0.0)
			var before: PackedFloat32Array = []
			for step: int in 13:
				if motion == "passing":
					var eye: Vector3 = middle + towards * distance + Vector3(sideways * step, 0.0, 0.0)
					camera.look_at_from_position(eye, eye - towards)
				else:
					var angle: float = deg_to_rad(0.25 * step)
					camera.look_at_from_position(
						middle + Vector3(sin(angle), 1.0, cos(angle)).normalized() * distance, middle
					)
				await frames(2 if step > 0 else 3)
				var seen: PackedFloat32Array = picture.luminance(
					_about_plant(tree.root.get_viewport().get_texture().get_image(), camera, plant, distance)
				)
				if step > 0:
					change[way] += picture.mean_difference(before, seen)
				before = seen
		var ratio: float = change[1] / maxf(change[0], 1e-9)
		figures.append("%s %.2f" % [motion, ratio])
		check(
			ratio <= 1.2, "%s: the far maple's impostor changes %.2f as much as its mesh, at most 1.2" % [motion, ratio]
		)
	stage.free()
	stage = null
	tree.root.size = window
	print("     the maple at %.0f m, its impostor's change a frame of its mesh's: %s" % [distance, ", ".join(figures)])


## The square of [param image] about its middle that holds [param plant] (its impostor's frame, at
## its largest scale, with a margin) seen by [param camera] from [param distance] metres: the lone
## plant's tests count pixels only there (a GDScript loop over a whole 1 280 × 720 picture takes a
## good part of a second).
static func _about_plant(image: Image, camera: Camera3D, plant: SunflowerPlant, distance: float) -> Image:
	var metres: float = plant.impostor_frame().x * plant.height / plant.height_units * plant.scale_max
	var pixels_per_metre: float = image.get_height() / (2.0 * distance * tan(deg_to_rad(camera.fov * 0.5)))
	var side: int = mini(ceili(metres * pixels_per_metre * 1.3) + 16, mini(image.get_width(), image.get_height()))
	return image.get_region(Rect2i((image.get_size() - Vector2i(side, side)) / 2, Vector2i(side, side)))


## A plant drawn part by part with empty slots: the empty slots' near buckets are not filled (the
## renderer refuses instances of no mesh, an engine error this runner fails on), and the part there
## is drawn.
func test_empty_slots_of_a_plant_drawn_part_by_part_fill_no_instances() -> void:
	stage = Stage.new(tree.root).root
	var plant: SunflowerPlant = SunflowerPlant.new()
	var trunk: BoxMesh = BoxMesh.new()
	trunk.size = Vector3(0.4, 3.0, 0.4)
	plant.mesh_level_1 = [trunk, null, null]
	plant.use_plant_material = false  # drawn part by part: a node per slot
	plant.part_lengths = Vector3(3.0, 0.0, 0.0)
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = Maps.filled(1, 1, ONE_PLANT_MAP)
	field.force_lod = SunflowerField.Lod.MESH_1
	stage.add_child(field)
	field.finish_build()
	var camera: Camera3D = Camera3D.new()
	stage.add_child(camera)
	camera.look_at_from_position(Vector3(0.25, 1.5, 8.0), Vector3(0.25, 1.5, 0.0))
	camera.make_current()
	for i: int in 3:
		field.advance(1.0 / 30.0)
		await frames(1)
	check(not plant.drawn_whole(), "drawn part by part")
	var drawn: int = 0
	for node: Node in field.find_children("Mesh1*", "MultiMeshInstance3D", true, false):
		var multimesh: MultiMesh = (node as MultiMeshInstance3D).multimesh
		if multimesh.mesh == null:
			check_eq(
				RenderingServer.multimesh_get_instance_count(multimesh.get_rid()), 0, "%s: no instances" % node.name
			)
		else:
			drawn += RenderingServer.multimesh_get_instance_count(multimesh.get_rid())
	check(drawn >= 1, "the trunk's bucket holds the plant")
	take_warnings()  # the plant has no impostor textures: it warns


## Pixels of petal yellow (bright red and green, little blue, no greener than red: the petals are
## (0.81, 0.67, 0.09) to (1.00, 0.98, 0.17); a grass blade's sunlit tip on the Compatibility renderer,
## (0.60, 0.62, 0.22), is not).
func _yellow_pixels(image: Image) -> int:
	var count: int = 0
	for y: int in range(0, image.get_height(), 2):
		for x: int in range(0, image.get_width(), 2):
			var c: Color = image.get_pixel(x, y)
			if c.r > 0.6 and c.g > 0.45 and c.b < 0.3 and c.r >= c.g:
				count += 1
	return count


## The test plant of [param file] made from its scene, with its impostors baked (once a run: the
## tests that need it share it); null when the bake failed.
func _baked_test_plant(file: String) -> SunflowerPlant:
	if not baked_plants.has(file):
		var plant: SunflowerPlant = SunflowerPlant.from_scene(load(TEST_PLANT_FOLDER.path_join(file)) as PackedScene)
		var result: Error = await plant.bake_impostors(tree.root, "user://scene_plants", file.get_basename())
		baked_plants[file] = plant if result == OK and plant.impostor_views != null else null
	return baked_plants[file]


## A patch of bushes (a dense, round plant), 45° above, just past where its impostors begin, in the
## sun with their shadows (cast from the impostors, SunflowerPlant.impostor_shadows): the impostors as
## bright as the meshes drawn there, where they are drawn. On the Compatibility renderer, which finds
## a pixel's place in the shadow from the quad's vertices, a quad through the bush's middle lay
## inside it, in its own shadow: dark middles, 0.894 of the meshes' brightness; 1.009 at the bush's
## mean depth along the view (impostor.gdshaderinc, receiver_front).
func test_a_dense_plants_impostors_in_the_sun_are_as_bright_as_its_meshes() -> void:
	var plant: SunflowerPlant = await _baked_test_plant("bottlebrush_bush.glb")
	if not check(plant != null, "bottlebrush_bush: baked"):
		return
	plant.impostor_shadows = true
	var cell: float = plant.spacing_metres()
	var centre: Vector3 = Vector3(2.5 * cell, 0.0, 2.5 * cell)
	var staged: Stage = Stage.new(tree.root, 400.0, centre)
	stage = staged.root
	var field: SunflowerField = _calm_field(plant, cell, 5, "user://dense_patch.field")
	var camera: Camera3D = Camera3D.new()
	stage.add_child(camera)
	var away: float = 1.25 * plant.lod_scale_used() * SunflowerField.DEFAULT_LOD_DISTANCES[2]
	camera.look_at_from_position(centre + Vector3(0.0, away, away) * sqrt(0.5), centre)
	camera.make_current()
	var auto: Image = await _field_picture(field, -1, "dense_patch_auto")
	var mesh_1: Image = await _field_picture(field, 0, "dense_patch_mesh1")
	var size: Vector2i = auto.get_size()
	var picture: Picture = Picture.new(size.x, size.y)
	var inside: PackedByteArray = picture.region(
		picture.luminance(await _impostors_alone(staged, field, plant, "dense_patch_impostors"))
	)
	staged.show_scenery(false)
	var planted: PackedByteArray = picture.region(
		picture.luminance(await _field_picture(field, -1, "dense_patch_alone"))
	)
	staged.show_scenery(true)
	var brightness: float = picture.brightness_of(auto, mesh_1, picture.grown(inside, BRIGHTNESS_GROWTH))
	print(
		"     bush patch %.1f m away at 45°, in the sun: impostors' brightness %.3f of the meshes'" % [away, brightness]
	)
	check(
		inside.count(1) >= 0.9 * planted.count(1) and planted.count(1) > 0,
		"the patch is drawn as impostors: %d of its %d pixels" % [inside.count(1), planted.count(1)]
	)
	check(absf(brightness - 1.0) <= 0.05, "the impostors' brightness %.3f of the meshes', within ±5 %%" % brightness)


## A field of each test plant, as the editor's Plant from scene… makes it (cells as wide as the
## plant, levels of detail by its size, the field at least three times as deep as the plant's
## impostors begin; the maple with its impostor shadows off, MESH_SHADOWS), calm, from head height
## in it, from 40 m outside and from 25 m up at 45°, against the same view with every plant at
## mesh 1 (what a player compares the far levels with): the pictures' SSIM, anti-aliased (drawn
## larger and box-filtered back, [constant FIELD_SAMPLES_A_SIDE]), and the impostors' brightness where
## they are drawn (found with every mesh drawn black) and leaf green there against the meshes'. For a
## thin plant at 45° it measures how alike its meshes' own pictures are [constant CEILING_SHIFT] apart.
func test_a_field_of_each_test_plant_looks_like_its_meshes() -> void:
	var window: Vector2i = tree.root.size
	for file: String in TEST_PLANTS:
		var plant: SunflowerPlant = await _baked_test_plant(file)
		if check(plant != null, "%s: baked" % file):
			await _compare_field(file.get_basename(), plant, window)
	tree.root.size = window


## A calm field of [param plant] on [member stage], [param cells] × [param cells] cells of
## [param cell] metres (its map said read from [param map_path]), built and not processed (the test
## advances it).
func _calm_field(plant: SunflowerPlant, cell: float, cells: int, map_path: String) -> SunflowerField:
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.cell_size = cell
	field.map = Maps.filled(cells, cells, map_path)
	field.wind_power = 0.0
	stage.add_child(field)
	field.finish_build()
	field.set_process(false)
	return field


func _compare_field(plant_name: String, plant: SunflowerPlant, window: Vector2i) -> void:
	var cell: float = maxf(0.5, plant.spacing_metres())
	var impostors_from: float = SunflowerField.DEFAULT_LOD_DISTANCES[2]
	var cells: int = ceili(maxf(60.0, 3.0 * plant.lod_scale_used() * impostors_from) / cell)
	var side: float = cells * cell
	var staged: Stage = Stage.new(tree.root, side * 4.0, Vector3(side * 0.5, 0.0, side * 0.5))
	stage = staged.root
	plant.impostor_shadows = not plant_name in MESH_SHADOWS
	var field: SunflowerField = _calm_field(plant, cell, cells, "user://scene_plant_field.field")
	var camera: Camera3D = Camera3D.new()
	camera.far = side * 4.0
	stage.add_child(camera)
	camera.make_current()
	var small: Picture = Picture.new(window.x, window.y)
	var middle: float = side * 0.5
	var views: Dictionary = {
		"inside": [Vector3(middle, 1.7, side * 0.75), Vector3(middle, 1.4, side * 0.75 - 25.0)],
		"outside40": [Vector3(middle, 1.7, side + 40.0), Vector3(middle, 1.0, side - 30.0)],
		"above45": [Vector3(middle, 25.0, side - 5.0), Vector3(middle, 0.0, side - 30.0)],
	}
	var figures: Dictionary = {}
	var thin: bool = plant.impostor_thin_from >= 0.0
	for view: String in views:
		var samples: int = FIELD_SAMPLES_A_SIDE
		if thin and view == "above45":
			var asked: String = OS.get_environment("FIELD_THIN_SAMPLES")  # a measurement's, 8: 64 samples a pixel
			samples = int(asked) if asked.is_valid_int() else THIN_FIELD_SAMPLES_A_SIDE
		if tree.root.size != window * samples:
			tree.root.size = window * samples
			await RenderingServer.frame_post_draw
		var size: Vector2i = tree.root.get_visible_rect().size
		var picture: Picture = Picture.new(size.x, size.y)
		camera.look_at_from_position(views[view][0], views[view][1])
		var auto: Image = await _field_picture(field, -1, "%s_%s_auto" % [plant_name, view])
		var mesh_1: Image = await _field_picture(field, 0, "%s_%s_mesh1" % [plant_name, view])
		# For a thin plant at 45°, the same meshes from a little to the side: how alike two pictures of
		# them are at all (leaves of less than a pixel fall on other pixels), a ceiling for any far level's
		# SSIM. (At head height the near plants would move by pixels; from 40 m outside the fields score
		# 0.93 or more.)
		var moved: Image = null
		if thin and view == "above45":
			camera.global_position += camera.global_basis.x * CEILING_SHIFT
			moved = await _field_picture(field, 0, "%s_%s_mesh1_moved" % [plant_name, view])
			camera.look_at_from_position(views[view][0], views[view][1])
		var impostor_shade: Image = null
		if view == "above45" and plant_name in MESH_SHADOWS:
			impostor_shade = await _with_impostor_shadows(
				field, plant, "%s_%s_auto_impostor_shadows" % [plant_name, view]
			)
		# A measurement's (FIELD_FULL_SHADOWS=1): the all-mesh-1 picture with every plant casting from
		# mesh 1 (SunflowerField.cheap_shadows off), the shade no approximation changes.
		var full_shadows: Image = null
		if impostor_shade and OS.get_environment("FIELD_FULL_SHADOWS") == "1":
			field.cheap_shadows = false
			full_shadows = await _field_picture(field, 0, "%s_%s_mesh1_full_shadows" % [plant_name, view])
			field.cheap_shadows = true
		var meshes_black: Image = await _impostors_alone(staged, field, plant, "%s_%s_impostors" % [plant_name, view])
		var inside: PackedByteArray = picture.region(picture.luminance(meshes_black))
		var around: PackedByteArray = picture.grown(inside, BRIGHTNESS_GROWTH * samples / FIELD_SAMPLES_A_SIDE)
		var brightness: float = picture.brightness_of(auto, mesh_1, around) if inside.count(1) > 0 else 1.0
		# Leaf green where the impostors are drawn (grown as for the brightness), ours against the meshes':
		# at least 0.85 of theirs from 40 m outside and at 45° (the far maple's filtered views mixed each
		# pixel's leaf and twig: 0.82 at 45° drawn at 1 280 × 720; one texel of one view a pixel where it
		# is thin. At 2 560 × 1 440, thin only from its measured level: 0.65; from mip −0.5 on, 1.04).
		var green: Vector2 = Vector2(
			picture.mean_in(picture.leaf_green(auto), around), picture.mean_in(picture.leaf_green(mesh_1), around)
		)
		if view != "inside" and green.y > 0.0:
			check(
				green.x / green.y >= 0.85,
				(
					"%s field %s: leaf green where the impostors are drawn %.3f of the meshes' (%.3f of %.3f), at least 0.85"
					% [plant_name, view, green.x / green.y, green.x, green.y]
				)
			)
		check_eq(_yellow_pixels(auto), 0, "%s field %s: no sunflower yellow" % [plant_name, view])
		while auto.get_width() > window.x:
			auto.shrink_x2()
			mesh_1.shrink_x2()
			if moved:
				moved.shrink_x2()
			if impostor_shade:
				impostor_shade.shrink_x2()
			if full_shadows:
				full_shadows.shrink_x2()
		if full_shadows:
			var full: PackedFloat32Array = small.luminance(full_shadows)
			print(
				(
					(
						"     %s field at 45° against its plants all casting from mesh 1: SSIM %.3f with impostor"
						+ " shadows, %.3f with the meshes' (auto), %.3f the all-mesh-1 picture (mesh 3 casting)"
					)
					% [
						plant_name,
						small.ssim(small.luminance(impostor_shade), full),
						small.ssim(small.luminance(auto), full),
						small.ssim(small.luminance(mesh_1), full)
					]
				)
			)
		if impostor_shade:
			_compare_shade(
				plant_name, impostor_shade, auto, small.ssim(small.luminance(impostor_shade), small.luminance(mesh_1))
			)
		var reference: PackedFloat32Array = small.luminance(mesh_1)
		var similarity: float = small.ssim(small.luminance(auto), reference)
		var ceiling: float = -1.0
		if moved:
			ceiling = small.ssim(small.luminance(moved), reference)
			print(
				(
					"     %s field at 45°, SSIM by eighths of the picture from the top, ours / the meshes' own moved: %s"
					% [plant_name, " ".join(_by_eighths(auto, moved, mesh_1))]
				)
			)
		var share: float = float(inside.count(1)) / inside.size()
		figures[view] = [similarity, brightness, share, green, ceiling]
		# Brightness where the impostors are 2 % of the picture or more (less is a few rows at the horizon).
		if share >= 0.02:
			check(
				absf(brightness - 1.0) <= 0.1,
				(
					"%s field %s: the impostors' brightness %.3f of the meshes', within ±10 %%"
					% [plant_name, view, brightness]
				)
			)
	# The Sapling plants' leaves are foliage cards, their levels 2 and 3 thinned: other leaves than mesh 1's.
	var least: float = THINNED_FIELD_LEAST_SSIM if plant_name + ".glb" in TEST_PLANTS else 0.95
	check(
		figures["inside"][0] >= least,
		"%s field at head height: SSIM %.3f, at least %.2f" % [plant_name, figures["inside"][0], least]
	)
	var least_above: float = minf(0.85, figures["above45"][4] - FIELD_SSIM_BELOW_CEILING) if thin else 0.85
	check(
		figures["above45"][0] >= least_above,
		(
			"%s field 25 m up at 45°, anti-aliased: SSIM %.3f, at least %.3f"
			% [plant_name, figures["above45"][0], least_above]
		)
	)
	var parts: PackedStringArray = []
	for view: String in figures:
		var green: Vector2 = figures[view][3]
		parts.append(
			(
				"%s %.3f%s / %.3f / %.0f %% / %.1f of %.1f %%"
				% [
					view,
					figures[view][0],
					" (%.3f)" % figures[view][4] if figures[view][4] >= 0.0 else "",
					figures[view][1],
					100.0 * figures[view][2],
					100.0 * green.x,
					100.0 * green.y
				]
			)
		)
	print(
		(
			(
				"     %s field (%d × %d cells of %.2f m), SSIM anti-aliased (thin at 45°: the meshes' own moved %.0f cm)"
				+ " / impostors' brightness / their share / leaf green there, ours of the meshes': %s"
			)
			% [plant_name, cells, cells, cell, 100.0 * CEILING_SHIFT, "; ".join(parts)]
		)
	)
	stage.free()
	stage = null


## The picture [method _field_picture] draws with [param plant]'s impostor shadows on (its near plants
## cast from its impostors from SunflowerField.impostor_shadows_from on); then off again.
func _with_impostor_shadows(field: SunflowerField, plant: SunflowerPlant, name: String) -> Image:
	plant.impostor_shadows = true
	field.finish_build()
	var image: Image = await _field_picture(field, -1, name)
	plant.impostor_shadows = false
	field.finish_build()
	return image


## The shade of [param ours] (a field whose near plants cast from their impostors) against
## [param theirs] (the same field whose plants cast from their meshes), eighth by eighth of the
## height: mean brightness and dappling ([method _shade]) alike (SSIM [param similarity] to the
## all-mesh-1 picture is printed, not checked: it credits a speck of shade only where the meshes'
## falls on the same pixel).
func _compare_shade(plant_name: String, ours: Image, theirs: Image, similarity: float) -> void:
	var parts: PackedStringArray = []
	var worst: Vector2 = Vector2.ZERO  # the largest departures of brightness and contrast
	var size: Vector2i = ours.get_size()
	for k: int in 8:
		var rows: Rect2i = Rect2i(0, k * (size.y / 8), size.x, size.y / 8)
		var ratio: Vector2 = (
			Picture.shade(ours.get_region(rows), SHADE_BLOCK) / Picture.shade(theirs.get_region(rows), SHADE_BLOCK)
		)
		parts.append("%.3f / %.2f" % [ratio.x, ratio.y])
		worst = Vector2(maxf(worst.x, absf(ratio.x - 1.0)), maxf(worst.y, absf(ratio.y - 1.0)))
	print(
		(
			(
				"     %s field at 45° with its impostor shadows on: SSIM %.3f; by eighths from the top, its"
				+ " brightness / contrast of the meshes' shadows': %s"
			)
			% [plant_name, similarity, " ".join(parts)]
		)
	)
	check(
		worst.x <= SHADE_BRIGHTNESS_WITHIN,
		(
			"%s field at 45°: impostor shadows as dark as the meshes' in every eighth (%.1f %% off, within %.0f %%)"
			% [plant_name, 100.0 * worst.x, 100.0 * SHADE_BRIGHTNESS_WITHIN]
		)
	)
	check(
		worst.y <= SHADE_CONTRAST_WITHIN,
		(
			"%s field at 45°: impostor shadows dappled as the meshes' in every eighth (%.1f %% off, within %.0f %%)"
			% [plant_name, 100.0 * worst.y, 100.0 * SHADE_CONTRAST_WITHIN]
		)
	)


## The SSIM of [param ours] and of [param theirs] against [param reference], each eighth of the
## pictures' height on its own, from the top, as "ours/theirs".
func _by_eighths(ours: Image, theirs: Image, reference: Image) -> PackedStringArray:
	var size: Vector2i = reference.get_size()
	var strip: Picture = Picture.new(size.x, size.y / 8)
	var out: PackedStringArray = []
	for k: int in 8:
		var rows: Rect2i = Rect2i(0, k * (size.y / 8), size.x, size.y / 8)
		var under: PackedFloat32Array = strip.luminance(reference.get_region(rows))
		out.append(
			(
				"%.2f/%.2f"
				% [
					strip.ssim(strip.luminance(ours.get_region(rows)), under),
					strip.ssim(strip.luminance(theirs.get_region(rows)), under)
				]
			)
		)
	return out


## The window's picture of [param field] at [param force] (-1: automatic levels) after ten updates,
## saved to the artifacts as scene_field_[param name].png.
func _field_picture(field: SunflowerField, force: int, name: String) -> Image:
	field.force_lod = force
	for i: int in 10:
		field.advance(1.0 / 60.0)
	await RenderingServer.frame_post_draw
	var image: Image = tree.root.get_viewport().get_texture().get_image()
	image.save_png(artifact_path("scene_field_%s.png" % name))
	return image


## The picture of [param field] with every mesh level of [param plant] drawn black and unshaded, no
## ground and a black sky: what is not black is impostor. The plant's meshes are put back.
func _impostors_alone(staged: Stage, field: SunflowerField, plant: SunflowerPlant, name: String) -> Image:
	var black: StandardMaterial3D = Dressing.unlit_black()
	var kept: Array = [plant.mesh_level_1, plant.mesh_level_2, plant.mesh_level_3]
	Dressing.dress_parts(plant, func(_level: int, _part: int) -> Material: return black)
	staged.show_scenery(false)
	var image: Image = await _field_picture(field, -1, name)
	staged.show_scenery(true)
	plant.mesh_level_1 = kept[0]
	plant.mesh_level_2 = kept[1]
	plant.mesh_level_3 = kept[2]
	return image
