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


## A tree whose twigs are most of what it covers, as a weeping willow's: a trunk 3 m tall, [param twigs]
## drooping twigs round its top (tubes of 8 bends, 48 triangles each) and seven green leaf cards beside
## each twig, the twigs (brown) and the leaves on nodes of their own.
static func twig_curtain(twigs: int) -> PackedScene:
	var positions: PackedVector3Array = []
	var indices: PackedInt32Array = []
	var tube: Callable = func(spine: PackedVector3Array, radius: float) -> void:
		for bend: int in spine.size():
			var along: Vector3 = spine[mini(bend + 1, spine.size() - 1)] - spine[maxi(bend - 1, 0)]
			var across: Vector3 = along.cross(Vector3.UP if absf(along.normalized().y) < 0.9 else Vector3.RIGHT)
			across = across.normalized() * radius
			for side: int in 3:
				positions.append(spine[bend] + across.rotated(along.normalized(), TAU * side / 3.0))
		for bend: int in spine.size() - 1:
			for side: int in 3:
				var a: int = positions.size() - 3 * spine.size() + 3 * bend + side
				var b: int = a - side + (side + 1) % 3
				indices.append_array(PackedInt32Array([a, b + 3, b, a, a + 3, b + 3]))
	tube.call(PackedVector3Array([Vector3.ZERO, Vector3(0, 3, 0)]), 0.08)
	var tips: PackedVector3Array = []
	for twig: int in twigs:
		var out: Vector3 = Vector3.RIGHT.rotated(Vector3.UP, TAU * (twig + 0.37 * (twig % 3)) / twigs)
		var spine: PackedVector3Array = []
		for bend: int in 9:
			var along: float = bend / 8.0
			spine.append(
				(
					out * (0.1 + 1.2 * sin(along * PI * 0.5))
					+ Vector3.UP * (3.0 - (2.0 + 0.5 * (twig % 2)) * along * along)
				)
			)
		tube.call(spine, 0.03)
		tips.append_array(spine.slice(2))
	var twig_arrays: Array = surface_arrays(positions, indices)
	var corners: PackedVector3Array = []
	var leaf_indices: PackedInt32Array = []
	for leaf: int in tips.size():
		# Beside its twig, the sides taking turns.
		var side: Vector3 = Vector3(tips[leaf].z, 0.0, -tips[leaf].x).normalized() * (0.02 if leaf % 2 else -0.02)
		var near: Vector3 = tips[leaf] + side * 2.0
		var far: Vector3 = tips[leaf] + side * 10.0
		var first: int = corners.size()
		leaf_indices.append_array(PackedInt32Array([first, first + 1, first + 2, first, first + 2, first + 3]))
		corners.append_array(
			PackedVector3Array(
				[near - Vector3.UP * 0.1, far - Vector3.UP * 0.1, far + Vector3.UP * 0.1, near + Vector3.UP * 0.1]
			)
		)
	var leaves: Array = surface_arrays(corners, leaf_indices)
	var green: StandardMaterial3D = StandardMaterial3D.new()
	green.albedo_color = Color(0.2, 0.5, 0.1)
	var bark: StandardMaterial3D = StandardMaterial3D.new()
	bark.albedo_color = Color(0.35, 0.25, 0.15)
	var root: Node3D = Node3D.new()
	root.name = "TwigCurtain"
	for part: Array in [["Twigs", twig_arrays, bark], ["Leaves", leaves, green]]:
		var mesh: ArrayMesh = ArrayMesh.new()
		mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, part[1])
		var node: MeshInstance3D = MeshInstance3D.new()
		node.name = part[0]
		node.mesh = mesh
		node.material_override = part[2]
		root.add_child(node)
	return packed(root)


## A surface's arrays of [param positions] and [param indices] alone.
static func surface_arrays(positions: PackedVector3Array, indices: PackedInt32Array) -> Array:
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = positions
	arrays[Mesh.ARRAY_INDEX] = indices
	return arrays


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
