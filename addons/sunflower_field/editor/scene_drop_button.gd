@tool
extends Button
## A button that takes a plant scene: dropped on it from the FileSystem dock, or chosen in a file
## dialog when pressed. Says which scene with [signal scene_chosen].

## A scene file was dropped or chosen.
signal scene_chosen(path: String)

## What the button says while it waits for a scene.
const TEXT: String = "Plant from scene…"
## What its tooltip says while it waits.
const TOOLTIP: String = (
	"Make a plant of a scene (drop a .glb, .gltf, .blend or .tscn here, or press to choose one): its"
	+ " meshes merged with their transforms and materials, its levels of detail, its frame from its"
	+ " bounds; saved beside the scene and its impostors baked."
)


func _init() -> void:
	text = TEXT
	# A long text (a step of the import) is cut short rather than widening the inspector's dock.
	clip_text = true
	text_overrun_behavior = TextServer.OVERRUN_TRIM_ELLIPSIS
	tooltip_text = TOOLTIP
	pressed.connect(_choose)


## Whether [param path] names a scene the engine can load.
static func is_scene(path: String) -> bool:
	return ResourceLoader.get_recognized_extensions_for_type("PackedScene").has(path.get_extension().to_lower())


func _can_drop_data(_at_position: Vector2, data: Variant) -> bool:
	return _dropped_scene(data) != ""


func _drop_data(_at_position: Vector2, data: Variant) -> void:
	scene_chosen.emit(_dropped_scene(data))


## The one scene file a drag from the FileSystem dock carries, or "".
static func _dropped_scene(data: Variant) -> String:
	if not (data is Dictionary) or data.get("type", "") != "files":
		return ""
	var files: PackedStringArray = data.get("files", PackedStringArray())
	return files[0] if files.size() == 1 and is_scene(files[0]) else ""


func _choose() -> void:
	var dialog: EditorFileDialog = EditorFileDialog.new()
	dialog.file_mode = EditorFileDialog.FILE_MODE_OPEN_FILE
	dialog.access = EditorFileDialog.ACCESS_RESOURCES
	dialog.title = "Plant from scene"
	for extension: String in ResourceLoader.get_recognized_extensions_for_type("PackedScene"):
		dialog.add_filter("*." + extension)
	dialog.file_selected.connect(
		func(path: String) -> void:
			scene_chosen.emit(path)
			dialog.queue_free()
	)
	dialog.canceled.connect(dialog.queue_free)
	EditorInterface.get_base_control().add_child(dialog)
	dialog.popup_file_dialog()
