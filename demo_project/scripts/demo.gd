extends Node3D
## The Sunflower Field demo: fly over a field, change the wind, swap plant parts, pick a map.
## It uses the addon only through its public API, as a game would.
##
## Command line (after --):
##   --map PATH               any .field file (res://, user:// or absolute)
##   --part LEVEL,PART,PATH   replace a part with a glTF mesh (level 1-3, part bottom/middle/head)
##   --frames N               recording mode: fly the scripted path for N frames, then quit
##   --path FILE              the recording path (lines "x y z tx ty tz"); default: a built-in flight
##   --view NAME              record from a still view instead: inside, outside40, above45, down60
##   --draw-distance M        the field's max_draw_distance (and the native baseline's cut-off)
##   --tile-merge M           the field's tile_merge_distance (0: far tiles never merge)
##   --screenshot PATH        save the last frame (recording mode; 60 frames if --frames is not given)
##   --screenshot-every K     also save every K-th frame, as PATH with the frame number
##   --stats PATH             write frame times, LOD counts and the renderer as JSON
##   --force-lod N            draw every plant as one representation (0-2 meshes, 3 sprite, 4 billboard)
##   --culling off            do not skip plants outside the camera's view
##   --baseline native        draw the field the Godot-native way instead (benchmark baseline): whole
##                            plants near, front-view quads far; native-whole: whole plants everywhere;
##                            native-hashed: the far quads' alpha test hashed (the far field keeps its cover)
##   --wind P                 the wind power (0: calm)
##   --whole off              draw the near plants part by part (SunflowerPlant.draw_whole off)
##   --cheap-shadows off      near plants at mesh 1 and 2 cast shadows from the mesh they are drawn with
##   --impostor-shadows FROM  near plants at this level on cast from impostors: mesh2, mesh3 (default), never
##   --shadows off            the sun casts no shadows (the fragment cost alone, for the far-plant benchmark)
##   --budget-primitives N    hold the near meshes to N triangles a frame (Project Settings:
##                            sunflower_field/frame_budget/max_primitives)
##   --budget-gpu-ms MS       hold the frame's GPU time to MS milliseconds (sunflower_field/frame_budget/gpu_ms)
##   --no-hud                 hide the heads-up display (pictures for measurements)
##   --load-changes           restore the plants as the last run left them (trampled, cut: saved at quit)
##   --cut-every K            recording mode: swing the scythe (X) every K-th frame

const MAP_NAMES: PackedStringArray = [
	"Demo field (40 x 30)",
	"Large field (400 x 300)",
	"Hills (240 x 240, on a terrain)",
	"Plants (maples, bushes, grass from Blender's Sapling, on the hills)",
	"Hillside (the same plants placed by rules: fields/hillside.field)",
]
const MAP_PATHS: PackedStringArray = [
	"res://fields/demo.field",
	"res://fields/large.field",
	"res://fields/hills.field",
	"res://fields/plants.field",
	DemoHillside.MAP_PATH,
]
## The maps that stand on the demo's hills (ground source Colliders); the others lie on the plane.
const HILLS_MAPS: PackedStringArray = ["hills.field", "plants.field", "hillside.field"]
## The maps whose legend grows the test plants (DemoPlants).
const PLANTS_MAPS: PackedStringArray = ["plants.field", "hillside.field"]
const INCREMENTS: PackedFloat32Array = [0.1, 10.0]
## The frame budget's Project Settings (the addon's field_project_settings.gd).
const BUDGET_PRIMITIVES: String = "sunflower_field/frame_budget/max_primitives"
const BUDGET_GPU_MS: String = "sunflower_field/frame_budget/gpu_ms"
const TRIANGLES_SPRITE: int = 4
const TRIANGLES_BILLBOARD: int = 2
## Below this eye height the camera is a pusher: the flowers part around it.
const PUSHER_HEIGHT: float = 2.5
## How far around the low camera the flowers part, metres (wide enough to see the parting ahead).
const PUSHER_RADIUS: float = 1.1

