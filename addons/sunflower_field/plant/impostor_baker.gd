@tool
extends RefCounted
## Bakes a [SunflowerPlant]'s multi-view impostor: renders its level-1 parts (a coarser level when
## level 1 has more than [constant BAKE_TRIANGLES] triangles), stacked as the plant
## stands, from [constant SunflowerPlant.ATLAS_VIEWS] directions (around it, and from the side up to
## straight above), orthographic, on a transparent background, each view framing the square of
## [method SunflowerPlant.impostor_frame] about the plant's middle, into atlases: the colours
## (materials drawn unshaded, albedo only: the field's lights shade the impostors once, like the
## meshes), the normals in the plant's own frame, the depths along the view and, when any part
## gives off light, the light given off (the parts' own materials lit by nothing), and when any lets
## light through from behind, that light (their back-light). One copy of the plant per view, turned
## so that a single camera sees it from that view's direction; the camera draws a tile of views at a
## time, as many as [constant TRIANGLES_PER_RENDER] allows. Needs a renderer (not
## [code]--headless[/code]); the work takes frames, so [method bake] is awaited.

const BakeLight: GDScript = preload("bake_light.gd")
const ViewsMeasure: GDScript = preload("views_measure.gd")

## Pixels per view square (a thin plant's views: [constant CELL_PIXELS] × [constant SUPERSAMPLE]).
const CELL_PIXELS: int = 128
## Each view is drawn this many times as wide and high, without multisampling, and averaged down
## ([method _read_pass]): a pixel of the atlas then holds the share of it the plant covers (a leaf a
## quarter of a pixel wide is a quarter of alpha) in the plant's own colour. Multisampled, the
## engine's resolve darkened partly covered pixels (to about cover² of their colour, the
## background's black mixed in twice), and a tree of small leaves, most of its pixels partly
## covered, baked much darker than its meshes.
const SUPERSAMPLE: int = 2
## The most triangles one render of the bake draws: a tile of views is drawn at a time (a frame
## each), as large as keeps the plant's copies in it under this (at least one view). Drawn all at
## once, the 120 views of an 8 500-triangle bush held the editor for one 2.8 s frame under the
## software renderer here, and those of a 300 000-triangle ball 12 s a pass; in tiles of this size
## the longest editor frame of either drop is 1.6 s (tests/editor_bake's probe; a smaller budget
## gave 1.4 s, and the ball's bake took 155 s instead of 100, a frame being most of a second of the
## editor's own drawing).
const TRIANGLES_PER_RENDER: int = 1_000_000
## The most triangles of the mesh level the bake draws: a plant with more at level 1 is drawn from its
## finest level within this ([method bake_level]). A view is drawn 256 pixels wide; 100 000
## triangles there are already more than its pixels, and a 300 000-triangle plant's bake from level 1
## took 111 editor frames (100 s under the software renderer) where its level 3 takes 15.
const BAKE_TRIANGLES: int = 100_000
## Frames waited before a tile is read back: the viewport, asked to update once, draws the tile in
## the next frame (three frames gave the same atlases, in test_bake, on both renderers, and each
## frame waited costs a whole editor frame).
const SETTLE_FRAMES: int = 1
## Added to the mip level the parts' textures are read at in the bake. The views are drawn much
## larger than the plant is where its impostors are shown, so unbiased they read a leaf texture's
## fine detail, which the meshes there average away: a grass clump's blades (a dark midrib down a
## card 3 texels wide) baked with the midrib in a third of their texels, and the grass field 25 m up
## at 45° drew at 0.88 of its meshes' brightness. Biased, the views read textures as the meshes do
## farther than they are drawn, so close up the impostor is brighter than the mesh. 1 keeps both
## within a tenth (test_scene_plant, the grass clump and the bush): close up 1.06 and 1.09 of the
## mesh's brightness (2: 1.12 and 1.11), their fields 0.93–1.01 (2: 0.96–1.03). Geometry is not
## blurred by it, and a plant whose parts are untextured (the built-in sunflower, the maple) bakes
## the same.
const TEXTURE_MIP_BIAS: float = 1.0
## Draws the plant's normals in its own frame as colours (0–1 for −1–1), through
## [constant AS_CODE_SHADER]'s as_code().
const NORMALS_SHADER: String = """
shader_type spatial;
render_mode unshaded, cull_disabled;
%s
void fragment() {
	vec3 world = (INV_VIEW_MATRIX * vec4(NORMAL, 0.0)).xyz;
	ALBEDO = as_code(normalize(transpose(mat3(MODEL_MATRIX)) * world) * 0.5 + 0.5);
}
"""

