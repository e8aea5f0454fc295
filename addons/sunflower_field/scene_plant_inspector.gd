@tool
extends EditorInspectorPlugin
## Above a [SunflowerField]'s [code]plant[/code] property: "Plant from scene…", which takes a scene
## dropped on it from the FileSystem dock or chosen in a dialog. The scene becomes a [FieldPlant]
## ([method FieldPlant.from_scene]) saved beside it ([code]<scene>_plant.tres[/code] and its meshes
## as [code]<scene>_plant_mesh1.res[/code] …), its impostors are baked at once (a progress bar shows
## the steps), and it becomes the field's plant in one undoable action, which also widens the field's
## cells to the plant's width when they are narrower (trees 0.5 m apart would stand in each other).

const SceneDropButton: GDScript = preload("scene_drop_button.gd")
const ScenePlant: GDScript = preload("scene_plant.gd")
## What the progress bar shows, step by step.
const STEPS: PackedStringArray = ["Merging the scene's meshes…", "Saving the plant…", "Baking its impostors…"]

var _undo: EditorUndoRedoManager


func _init(undo: EditorUndoRedoManager) -> void:
	_undo = undo


func _can_handle(object: Object) -> bool:
	return object is SunflowerField


func _parse_property(
	object: Object, _type: Variant.Type, name: String, _hint: PropertyHint, _text: String, _usage: int, _wide: bool
) -> bool:
	if name != "plant":
		return false
	var box: VBoxContainer = VBoxContainer.new()
	var button: Button = SceneDropButton.new()
	var bar: ProgressBar = ProgressBar.new()
	bar.max_value = STEPS.size()
	bar.visible = false
	box.add_child(button)
	box.add_child(bar)
	button.scene_chosen.connect(func(path: String) -> void: make_plant(path, object as SunflowerField, button, bar))
	add_custom_control(box)
	return false  # the plant's own editor stays below


## Makes the scene at [param path] the plant of [param field] (see the script's description); await
## it. Returns the plant, or null when the scene cannot be loaded, has nothing to draw or cannot be
## saved (the error names it), or when the field left the edited scene during the bake (a warning says
## where the plant is saved). [param button] and [param bar] show the progress when given.
func make_plant(path: String, field: SunflowerField, button: Button = null, bar: ProgressBar = null) -> FieldPlant:
	_show_step(0, button, bar)
	var scene: PackedScene = load(path) as PackedScene
	var plant: FieldPlant = FieldPlant.from_scene(scene) if scene else null
	if scene == null:
		push_error("Plant from scene: %s is not a scene" % path)
	if plant == null:
		_show_step(-1, button, bar)
		return null
	_show_step(1, button, bar)
	var base: String = _free_base(path.get_basename() + "_plant")
	var error: Error = _save(plant, base)
	if error != OK:
		push_error("Plant from scene: cannot save %s.tres (%s)" % [base, error_string(error)])
		_show_step(-1, button, bar)
		return null
	_show_step(2, button, bar)
	error = await plant.bake_impostors(EditorInterface.get_base_control())
	if error != OK:
		push_error("Plant from scene: the impostors of %s.tres were not baked (%s)" % [base, error_string(error)])
	if not _in_edited_scene(field):
		push_warning(
			(
				(
					"Plant from scene: the field left the edited scene while %s.tres baked (removed, undone or its scene"
					+ " closed); the plant is saved there, not given to any field"
				)
				% base
			)
		)
		_show_step(-1, button, bar)
		return null
	var triangles: Array = [1, 2, 3].map(
		func(level: int) -> int: return ScenePlant.triangle_count(plant.get("mesh_level_%d" % level)[0])
	)
	print(
		(
			"Plant from scene: %s.tres from %s, %.2f m tall, %d / %d / %d triangles at mesh 1 / 2 / 3"
			% ([base, path, plant.height] + triangles)
		)
	)
	# Plants wider than the field's cells would stand inside each other: the cells widen to the plant.
	var spacing: float = plant.spacing_metres()
	_undo.create_action("Plant from scene", UndoRedo.MERGE_DISABLE, field)
	_undo.add_do_property(field, &"plant", plant)
	_undo.add_undo_property(field, &"plant", field.plant)
	if spacing > field.cell_size:
		print(
			(
				"Plant from scene: the field's cell_size goes from %.2f to %.2f m, the plant's width"
				% [field.cell_size, spacing]
			)
		)
		_undo.add_do_property(field, &"cell_size", spacing)
		_undo.add_undo_property(field, &"cell_size", field.cell_size)
	_undo.commit_action()
	_show_step(-1, button, bar)
	return plant


## True while [param field] is a node of the scene being edited (the undo action needs it there).
static func _in_edited_scene(field: Variant) -> bool:
	if not is_instance_valid(field) or not (field as Node).is_inside_tree():
		return false
	var root: Node = EditorInterface.get_edited_scene_root()
	return root != null and (root == field or root.is_ancestor_of(field as Node))


## [param base] (a path without extension), or with _2, _3 … added when a plant of that name exists.
static func _free_base(base: String) -> String:
	var candidate: String = base
	var number: int = 1
	while ResourceLoader.exists(candidate + ".tres"):
		number += 1
		candidate = "%s_%d" % [base, number]
	return candidate


## Saves [param plant]'s meshes as [param base]_meshN.res (a level that is the one above's is saved
## once) and the plant, naming them, as [param base].tres; each takes its file's path.
static func _save(plant: FieldPlant, base: String) -> Error:
	var saved: Array[Mesh] = []
	for level: int in 3:
		var mesh: Mesh = plant.get_part_mesh(level, 0)
		if mesh and not saved.has(mesh):
			var path: String = "%s_mesh%d.res" % [base, level + 1]
			var error: Error = ResourceSaver.save(mesh, path, ResourceSaver.FLAG_COMPRESS)
			if error != OK:
				return error
			mesh.take_over_path(path)
			saved.append(mesh)
	var result: Error = ResourceSaver.save(plant, base + ".tres")
	if result == OK:
		plant.take_over_path(base + ".tres")
	return result


## Shows step [param step] of [constant STEPS] on the button and bar; -1: done, both as before.
## (Untyped: the inspector frees its controls when another object is selected, which a bake outlasts.)
static func _show_step(step: int, shown_button: Variant, shown_bar: Variant) -> void:
	var button: Button = shown_button as Button if is_instance_valid(shown_button) else null
	var bar: ProgressBar = shown_bar as ProgressBar if is_instance_valid(shown_bar) else null
	if button:
		button.disabled = step >= 0
		button.text = STEPS[step] if step >= 0 else SceneDropButton.TEXT
	if bar:
		bar.visible = step >= 0
		bar.value = step + 1
