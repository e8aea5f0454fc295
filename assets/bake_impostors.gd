extends SceneTree
## Renders the sprite and billboard textures from the level-1 model: front (facing the head) and
## side views, orthographic, on a transparent background, framed exactly like SunflowerField's
## impostor quads (the addon's impostor_set.gd: its WIDTH_UNITS × height_units() model units).
##
## Needs a real renderer (not --headless): xvfb-run godot --path <project with the addon> \
##     --script assets/bake_impostors.gd -- <output folder>

const ImpostorSet: GDScript = preload("res://addons/sunflower_field/impostor_set.gd")
const PartMeshes: GDScript = preload("res://addons/sunflower_field/part_meshes.gd")
const PIXELS_PER_UNIT: float = 150.0


func _init() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	if args.is_empty():
		printerr("usage: xvfb-run godot --path <project> --script bake_impostors.gd -- <output folder>")
		quit(2)
		return
	_bake.call_deferred(args[0])


func _bake(out_dir: String) -> void:
	var width_units: float = ImpostorSet.WIDTH_UNITS
	var height_units: float = ImpostorSet.height_units()
	var viewport: SubViewport = SubViewport.new()
	viewport.size = Vector2i(roundi(width_units * PIXELS_PER_UNIT), roundi(height_units * PIXELS_PER_UNIT))
	viewport.transparent_bg = true
	viewport.msaa_3d = Viewport.MSAA_4X
	viewport.own_world_3d = true
	viewport.render_target_update_mode = SubViewport.UPDATE_ALWAYS
	root.add_child(viewport)

	var environment: Environment = Environment.new()
	environment.background_mode = Environment.BG_CLEAR_COLOR
	environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	environment.ambient_light_color = Color(0.75, 0.8, 0.9)
	environment.ambient_light_energy = 0.55
	var world: WorldEnvironment = WorldEnvironment.new()
	world.environment = environment
	viewport.add_child(world)
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.light_energy = 1.1
	viewport.add_child(sun)

	# The plant, upright: parts chained end to start. Drawn unshaded, so the texture holds plain
	# albedo and the field's own lights shade the impostors once, like the meshes.
	var albedo_only: StandardMaterial3D = StandardMaterial3D.new()
	albedo_only.vertex_color_use_as_albedo = true
	albedo_only.vertex_color_is_srgb = true
	albedo_only.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	albedo_only.cull_mode = BaseMaterial3D.CULL_DISABLED
	var y: float = 0.0
	var parts: PartMeshes = PartMeshes.new()
	for part: int in parts.get_parts_per_level():
		var instance: MeshInstance3D = MeshInstance3D.new()
		instance.mesh = parts.get_mesh(0, part)
		instance.position.y = y
		instance.material_override = albedo_only
		viewport.add_child(instance)
		y += 1.0

	var camera: Camera3D = Camera3D.new()
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = height_units
	camera.keep_aspect = Camera3D.KEEP_HEIGHT
	viewport.add_child(camera)

	var views: Dictionary = {
		"front": [Vector3(0.0, height_units * 0.5, 10.0), Vector3(0.0, height_units * 0.5, 0.0)],
		"side": [Vector3(10.0, height_units * 0.5, 0.0), Vector3(0.0, height_units * 0.5, 0.0)],
	}
	for view: String in views:
		var from: Vector3 = views[view][0]
		camera.look_at_from_position(from, views[view][1])
		# Light from the camera's side and above, so each view is lit like the field's sun.
		sun.look_at_from_position(from + Vector3(3.0, 8.0, 0.0), Vector3.ZERO)
		for i: int in 4:
			await RenderingServer.frame_post_draw
		var image: Image = viewport.get_texture().get_image()
		image.convert(Image.FORMAT_RGBA8)
		_bleed_colours(image)
		var path: String = out_dir.path_join("sunflower_%s.png" % view)
		var error: Error = image.save_png(path)
		print("%s: %s (%dx%d) %s" % [view, path, image.get_width(), image.get_height(), error_string(error)])
	quit()


## Copies colours of opaque pixels into their transparent neighbours, so filtering and mipmaps
## do not pull dark fringes into the alpha-tested edges.
func _bleed_colours(image: Image) -> void:
	var width: int = image.get_width()
	var height: int = image.get_height()
	for pass_index: int in 6:
		var source: Image = image.duplicate()
		for py: int in height:
			for px: int in width:
				if source.get_pixel(px, py).a > 0.02:
					continue
				var sum: Color = Color(0, 0, 0, 0)
				var count: int = 0
				for offset: Vector2i in [Vector2i(1, 0), Vector2i(-1, 0), Vector2i(0, 1), Vector2i(0, -1)]:
					var q: Vector2i = Vector2i(px, py) + offset
					if q.x < 0 or q.y < 0 or q.x >= width or q.y >= height:
						continue
					var c: Color = source.get_pixel(q.x, q.y)
					if c.a > 0.02 or (pass_index > 0 and c.r + c.g + c.b > 0.0):
						sum += Color(c.r, c.g, c.b, 0.0)
						count += 1
				if count > 0:
					var keep_alpha: float = source.get_pixel(px, py).a
					image.set_pixel(px, py, Color(sum.r / count, sum.g / count, sum.b / count, keep_alpha))