var _map_path: String = MAP_PATHS[0]
var _stats_timer: float = 0.0
var _draw_distance: float = NativeBaseline.CUT_OFF
## The recording mode (the benchmark harness), configured from the command line.
var _recording: DemoRecording = DemoRecording.new()
## Trampling, the scythe, the events' counts and the save of the changes.
var _play: DemoPlay = DemoPlay.new()
var _load_changes: bool = false
var _cut_every: int = 0

@onready var _field: SunflowerField = $Field
@onready var _camera: FlyCamera = $Camera
@onready var _hud: DemoHud = $Hud
@onready var _ground: MeshInstance3D = $Ground
@onready var _hills: DemoHills = $Hills


func _ready() -> void:
	_field.field_built.connect(_on_field_built)
	_field.map_error.connect(_on_map_error)
	_hud.map_chosen.connect(load_map)
	_recording.name = "Recording"
	add_child(_recording)
	_recording.before_quit = func() -> void: _play.save(_map_path)
	_play.name = "Play"
	add_child(_play)
	_play.setup(_field, _camera)
	var parts: PackedStringArray = []
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var i: int = 0
	while i < args.size():
		var value: String = args[i + 1] if i + 1 < args.size() else ""
		match args[i]:
			"--map":
				_map_path = value
			"--part":
				parts.append(value)
			"--frames":
				_recording.frames_total = value.to_int()
			"--path":
				_recording.path_file = value
			"--view":
				_recording.view = value
			"--draw-distance":
				_draw_distance = value.to_float()
				_field.max_draw_distance = _draw_distance
			"--tile-merge":
				_field.tile_merge_distance = value.to_float()
			"--screenshot":
				_recording.screenshot = value
			"--screenshot-every":
				_recording.screenshot_every = value.to_int()
			"--stats":
				_recording.stats_path = value
			"--force-lod":
				_field.force_lod = value.to_int()
			"--culling":
				_field.frustum_culling = value != "off"
			"--baseline":
				_recording.baseline = value
			"--whole":
				var own: SunflowerPlant = SunflowerPlant.default_plant().duplicate()
				own.draw_whole = value != "off"
				_field.plant = own
			"--wind":
				_field.wind_power = value.to_float()
			"--cheap-shadows":
				_field.cheap_shadows = value != "off"
			"--impostor-shadows":
				var levels: Dictionary = {"mesh2": SunflowerField.Lod.MESH_2, "mesh3": SunflowerField.Lod.MESH_3}
				_field.impostor_shadows_from = levels.get(value, SunflowerField.Lod.SPRITE)
			"--shadows":
				($Sun as DirectionalLight3D).shadow_enabled = value != "off"
			"--budget-primitives":
				ProjectSettings.set_setting(BUDGET_PRIMITIVES, value.to_int())
			"--budget-gpu-ms":
				ProjectSettings.set_setting(BUDGET_GPU_MS, value.to_float())
			"--no-hud":
				_hud.visible = false
				i -= 1
			"--load-changes":
				_load_changes = true
				i -= 1
			"--cut-every":
				_cut_every = value.to_int()
			_:
				_fail("unknown argument '%s' (see demo.gd for the options)" % args[i])
				i -= 1
		i += 2
	var stats_wanted: bool = not _recording.stats_path.is_empty()
	if _recording.wanted() and _recording.frames_total < 0:
		_recording.frames_total = 60
	if stats_wanted:
		for frame: int in 3:  # the scene without a field, drawn: what the renderer holds anyway
			await get_tree().process_frame
		_recording.buffer_memory["before"] = RenderingServer.get_rendering_info(
			RenderingServer.RENDERING_INFO_BUFFER_MEM_USED
		)
	_place_view_camera()
	var build_start: int = Time.get_ticks_usec()
	await load_map(_map_path)
	while _field.is_building():  # a large map builds in the background; the HUD shows its progress
		await get_tree().process_frame
	if stats_wanted:
		await get_tree().process_frame  # the field's first frame: its buffers are allocated
		_recording.buffer_memory["field"] = RenderingServer.get_rendering_info(
			RenderingServer.RENDERING_INFO_BUFFER_MEM_USED
		)
	if _recording.baseline.begins_with("native"):
		_build_native_baseline()
		if stats_wanted:
			await get_tree().process_frame
			_recording.buffer_memory["baseline"] = RenderingServer.get_rendering_info(
				RenderingServer.RENDERING_INFO_BUFFER_MEM_USED
			)
	_recording.build_ms = (Time.get_ticks_usec() - build_start) / 1000.0
	_recording.map_path = _map_path
	print("demo: %s built in %.0f ms; %s" % [_map_path, _recording.build_ms, _field.get_build_stats()])
	for argument: String in parts:
		apply_part_argument(argument)
	if _load_changes:
		var problem: String = _play.load_saved(_map_path)
		if not problem.is_empty():
			_fail(problem)
	if _recording.frames_total >= 0:
		_recording.start(_field, _camera)


