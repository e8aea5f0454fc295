@tool
extends EditorInspectorPlugin
## Above a [SunflowerField]'s [code]plant[/code] property: "Plant from scene…", which takes a scene
## dropped on it from the FileSystem dock or chosen in a dialog. The scene becomes a [SunflowerPlant]
## ([method SunflowerPlant.from_scene]) saved beside it ([code]<scene>_plant.tres[/code] and its meshes
## as [code]<scene>_plant_mesh1.res[/code] …), its impostors are baked at once (a progress bar shows
## the steps), and it becomes the field's plant in one undoable action, which also widens the field's
## cells to the plant's width when they are narrower (trees 0.5 m apart would stand in each other).

const SceneDropButton: GDScript = preload("scene_drop_button.gd")
const ScenePlant: GDScript = preload("../plant/scene_plant.gd")
## What the progress bar shows, step by step.
const STEPS: PackedStringArray = ["Merging the scene's meshes…", "Saving the plant…", "Baking its impostors…"]

var _undo: EditorUndoRedoManager
## The inspector builds its controls anew whenever it refreshes, which a running import outlasts: the
## progress is kept per field (instance id → [step, detail, share done]) and shown on the field's
## newest button and bar (instance id → [button, bar]).
var _progress: Dictionary = {}
var _controls: Dictionary = {}


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
	_controls[object.get_instance_id()] = [button, bar]
	_show_progress(object.get_instance_id())
	return false  # the plant's own editor stays below


## Makes the scene at [param path] the plant of [param field] (see the script's description); await
## it. Returns the plant, or null when the scene cannot be loaded, has nothing to draw or cannot be
## saved (the error names it), or when the field left the edited scene during the bake (a warning says
## where the plant is saved). [param button] and [param bar] show the progress when given.
func make_plant(path: String, field: SunflowerField, button: Button = null, bar: ProgressBar = null) -> SunflowerPlant:
	var id: int = field.get_instance_id()
	if button:
		_controls[id] = [button, bar]
	_show_step(id, 0)
	await _drawn(button != null)  # the step shows before the merge holds the frame
	var scene: PackedScene = await _loaded(path)
	var plant: SunflowerPlant = await _merged(scene) if scene else null
	if scene == null:
		push_error("Plant from scene: %s is not a scene" % path)
	if plant == null:
		_show_step(id, -1)
		return null
	_show_step(id, 1)
	await _drawn(button != null)
	var base: String = _free_base(path.get_basename() + "_plant")
	var error: Error = _save(plant, base)
	if error != OK:
		push_error("Plant from scene: cannot save %s.tres (%s)" % [base, error_string(error)])
		_show_step(id, -1)
		return null
	_show_step(id, 2)
	error = await plant.bake_impostors(
		EditorInterface.get_base_control(),
		"",
		"",
		func(step: String, done: float) -> void: _show_step(id, 2, step, done)
	)
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
		_show_step(id, -1)
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
	_show_step(id, -1)
	return plant


## The resource at [param path] loaded on the loader's threads while the editor draws its frames (a
## scene of a million triangles takes seconds to read), when it is a scene; else null.
static func _loaded(path: String) -> PackedScene:
	if ResourceLoader.load_threaded_request(path) != OK:
		return null
	while ResourceLoader.load_threaded_get_status(path) == ResourceLoader.THREAD_LOAD_IN_PROGRESS:
		await (Engine.get_main_loop() as SceneTree).process_frame
	return ResourceLoader.load_threaded_get(path) as PackedScene


## [method SunflowerPlant.from_scene] of [param scene] on a worker thread while the editor draws its frames
## (a scene of a million triangles takes seconds to merge and simplify); await it.
static func _merged(scene: PackedScene) -> SunflowerPlant:
	var made: Array[SunflowerPlant] = [null]
	var task: int = WorkerThreadPool.add_task(func() -> void: made[0] = SunflowerPlant.from_scene(scene))
	while not WorkerThreadPool.is_task_completed(task):
		await (Engine.get_main_loop() as SceneTree).process_frame
	WorkerThreadPool.wait_for_task_completion(task)
	return made[0]


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
static func _save(plant: SunflowerPlant, base: String) -> Error:
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


## Keeps step [param step] of [constant STEPS] as the progress of the field of instance [param id]
## ([param detail]: the part under way, [param done]: the share of the step done; -1: done) and shows
## it on the field's controls.
func _show_step(id: int, step: int, detail: String = "", done: float = 0.0) -> void:
	if step < 0:
		_progress.erase(id)
	else:
		_progress[id] = [step, detail, done]
	_show_progress(id)


## Shows the progress of the field of instance [param id] on its newest button and bar (as before
## when none runs); nothing when the inspector has freed them.
func _show_progress(id: int) -> void:
	var shown: Array = _controls.get(id, [null, null])
	var button: Button = shown[0] as Button if is_instance_valid(shown[0]) else null
	var bar: ProgressBar = shown[1] as ProgressBar if is_instance_valid(shown[1]) else null
	if button == null and bar == null:
		_controls.erase(id)
	var state: Array = _progress.get(id, [-1, "", 0.0])
	var step: int = state[0]
	if button:
		button.disabled = step >= 0
		button.text = (
			SceneDropButton.TEXT
			if step < 0
			else STEPS[step].trim_suffix("…") + (": %s…" % state[1] if not str(state[1]).is_empty() else "…")
		)
		button.tooltip_text = button.text if step >= 0 else SceneDropButton.TOOLTIP
	if bar:
		bar.visible = step >= 0
		bar.value = step + float(state[2])


## Waits, when the progress is shown ([param shown]), until a frame has been drawn with its step.
static func _drawn(shown: bool) -> void:
	if shown:
		await (Engine.get_main_loop() as SceneTree).process_frame
		await (Engine.get_main_loop() as SceneTree).process_frame
