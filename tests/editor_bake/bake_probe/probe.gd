@tool
extends EditorPlugin
## Selects res://my_plant.tres in the inspector as a user would, saves a picture of the editor,
## presses the inspector's "Bake impostors" button and checks that the textures were written,
## imported and saved into the plant. Prints "probe: ok" or what failed, then quits the editor.

const PLANT_PATH: String = "res://my_plant.tres"


func _enter_tree() -> void:
	if OS.get_environment("RUN_PROBE") == "1":  # not while tools/import_project.sh imports the project
		_run.call_deferred()


func _run() -> void:
	var tree: SceneTree = EditorInterface.get_base_control().get_tree()
	for i: int in 120:  # let the editor settle (first scan, plugins)
		await tree.process_frame
	var problems: PackedStringArray = []
	var plant: Resource = load(PLANT_PATH)
	EditorInterface.edit_resource(plant)
	for i: int in 30:
		await tree.process_frame
	var button: Button = _find_button(EditorInterface.get_inspector(), "Bake impostors")
	var shot: String = OS.get_environment("PROBE_SHOT")
	if not shot.is_empty():
		EditorInterface.get_base_control().get_viewport().get_texture().get_image().save_png(shot)
	if button == null:
		problems.append("no 'Bake impostors' button in the plant's inspector")
	else:
		button.pressed.emit()
		for i: int in 600:
			await tree.process_frame
			if plant.impostor_views != null and button.text == "Bake impostors":
				break
		for kind: String in FieldPlant.IMPOSTOR_TEXTURES:
			var path: String = "res://my_plant_%s.png" % kind
			if not FileAccess.file_exists(path):
				problems.append("%s was not written" % path)
		var views: Texture2D = plant.impostor_views
		if views == null or views.resource_path != "res://my_plant_views.png":
			problems.append("the plant's views atlas is not the imported file: %s" % views)
		var saved: String = FileAccess.get_file_as_string(PLANT_PATH)
		if not Array(FieldPlant.IMPOSTOR_TEXTURES).all(
			func(k: String) -> bool: return saved.contains("my_plant_%s.png" % k)
		):
			problems.append("the plant file does not name its new atlases")
		var image: Image = views.get_image() if views else null
		if image == null or image.is_empty() or image.detect_alpha() == Image.ALPHA_NONE:
			problems.append("the views atlas is empty or has no transparent background")
		elif not image.has_mipmaps():
			problems.append("the views atlas was imported without mipmaps")
	print("probe: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	await tree.create_timer(3.0).timeout  # no pipeline left compiling at exit (godot#117064 deadlocks it)
	tree.quit(0 if problems.is_empty() else 1)


func _find_button(node: Node, text: String) -> Button:
	if node is Button and (node as Button).text == text:
		return node
	for child: Node in node.get_children(true):
		var found: Button = _find_button(child, text)
		if found:
			return found
	return null
