@tool
extends RefCounted
## "Generate from rules" in the editor: runs a field's [SunflowerPlacementRules] on a worker thread
## and writes what they place into the field's map file as one undo/redo action, keeping every cell
## painted by hand since the last generation. What the last generation gave is kept beside the map
## as [code]<map>.field.generated[/code] (the same text format, not imported): a cell where the map
## differs from it was edited by hand, and keeps its edit.

const Native: GDScript = preload("../native/native.gd")
const FieldLegend: GDScript = preload("../runtime/field_legend.gd")
## Added to a map's path for the last generation's cells.
const GENERATED_SUFFIX: String = ".generated"
## What [member _running] holds for a field while its ground is read, and once that is cancelled.
const PREPARING: StringName = &"preparing"
const CANCELLED: StringName = &"cancelled"

## The last message (an error or what was done), for tools and tests.
var last_message: String = ""

var _undo_redo: EditorUndoRedoManager
var _painter: RefCounted
var _running: Dictionary = {}  # field → PREPARING, CANCELLED, then its native placement while it generates


func _init(undo_redo: EditorUndoRedoManager, painter: RefCounted) -> void:
	_undo_redo = undo_redo
	_painter = painter


## Whether [param field]'s rules are generating now.
func is_running(field: SunflowerField) -> bool:
	return _running.has(field)


## Stops [param field]'s generation; its map stays as it was.
func cancel(field: SunflowerField) -> void:
	if _running.get(field) is RefCounted:
		_running[field].cancel()
	if _running.has(field):
		_running[field] = CANCELLED  # (also when the worker had not begun: its cancel() came too early)


## Generates [param field]'s map from its rules (awaitable: the ground is read a few milliseconds a
## frame, then the rules run on a worker thread, while the editor draws). [param progress], when
## valid, is called with what is being done ("reading the ground") and the share of it done (0–1;
## -1 while the rules run, which is not measured: a million cells take a tenth of a second).
## Returns OK, ERR_SKIP when cancelled, or an error after saying what is wrong.
func generate(field: SunflowerField, progress: Callable = Callable()) -> Error:
	var problem: String = _problem(field)
	if not problem.is_empty():
		return _fail("SunflowerField %s: %s" % [field.name, problem])
	var path: String = field.map.source_path
	var size: Vector2i = Vector2i(field.map.columns, field.map.rows)
	var original: PackedByteArray = field.map.text
	_running[field] = PREPARING
	var placement: RefCounted = await field.placement_rules.prepare_in_steps(
		field,
		SunflowerPlacementRules.GROUND_READ_BUDGET_USEC,
		func(share: float) -> bool:
			if progress.is_valid():
				progress.call("reading the ground", share)
			return _running.get(field) == PREPARING
	)
	var stopped: Error = _stopped_preparing(field, placement)
	if stopped != OK:
		return stopped
	if progress.is_valid():
		progress.call("placing", -1.0)
	_running[field] = placement
	var out: Array[PackedByteArray] = []
	var task: int = WorkerThreadPool.add_task(
		func() -> void: out.append(placement.generate(0, 0, size.x, size.y, 0)), false, "Sunflower Field: placement"
	)
	# At least one frame passes, however fast the rules: a press in the same frame always cancels.
	await Engine.get_main_loop().process_frame
	while not WorkerThreadPool.is_task_completed(task):
		await Engine.get_main_loop().process_frame
	WorkerThreadPool.wait_for_task_completion(task)
	var cancelled: bool = _running.get(field) is StringName and _running.get(field) == CANCELLED
	_running.erase(field)
	var cells: PackedByteArray = out[0] if not out.is_empty() else PackedByteArray()
	if not is_instance_valid(field):
		return _fail("SunflowerField: the field left the scene while its rules ran; nothing written")
	if cells.is_empty() or cancelled:
		return _cancelled(field)
	if field.map == null or field.map.source_path != path or field.map.text != original:
		return _fail("SunflowerField: the map %s changed while its rules ran; nothing written" % path)
	return _commit(field, placement, cells)


