@tool
extends EditorPlugin
## Opens res://paint.tscn in the editor, selects its field and drives the addon's painter with
## synthetic mouse events through a camera looking down: a stroke paints only within the brush,
## Ctrl-drag erases, undo restores the file byte for byte and the plants, redo repeats, the file
## reimports to the field shown, and a stroke on a missing file says so and changes nothing.
## Prints "probe: ok" or the failures, then quits the editor.

const MAP_PATH: String = "res://paint.field"
const CELL: float = 0.5

var _problems: PackedStringArray = []
var _tree: SceneTree


func _enter_tree() -> void:
	if OS.get_environment("RUN_PROBE") == "1":  # not while tools/import_project.sh imports the project
		_run.call_deferred()


func _run() -> void:
	_tree = EditorInterface.get_base_control().get_tree()
	await _frames(60)
	EditorInterface.open_scene_from_path("res://paint.tscn")
	await _frames(30)
	var root: Node = EditorInterface.get_edited_scene_root()
	var field: SunflowerField = root.get_node("Field") as SunflowerField
	EditorInterface.edit_node(field)
	await _frames(5)
	field.finish_build()
	var painter: RefCounted = load("res://addons/sunflower_field/editor/field_painter.gd").get("active")
	_check(painter != null and painter.toolbar.visible, "the painter's toolbar shows for a selected field")
	await _check_toolbar_follows_the_field(painter, field)
	var camera: Camera3D = Camera3D.new()
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = 40.0
	root.add_child(camera)
	camera.global_transform = Transform3D(Basis.from_euler(Vector3(-PI / 2.0, 0.0, 0.0)), Vector3(10.0, 50.0, 7.5))
	var original: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	var plants_before: int = field.get_plant_count()
	var cells_before: Dictionary = _cells(original)
	var undo_redo: EditorUndoRedoManager = EditorInterface.get_editor_undo_redo()
	var history: UndoRedo = undo_redo.get_history_undo_redo(undo_redo.get_object_history_id(field))
	var version_before: int = history.get_version()

	# Paint a stroke in the empty east half: only the cells within the brush of the points visited.
	painter.set_mode(1)  # Paint
	painter.radius = 1.5
	painter.density = 1.0
	var points: Array[Vector3] = [Vector3(15.0, 0.0, 5.0), Vector3(15.5, 0.0, 7.0), Vector3(16.0, 0.0, 9.0)]
	_drag(painter, camera, points, false)
	await _frames(3)
	var painted: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	_check(painted != original, "the stroke wrote the file")
	_check(painted.get_string_from_utf8().begins_with("# Painting test field"), "the comment line is kept")
	var cells_after: Dictionary = _cells(painted)
	var added: int = 0
	for cell: Vector2i in cells_after:
		if cells_before.has(cell):
			continue
		added += 1
		_check(_near_any(cell, points, 1.5 + 0.01), "cell %s painted outside the brush" % cell)
	for x: int in range(20, 40):
		for y: int in 30:
			var cell: Vector2i = Vector2i(x, y)
			if _near_any(cell, points, 1.5 - 0.01):
				_check(cells_after.has(cell), "cell %s within the brush not painted" % cell)
	_check(added > 20, "the stroke painted the cells in reach (%d)" % added)
	field.finish_build()
	await _frames(2)
	field.finish_build()
	_check(field.get_plant_count() == plants_before + added, "the field shows the painted plants")
	_check(field.map.text == painted, "the field's map is the reimported file")

	# Undo restores the file byte for byte and the plants; redo paints again.
	_press_shortcut(KEY_Z)  # Ctrl+Z, as a user undoes
	await _frames(2)
	field.finish_build()
	_check(FileAccess.get_file_as_bytes(MAP_PATH) == original, "undo restores the file byte for byte")
	_check(field.get_plant_count() == plants_before, "undo restores the plants")
	# The editor calls a scene changed while its history's version differs from the saved one.
	_check(history.get_version() == version_before, "after the undo the scene is as unchanged as before")
	_press_shortcut(KEY_Y)  # Ctrl+Y
	await _frames(2)
	field.finish_build()
	_check(FileAccess.get_file_as_bytes(MAP_PATH) == painted, "redo writes the painted map again")
	_check(field.get_plant_count() == plants_before + added, "redo shows the painted plants")

	# Ctrl-drag erases the planted west half within the brush.
	var erase_points: Array[Vector3] = [Vector3(5.0, 0.0, 7.5)]
	_drag(painter, camera, erase_points, true)
	await _frames(2)
	var erased: Dictionary = _cells(FileAccess.get_file_as_bytes(MAP_PATH))
	var removed: int = 0
	for cell: Vector2i in cells_after:
		if not erased.has(cell):
			removed += 1
			_check(_near_any(cell, erase_points, 1.51), "cell %s erased outside the brush" % cell)
	_check(removed > 20, "Ctrl-drag erased the cells in reach (%d)" % removed)

	# A map whose file is gone: a clear error, nothing written, no undo step.
	var version: int = history.get_version()
	var orphan: SunflowerFieldMap = SunflowerFieldMap.new()
	orphan.source_path = "res://gone.field"
	orphan.text = painted
	field.map = orphan
	_drag(painter, camera, points, false)
	_check(str(painter.last_error).contains("res://gone.field"), "the error names the file: " + str(painter.last_error))
	_check(not FileAccess.file_exists("res://gone.field"), "nothing written")
	_check(history.get_version() == version, "no undo step")

	# New map: an empty 30 x 20 map saved beside the scene, given to the field; undo gives the old.
	field.map = load(MAP_PATH)
	var start: int = Time.get_ticks_msec()
	var made: String = painter.map_files.new_map(field, 30, 20, false)
	var took: int = Time.get_ticks_msec() - start
	print("probe: New map took %d ms" % took)
	_check(took < 2000, "New map answers within 2 s (%d ms)" % took)
	_check(made == "res://field.field" and FileAccess.file_exists(made), "a new map beside the scene: " + made)
	field.finish_build()
	_check(field.map.source_path == made and field.get_plant_count() == 0, "the field has the new, empty map")
	_check(field.get_simulation().get_map_columns() == 30, "30 columns")
	# The new file is imported when the editor next scans its files, not in New map's frame (a reimport
	# there redrew the editor for its progress dialog: 3.9 s under the software renderer).
	_check(not FileAccess.file_exists(made + ".import"), "New map leaves the import to the next scan")
	var filesystem: EditorFileSystem = EditorInterface.get_resource_filesystem()
	filesystem.scan()
	for i: int in 600:
		await _frames(1)
		if not filesystem.is_scanning() and FileAccess.file_exists(made + ".import"):
			break
	_check(FileAccess.file_exists(made + ".import"), "the new map file imported at the next scan")
	var loaded: SunflowerFieldMap = load(made) as SunflowerFieldMap
	_check(loaded != null and loaded.columns == 30 and loaded.text == field.map.text, "it loads as the map made")
	_check(field.map.source_path == made and field.map.columns == 30, "the field keeps the new map")
	history.undo()
	field.finish_build()
	_check(field.map.source_path == MAP_PATH, "undo gives the field its map back")
	# Resize: 50 x 25 keeps the cells both sizes share (the first 25 rows); undo restores the bytes.
	var before_resize: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	var kept: int = 0
	for cell: Vector2i in _cells(before_resize):
		kept += 1 if cell.y < 25 else 0
	_check(painter.map_files.resize_map(field, 50, 25), "resized")
	await _frames(2)
	field.finish_build()
	_check(FileAccess.get_file_as_string(MAP_PATH).contains("\n50 25\n"), "the header says 50 25")
	_check(field.get_plant_count() == kept, "the shared cells kept (%d of %d)" % [field.get_plant_count(), kept])
	history.undo()
	_check(FileAccess.get_file_as_bytes(MAP_PATH) == before_resize, "undo restores the map before the resize")
	await _generate_paint_move_generate(painter, camera, field, history)
	camera.free()
	# With PROBE_SHOT set (a run under Xvfb): a picture of the editor with the brush over the field.
	var shot: String = OS.get_environment("PROBE_SHOT")
	if not shot.is_empty():
		await _picture(painter, field, shot)
	print("probe: " + ("ok" if _problems.is_empty() else "; ".join(_problems)))
	_tree.quit(0 if _problems.is_empty() else 1)


