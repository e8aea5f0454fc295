class_name DemoRecording
extends Node
## The demo's recording mode, also the benchmark harness: flies the camera along a path (or holds a
## still view) for a number of frames, saves screenshots, measures frame and update times, the
## levels' counts and the renderer's own counts, writes them as JSON and quits: with exit code 1
## after any failure ([method fail]). It reads the field through its public API only.

## How long a recording waits after its last frame before it quits (see _finish).
const EXIT_SETTLE_SECONDS: float = 3.0

## Frames to record (negative: not recording).
var frames_total: int = -1
## The recording path's file (lines "x y z tx ty tz"); empty: a built-in flight.
var path_file: String = ""
## A still view instead of a path: inside, outside40, above45, down60.
var view: String = ""
var screenshot: String = ""
var screenshot_every: int = 0
var stats_path: String = ""
## "native", "native-whole" or "native-hashed" when the Godot-native baseline draws the field instead.
var baseline: String = ""
var map_path: String = ""
var build_ms: float = 0.0
## The renderer's buffer memory before the map, after the field and after the baseline.
var buffer_memory: Dictionary = {}
## The baseline's node, for its chunk count (or null).
var baseline_node: Node
## Called once the recording is done, before the demo quits.
var before_quit: Callable

var _field: SunflowerField
var _camera: FlyCamera
var _camera_path: CameraPath
var _frame: int = 0
var _exit_code: int = 0
var _frame_times: PackedFloat32Array = []
var _update_times: PackedFloat32Array = []
var _lod_sums: PackedFloat64Array = [0, 0, 0, 0, 0]
var _last_ticks: int = 0
## The renderer's own counts per recorded frame (draw calls, objects, primitives: Arrays, which
## are shared by reference).
var _rendering: Dictionary = {"draw_calls": [], "objects": [], "primitives": []}


## Whether the command line asked for a recording (frames, a screenshot or statistics).
func wanted() -> bool:
	return frames_total >= 0 or not (screenshot.is_empty() and stats_path.is_empty())


## Whether the frames are being recorded now.
func is_running() -> bool:
	return frames_total >= 0 and _camera_path != null


## Says what went wrong, to the log; the run will exit with 1.
func fail(message: String) -> void:
	printerr("demo: FAILED: " + message)
	_exit_code = 1


## Takes the camera along the path from the next frame on (the field is built).
func start(field: SunflowerField, camera: FlyCamera) -> void:
	_field = field
	_camera = camera
	var size: Vector2 = field_size(_field.map, _field.cell_size)
	if path_file.is_empty():
		_camera_path = CameraPath.built_in(size, _camera.ground_below)
	else:
		var errors: Array[String] = []
		_camera_path = CameraPath.from_file(path_file, errors)
		if _camera_path == null:
			fail(errors[0])
			_camera_path = CameraPath.built_in(size, _camera.ground_below)
	if not view.is_empty():
		_camera_path = CameraPath.view(view, size)
		if _camera_path == null:
			fail("unknown view '%s' (inside, outside40, above45, down60)" % view)
			_camera_path = CameraPath.built_in(size, _camera.ground_below)
	_camera.manual = false
	_last_ticks = Time.get_ticks_usec()


## The ground a field of [param map] covers with cells [param cell_size] metres wide (x, z), where
## the camera paths and views are placed.
static func field_size(map: SunflowerFieldMap, cell_size: float) -> Vector2:
	return Vector2(map.columns, map.rows) * cell_size


## The recorded frames so far.
func get_frame() -> int:
	return _frame


## One recorded frame: the last frame's figures, then the camera moved for the next.
func record_frame() -> void:
	var now: int = Time.get_ticks_usec()
	if _frame > 0:
		_frame_times.append((now - _last_ticks) / 1000.0)
		if baseline.is_empty():
			_update_times.append(_field.get_frame_stats()["update_ms"])
		var counts: PackedInt32Array = _field.get_lod_counts()
		for lod: int in 5:
			_lod_sums[lod] += counts[lod]
		# The frame drawn last (all viewports).
		(_rendering["draw_calls"] as Array).append(
			RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_DRAW_CALLS_IN_FRAME)
		)
		(_rendering["objects"] as Array).append(
			RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_OBJECTS_IN_FRAME)
		)
		(_rendering["primitives"] as Array).append(
			RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_PRIMITIVES_IN_FRAME)
		)
	_last_ticks = now
	_camera.transform = _camera_path.sample(float(_frame) / maxf(frames_total - 1, 1))
	if screenshot_every > 0 and _frame % screenshot_every == 0 and not screenshot.is_empty() and _frame > 0:
		_save_screenshot("%s_%04d.png" % [screenshot.get_basename(), _frame])
	_frame += 1
	if _frame >= frames_total:
		frames_total = -1
		_finish.call_deferred()


