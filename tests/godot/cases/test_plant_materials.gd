extends TestCase
## A plant's own part materials drawn through the addon's plant material (plant/plant_material.gd):
## what the engine draws beside it, the scene drawn plainly, at the same view. (The plain
## StandardMaterial3D settings the material carries are test_render's: the demo field drawn five ways.)

const Picture: GDScript = preload("res://runner/picture.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")
const Stage: GDScript = preload("res://runner/stage.gd")

var scene: Node3D


func before_each() -> void:
	scene = Stage.new(tree.root).root


func after_each() -> void:
	scene.free()


## A StandardMaterial3D with Alpha Hash (the engine's choice for foliage) is drawn through the plant
## material, hashed as the engine hashes it: the plant is drawn whole (its levels cross-fade, it bends
## in the wind), and a card whose alpha runs from 0 to 1 across it, seen close up, keeps as many
## pixels, as bright, as the scene drawn plainly (each within ±10 %; on the Compatibility renderer,
## which draws Alpha Hash opaque, half the pixels: the ramp's mean alpha). (Such a material was kept
## as it was: its plant drawn part by part, without fades, leaning rigidly.)
func test_an_alpha_hash_material_is_drawn_as_the_plant_material() -> void:
	var ramp: Image = Image.create(32, 32, false, Image.FORMAT_RGBA8)
	for y: int in 32:
		for x: int in 32:
			ramp.set_pixel(x, y, Color(0.3, 0.7, 0.2, (x + 0.5) / 32.0))
	var leaf: StandardMaterial3D = StandardMaterial3D.new()
	leaf.albedo_texture = ImageTexture.create_from_image(ramp)
	leaf.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_HASH
	leaf.cull_mode = BaseMaterial3D.CULL_DISABLED
	var card: QuadMesh = QuadMesh.new()
	card.material = leaf
	var root: Node3D = Node3D.new()
	root.name = "HashedCard"
	var node: MeshInstance3D = MeshInstance3D.new()
	node.name = "Leaf"
	node.mesh = card
	node.position = Vector3(0.0, 0.5, 0.0)
	root.add_child(node)
	var seen: Dictionary = await _beside_its_scene(Scenes.packed(root), Vector3(0.0, 0.5, 1.6), "alpha_hash")
	if seen.is_empty():
		return
	var cover: float = seen.cover
	var brightness: float = seen.brightness
	# The Compatibility renderer draws Alpha Hash opaque (godot#103094): there the scene shows the whole
	# card, and the plant material, hashing as Forward+ does, keeps the ramp's mean alpha of it.
	var expected: float = 0.5 if RenderingServer.get_current_rendering_method() == "gl_compatibility" else 1.0
	print(
		(
			(
				"     an Alpha Hash card drawn by the plant material: %.3f of the pixels of the scene drawn plainly (%d),"
				+ " %.3f as bright"
			)
			% [cover, seen.covered.x, brightness]
		)
	)
	check(
		absf(cover / expected - 1.0) <= 0.1,
		"%.1f of the scene's card's pixels (%.3f of %d), ±10 %%" % [expected, cover, seen.covered.x]
	)
	check(absf(brightness - 1.0) <= 0.1, "as bright as the scene's hashed card (%.3f)" % brightness)