## The toolbar follows the field: its symbol list names the plant grown now, Paint and Erase are
## disabled (saying why) while the field has no map, and the brush takes Erase's colour at once.
func _check_toolbar_follows_the_field(painter: RefCounted, field: SunflowerField) -> void:
	var symbols: OptionButton = painter.toolbar.get_child(2) as OptionButton
	var paint: Button = painter.toolbar.get_child(0) as Button
	_check(symbols.get_item_text(0).contains(field.get_plant_types()[0].name), "the symbol list names the plant")
	var red: SunflowerPlant = load("res://addons/sunflower_field/plants/red_sunflower.tres")
	field.plant = red
	await _frames(3)
	field.finish_build()
	_check(symbols.get_item_text(0).contains(red.name), "the list follows a new plant: " + symbols.get_item_text(0))
	field.plant = null
	var kept: SunflowerFieldMap = field.map
	field.map = null
	EditorInterface.get_inspector().property_edited.emit("map")  # as the inspector does after an edit
	await _frames(2)
	_check(
		paint.disabled and paint.tooltip_text.contains("no map"), "Paint is off without a map: " + paint.tooltip_text
	)
	field.map = kept
	await _frames(3)
	field.finish_build()
	_check(not paint.disabled, "Paint is on again with the map back")
	painter.set_mode(1)  # Paint
	var camera: Camera3D = Camera3D.new()
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = 40.0
	field.add_sibling(camera)
	camera.global_transform = Transform3D(Basis.from_euler(Vector3(-PI / 2.0, 0.0, 0.0)), Vector3(10.0, 50.0, 7.5))
	var motion: InputEventMouseMotion = InputEventMouseMotion.new()
	motion.position = camera.unproject_position(field.to_global(Vector3(10.0, 0.0, 7.5)))
	painter.handle_input(camera, motion)
	var circle: MeshInstance3D = painter.get_circle()
	if _check(circle != null, "the brush circle shows over the field"):
		var colour: Color = (circle.material_override as StandardMaterial3D).albedo_color
		painter.set_mode(2)  # Erase, straight from Paint
		var erase_colour: Color = (circle.material_override as StandardMaterial3D).albedo_color
		_check(colour != erase_colour and erase_colour == painter.brush_colour(), "the brush turns Erase's colour")
	painter.set_mode(0)
	camera.free()


