@tool
extends EditorImportPlugin
## Imports [code].field[/code] text maps as [SunflowerFieldMap] resources. A malformed map fails
## to import with an error naming the file, line and column.

const Native: GDScript = preload("../native/native.gd")


func _get_importer_name() -> String:
	return "sunflower_field.field_map"


func _get_visible_name() -> String:
	return "Sunflower Field Map"


func _get_recognized_extensions() -> PackedStringArray:
	return PackedStringArray(["field"])


func _get_save_extension() -> String:
	return "res"


func _get_resource_type() -> String:
	return "Resource"


func _get_priority() -> float:
	return 1.0


func _get_import_order() -> int:
	return 0


func _get_preset_count() -> int:
	return 1


func _get_preset_name(_preset_index: int) -> String:
	return "Default"


## No options: a map may hold any printable symbol; its field's legend says what each one is, and
## the field reports a symbol its legend lacks when it loads the map.
func _get_import_options(_path: String, _preset_index: int) -> Array[Dictionary]:
	return []


func _get_option_visibility(_path: String, _option_name: StringName, _options: Dictionary) -> bool:
	return true


func _import(
	source_file: String,
	save_path: String,
	_options: Dictionary,
	_platform_variants: Array[String],
	_gen_files: Array[String]
) -> Error:
	var errors: Array[String] = []
	var field_map: SunflowerFieldMap = SunflowerFieldMap.from_file(source_file, errors)
	if field_map == null:
		push_error(errors[0])
		return ERR_FILE_CANT_READ
	# Without the native library the map is saved unchecked (its columns, rows and plants stay 0) and
	# checked when a field loads it; the one missing-library error has been said already.
	var message: String = field_map.check_format() if Native.is_available() else ""
	if not message.is_empty():
		push_error("Sunflower Field: cannot import " + message)
		return ERR_PARSE_ERROR
	return ResourceSaver.save(field_map, "%s.%s" % [save_path, _get_save_extension()])