## After the ground is read: OK to go on with [param placement], or why [param field] stops
## (gone, cancelled, or rules that cannot run), its run forgotten.
func _stopped_preparing(field: SunflowerField, placement: RefCounted) -> Error:
	var state: Variant = _running.get(field)
	if placement != null and is_instance_valid(field) and state == PREPARING:
		return OK
	_running.erase(field)
	if not is_instance_valid(field):
		return _fail("SunflowerField: the field left the scene while its ground was read; nothing written")
	if state == CANCELLED:
		return _cancelled(field)
	return _fail("SunflowerField %s: the placement rules cannot run (the error above says why)" % field.name)


func _cancelled(field: SunflowerField) -> Error:
	last_message = "SunflowerField %s: the generation was cancelled; the map is as it was" % field.name
	print(last_message)
	return ERR_SKIP


## What keeps [param field] from generating, or "".
func _problem(field: SunflowerField) -> String:
	if _running.has(field):
		return "its rules are generating already"
	if field.placement_rules == null:
		return "it has no placement_rules to generate from"
	if field.map == null or not field.map.source_path.begins_with("res://") or field.map.source_path.contains("::"):
		return "give it a map file first (New map… above its inspector)"
	return ""


## Writes [param cells] (what the rules gave, of the field's map size) into the field's map, the
## cells painted by hand since the last generation kept, as one undo/redo action.
func _commit(field: SunflowerField, placement: RefCounted, cells: PackedByteArray) -> Error:
	var path: String = field.map.source_path
	var original: PackedByteArray = field.map.text
	var size: Vector2i = Vector2i(field.map.columns, field.map.rows)
	var symbols: String = FieldLegend.plant_symbols(field.legend)
	var base_path: String = path + GENERATED_SUFFIX
	var base_before: PackedByteArray = (
		FileAccess.get_file_as_bytes(base_path) if FileAccess.file_exists(base_path) else PackedByteArray()
	)
	var kept: PackedByteArray = cells
	var edits: int = 0
	if not base_before.is_empty():
		var before: PackedByteArray = placement.read_map_cells(base_before, symbols)
		var edited: PackedByteArray = placement.read_map_cells(original, symbols)
		if before.size() == cells.size() and edited.size() == cells.size():
			kept = placement.keep_hand_edits(before, edited, cells)
			for i: int in cells.size():
				edits += 1 if edited[i] != before[i] else 0
		else:
			push_warning(
				(
					"SunflowerField %s: %s is not of the map's size; no cell painted by hand was told apart"
					% [field.name, base_path]
				)
			)
	var text: PackedByteArray = field.placement_rules.map_text(kept, field, original)
	var header: String = (
		"# What the placement rules last gave %s (the editor tells hand edits apart by it)." % path.get_file()
	)
	var base: PackedByteArray = placement.write_map(cells, size.x, size.y, symbols, header, PackedByteArray())
	if text.is_empty() or base.is_empty():
		return _fail("SunflowerField %s: the generated map could not be written as text" % field.name)
	_undo_redo.create_action("Generate field map from rules", UndoRedo.MERGE_DISABLE, field)
	_undo_redo.add_do_method(self, &"_write_base", base_path, base)
	_undo_redo.add_do_method(_painter.map_files, &"write_map", field, path, text)
	_undo_redo.add_undo_method(self, &"_write_base", base_path, base_before)
	_undo_redo.add_undo_method(_painter.map_files, &"write_map", field, path, original)
	_undo_redo.commit_action()
	last_message = (
		"SunflowerField %s: %s generated from its rules (%d x %d cells), %d cells painted by hand kept"
		% [field.name, path, size.x, size.y, edits]
	)
	print(last_message)
	return OK


## Writes the last generation's cells to [param path] ([param bytes] empty: removes the file).
func _write_base(path: String, bytes: PackedByteArray) -> void:
	if bytes.is_empty():
		if FileAccess.file_exists(path):
			DirAccess.remove_absolute(path)
		return
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	if file == null:
		push_error("SunflowerField: cannot write %s (%s)" % [path, error_string(FileAccess.get_open_error())])
		return
	file.store_buffer(bytes)
	file.close()


func _fail(message: String) -> Error:
	last_message = message
	push_error(message)
	return FAILED