## Draws how far each point lies along the view from the plant's middle (the plane through its
## copy's origin, facing the camera), in shares of the view's square: 0.5 + z / square, through
## [constant AS_CODE_SHADER]'s as_code().
const DEPTHS_SHADER: String = """
shader_type spatial;
render_mode unshaded, cull_disabled;
uniform float square = 1.0;
%s
void fragment() {
	float z = (INV_VIEW_MATRIX * vec4(VERTEX, 1.0)).z;
	ALBEDO = as_code(vec3(clamp(0.5 + z / square, 0.0, 1.0)));
}
"""
## The colour an unshaded pass writes for the bake to read back [code]code[/code] (0–1): Forward+
## and Mobile convert what they draw to sRGB, so they are handed the linear value that converts to the
## code; the Compatibility renderer writes an unshaded colour as it is (handed the linear value, it
## stored each code as its linear value: a normal's 0.50 as 0.22, which darkened and turned every
## impostor of a plant baked there; test_bake).
const AS_CODE_SHADER: String = """
vec3 as_code(vec3 code) {
#if CURRENT_RENDERER == RENDERER_COMPATIBILITY
	return code;
#else
	return mix(pow((code + 0.055) / 1.055, vec3(2.4)), code / 12.92, step(code, vec3(0.04045)));
#endif
}
"""

## The bake's steps as [method bake] reports them: three passes, back-light, emission, writing, importing.
const STEPS: float = 7.0

## When above 0, used instead of [constant TRIANGLES_PER_RENDER] ([method test_set_triangles_per_render]).
static var _test_triangles_per_render: int = 0


## The bake's world: its viewport (a tile of views large), the camera that frames one tile at a
## time, the tile's size in views, a view square's side in metres and the mesh level drawn.
class Stage:
	var viewport: SubViewport
	var camera: Camera3D
	var tile: Vector2i
	var square: float
	var level: int


## Renders [param plant]'s impostor atlases in a viewport under [param host] (any node in a tree
## that draws: the editor's base control, the field), saves them as
## [code]<folder>/<base_name>_views.png[/code], [code]_normals.png[/code], [code]_depths.png[/code]
## and, for a plant that glows or lets light through, [code]_emission.png[/code] and
## [code]_backlight.png[/code] (default: beside the plant's resource file, named after it), and gives
## them to the plant (reimported in the editor; loaded from the files elsewhere). Returns OK, or an
## error after pushing what went wrong. [param progress], when valid, is called with each step's
## name and the share of the bake done before it (0–1), a drawn frame ahead of the step.
static func bake(
	plant: SunflowerPlant, host: Node, folder: String = "", base_name: String = "", progress: Callable = Callable()
) -> Error:
	# The editor draws a frame only when something on screen changed; the bake waits for drawn frames
	# of its own viewport, so frames are drawn continuously while it runs.
	var low_processor: bool = OS.low_processor_usage_mode
	OS.low_processor_usage_mode = false
	var result: Error = await _bake(plant, host, folder, base_name, progress)
	OS.low_processor_usage_mode = low_processor
	return result


