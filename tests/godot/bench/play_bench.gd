extends SceneTree
## Play's changes in the engine (numbers, not pass/fail; tools/bench.sh runs it under Xvfb with
## Vulkan lavapipe, so that the far tiles' hidden-cells texture is really uploaded): a million-plant
## field (1000 x 1000 cells, 500 x 500 m), the camera in its middle. Each measured frame either lands
## 1 000 changes (a scythe's circle beside the camera, a trail across the field, cells scattered over
## it: SunflowerField.play.change_plants; and plants of another type put by the camera and scattered:
## put_plants; then the field's frame) or none. Prints the main thread's
## time of such frames as medians, and what the changes added.

const RUNS: int = 15
const SIDE: int = 1000


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var lines: PackedStringArray = ["%d %d" % [SIDE, SIDE]]
	for row: int in SIDE:
		lines.append("*".repeat(SIDE))
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "res://play_bench.field"
	field_map.text = "\n".join(lines).to_utf8_buffer()
	var camera: Camera3D = Camera3D.new()
	camera.name = "Camera"
	root.add_child(camera)
	camera.global_transform = Transform3D(Basis.from_euler(Vector3(-0.3, 0.0, 0.0)), Vector3(250.0, 1.7, 250.0))
	camera.current = true
	var field: SunflowerField = SunflowerField.new()
	field.legend = {"m": SunflowerPlant.default_plant().duplicate()}  # a second plant type, for the plants put
	field.map = field_map
	root.add_child(field)
	await process_frame
	field.finish_build()
	field.set_process(false)  # the loop below runs the field's frames and times them
	for i: int in 30:
		field.advance(1.0 / 60.0)
		await process_frame
	var shapes: Dictionary = {
		"a scythe's circle by the camera":
		field.play.get_cells_in_circle(Vector3(254.0, 0.0, 250.0), 8.92).slice(0, 1000),
		"a trail across the field": PackedInt32Array(range(700 * SIDE, 701 * SIDE)),
		"scattered over the whole field": _scattered(),
		"plants of another type put by the camera":
		field.play.get_cells_in_circle(Vector3(254.0, 0.0, 250.0), 8.92).slice(0, 1000),
		"plants of another type put, scattered": _scattered(),
	}
	print("| changes | cells | frame ms (median) | frame without changes ms | added ms |")
	print("|---|---|---|---|---|")
	for shape: String in shapes:
		var cells: PackedInt32Array = shapes[shape]
		var with_changes: PackedFloat64Array = []
		var without: PackedFloat64Array = []
		for run: int in RUNS:
			var start: int = Time.get_ticks_usec()
			if shape.begins_with("plants"):
				field.play.put_plants(cells, 1)
			else:
				field.play.change_plants(cells, SunflowerFieldPlay.Change.CUT)
			field.advance(1.0 / 60.0)
			with_changes.append((Time.get_ticks_usec() - start) / 1000.0)
			await process_frame
			start = Time.get_ticks_usec()
			field.advance(1.0 / 60.0)
			without.append((Time.get_ticks_usec() - start) / 1000.0)
			await process_frame
			field.play.change_plants(cells, SunflowerFieldPlay.Change.RESTORE)
			field.advance(1.0 / 60.0)
			await process_frame
		var a: float = _median(with_changes)
		var b: float = _median(without)
		print("| %s | %d | %.3f | %.3f | %.3f |" % [shape, cells.size(), a, b, a - b])
	quit(0)


static func _scattered() -> PackedInt32Array:
	var random: RandomNumberGenerator = RandomNumberGenerator.new()
	random.seed = 2008
	var picked: Dictionary = {}
	while picked.size() < 1000:
		picked[random.randi_range(0, SIDE * SIDE - 1)] = true
	var cells: PackedInt32Array = PackedInt32Array(picked.keys())
	cells.sort()
	return cells


static func _median(values: PackedFloat64Array) -> float:
	var sorted: PackedFloat64Array = values.duplicate()
	sorted.sort()
	return sorted[sorted.size() / 2]
