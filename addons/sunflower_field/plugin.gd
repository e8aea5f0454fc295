@tool
extends EditorPlugin
## Registers the importer that turns [code].field[/code] maps into [SunflowerFieldMap] resources,
## shows the progress of fields building in the background in the 3D editor's toolbar, and adds
## the "Bake impostors" button to the inspector of plants and fields.
## The [SunflowerField] node itself is registered by its [code]class_name[/code].

const Native: GDScript = preload("native.gd")

var _importer: EditorImportPlugin
var _progress: Control
var _inspector: EditorInspectorPlugin


func _enter_tree() -> void:
	if not Native.is_available():
		Native.report_missing()
	_importer = preload("field_map_import_plugin.gd").new()
	add_import_plugin(_importer)
	_progress = preload("build_progress_bar.gd").new()
	add_control_to_container(CONTAINER_SPATIAL_EDITOR_MENU, _progress)
	_inspector = preload("impostor_inspector.gd").new()
	add_inspector_plugin(_inspector)


func _exit_tree() -> void:
	remove_import_plugin(_importer)
	_importer = null
	remove_control_from_container(CONTAINER_SPATIAL_EDITOR_MENU, _progress)
	_progress.queue_free()
	_progress = null
	remove_inspector_plugin(_inspector)
	_inspector = null
