@tool
extends RefCounted
## A field's map file in the editor: a new map, a resized one, and a painted or generated map
## written back in the canonical form (see fields/FORMAT.md), each one undo/redo action; the field is
## given the written map at once and the file reimported at a later frame, when no import runs.
## The painter (field_painter.gd), the map inspector's buttons and Generate from rules write through it.

const Native: GDScript = preload("../native/native.gd")
const FieldLegend: GDScript = preload("../runtime/field_legend.gd")

## The last error ("" when none), for tests and the painter's toolbar.
var last_error: String = ""

var _undo_redo: EditorUndoRedoManager
var _reimporting: bool = false  # a reimport is running, the editor's or ours (see _give_reimported)


func _init(undo_redo: EditorUndoRedoManager) -> void:
	_undo_redo = undo_redo
	if Engine.is_editor_hint():  # tools and tests also paint outside the editor
		var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
		filesystem.resources_reimporting.connect(func(_paths: PackedStringArray) -> void: _reimporting = true)
		filesystem.resources_reimported.connect(func(_paths: PackedStringArray) -> void: _reimporting = false)


## A native map ([code]SunflowerMap[/code]) holding [param field]'s map, which must be a writable
## .field file in the project (to paint or resize it). Null (with an error) otherwise.
func open(field: SunflowerField) -> RefCounted:
	last_error = ""
	var field_map: SunflowerFieldMap = field.map
	if field_map == null:
		_fail("SunflowerField painter: the field has no map to paint; give it one (a .field file)")
		return null
	var path: String = field_map.source_path
	if not path.begins_with("res://") or not FileAccess.file_exists(path):
		_fail("SunflowerField painter: %s is not a .field file in the project; nothing to write back" % path)
		return null
	var writable: FileAccess = FileAccess.open(path, FileAccess.READ_WRITE)
	if writable == null:
		_fail(
			(
				"SunflowerField painter: %s cannot be written (%s); the map stays as it is"
				% [path, error_string(FileAccess.get_open_error())]
			)
		)
		return null
	writable.close()
	var editor: RefCounted = Native.create_map()
	if editor == null:
		return null
	var legend: Dictionary = field.legend
	var message: String = editor.load(
		field_map.text, path, FieldLegend.object_symbols(legend), FieldLegend.plant_symbols(legend), 0
	)
	if not message.is_empty():
		_fail("SunflowerField painter: the map cannot be painted: " + message)
		return null
	return editor


## A new map for [param field]: [param columns] × [param rows] cells, every one a sunflower when
## [param filled], saved as a new [code].field[/code] beside the edited scene and given to the field
## as one undo/redo action. Returns the file's path, or "" (with an error).
func new_map(field: SunflowerField, columns: int, rows: int, filled: bool) -> String:
	var editor: RefCounted = Native.create_map()
	if editor == null:
		return ""
	var lines: PackedStringArray = [
		"# A field map made in the editor (see fields/FORMAT.md).", "%d %d" % [columns, rows]
	]
	for row: int in rows:
		lines.append("*".repeat(columns) if filled else "")
	var message: String = editor.load("\n".join(lines).to_utf8_buffer(), "new map", "", "", 0)
	if not message.is_empty():
		_fail("SunflowerField: cannot make a %d x %d map: %s" % [columns, rows, message])
		return ""
	var scene: Node = field.get_tree().edited_scene_root if field.is_inside_tree() else null
	var folder: String = (
		scene.scene_file_path.get_base_dir() if scene and not scene.scene_file_path.is_empty() else "res://"
	)
	var path: String = folder.path_join(str(field.name).to_snake_case() + ".field")
	var serial: int = 2
	while FileAccess.file_exists(path):
		path = folder.path_join("%s_%d.field" % [str(field.name).to_snake_case(), serial])
		serial += 1
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	if file == null:
		_fail("SunflowerField: cannot write %s (%s)" % [path, error_string(FileAccess.get_open_error())])
		return ""
	var bytes: PackedByteArray = editor.write()
	file.store_buffer(bytes)
	file.close()
	var made: SunflowerFieldMap = _unimported(path, bytes)
	_undo_redo.create_action("New field map", UndoRedo.MERGE_DISABLE, field)
	_undo_redo.add_do_property(field, &"map", made)
	_undo_redo.add_undo_property(field, &"map", field.map)
	_undo_redo.commit_action()
	return path