static func _bake(plant: SunflowerPlant, host: Node, folder: String, base_name: String, progress: Callable) -> Error:
	if plant == null or host == null or not host.is_inside_tree():
		push_error("Bake impostors: needs a plant and a node in the scene tree to render under")
		return ERR_INVALID_PARAMETER
	if DisplayServer.get_name() == "headless":
		push_error("Bake impostors: rendering is off (--headless); run with a display or under Xvfb")
		return ERR_UNAVAILABLE
	if folder.is_empty():
		folder = (plant.resource_path.get_base_dir() if plant.resource_path.begins_with("res://") else "user://")
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
	for problem: String in BakeLight.lighting_not_baked(plant, bake_level(plant)):
		push_warning("Bake impostors: " + problem)
	var stage: Stage = _stage(plant)
	var viewport: SubViewport = stage.viewport
	host.add_child(viewport)
	var images: Array[Image] = []
	var kinds: PackedStringArray = SunflowerPlant.IMPOSTOR_TEXTURES.duplicate()
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		_tell(progress, "drawing its " + kind, images.size() / STEPS)
		if kind != "views":
			var coded: ShaderMaterial = ShaderMaterial.new()
			coded.shader = Shader.new()
			coded.shader.code = (NORMALS_SHADER if kind == "normals" else DEPTHS_SHADER) % AS_CODE_SHADER
			if kind == "depths":
				coded.set_shader_parameter("square", plant.impostor_frame().x)
			for instance: Node in viewport.find_children("*", "MeshInstance3D", true, false):
				(instance as MeshInstance3D).material_override = coded
		var image: Image = null
		if kind == "views":
			image = await _read_views(stage)
		else:
			image = await _read_pass(stage)
		if image == null:
			viewport.queue_free()
			push_error("Bake impostors: the %s rendered nothing (no renderer?)" % kind)
			return ERR_CANT_CREATE
		images.append(image)
	_tell(progress, "drawing its back-light", 3.0 / STEPS)
	var through: Image = await BakeLight.backlight(stage, _read_pass)
	_tell(progress, "drawing its emission", 4.0 / STEPS)
	var glow: BakeLight.Glow = await BakeLight.emission(stage, plant, _read_pass)
	viewport.queue_free()
	if glow.image:
		kinds.append(SunflowerPlant.EMISSION_TEXTURE)
		images.append(glow.image)
	if through:
		kinds.append(SunflowerPlant.BACKLIGHT_TEXTURE)
		images.append(through)
	# Writing and importing the atlases take whole frames of their own: their step is drawn first.
	await _tell_drawn(progress, "writing its atlases", 5.0 / STEPS, host.get_tree())
	var paths: PackedStringArray = []
	for i: int in images.size():
		var path: String = folder.path_join("%s_%s.png" % [base_name, kinds[i]])
		var saved: Error = images[i].save_png(path)
		if saved != OK:
			push_error("Bake impostors: cannot write %s (%s)" % [path, error_string(saved)])
			return saved
		paths.append(path)
	plant.impostor_emission_range = glow.energy_range
	ViewsMeasure.measure(plant, images[0])
	await _tell_drawn(progress, "importing its atlases", 6.0 / STEPS, host.get_tree())
	await _give_textures(plant, kinds, paths, images, host.get_tree())
	return OK


static func _tell(progress: Callable, step: String, done: float) -> void:
	if progress.is_valid():
		progress.call(step, done)


## [method _tell], then (when someone shows the progress) two frames of [param tree], so that the
## step is drawn before work that holds a whole frame.
static func _tell_drawn(progress: Callable, step: String, done: float, tree: SceneTree) -> void:
	_tell(progress, step, done)
	if progress.is_valid():
		await tree.process_frame
		await tree.process_frame


## The picture of a pass, as 8-bit RGBA at the atlas' size: [method _read_drawn] brought down by
## [method _average_down] on a worker thread (it takes most of a second for a 120-view atlas on one
## core; the editor draws meanwhile). Null when nothing was rendered.
static func _read_pass(stage: Stage) -> Image:
	var image: Image = await _read_drawn(stage)
	if image != null:
		await _on_worker(_average_down.bind(image))
	return image