## Placement by rules as a user meets it: rules that plant everything but a road, "Generate from
## rules" pressed above the field's inspector, a patch erased by hand, the road moved, Generate
## again: the new road is clear, the old one planted, the erased patch still empty; Ctrl+Z takes
## back each step, the file byte for byte.
func _generate_paint_move_generate(
	painter: RefCounted, camera: Camera3D, field: SunflowerField, history: UndoRedo
) -> void:
	var road: Path3D = Path3D.new()
	road.name = "Road"
	road.curve = Curve3D.new()
	road.curve.add_point(Vector3(0.0, 0.0, 10.0))
	road.curve.add_point(Vector3(20.0, 0.0, 10.0))
	field.get_parent().add_child(road)
	road.owner = field.owner
	var everything: SunflowerPlacementLayer = SunflowerPlacementLayer.new()
	everything.paths_use = true
	everything.paths_nodes = [NodePath("../Road")]
	everything.paths_half_width = 2.0
	everything.paths_falloff = 0.0
	var rules: SunflowerPlacementRules = SunflowerPlacementRules.new()
	rules.layers = [everything]
	field.placement_rules = rules
	EditorInterface.edit_node(null)
	await _frames(2)
	EditorInterface.edit_node(field)
	await _frames(3)
	var before: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	# Generate pressed, and pressed again at once: cancelled, the map as it was.
	var controls: Array = _generate_controls()
	if _check(controls.size() == 2, "a Generate from rules button and its progress bar above the field"):
		controls[0].pressed.emit()
		controls[0].pressed.emit()
		for i: int in 100:
			await _frames(1)
			if not is_instance_valid(controls[0]) or controls[0].text == "Generate from rules":
				break
		_check(
			FileAccess.get_file_as_bytes(MAP_PATH) == before and not FileAccess.file_exists(MAP_PATH + ".generated"),
			"a generation cancelled at once leaves the map as it was"
		)
	var first: PackedByteArray = await _press_generate(field, before)
	var road_at: Callable = func(cell: Vector2i, z: float) -> bool: return absf((cell.y + 0.5) * CELL - z) <= 2.0
	var cells: Dictionary = _cells(first)
	var wrong: int = 0
	for x: int in 40:
		for y: int in 30:
			wrong += 1 if cells.has(Vector2i(x, y)) == road_at.call(Vector2i(x, y), 10.0) else 0
	_check(not first.is_empty() and wrong == 0, "Generate planted every cell but the road's (%d wrong)" % wrong)
	_check(FileAccess.file_exists(MAP_PATH + ".generated"), "the generation's cells kept beside the map")
	# A patch erased by hand, away from both roads.
	var patch: Array[Vector3] = [Vector3(6.0, 0.0, 5.0)]
	painter.set_mode(1)
	_drag(painter, camera, patch, true)
	await _frames(2)
	var erased: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	var hole: Array[Vector2i] = []
	for cell: Vector2i in _cells(first):
		if not _cells(erased).has(cell):
			hole.append(cell)
	_check(hole.size() > 20, "the hand erased a patch (%d cells)" % hole.size())
	painter.set_mode(0)
	# The road moves south; Generate again.
	road.curve.set_point_position(0, Vector3(0.0, 0.0, 12.0))
	road.curve.set_point_position(1, Vector3(20.0, 0.0, 12.0))
	var second: PackedByteArray = await _press_generate(field, erased)
	cells = _cells(second)
	wrong = 0
	var refilled: int = 0
	for x: int in 40:
		for y: int in 30:
			var cell: Vector2i = Vector2i(x, y)
			if hole.has(cell):
				refilled += 1 if cells.has(cell) else 0
			elif cells.has(cell) == road_at.call(cell, 12.0):
				wrong += 1
	_check(wrong == 0, "the moved road is clear and the old one planted (%d wrong)" % wrong)
	_check(refilled == 0, "the patch erased by hand stays empty (%d refilled)" % refilled)
	# A patch over the new road's verge erased, then painted back with the brush following rule 1
	# (chosen in the toolbar): the verge fills again, the road stays clear.
	var verge: Array[Vector3] = [Vector3(15.0, 0.0, 14.5)]
	painter.set_mode(1)
	_drag(painter, camera, verge, true)
	await _frames(2)
	var cleared: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	_check(_cells(cleared).size() < _cells(second).size(), "the verge erased")
	var rules_box: OptionButton = null
	for node: Node in painter.toolbar.find_children("*", "OptionButton", true, false):
		if (
			(node as OptionButton).item_count > 1
			and (node as OptionButton).get_item_text(1).begins_with("where rule 1")
		):
			rules_box = node as OptionButton
	if _check(rules_box != null and rules_box.visible, "the toolbar offers the field's rule to follow"):
		rules_box.select(1)
		rules_box.item_selected.emit(1)
		while painter.rule_brush.is_reading():
			await _frames(1)
		_drag(painter, camera, verge, false)
		await _frames(2)
		# With PROBE_GENERATE_SHOT set (a run under Xvfb): the editor showing the field generated
		# again and its verge repainted, the rule still chosen in the toolbar.
		var shot: String = OS.get_environment("PROBE_GENERATE_SHOT")
		if not shot.is_empty():
			await _miniature_picture(field, shot)
		rules_box.select(0)
		rules_box.item_selected.emit(0)
	var repainted: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	_check(
		_cells(repainted) == _cells(second),
		(
			"the brush following the rule refilled the verge and left the road clear (%d cells, %d generated)"
			% [_cells(repainted).size(), _cells(second).size()]
		)
	)
	painter.set_mode(0)
	# Undo each step.
	for step: Array in [
		[cleared, "the rule's stroke"],
		[second, "the verge's erase"],
		[erased, "the second generation"],
		[first, "the erase"],
		[before, "the first generation"],
	]:
		history.undo()
		await _frames(2)
		_check(FileAccess.get_file_as_bytes(MAP_PATH) == step[0], "undo of %s restores the file" % step[1])
	_check(not FileAccess.file_exists(MAP_PATH + ".generated"), "undo of the first generation removes its cells")
	field.placement_rules = null
	road.queue_free()
	print(
		(
			"probe: Generate from rules, a patch erased, the road moved, Generate again, a verge repainted"
			+ " following the rule, five undos: checked"
		)
	)