## Meshes with no material (shapes put together in the editor) are drawn with the engine's default
## look through the plant material: the plant is drawn whole (it fades and bends), as the scene drawn
## plainly shows it (SSIM at least 0.98; the pixels it covers within ±3 % as bright). (Kept without
## a material, the plant was drawn part by part, leaning rigidly.)
func test_meshes_without_a_material_are_drawn_as_the_engine_draws_them() -> void:
	var root: Node3D = Node3D.new()
	root.name = "Shapes"
	var trunk: MeshInstance3D = MeshInstance3D.new()
	trunk.name = "Trunk"
	trunk.mesh = CylinderMesh.new()  # 2 m tall, 0.5 m round: no material
	trunk.position = Vector3(0.0, 1.0, 0.0)
	root.add_child(trunk)
	var crown: MeshInstance3D = MeshInstance3D.new()
	crown.name = "Crown"
	crown.mesh = SphereMesh.new()
	crown.scale = Vector3(1.6, 1.2, 1.6)
	crown.position = Vector3(0.0, 2.4, 0.0)
	root.add_child(crown)
	var seen: Dictionary = await _beside_its_scene(Scenes.packed(root), Vector3(1.0, 1.5, 3.0), "no_material")
	if seen.is_empty():
		return
	var similarity: float = Picture.new(640, 360).ssim(seen.pictures[1], seen.pictures[0])
	print(
		(
			"     shapes without a material drawn by the plant material: SSIM %.4f, %.3f of the pixels, %.3f as bright"
			% [similarity, seen.cover, seen.brightness]
		)
	)
	check(similarity >= 0.98, "as the scene shows them (SSIM %.4f, at least 0.98)" % similarity)
	check(absf(seen.cover - 1.0) <= 0.03, "as many pixels as the scene (%.3f, ±3 %%)" % seen.cover)
	check(absf(seen.brightness - 1.0) <= 0.03, "as bright as the scene (%.3f, ±3 %%)" % seen.brightness)


## The plant made of [param packed] (checked: drawn whole, through the plant material; else {}), drawn
## alone by a calm field at mesh 1 beside the scene drawn plainly at its root, no shadows, from
## [param eye] (from the root) looking at the plant's middle:
## [code]{"pictures": [scene's, field's], "covered", "cover", "brightness"}[/code]: covered (Vector2),
## the pixels each changes from the empty picture (the scene's, the field's); cover, the field's of
## the scene's; brightness, the field's mean luminance over its pixels of the scene's. The pictures
## are saved as material_[param name]_none / _plain / _field.png.
func _beside_its_scene(packed: PackedScene, eye: Vector3, name: String) -> Dictionary:
	var plant: SunflowerPlant = SunflowerPlant.from_scene(packed)
	if not check(plant != null and plant.drawn_whole(), "%s: a plant drawn whole, through the plant material" % name):
		return {}
	plant.yaw_range = 0.0
	for light: Node in scene.find_children("*", "DirectionalLight3D", true, false):
		(light as DirectionalLight3D).shadow_enabled = false
	var both: Array[Node3D] = Scenes.plant_beside_its_scene(scene, plant, packed)
	var field: SunflowerField = both[0] as SunflowerField
	var plain: Node3D = both[1]
	field.force_lod = 0
	field.advance(0.0)
	var place: Vector3 = plain.position
	var camera: Camera3D = Camera3D.new()
	scene.add_child(camera)
	camera.make_current()
	camera.look_at_from_position(place + eye, place + Vector3(0.0, 0.5 * plant.height, 0.0))
	var picture: Picture = Picture.new(640, 360)
	var seen: Array[PackedFloat32Array] = []  # the background, then the scene, then the field
	for shown: Node3D in [null, plain, field]:
		plain.visible = shown == plain
		field.visible = shown == field
		await frames(4)
		var way: String = "none" if shown == null else ("plain" if shown == plain else "field")
		var image: Image = tree.root.get_viewport().get_texture().get_image()
		image.save_png(artifact_path("material_%s_%s.png" % [name, way]))
		seen.append(picture.luminance(image))
	var covered: Vector2 = Vector2.ZERO
	var light: Vector2 = Vector2.ZERO
	for i: int in seen[0].size():
		for way: int in 2:
			if absf(seen[way + 1][i] - seen[0][i]) > 0.02:
				covered[way] += 1.0
				light[way] += seen[way + 1][i]
	return {
		"pictures": [seen[1], seen[2]],
		"covered": covered,
		"cover": covered.y / maxf(covered.x, 1.0),
		"brightness": (light.y / maxf(covered.y, 1.0)) / maxf(light.x / maxf(covered.x, 1.0), 1e-6),
	}