## With a still view (--view), the camera is put there before the field builds, so that the far
## tiles' records are ordered for it from the start (as a game's camera stands at its spawn point).
func _place_view_camera() -> void:
	if _recording.view.is_empty() or not ResourceLoader.exists(_map_path):
		return
	var map: SunflowerFieldMap = load(_map_path) as SunflowerFieldMap
	var path: CameraPath = (
		CameraPath.view(_recording.view, DemoRecording.field_size(map, _field.cell_size)) if map else null
	)
	if path:
		_camera.transform = path.sample(0.0)


## Loads a map; an imported res:// map is used as a resource, any other path is read directly.
## A large map builds in the background while the current field stays (the project setting
## sunflower_field/performance/background_build).
func load_map(path: String) -> void:
	if PLANTS_MAPS.has(path.get_file()) and not _field.legend.has("t"):
		_hud.show_message("making the plants of the Plants map (their impostors bake on first use)…")
		var legend: Dictionary = _field.legend.duplicate()
		legend.merge(await DemoPlants.legend(self))
		_field.legend = legend
		_hud.clear_message()
	var hilly: bool = HILLS_MAPS.has(path.get_file())
	_hills.set_enabled(hilly)
	_ground.visible = not hilly
	_field.ground_source = SunflowerField.GroundSource.COLLIDERS if hilly else SunflowerField.GroundSource.FLAT
	var imported: Resource = load(path) if path.begins_with("res://") and ResourceLoader.exists(path) else null
	if imported is SunflowerFieldMap:
		_field.map = imported
	elif _field.load_map_file(path, true) != OK:
		return  # the field says why, through map_error
	_map_path = path
	_hud.set_maps(MAP_NAMES, MAP_PATHS, path)


## Applies a "LEVEL,PART,PATH" part replacement; returns an empty string or the error shown.
func apply_part_argument(argument: String) -> String:
	var parsed: Dictionary = PartLoader.parse_argument(argument)
	if parsed.has("error"):
		_hud.show_message(parsed["error"])
		return parsed["error"]
	return load_part(parsed["lod"], parsed["part"], parsed["path"])


## Replaces one part with the first mesh of a glTF file; returns an empty string or the error shown.
func load_part(lod: int, part: int, path: String) -> String:
	var loaded: Dictionary = PartLoader.load_mesh(path)
	if loaded.has("error"):
		_hud.show_message("cannot use the part: " + loaded["error"])
		return loaded["error"]
	_field.set_part_mesh(lod, part, loaded["mesh"])
	var message: String = loaded.get(
		"warning", "mesh %d %s replaced by %s" % [lod + 1, SunflowerField.Part.keys()[part].to_lower(), path.get_file()]
	)
	_hud.show_message(message)
	if lod == 0 and DisplayServer.get_name() != "headless":
		_rebake_impostors.call_deferred(message)  # the far levels show the new part too
	return ""


