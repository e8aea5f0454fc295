extends SceneTree
## Painting benchmark (numbers, not pass/fail; tools/bench.sh runs it headless): a brush stroke
## across a million-plant field (1000 x 1000 cells, 500 x 500 m), one mouse move a frame, with the
## addon's painter. Prints the main thread's time per frame (the painter's input handling plus the
## field's frame: its build step and update) as median and max, the stroke's start, and the chunks
## the previews made against those they kept.

const FRAMES: int = 90
const FieldPainter: GDScript = preload("res://addons/sunflower_field/editor/field_painter.gd")


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var lines: PackedStringArray = ["1000 1000"]
	for row: int in 1000:
		lines.append("*".repeat(600))  # the east 400 columns empty: room to paint
	var dir: String = "user://paint_bench"
	DirAccess.make_dir_recursive_absolute(dir)
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "res://paint_bench.field"  # not written: the stroke is not committed
	field_map.text = "\n".join(lines).to_utf8_buffer()
	var field: SunflowerField = SunflowerField.new()
	field.map = field_map
	root.add_child(field)
	var camera: Camera3D = Camera3D.new()
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = 60.0
	root.add_child(camera)
	camera.global_transform = Transform3D(Basis.from_euler(Vector3(-PI / 2.0, 0.0, 0.0)), Vector3(400.0, 100.0, 250.0))
	camera.current = true
	await process_frame
	field.finish_build()
	field.set_process(false)  # the loop below runs its frames and times them
	var painter: RefCounted = FieldPainter.new(null)
	painter.edit(field)
	painter.set_mode(1)
	painter.radius = 3.0
	# The stroke's map must be a file in the project for the painter to begin: stand one in.
	var file: FileAccess = FileAccess.open("res://paint_bench.field", FileAccess.WRITE)
	var begin_ms: float = 0.0
	var frame_ms: PackedFloat64Array = []
	if file == null:
		print("paint bench: cannot write res://paint_bench.field")
		quit(1)
		return
	file.store_buffer(field_map.text)
	file.close()
	var press: InputEventMouseButton = InputEventMouseButton.new()
	press.button_index = MOUSE_BUTTON_LEFT
	press.pressed = true
	press.position = camera.unproject_position(Vector3(380.0, 0.0, 230.0))
	var start: int = Time.get_ticks_usec()
	painter.handle_input(camera, press)
	begin_ms = (Time.get_ticks_usec() - start) / 1000.0
	var made: int = 0
	var kept: int = 0
	var builds: int = 0
	for i: int in FRAMES:
		var motion: InputEventMouseMotion = InputEventMouseMotion.new()
		motion.button_mask = MOUSE_BUTTON_MASK_LEFT
		motion.position = camera.unproject_position(Vector3(380.0 + 0.4 * i, 0.0, 230.0 + 0.3 * i))
		var frame_start: int = Time.get_ticks_usec()
		painter.handle_input(camera, motion)
		var input_usec: int = Time.get_ticks_usec() - frame_start
		var was_building: bool = field.is_building()
		# The field's frame, run here instead of by the engine so that it can be timed alone.
		var process_start: int = Time.get_ticks_usec()
		field._process(1.0 / 60.0)
		frame_ms.append((input_usec + Time.get_ticks_usec() - process_start) / 1000.0)
		await process_frame
		var stats: Dictionary = field.get_build_stats()
		if was_building and not field.is_building():
			builds += 1
			made += stats.tiles_made
			kept += stats.tiles_kept
	frame_ms.sort()
	print("| stroke begin ms | frame median ms | frame max ms | previews built | tiles made | tiles kept |")
	print("|---|---|---|---|---|---|")
	print(
		(
			"| %.1f | %.2f | %.2f | %d | %d | %d |"
			% [begin_ms, frame_ms[frame_ms.size() / 2], frame_ms[-1], builds, made, kept]
		)
	)
	DirAccess.remove_absolute(ProjectSettings.globalize_path("res://paint_bench.field"))
	painter.release()
	field.free()
	quit()