func _finish() -> void:
	if DisplayServer.get_name() == "headless":
		if not screenshot.is_empty():
			fail("no screenshot without a display (run under xvfb-run)")
	else:
		await RenderingServer.frame_post_draw  # headless mode draws nothing, so this would never come
		if not screenshot.is_empty():
			_save_screenshot(screenshot)
	var counts: PackedInt32Array = _field.get_lod_counts()
	print(
		(
			"demo: %d plants; per level (mesh 1, mesh 2, mesh 3, sprite, billboard): %s"
			% [_field.get_plant_count(), counts]
		)
	)
	print(
		(
			"demo: frame time median %.2f ms, native update median %.3f ms"
			% [_median(_frame_times), _median(_update_times)]
		)
	)
	if not stats_path.is_empty():
		_write_stats()
	if before_quit.is_valid():
		before_quit.call()
	# A recording ends a few frames after its first: the renderer may still compile a pipeline in the
	# background, and quitting then can deadlock the engine's exit (godot#117064).
	await get_tree().create_timer(EXIT_SETTLE_SECONDS).timeout
	get_tree().quit(_exit_code)


func _save_screenshot(path: String) -> void:
	var image: Image = get_viewport().get_texture().get_image()
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	var error: Error = image.save_png(path)
	print("demo: screenshot %s (%s)" % [path, error_string(error)])
	if error != OK:
		fail("cannot save the screenshot %s (%s)" % [path, error_string(error)])


func _write_stats() -> void:
	var frames: int = _frame_times.size()
	var mean_counts: Array[float] = []
	for lod: int in 5:
		mean_counts.append(_lod_sums[lod] / maxf(frames, 1))
	var stats: Dictionary = {
		"map": map_path,
		"plants": _field.get_plant_count(),
		"build_ms": build_ms,
		"build": _field.get_build_stats(),
		"force_lod": _field.force_lod,
		"culling": _field.frustum_culling,
		"baseline": baseline,
		"native_memory_bytes": _field.get_frame_stats()["memory_bytes"],
		"frames": frames,
		"frame_ms": _summary(_frame_times),
		"native_update_ms": _summary(_update_times),
		"frame_times_ms": Array(_frame_times),
		"native_update_times_ms": Array(_update_times),
		"lod_counts_final": Array(_field.get_lod_counts()),
		"view": view,
		"camera_transform": var_to_str(_camera.global_transform),
		"camera_fov": _camera.fov,
		"camera_near": _camera.near,
		"camera_far": _camera.far,
		"draw_distance": _field.max_draw_distance,
		"tile_merge_distance": _field.tile_merge_distance,
		"draw_calls": _summary(PackedFloat32Array(_rendering["draw_calls"])),
		"objects": _summary(PackedFloat32Array(_rendering["objects"])),
		"primitives": _summary(PackedFloat32Array(_rendering["primitives"])),
		"primitives_per_frame": _rendering["primitives"],
		"draw_calls_per_frame": _rendering["draw_calls"],
		"buffer_memory_bytes": buffer_memory,
		"baseline_chunks": baseline_node.get_child_count() if baseline_node else 0,
		"lod_counts_mean": mean_counts,
		"budget_primitives": ProjectSettings.get_setting("sunflower_field/frame_budget/max_primitives", 0),
		"budget_gpu_ms": ProjectSettings.get_setting("sunflower_field/frame_budget/gpu_ms", 0.0),
		"quality_final": _field.get_quality(),
		"near_primitives_final": _field.get_frame_stats()["near_primitives"],
		"engine": Engine.get_version_info()["string"],
		"renderer": RenderingServer.get_current_rendering_method(),
		"driver": RenderingServer.get_current_rendering_driver_name(),
		"adapter": RenderingServer.get_video_adapter_name(),
		"adapter_vendor": RenderingServer.get_video_adapter_vendor(),
	}
	DirAccess.make_dir_recursive_absolute(stats_path.get_base_dir())
	var file: FileAccess = FileAccess.open(stats_path, FileAccess.WRITE)
	if file == null:
		fail("cannot write %s (%s)" % [stats_path, error_string(FileAccess.get_open_error())])
		return
	file.store_string(JSON.stringify(stats, "  "))
	file.close()
	print("demo: stats %s" % stats_path)


func _summary(values: PackedFloat32Array) -> Dictionary:
	if values.is_empty():
		return {"median": 0.0, "p99": 0.0, "mean": 0.0, "max": 0.0}
	var sorted: PackedFloat32Array = values.duplicate()
	sorted.sort()
	var total: float = 0.0
	for v: float in sorted:
		total += v
	return {
		"median": sorted[sorted.size() / 2],
		"p99": sorted[mini(sorted.size() - 1, int(sorted.size() * 0.99))],
		"mean": total / sorted.size(),
		"max": sorted[sorted.size() - 1],
	}


func _median(values: PackedFloat32Array) -> float:
	return _summary(values)["median"]