## Bakes the field's impostors from its level-1 parts after a part swap, so sprites and billboards
## match the meshes.
func _rebake_impostors(message: String) -> void:
	if await _field.bake_impostors() == OK:
		_hud.show_message(message + "; impostors baked to match")


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed("wind_more"):
		_field.increase_wind()
	elif event.is_action_pressed("wind_less"):
		_field.decrease_wind()
	elif event.is_action_pressed("wind_direction_x"):
		_field.wind_direction = _step_direction(_field.wind_direction, 0)
	elif event.is_action_pressed("wind_direction_z"):
		_field.wind_direction = _step_direction(_field.wind_direction, 1)
	elif event.is_action_pressed("toggle_increment"):
		_field.wind_increment = (
			INCREMENTS[1] if is_equal_approx(_field.wind_increment, INCREMENTS[0]) else INCREMENTS[0]
		)
	elif event.is_action_pressed("walk_mode"):
		_camera.walking = not _camera.walking
		_hud.show_message("walk mode: head height, the flowers part around you" if _camera.walking else "fly mode")
	elif event.is_action_pressed("wind_model"):
		var natural: bool = _field.wind.model == SunflowerWind.Model.NATURAL
		_field.wind.model = SunflowerWind.Model.THESIS if natural else SunflowerWind.Model.NATURAL
		_hud.show_message("wind model: " + _wind_model_name())
	elif event.is_action_pressed("toggle_wireframe"):
		var wireframe: bool = get_viewport().debug_draw != Viewport.DEBUG_DRAW_WIREFRAME
		get_viewport().debug_draw = Viewport.DEBUG_DRAW_WIREFRAME if wireframe else Viewport.DEBUG_DRAW_DISABLED
	elif event.is_action_pressed("toggle_help"):
		_hud.toggle_help()
	elif event.is_action_pressed("next_map"):
		load_map(MAP_PATHS[(MAP_PATHS.find(_map_path) + 1) % MAP_PATHS.size()])
	elif event.is_action_pressed("load_part"):
		_open_part_dialog()
	elif event.is_action_pressed("cut_plants"):
		_hud.show_message("scythe: %d plants cut" % _play.swing_scythe())
	elif event.is_action_pressed("sow_plants"):
		_hud.show_message("sown: %d plants" % _play.sow())
	elif event.is_action_pressed("quit"):
		if Input.mouse_mode == Input.MOUSE_MODE_CAPTURED:
			Input.mouse_mode = Input.MOUSE_MODE_VISIBLE
		else:
			_play.save(_map_path)
			get_tree().quit()


func _process(delta: float) -> void:
	# Flying low (or walking), the camera is a body among the flowers: they part around it.
	var low: bool = _camera.global_position.y < PUSHER_HEIGHT
	if low != _camera.is_in_group(_field.pusher_group):
		if low:
			_camera.set_meta(&"push_radius", PUSHER_RADIUS)
			_camera.add_to_group(_field.pusher_group)
		else:
			_camera.remove_from_group(_field.pusher_group)
	_stats_timer -= delta
	if _stats_timer <= 0.0:
		_stats_timer = 0.25
		_hud.set_stats(_stats_text())
	if _recording.is_running():  # recording starts once the field is built
		if _cut_every > 0 and _recording.get_frame() % _cut_every == _cut_every - 1:
			_play.swing_scythe()
		_recording.record_frame()


## Steps one component of the wind direction by 0.5 through -1 … 1 (thesis keys F4 / F5).
func _step_direction(direction: Vector2, axis: int) -> Vector2:
	var stepped: Vector2 = direction.normalized()
	stepped[axis] = wrapf(snappedf(stepped[axis], 0.5) + 0.5, -1.0, 1.5)
	if stepped.is_zero_approx():
		stepped[axis] = 0.5
	return stepped


func _on_field_built(_plants: int) -> void:
	var size: Vector2 = Vector2(_field.map.columns, _field.map.rows) * _field.cell_size
	var plane: PlaneMesh = _ground.mesh as PlaneMesh
	plane.size = size + Vector2(400.0, 400.0)
	_ground.position = Vector3(size.x * 0.5, 0.0, size.y * 0.5)
	var eye: Vector3 = Vector3(0.6 * size.x, 2.4, size.y + 3.5)
	var target: Vector3 = Vector3(0.45 * size.x, 1.0, size.y - 11.0)
	eye.y += _camera.ground_below(eye)
	target.y += _camera.ground_below(target)
	_camera.set_start(eye, target)


