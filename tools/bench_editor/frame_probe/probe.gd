@tool
extends EditorPlugin
## Measures the editor's frames: first 120 frames with no scene open (what the editor costs by
## itself), then from the moment res://million.tscn is opened until its field is built and 120
## frames more. Prints one Markdown row per phase, "probe: ok", and quits the editor.

const SCENE: String = "res://million.tscn"
const SETTLE_FRAMES: int = 120

var _tree: SceneTree


func _enter_tree() -> void:
	if OS.get_environment("RUN_PROBE") == "1":  # not while the project is imported
		_run.call_deferred()


func _run() -> void:
	_tree = EditorInterface.get_base_control().get_tree()
	await _frames(60)  # the editor's own start-up
	var idle: PackedFloat64Array = await _frame_times(SETTLE_FRAMES, Callable())
	var start: int = Time.get_ticks_usec()
	EditorInterface.open_scene_from_path(SCENE)
	var open_ms: float = (Time.get_ticks_usec() - start) / 1000.0
	var field: SunflowerField = EditorInterface.get_edited_scene_root().get_node("SunflowerField") as SunflowerField
	# The first interval runs from before the open call: opening the scene holds that frame.
	var building: PackedFloat64Array = await _frame_times(-1, func() -> bool: return not field.is_building(), start)
	var built_ms: float = (Time.get_ticks_usec() - start) / 1000.0
	var after: PackedFloat64Array = await _frame_times(SETTLE_FRAMES, Callable())
	print("| phase | frames | median ms | longest ms | frames over 50 ms |")
	print("|---|---|---|---|---|")
	_row("editor alone, no scene", idle)
	_row("opening the scene (%.0f ms in open_scene_from_path) until built" % open_ms, building)
	_row("the built field, %d plants, shown" % field.get_plant_count(), after)
	print(
		"probe: build %.0f ms wall from the open call; the field's build stats %s" % [built_ms, field.get_build_stats()]
	)
	print(
		(
			"probe: ok"
			if field.get_plant_count() == 1000000
			else "probe: the field has %d plants" % field.get_plant_count()
		)
	)
	_tree.quit()


## Frame intervals: [param count] frames, or (count < 0) until [param done] returns true; the first
## from [param since] (a tick in microseconds; -1: now).
func _frame_times(count: int, done: Callable, since: int = -1) -> PackedFloat64Array:
	var times: PackedFloat64Array = []
	var last: int = since if since >= 0 else Time.get_ticks_usec()
	while (count >= 0 and times.size() < count) or (count < 0 and not done.call() and times.size() < 100000):
		await _tree.process_frame
		var now: int = Time.get_ticks_usec()
		times.append((now - last) / 1000.0)
		last = now
	return times


func _row(phase: String, times: PackedFloat64Array) -> void:
	var sorted: PackedFloat64Array = times.duplicate()
	sorted.sort()
	var over: int = 0
	for t: float in times:
		over += 1 if t > 50.0 else 0
	var median: float = sorted[sorted.size() / 2] if sorted.size() > 0 else 0.0
	var longest: float = sorted[sorted.size() - 1] if sorted.size() > 0 else 0.0
	print("| %s | %d | %.1f | %.1f | %d |" % [phase, times.size(), median, longest, over])


func _frames(count: int) -> void:
	for i: int in count:
		await _tree.process_frame