## Gives [param field]'s map [param columns] × [param rows] cells, keeping the cells both sizes share,
## written back to its file as one undo/redo action. False (with an error) when it cannot.
func resize_map(field: SunflowerField, columns: int, rows: int) -> bool:
	var editor: RefCounted = open(field)
	if editor == null:
		return false
	if not editor.resize(columns, rows):
		return _fail("SunflowerField: cannot resize the map to %d x %d" % [columns, rows])
	var original: PackedByteArray = field.map.text
	var resized: PackedByteArray = editor.write()
	if resized != original:
		_undo_redo.create_action("Resize field map", UndoRedo.MERGE_DISABLE, field)
		_undo_redo.add_do_method(self, &"write_map", field, field.map.source_path, resized)
		_undo_redo.add_undo_method(self, &"write_map", field, field.map.source_path, original)
		_undo_redo.commit_action()
	return true


## Writes [param bytes] to the map file [param path], gives [param field] that map at once (the next
## stroke starts from it), and, once the frame's undo/redo step is over and no other import runs,
## reimports the file and gives the field the imported map (a reimport inside an undo step leaves
## the editor's undo history inconsistent). On failure (a read-only or vanished file) says so and
## the field shows the file.
func write_map(field: SunflowerField, path: String, bytes: PackedByteArray) -> void:
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	if file == null:
		_fail(
			(
				"SunflowerField painter: cannot write %s (%s); the map is unchanged"
				% [path, error_string(FileAccess.get_open_error())]
			)
		)
		field.map = load(path) as SunflowerFieldMap if ResourceLoader.exists(path) else field.map
		return
	file.store_buffer(bytes)
	file.close()
	var written: SunflowerFieldMap = SunflowerFieldMap.new()
	written.source_path = path
	written.text = bytes
	written.check_format()
	written.take_over_path(path)  # what load(path) gives until the reimport lands
	field.map = written
	_give_reimported(field, path)  # not awaited: it waits for the next frame and other imports


## At the next frame, [param field] (when still there) takes the map file [param path] imported
## anew. (Not by call_deferred: a reimport while deferred calls are flushed opens the editor's
## progress dialog where it refuses to open, and it printed errors at every stroke under a display.)
func _give_reimported(field: Object, path: String) -> void:
	await Engine.get_main_loop().process_frame
	# One import at a time: a reimport (the editor's, after a scan, or ours) keeps its progress task
	# while it runs, and the frames it draws for it may resume this wait inside it.
	var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
	while _reimporting or filesystem.is_scanning():
		await Engine.get_main_loop().process_frame
	if is_instance_valid(field):
		_reimporting = true
		(field as SunflowerField).map = _reimported(path)
		_reimporting = false


## The map just written to the new file [param path] as [param bytes], as the resource the file's
## import will give: the import itself runs when the editor next scans its files (a reimport now
## redraws the whole editor for its progress dialog a few times: seconds under a software renderer).
func _unimported(path: String, bytes: PackedByteArray) -> SunflowerFieldMap:
	var made: SunflowerFieldMap = SunflowerFieldMap.new()
	made.source_path = path
	made.text = bytes
	made.check_format()
	made.take_over_path(path)
	EditorInterface.get_resource_filesystem().update_file(path)
	return made


## The map file [param path] imported anew (just written), as the resource fields load.
func _reimported(path: String) -> SunflowerFieldMap:
	var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
	filesystem.update_file(path)
	filesystem.reimport_files(PackedStringArray([path]))
	return ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_REPLACE) as SunflowerFieldMap


func _fail(message: String) -> bool:
	last_error = message
	push_error(message)
	return false