## The views pass: as [method _read_pass], or, for a thin plant (its views as [method _read_pass]
## gives them thin by ViewsMeasure.thin_from), at the size drawn ([constant SUPERSAMPLE] times as fine,
## each texel covered or not, its covered colours bled as [method _average_down] does). A thin
## crown's leaves are about a texel of the usual views: drawn larger than that (nearer than
## impostors begin on a screen of 1 600 lines or more, or close up) they were cut to the crown's
## dense middle (0.63–0.65 of its meshes' cover); twice as fine, they are a texel each where the
## impostor is drawn up to twice as large.
static func _read_views(stage: Stage) -> Image:
	var drawn: Image = await _read_drawn(stage)
	if drawn == null:
		return null
	var averaged: Image = drawn.duplicate() as Image
	await _on_worker(_average_down.bind(averaged))
	if ViewsMeasure.thin_from(ViewsMeasure.alpha_levels(averaged)) < 0.0:
		return averaged
	await _on_worker(_bleed.bind(drawn))
	return drawn


## Runs [param work] on a worker thread, drawing frames until it is done.
static func _on_worker(work: Callable) -> void:
	var task: int = WorkerThreadPool.add_task(work, false, "Sunflower Field: impostor pass")
	while not WorkerThreadPool.is_task_completed(task):
		await RenderingServer.frame_post_draw
	WorkerThreadPool.wait_for_task_completion(task)


## The pass as drawn: the stage's tiles drawn one a frame and put together ([constant SUPERSAMPLE]
## times as large as the atlas, each pixel covered or not). Null when nothing was rendered.
static func _read_drawn(stage: Stage) -> Image:
	var views: Vector2i = SunflowerPlant.ATLAS_VIEWS
	var pixels: int = CELL_PIXELS * SUPERSAMPLE
	var image: Image = null
	for top: int in range(0, views.y, stage.tile.y):
		for left: int in range(0, views.x, stage.tile.x):
			var middle: Vector2 = Vector2(left, top) + Vector2(stage.tile) * 0.5
			stage.camera.position = Vector3(middle.x * stage.square, -middle.y * stage.square, 4.0 * stage.square)
			stage.viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
			for i: int in SETTLE_FRAMES:
				await RenderingServer.frame_post_draw
			var drawn: Image = stage.viewport.get_texture().get_image()
			if drawn == null or drawn.is_empty():
				return null
			if image == null:
				image = Image.create_empty(views.x * pixels, views.y * pixels, false, drawn.get_format())
			image.blit_rect(drawn, Rect2i(Vector2i.ZERO, drawn.get_size()), Vector2i(left, top) * pixels)
	return image


## Turns the drawn picture [param image] (in place) into 8-bit RGBA at the atlas' size: its covered
## pixels' colours bled into their transparent neighbours, then averaged down, so that a pixel's
## alpha is the share of it covered and its colour that of what covers it; then bled again (so
## filtering and mipmaps do not pull dark fringes into the alpha-tested edges).
static func _average_down(image: Image) -> void:
	image.convert(Image.FORMAT_RGBA8)
	var size: int = SUPERSAMPLE
	while size > 1:
		image.fix_alpha_edges()  # within 4 pixels: every covered pixel's square of 2 × 2 is reached
		image.shrink_x2()
		size /= 2
	image.fix_alpha_edges()


## Turns the drawn picture [param image] (in place) into 8-bit RGBA at its size, its covered pixels'
## colours bled into their transparent neighbours (for filtering and mipmaps, as [method _average_down]).
static func _bleed(image: Image) -> void:
	image.convert(Image.FORMAT_RGBA8)
	image.fix_alpha_edges()


