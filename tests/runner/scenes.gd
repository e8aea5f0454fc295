extends RefCounted
## Scenes the tests build in code.


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
