@tool
@icon("icons/sunflower_field_map.svg")
class_name SunflowerFieldMap
extends Resource
## A field map: the text of a [code].field[/code] file (see [code]fields/FORMAT.md[/code]).
##
## Made by the importer from [code].field[/code] files, so exported games include the map, or by
## [method from_file] at run time. The text is kept as bytes and parsed by the native core, which
## reports errors with file, line and column.

const Native: GDScript = preload("native/native.gd")

## Where the map came from; names the file in error messages.
@export var source_path: String = ""
## The raw bytes of the map file. Setting them tells the fields that use the map.
@export var text: PackedByteArray = PackedByteArray():
	set(value):
		if value != text:
			text = value
			emit_changed()
## Columns declared by the header (filled when the map is checked).
@export var columns: int = 0
## Rows declared by the header (filled when the map is checked).
@export var rows: int = 0
## Sunflowers in the map (filled when the map is checked).
@export var plant_count: int = 0


## Reads a map from [param path] ([code]res://[/code], [code]user://[/code] or an absolute path)
## without checking it. A [code]res://[/code] map whose source text is not there (an exported game
## ships only the imported resource) is loaded as imported. Returns [code]null[/code] when the map
## cannot be read; [param r_error] (if given) receives the message.
static func from_file(path: String, r_error: Array[String] = []) -> SunflowerFieldMap:
	if not FileAccess.file_exists(path):
		if path.begins_with("res://") and ResourceLoader.exists(path):
			var imported: SunflowerFieldMap = load(path) as SunflowerFieldMap
			if imported:
				return imported
		r_error.append("%s: the map file does not exist" % path)
		return null
	var bytes: PackedByteArray = FileAccess.get_file_as_bytes(path)
	var open_error: Error = FileAccess.get_open_error()
	if open_error != OK:
		r_error.append("%s: cannot read the map (%s)" % [path, error_string(open_error)])
		return null
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = path
	field_map.text = bytes
	return field_map


## Parses the map with the [param legend] symbols (a field's legend: objects and plant types) allowed.
## Returns an empty string when the map is valid (and fills [member columns], [member rows],
## [member plant_count]), else [code]"file:line:column: message"[/code]. Only parses (the plants are
## laid out by the build), so it is cheap enough for the main thread: a million-cell map in a few
## milliseconds.
func check(legend: String = "", max_plants: int = 0) -> String:
	return _checked(Native.check_map(text, source_path, legend, false, max_plants), max_plants)


## Parses the map accepting any printable symbol where a legend symbol may stand: what the importer
## checks, since the symbols are checked against a field's legend when the field loads the map.
## Returns as [method check] does.
func check_format(max_plants: int = 0) -> String:
	return _checked(Native.check_map(text, source_path, "", true, max_plants), max_plants)


func _checked(message: String, max_plants: int) -> String:
	if message.is_empty():
		var figures: PackedInt32Array = Native.map_figures(text, max_plants)
		columns = figures[0]
		rows = figures[1]
		plant_count = figures[2]
	return message
