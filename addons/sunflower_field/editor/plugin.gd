@tool
extends EditorPlugin
## Registers the importer that turns [code].field[/code] maps into [SunflowerFieldMap] resources,
## shows the progress of fields building in the background in the 3D editor's toolbar, adds the
## "Bake impostors" button to the inspector of plants and fields and "Plant from scene…" above a
## field's plant, paints the selected field's map with the brush toolbar (field_painter.gd), and adds
## the machine-wide settings to Project Settings (field_project_settings.gd).
## The [SunflowerField] node itself is registered by its [code]class_name[/code].

const Native: GDScript = preload("../native/native.gd")

var _importer: EditorImportPlugin
var _progress: Control
var _inspector: EditorInspectorPlugin
var _painter: RefCounted
var _map_inspector: EditorInspectorPlugin
var _scene_plant_inspector: EditorInspectorPlugin


func _enter_tree() -> void:
	if not Native.is_available():
		Native.report_missing()
	else:
		preload("../runtime/field_project_settings.gd").register()  # the machine-wide settings, with their limits
	_importer = preload("field_map_import_plugin.gd").new()
	add_import_plugin(_importer)
	_progress = preload("build_progress_bar.gd").new()
	add_control_to_container(CONTAINER_SPATIAL_EDITOR_MENU, _progress)
	_inspector = preload("impostor_inspector.gd").new()
	add_inspector_plugin(_inspector)
	_painter = preload("field_painter.gd").new(get_undo_redo())
	add_control_to_container(CONTAINER_SPATIAL_EDITOR_MENU, _painter.toolbar)
	_map_inspector = preload("map_inspector.gd").new(
		_painter, preload("placement_generator.gd").new(get_undo_redo(), _painter)
	)
	add_inspector_plugin(_map_inspector)
	_scene_plant_inspector = preload("scene_plant_inspector.gd").new(get_undo_redo())
	add_inspector_plugin(_scene_plant_inspector)


func _exit_tree() -> void:
	remove_import_plugin(_importer)
	_importer = null
	remove_control_from_container(CONTAINER_SPATIAL_EDITOR_MENU, _progress)
	_progress.queue_free()
	_progress = null
	remove_inspector_plugin(_inspector)
	_inspector = null
	remove_inspector_plugin(_map_inspector)
	_map_inspector = null
	remove_inspector_plugin(_scene_plant_inspector)
	_scene_plant_inspector = null
	remove_control_from_container(CONTAINER_SPATIAL_EDITOR_MENU, _painter.toolbar)
	_painter.release()
	_painter = null


func _handles(object: Object) -> bool:
	return object is SunflowerField


func _edit(object: Object) -> void:
	if _painter:  # the editor may still call in while it quits
		_painter.edit(object as SunflowerField)


func _make_visible(visible: bool) -> void:
	if _painter and not visible:
		_painter.edit(null)


func _forward_3d_gui_input(camera: Camera3D, event: InputEvent) -> int:
	var used: bool = _painter != null and _painter.handle_input(camera, event)
	return AFTER_GUI_INPUT_STOP if used else AFTER_GUI_INPUT_PASS
