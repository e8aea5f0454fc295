extends RefCounted
## Scenes the tests build in code.

const Maps: GDScript = preload("res://runner/maps.gd")


## [param root] and everything under it packed as a scene (every node owned by the root, so that it
## is saved); the nodes are freed.
static func packed(root: Node) -> PackedScene:
	for node: Node in root.find_children("*", "", true, false):
		node.owner = root
	var scene: PackedScene = PackedScene.new()
	scene.pack(root)
	root.free()
	return scene


## Green leaves cut by alpha: a texture of holes (every third square of 8 pixels clear).
static func holed_leaves() -> StandardMaterial3D:
	var holes: Image = Image.create(64, 64, false, Image.FORMAT_RGBA8)
	for y: int in 64:
		for x: int in 64:
			var clear: bool = (x / 8 + 2 * (y / 8)) % 3 == 0
			holes.set_pixel(x, y, Color(0.25, 0.55, 0.18, 0.0 if clear else 1.0))
	var leaves: StandardMaterial3D = StandardMaterial3D.new()
	leaves.albedo_texture = ImageTexture.create_from_image(holes)
	leaves.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	leaves.alpha_scissor_threshold = 0.5
	leaves.cull_mode = BaseMaterial3D.CULL_DISABLED
	return leaves


## A ShaderMaterial of a shader of [param code], named [param material_name] (the name the addon's
## warnings give a material).
static func shader_material(code: String, material_name: String = "") -> ShaderMaterial:
	var material: ShaderMaterial = ShaderMaterial.new()
	material.resource_name = material_name
	material.shader = Shader.new()
	material.shader.code = code
	return material


## [param plant] (made of [param packed]) alone in a calm field under [param parent], its levels
## not faded, each casting its own shadow (as the scene does), built and advanced (not processed), and
## the scene drawn plainly at the plant's root: [code][field, scene][/code], to draw one or the other.
static func plant_beside_its_scene(parent: Node, plant: SunflowerPlant, packed: PackedScene) -> Array[Node3D]:
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = Maps.filled(1, 1, "user://plant_beside_its_scene.field")
	field.wind_power = 0.0
	field.lod_fade = 0.0
	field.cheap_shadows = false
	parent.add_child(field)
	field.finish_build()
	field.set_process(false)
	field.advance(1.0)
	var plain: Node3D = packed.instantiate() as Node3D
	plain.position = field.get_plant_info(0)["position"]
	parent.add_child(plain)
	return [field, plain]
