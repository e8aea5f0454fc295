@tool
extends EditorPlugin
## Registers the importer that turns [code].field[/code] maps into [SunflowerFieldMap] resources.
## The [SunflowerField] node itself is registered by its [code]class_name[/code].

var _importer: EditorImportPlugin


func _enter_tree() -> void:
	_importer = preload("field_map_import_plugin.gd").new()
	add_import_plugin(_importer)


func _exit_tree() -> void:
	remove_import_plugin(_importer)
	_importer = null