## The inspector's "Generate from rules" button and its progress bar (the control after it: found
## by name, the bar of an inspector build not yet freed answered instead, as a new bar beside it is
## renamed), or [] when not there.
func _generate_controls() -> Array:
	for node: Node in EditorInterface.get_inspector().find_children("*", "Button", true, false):
		if (node as Button).text == "Generate from rules" and not node.is_queued_for_deletion():
			var parent: Node = node.get_parent()
			var next: Node = (
				parent.get_child(node.get_index() + 1) if node.get_index() + 1 < parent.get_child_count() else null
			)
			return [node, next] if next is ProgressBar else []
	return []


## Presses "Generate from rules" in the field's inspector and waits for the map file to change from
## [param before]; returns the new bytes (empty when nothing was written).
func _press_generate(field: SunflowerField, before: PackedByteArray) -> PackedByteArray:
	var controls: Array = _generate_controls()
	if not _check(controls.size() == 2, "a Generate from rules button and its progress bar above the field"):
		return PackedByteArray()
	# (Seen through its signal: a fast machine can finish a small map within the press.)
	var shown: Array[bool] = [false]
	var bar: ProgressBar = controls[1]
	var on_shown: Callable = func() -> void: shown[0] = shown[0] or bar.visible
	bar.visibility_changed.connect(on_shown)
	controls[0].pressed.emit()
	shown[0] = shown[0] or bar.visible
	for i: int in 300:
		await _frames(1)
		if FileAccess.get_file_as_bytes(MAP_PATH) != before:
			break
	await _frames(2)
	_check(shown[0], "the progress bar shows while the rules run")
	if is_instance_valid(bar):
		bar.visibility_changed.disconnect(on_shown)
	field.finish_build()
	var after: PackedByteArray = FileAccess.get_file_as_bytes(MAP_PATH)
	return after if _check(after != before, "Generate wrote the map") else PackedByteArray()