func _stats_text() -> String:
	var counts: PackedInt32Array = _field.get_lod_counts()
	var costs: Dictionary = _field.get_frame_stats()
	# Near meshes: the plants written this frame (frustum-culled), times their triangles.
	var triangles: int = costs["near_primitives"] + counts[3] * TRIANGLES_SPRITE + counts[4] * TRIANGLES_BILLBOARD
	var fps: float = Engine.get_frames_per_second()
	return (
		(
			"%d FPS (%.1f ms)   native update %.2f ms\n"
			+ "%d plants: mesh 1 %d, mesh 2 %d, mesh 3 %d, sprite %d, billboard %d\n"
			+ "triangles drawn ~%.2f M\n"
			+ "wind %.1f m/s towards (%.2f, %.2f), increment %.1f, %s model (F9)\n"
			+ "%s, %d pushed; %s%s"
		)
		% [
			fps,
			1000.0 / maxf(fps, 1.0),
			costs["update_ms"],
			_field.get_plant_count(),
			counts[0],
			counts[1],
			counts[2],
			counts[3],
			counts[4],
			triangles / 1.0e6,
			_field.wind_power,
			_field.wind_direction.x,
			_field.wind_direction.y,
			_field.wind_increment,
			_wind_model_name(),
			"walking (F8)" if _camera.walking else "flying (F8 walks)",
			_field.get_pushed_count(),
			_play.stats_text(),
			_budget_text(costs),
		]
	)


## The frame budget's line (its targets, what it saw and the quality it chose) on a line of its own;
## nothing without a budget.
func _budget_text(costs: Dictionary) -> String:
	var cap: int = ProjectSettings.get_setting(BUDGET_PRIMITIVES, 0)
	var gpu_ms: float = ProjectSettings.get_setting(BUDGET_GPU_MS, 0.0)
	if cap <= 0 and gpu_ms <= 0.0:
		return ""
	var targets: PackedStringArray = []
	if cap > 0:
		targets.append("%.2f M / %.2f M near triangles" % [costs["near_primitives"] / 1.0e6, cap / 1.0e6])
	if gpu_ms > 0.0:
		targets.append("GPU %.1f / %.1f ms" % [costs["gpu_ms"], gpu_ms])
	return "\nbudget: %s, quality %.2f" % [", ".join(targets), costs["quality"]]


func _wind_model_name() -> String:
	return "natural" if _field.wind.model == SunflowerWind.Model.NATURAL else "thesis"


func _open_part_dialog() -> void:
	var dialog: FileDialog = FileDialog.new()
	dialog.file_mode = FileDialog.FILE_MODE_OPEN_FILE
	dialog.access = FileDialog.ACCESS_FILESYSTEM
	dialog.filters = PackedStringArray(["*.gltf, *.glb ; glTF"])
	dialog.title = "Replace a plant part with a glTF mesh"
	dialog.add_option("Level", PackedStringArray(["Mesh 1", "Mesh 2", "Mesh 3"]), 0)
	dialog.add_option("Part", PackedStringArray(["Bottom", "Middle", "Head"]), 2)
	dialog.file_selected.connect(
		func(path: String) -> void:
			var options: Dictionary = dialog.get_selected_options()
			load_part(options.get("Level", 0), options.get("Part", 2), path)
	)
	dialog.canceled.connect(dialog.queue_free)
	dialog.file_selected.connect(func(_path: String) -> void: dialog.queue_free())
	add_child(dialog)
	dialog.popup_centered_ratio(0.6)


## Replaces the addon's field by the Godot-native baseline drawing the same map.
func _build_native_baseline() -> void:
	var baseline: NativeBaseline = NativeBaseline.new()
	baseline.name = "NativeBaseline"
	add_child(baseline)
	_recording.baseline_node = baseline
	var far_quads: bool = _recording.baseline != "native-whole"
	var hashed: bool = _recording.baseline == "native-hashed"
	var plants: int = baseline.build(_field.map, _field, _draw_distance, far_quads, hashed)
	if plants == 0:
		_fail("the native baseline was not built (its error is in the log)")
		return
	_field.visible = false
	_field.process_mode = Node.PROCESS_MODE_DISABLED
	var drawn: String = "mesh LOD near, front-view quads far" if far_quads else "whole plants with mesh LOD"
	_hud.show_message("baseline: %d plants as Godot-native chunked MultiMeshes: %s" % [plants, drawn])


## Shows a problem on the HUD; in recording mode it also goes to the log and the run exits with 1.
func _fail(message: String) -> void:
	_hud.show_message(message)
	if _recording.wanted():
		_recording.fail(message)


func _on_map_error(message: String) -> void:
	_fail(message)