## The direction view (column, row) of the atlas sees the plant from, and the image's right and up,
## in the plant's frame: as shaders/impostor.gdshader turns its quad.
static func view_basis(column: int, row: int) -> Basis:
	var azimuth: float = TAU * column / SunflowerPlant.ATLAS_VIEWS.x
	var elevation: float = 0.5 * PI * row / (SunflowerPlant.ATLAS_VIEWS.y - 1)
	var right: Vector3 = Vector3(cos(azimuth), 0.0, -sin(azimuth))
	var back: Vector3 = Vector3(sin(azimuth) * cos(elevation), sin(elevation), cos(azimuth) * cos(elevation))
	return Basis(right, back.cross(right), back)


## A world of its own with one copy of the plant's parts at the bake's level ([method bake_level])
## per view, each turned so that an orthographic camera looking down −z sees it from its view's
## direction in its square, and a transparent background; the viewport and camera one tile of views
## large.
static func _stage(plant: SunflowerPlant) -> Stage:
	var views: Vector2i = SunflowerPlant.ATLAS_VIEWS
	var frame: Vector2 = plant.impostor_frame()
	var stage: Stage = Stage.new()
	var level: int = bake_level(plant)
	stage.level = level
	stage.tile = tile_of(plant.triangle_count(level))
	stage.square = frame.x
	var viewport: SubViewport = SubViewport.new()
	stage.viewport = viewport
	viewport.name = "ImpostorBaker"
	viewport.size = stage.tile * CELL_PIXELS * SUPERSAMPLE
	viewport.transparent_bg = true
	viewport.msaa_3d = Viewport.MSAA_DISABLED
	# The parts' textures read as at the atlas' own size (log2 of the supersampling coarser).
	viewport.texture_mipmap_bias = TEXTURE_MIP_BIAS + log(SUPERSAMPLE) / log(2.0)
	viewport.own_world_3d = true
	viewport.debug_draw = Viewport.DEBUG_DRAW_UNSHADED
	viewport.render_target_update_mode = SubViewport.UPDATE_DISABLED
	var environment: Environment = Environment.new()
	environment.background_mode = Environment.BG_CLEAR_COLOR
	var world: WorldEnvironment = WorldEnvironment.new()
	world.environment = environment
	viewport.add_child(world)
	var stacked: Vector3 = plant.stacked_lengths()
	var lengths: Array[float] = [stacked.x, stacked.y, stacked.z]
	for row: int in views.y:
		for column: int in views.x:
			# The view's basis maps image axes to the plant's; its inverse turns the plant to the camera.
			var turn: Basis = view_basis(column, row).transposed()
			var square_centre: Vector3 = Vector3((column + 0.5) * frame.x, -(row + 0.5) * frame.x, 0.0)
			var copy: Node3D = Node3D.new()
			copy.transform = Transform3D(turn, square_centre - turn * Vector3(0.0, frame.y, 0.0))
			viewport.add_child(copy)
			var y: float = 0.0
			for part: int in lengths.size():
				var instance: MeshInstance3D = MeshInstance3D.new()
				instance.mesh = plant.mesh_drawn(level, part)
				for parameter: StringName in plant.instance_shader_parameters:
					instance.set_instance_shader_parameter(parameter, plant.instance_shader_parameters[parameter])
				instance.position.y = y
				copy.add_child(instance)
				y += lengths[part]
	var camera: Camera3D = Camera3D.new()
	camera.name = "Camera"
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = stage.tile.y * frame.x
	camera.keep_aspect = Camera3D.KEEP_HEIGHT
	camera.far = 8.0 * frame.x
	viewport.add_child(camera)
	stage.camera = camera
	return stage


## The mesh level (0–2) the bake draws: the finest of at most [constant BAKE_TRIANGLES] triangles,
## else the coarsest.
static func bake_level(plant: SunflowerPlant) -> int:
	for level: int in 2:
		if plant.triangle_count(level) <= BAKE_TRIANGLES:
			return level
	return 2


