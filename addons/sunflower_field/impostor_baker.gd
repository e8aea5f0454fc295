@tool
extends RefCounted
## Bakes a [FieldPlant]'s impostor textures: renders its level-1 parts, stacked as the plant stands,
## from the front (+z) and the side (+x), orthographic, on a transparent background, framed exactly
## like the impostor quads ([member FieldPlant.impostor_width] × [member FieldPlant.height_units]
## model units). Materials are drawn unshaded (albedo only): the field's lights shade the impostors
## once, like the meshes. The front view is also the billboard's. Needs a renderer (not
## [code]--headless[/code]); the work takes a few frames, so [method bake] is awaited.

const PIXELS_PER_UNIT: float = 150.0
const VIEWS: PackedStringArray = ["front", "side"]
## Rendered frames before a view is read back (the first ones may not have the meshes yet).
const SETTLE_FRAMES: int = 3


## Renders [param plant]'s front and side textures in a viewport under [param host] (any node in a
## tree that draws: the editor's base control, the field), saves them as
## [code]<folder>/<base_name>_front.png[/code] and [code]_side.png[/code] (default: beside the plant's
## resource file, named after it), and gives them to the plant (reimported in the editor; loaded
## from the files elsewhere). Returns OK, or an error after pushing what went wrong.
static func bake(plant: FieldPlant, host: Node, folder: String = "", base_name: String = "") -> Error:
	if plant == null or host == null or not host.is_inside_tree():
		push_error("Bake impostors: needs a plant and a node in the scene tree to render under")
		return ERR_INVALID_PARAMETER
	if DisplayServer.get_name() == "headless":
		push_error("Bake impostors: rendering is off (--headless); run with a display or under Xvfb")
		return ERR_UNAVAILABLE
	if folder.is_empty():
		folder = plant.resource_path.get_base_dir() if plant.resource_path.begins_with("res://") else "user://"
	if base_name.is_empty():
		base_name = (
			plant.resource_path.get_file().get_basename()
			if not plant.resource_path.is_empty() and not plant.resource_path.contains("::")
			else plant.name.to_snake_case()
		)
	var made: Error = DirAccess.make_dir_recursive_absolute(folder)
	if made != OK:
		push_error("Bake impostors: cannot make the folder %s (%s)" % [folder, error_string(made)])
		return made
	var viewport: SubViewport = _stage(plant)
	host.add_child(viewport)
	var paths: PackedStringArray = []
	var images: Array[Image] = []
	var camera: Camera3D = viewport.get_node("Camera")
	var middle: float = plant.height_units * 0.5
	for view: String in VIEWS:
		var eye: Vector3 = Vector3(0.0, middle, 50.0) if view == "front" else Vector3(50.0, middle, 0.0)
		camera.look_at_from_position(eye, Vector3(0.0, middle, 0.0))
		viewport.render_target_update_mode = SubViewport.UPDATE_ALWAYS
		for i: int in SETTLE_FRAMES:
			await RenderingServer.frame_post_draw
		var image: Image = viewport.get_texture().get_image()
		if image == null or image.is_empty():
			viewport.queue_free()
			push_error("Bake impostors: the %s view rendered nothing (no renderer?)" % view)
			return ERR_CANT_CREATE
		image.convert(Image.FORMAT_RGBA8)
		bleed_colours(image)
		var path: String = folder.path_join("%s_%s.png" % [base_name, view])
		var saved: Error = image.save_png(path)
		if saved != OK:
			viewport.queue_free()
			push_error("Bake impostors: cannot write %s (%s)" % [path, error_string(saved)])
			return saved
		paths.append(path)
		images.append(image)
	viewport.queue_free()
	_give_textures(plant, paths, images)
	return OK


## A world of its own with the plant's level-1 parts, unshaded, an orthographic camera framing the
## impostor rectangle, and a transparent background.
static func _stage(plant: FieldPlant) -> SubViewport:
	var viewport: SubViewport = SubViewport.new()
	viewport.name = "ImpostorBaker"
	viewport.size = Vector2i(
		maxi(8, roundi(plant.impostor_width * PIXELS_PER_UNIT)), maxi(8, roundi(plant.height_units * PIXELS_PER_UNIT))
	)
	viewport.transparent_bg = true
	viewport.msaa_3d = Viewport.MSAA_4X
	viewport.own_world_3d = true
	viewport.debug_draw = Viewport.DEBUG_DRAW_UNSHADED
	viewport.render_target_update_mode = SubViewport.UPDATE_ALWAYS
	var environment: Environment = Environment.new()
	environment.background_mode = Environment.BG_CLEAR_COLOR
	var world: WorldEnvironment = WorldEnvironment.new()
	world.environment = environment
	viewport.add_child(world)
	var lengths: Array[float] = [plant.part_lengths.x, plant.part_lengths.y, plant.part_lengths.z]
	var y: float = 0.0
	for part: int in lengths.size():
		var instance: MeshInstance3D = MeshInstance3D.new()
		instance.mesh = plant.mesh_drawn(0, part)
		instance.position.y = y
		viewport.add_child(instance)
		y += lengths[part]
	var camera: Camera3D = Camera3D.new()
	camera.name = "Camera"
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = plant.height_units
	camera.keep_aspect = Camera3D.KEEP_HEIGHT
	camera.far = 200.0
	viewport.add_child(camera)
	return viewport


## Hands the textures to the plant: in the editor reimported from the files (and the plant saved
## when it is a file), elsewhere made from the images.
static func _give_textures(plant: FieldPlant, paths: PackedStringArray, images: Array[Image]) -> void:
	var textures: Array[Texture2D] = []
	var in_project: bool = Engine.is_editor_hint() and paths[0].begins_with("res://")
	if in_project:
		var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
		filesystem.update_file(paths[0])
		filesystem.update_file(paths[1])
		filesystem.reimport_files(paths)
		for path: String in paths:
			textures.append(ResourceLoader.load(path, "Texture2D", ResourceLoader.CACHE_MODE_REPLACE) as Texture2D)
	else:
		for image: Image in images:
			var texture: ImageTexture = ImageTexture.create_from_image(image)
			texture.resource_name = plant.name
			textures.append(texture)
	plant.front_texture = textures[0]
	plant.side_texture = textures[1]
	plant.billboard_texture = textures[0]
	if in_project and plant.resource_path.begins_with("res://") and not plant.resource_path.contains("::"):
		ResourceSaver.save(plant)


## Copies colours of opaque pixels into their transparent neighbours, so filtering and mipmaps do
## not pull dark fringes into the alpha-tested edges.
static func bleed_colours(image: Image) -> void:
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