## The editor with [param field] as a miniature in front of its default view (a few metres from
## the origin), saved to [param path]; the field's size and place are given back.
func _miniature_picture(field: SunflowerField, path: String) -> void:
	var before: Array = [field.cell_size, field.plant_height, field.position]
	field.cell_size = 0.12
	field.plant_height = 0.45
	field.position = Vector3(-2.4, 0.0, -1.8)
	field.finish_build()
	await _frames(20)
	EditorInterface.get_base_control().get_viewport().get_texture().get_image().save_png(path)
	field.cell_size = before[0]
	field.plant_height = before[1]
	field.position = before[2]
	field.finish_build()


## The editor as a user sees it while painting: the brush (moved over the field through the
## editor's own camera) over the field, saved to [param path].
func _picture(painter: RefCounted, field: SunflowerField, path: String) -> void:
	# A miniature of the painted field in front of the editor's default view (a few metres from the
	# origin), so the picture shows the field, the painted strip and the brush.
	field.map = load(MAP_PATH)
	field.cell_size = 0.12
	field.plant_height = 0.45
	field.position = Vector3(-2.4, 0.0, -1.8)
	field.finish_build()
	painter.radius = 0.35
	var viewport: SubViewport = EditorInterface.get_editor_viewport_3d(0)
	var eye: Camera3D = viewport.get_camera_3d()
	for i: int in 30:
		var motion: InputEventMouseMotion = InputEventMouseMotion.new()
		motion.position = eye.unproject_position(field.to_global(Vector3(3.0, 0.0, 1.3)))
		painter.handle_input(eye, motion)
		await _tree.process_frame
	EditorInterface.get_base_control().get_viewport().get_texture().get_image().save_png(path)