## The tile of views (columns, rows) one render draws for a plant of [param triangles] triangles:
## whole rows while a row fits in [constant TRIANGLES_PER_RENDER], else part of a row; its sides
## divide the atlas' so that every tile is whole.
static func tile_of(triangles: int) -> Vector2i:
	var views: Vector2i = SunflowerPlant.ATLAS_VIEWS
	var budget: int = _test_triangles_per_render if _test_triangles_per_render > 0 else TRIANGLES_PER_RENDER
	var fits: int = maxi(budget / maxi(triangles, 1), 1)
	var rows: int = _largest_divisor(views.y, fits / views.x)
	return Vector2i(views.x, rows) if rows > 0 else Vector2i(_largest_divisor(views.x, fits), 1)


## Test hook: bakes draw tiles of at most [param triangles] (0: [constant TRIANGLES_PER_RENDER]).
static func test_set_triangles_per_render(triangles: int) -> void:
	_test_triangles_per_render = triangles


## The largest divisor of [param whole] that is at most [param most] (0 when [param most] < 1).
static func _largest_divisor(whole: int, most: int) -> int:
	for divisor: int in range(mini(whole, most), 0, -1):
		if whole % divisor == 0:
			return divisor
	return 0


## Hands the textures of [param kinds] to the plant (and no emission or back-light texture when they
## hold none): in the editor reimported from the files (and the plant saved when it is a file),
## elsewhere made from the images.
static func _give_textures(
	plant: SunflowerPlant, kinds: PackedStringArray, paths: PackedStringArray, images: Array[Image], tree: SceneTree
) -> void:
	var textures: Array[Texture2D] = []
	var in_project: bool = Engine.is_editor_hint() and paths[0].begins_with("res://")
	if in_project:
		var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
		for path: String in paths:
			filesystem.update_file(path)
		_write_import_settings(paths)
		for path: String in paths:  # one a frame: each import holds the editor's frame
			filesystem.reimport_files(PackedStringArray([path]))
			await tree.process_frame
		for path: String in paths:
			textures.append(ResourceLoader.load(path, "Texture2D", ResourceLoader.CACHE_MODE_REPLACE) as Texture2D)
	else:
		for image: Image in images:
			textures.append(atlas_texture(image, plant.name))
	plant.impostor_emission = null
	plant.impostor_backlight = null
	for i: int in textures.size():
		plant.set("impostor_" + kinds[i], textures[i])
	if in_project and plant.resource_path.begins_with("res://") and not plant.resource_path.contains("::"):
		ResourceSaver.save(plant)


## An atlas [param image] as baked (or read back from a baked file) as the texture the impostors
## draw outside the editor: premultiplied by coverage, with mipmaps, as the import makes it.
static func atlas_texture(image: Image, texture_name: String) -> ImageTexture:
	image.premultiply_alpha()
	image.generate_mipmaps()
	var texture: ImageTexture = ImageTexture.create_from_image(image)
	texture.resource_name = texture_name
	return texture


## The atlases import losslessly, premultiplied by coverage and with mipmaps (the shader divides the
## coverage out and keeps it across the mipmaps), the normals as plain data (no normal-map
## compression).
static func _write_import_settings(paths: PackedStringArray) -> void:
	for path: String in paths:
		var settings: ConfigFile = ConfigFile.new()
		settings.load(path + ".import")  # kept where it exists
		settings.set_value("remap", "importer", "texture")
		settings.set_value("remap", "type", "CompressedTexture2D")
		settings.set_value("params", "compress/mode", 0)
		settings.set_value("params", "mipmaps/generate", true)
		settings.set_value("params", "process/fix_alpha_border", true)
		settings.set_value("params", "process/premult_alpha", true)
		settings.set_value("params", "detect_3d/compress_to", 0)
		settings.save(path + ".import")
