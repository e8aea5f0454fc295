extends SceneTree
## Build benchmark (numbers, not pass/fail; tools/bench.sh runs it under Xvfb, Forward+ on Vulkan
## lavapipe): a million-plant map (1000 × 1000 cells, read from a file) loaded in the background with
## [method SunflowerField.load_map_file] while the scene is drawn, the camera 20 m off the field's
## edge. A small field is built and drawn first, so the shaders are compiled before the clock starts.
## Prints the load call's own time, the build's wall time until [signal SunflowerField.field_built],
## the frames it spanned and the longest of them, its longest step and main-thread and worker time,
## then the first frame that draws the field and the median of the next three (rendering alone).

const Maps: GDScript = preload("res://runner/maps.gd")
const SIDE: int = 1000
const WARM_FRAMES: int = 20
const DRAWN_FRAMES: int = 3


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var path: String = "user://build_bench.field"
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	file.store_buffer(Maps.filled(SIDE, SIDE, path).text)
	file.close()
	var camera: Camera3D = Camera3D.new()
	root.add_child(camera)
	camera.look_at_from_position(Vector3(250.0, 1.7, 520.0), Vector3(250.0, 1.0, 400.0))
	camera.make_current()
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.shadow_enabled = true
	sun.rotation_degrees = Vector3(-50.0, 30.0, 0.0)
	root.add_child(sun)
	var field: SunflowerField = SunflowerField.new()
	root.add_child(field)
	field.position = Vector3(250.0, 0.0, 505.0)  # the warm-up field in view
	field.map = Maps.filled(20, 20, "user://warm.field")
	field.finish_build()
	for i: int in WARM_FRAMES:
		await process_frame
	field.position = Vector3.ZERO
	var start: int = Time.get_ticks_usec()
	if field.load_map_file(path, true) != OK:
		print("build bench: the map did not load")
		quit(1)
		return
	var call_ms: float = (Time.get_ticks_usec() - start) / 1000.0
	var last: int = Time.get_ticks_usec()
	var longest_ms: float = 0.0
	var frames: int = 0
	var first_ms: float = 0.0
	while field.is_building():
		await process_frame
		var now: int = Time.get_ticks_usec()
		if field.is_building():
			longest_ms = maxf(longest_ms, (now - last) / 1000.0)
			frames += 1
		else:  # the field was swapped in during the last frame, which drew it
			first_ms = (now - last) / 1000.0
		last = now
	var stats: Dictionary = field.get_build_stats()
	var drawn: PackedFloat32Array = []
	for i: int in DRAWN_FRAMES:
		await process_frame
		var now: int = Time.get_ticks_usec()
		drawn.append((now - last) / 1000.0)
		last = now
	drawn.sort()
	var header: PackedStringArray = [
		"plants",
		"load call",
		"build wall",
		"frames, longest",
		"longest step",
		"main thread / worker",
		"first frame drawing it",
		"next frames' median",
	]
	print("| %s |" % " | ".join(header))
	print("|---|---|---|---|---|---|---|---|")
	print(
		(
			"| %d | %.1f ms | %.0f ms | %d, %.1f ms | %.1f ms | %.0f / %.0f ms | %.0f ms | %.0f ms |"
			% [
				field.get_plant_count(),
				call_ms,
				stats["total_ms"],
				frames,
				longest_ms,
				stats["longest_step_ms"],
				stats["main_thread_ms"],
				stats["worker_ms"],
				first_ms,
				drawn[drawn.size() / 2],
			]
		)
	)
	field.free()
	quit(0)