## Ctrl+[param key] pressed and released in the editor's window, as a user presses a shortcut.
func _press_shortcut(key: Key) -> void:
	for down: bool in [true, false]:
		var event: InputEventKey = InputEventKey.new()
		event.keycode = key
		event.physical_keycode = key
		event.ctrl_pressed = true
		event.pressed = down
		EditorInterface.get_base_control().get_viewport().push_input(event)


## A left drag through [param points] (Ctrl held when [param ctrl]): press, moves, release.
func _drag(painter: RefCounted, camera: Camera3D, points: Array[Vector3], ctrl: bool) -> void:
	var press: InputEventMouseButton = InputEventMouseButton.new()
	press.button_index = MOUSE_BUTTON_LEFT
	press.pressed = true
	press.ctrl_pressed = ctrl
	press.position = camera.unproject_position(points[0])
	painter.handle_input(camera, press)
	for point: Vector3 in points.slice(1):
		var motion: InputEventMouseMotion = InputEventMouseMotion.new()
		motion.position = camera.unproject_position(point)
		motion.button_mask = MOUSE_BUTTON_MASK_LEFT
		motion.ctrl_pressed = ctrl
		painter.handle_input(camera, motion)
	var release: InputEventMouseButton = InputEventMouseButton.new()
	release.button_index = MOUSE_BUTTON_LEFT
	release.pressed = false
	release.position = camera.unproject_position(points[-1])
	painter.handle_input(camera, release)


## The plant cells of a map's text (canonical or not: rows after the header, '*' only here).
func _cells(bytes: PackedByteArray) -> Dictionary:
	var cells: Dictionary = {}
	var lines: PackedStringArray = bytes.get_string_from_utf8().split("\n")
	var header: int = 0
	while lines[header].begins_with("#"):
		header += 1
	for row: int in range(header + 1, lines.size()):
		var line: String = lines[row]
		for column: int in line.length():
			if line[column] == "*":
				cells[Vector2i(column, row - header - 1)] = true
	return cells


func _near_any(cell: Vector2i, points: Array[Vector3], reach: float) -> bool:
	var centre: Vector2 = (Vector2(cell) + Vector2(0.5, 0.5)) * CELL
	for point: Vector3 in points:
		if centre.distance_to(Vector2(point.x, point.z)) <= reach:
			return true
	return false


func _check(condition: bool, message: String) -> bool:
	if not condition and _problems.size() < 12:
		_problems.append(message)
	return condition


func _frames(count: int) -> void:
	for i: int in count:
		await _tree.process_frame
