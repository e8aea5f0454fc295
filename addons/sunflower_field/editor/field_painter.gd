@tool
extends RefCounted
## Painting a field in the editor: with a [SunflowerField] selected, a toolbar in the 3D editor
## offers Paint and Erase, the symbol to paint ('*' and the legend's symbols), the brush radius (m)
## and density (the share of cells a stroke fills, seeded), and a layer of the field's placement
## rules to follow ([code]rule_brush.gd[/code]: paint only where its filters let the plant grow). A
## circle follows the mouse on the
## field's ground; a stroke changes the map in the native core and shows it as it goes; on release
## the [code].field[/code] file is written back in the canonical form (see fields/FORMAT.md) by
## [code]map_files.gd[/code], and the stroke is one undo/redo action. Ctrl-drag erases.

## What a drag does.
enum Mode { OFF, PAINT, ERASE }

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")
const RuleBrush: GDScript = preload("rule_brush.gd")
const MapFiles: GDScript = preload("map_files.gd")
## The stroke's preview is rebuilt at most this often, milliseconds.
const PREVIEW_INTERVAL_MS: int = 60
const CIRCLE_SEGMENTS: int = 48

## The painter of the editor's plugin (tests drive it).
static var active: RefCounted

var mode: Mode = Mode.OFF
## The map symbol painted: '*' or one of the legend's.
var symbol: String = "*"
## Brush radius, metres.
var radius: float = 2.0
## The share of cells in reach a painting stroke fills, 0 to 1.
var density: float = 1.0
## New map, Resize map and the map file written back (see [code]map_files.gd[/code]).
var map_files: MapFiles
## The layer of the field's placement rules a stroke follows (see [code]rule_brush.gd[/code]).
var rule_brush: RuleBrush = RuleBrush.new()
## The toolbar (added to the 3D editor's menu by the plugin).
var toolbar: HBoxContainer
## The last error a stroke ran into ("" when none), for tests and the toolbar's tooltip.
var last_error: String = ""

var _undo_redo: EditorUndoRedoManager
var _field: SunflowerField
var _stroke: RefCounted  # the native map (SunflowerMap) a stroke paints
var _erasing: bool = false  # the stroke erases (Erase mode, or Ctrl held when it began)
var _original: PackedByteArray
var _original_map: SunflowerFieldMap
var _seed: int = 0
var _last_preview_ms: int = 0
var _preview_due: bool = false
var _circle: MeshInstance3D
var _buttons: Dictionary = {}
var _symbols: OptionButton
var _radius_box: SpinBox
var _density_box: SpinBox
var _rules_box: OptionButton


func _init(undo_redo: EditorUndoRedoManager) -> void:
	_undo_redo = undo_redo
	map_files = MapFiles.new(undo_redo)
	active = self
	toolbar = HBoxContainer.new()
	toolbar.name = "SunflowerFieldPainter"
	for entry: Array in [["Paint", Mode.PAINT], ["Erase", Mode.ERASE]]:
		var button: Button = Button.new()
		button.text = entry[0]
		button.toggle_mode = true
		button.tooltip_text = "%s the field's map with the brush (Ctrl-drag erases)" % entry[0]
		button.toggled.connect(func(on: bool) -> void: set_mode(entry[1] if on else Mode.OFF))
		toolbar.add_child(button)
		_buttons[entry[1]] = button
	_symbols = OptionButton.new()
	_symbols.tooltip_text = "The map symbol painted"
	_symbols.item_selected.connect(func(index: int) -> void: symbol = _symbols.get_item_text(index).left(1))
	toolbar.add_child(_symbols)
	_radius_box = _spin_box("Brush radius", 0.25, 50.0, 0.25, radius, " m")
	_radius_box.value_changed.connect(func(value: float) -> void: radius = value)
	_density_box = _spin_box("Density: the share of cells a stroke fills", 0.05, 1.0, 0.05, density, "")
	_density_box.prefix = "density"  # a bare "1.0" in the toolbar named nothing
	_density_box.value_changed.connect(func(value: float) -> void: density = value)
	_rules_box = OptionButton.new()
	_rules_box.tooltip_text = (
		"Paint only where a layer of the field's placement rules lets its plant grow (its height, slope,"
		+ " noise, mask, path, exclusion and spacing filters); the density is the brush's"
	)
	_rules_box.item_selected.connect(func(index: int) -> void: follow_rule(index - 1))
	toolbar.add_child(_rules_box)
	toolbar.visible = false
	if Engine.is_editor_hint():  # tools and tests also paint outside the editor
		EditorInterface.get_inspector().property_edited.connect(_on_property_edited)


## Lets go of the editor (the plugin leaves): frees the toolbar; no painter is active any more.
func release() -> void:
	edit(null)
	if Engine.is_editor_hint() and EditorInterface.get_inspector().property_edited.is_connected(_on_property_edited):
		EditorInterface.get_inspector().property_edited.disconnect(_on_property_edited)
	if is_instance_valid(toolbar):
		if toolbar.is_inside_tree():
			toolbar.queue_free()
		else:
			toolbar.free()
	if active == self:
		active = null


## Paints [param field] from now on (null: none); the toolbar shows while there is one.
func edit(field: SunflowerField) -> void:
	if field == _field:
		return
	_end_stroke(false)
	_remove_circle()
	if is_instance_valid(_field) and _field.field_built.is_connected(_on_field_built):
		_field.field_built.disconnect(_on_field_built)
	_field = field
	rule_brush.follow(field, -1)
	toolbar.visible = _field != null
	if _field:
		_field.field_built.connect(_on_field_built)  # the plant, legend or map may have changed
		refresh()


## Brings the toolbar in step with the field: the symbols its plant and legend offer (keeping the one
## chosen while it is still there), and Paint and Erase only while it has a map to paint.
func refresh() -> void:
	if _field == null:
		return
	var chosen: String = symbol
	_symbols.clear()
	_symbols.add_item("* (%s)" % _field.get_plant_types()[0].name)
	for key: Variant in _field.legend:
		var value: Variant = _field.legend[key]
		var what: String = (value as SunflowerPlant).name if value is SunflowerPlant else "object"
		_symbols.add_item("%s (%s)" % [str(key), what])
	symbol = "*"
	_symbols.select(0)
	for index: int in _symbols.item_count:
		if _symbols.get_item_text(index).left(1) == chosen:
			_symbols.select(index)
			symbol = chosen
	_refresh_rules()
	var paintable: bool = _field.map != null
	for key: Mode in _buttons:
		var button: Button = _buttons[key]
		button.disabled = not paintable
		button.tooltip_text = (
			"%s the field's map with the brush (Ctrl-drag erases)" % button.text
			if paintable
			else "The field has no map to paint: press New map… in its inspector, or give it a .field file"
		)
	if not paintable:
		set_mode(Mode.OFF)


## The rules box: "anywhere" and a line a layer of the field's placement rules, the one followed
## kept while it is still there.
func _refresh_rules() -> void:
	var layers: Array[SunflowerPlacementLayer] = []
	if _field.placement_rules:
		layers = _field.placement_rules.layers
	_rules_box.clear()
	_rules_box.add_item("anywhere")
	for i: int in layers.size():
		var plant: String = layers[i].plant if layers[i] else "?"
		_rules_box.add_item("where rule %d lets %s grow" % [i + 1, plant])
	_rules_box.visible = not layers.is_empty()
	if rule_brush.layer >= layers.size():
		rule_brush.follow(_field, -1)
	_rules_box.select(rule_brush.layer + 1)


## Paints following layer [param index] of the field's placement rules (-1: anywhere) from now on:
## its plant becomes the symbol painted, and the field's ground is read for it.
func follow_rule(index: int) -> void:
	var layers: Array[SunflowerPlacementLayer] = []
	if _field and _field.placement_rules:
		layers = _field.placement_rules.layers
	index = index if index < layers.size() else -1
	if index >= 0 and layers[index]:
		for item: int in _symbols.item_count:
			if _symbols.get_item_text(item).left(1) == layers[index].plant:
				_symbols.select(item)
				symbol = layers[index].plant
	_rules_box.select(index + 1)
	rule_brush.follow(_field, index)


func _on_field_built(_plant_count: int) -> void:
	refresh()


func _on_property_edited(property: String) -> void:
	if _field and EditorInterface.get_inspector().get_edited_object() == _field:
		if property in ["map", "plant", "legend", "placement_rules"]:
			refresh()
		if property.begins_with("ground_") or property.begins_with("height_") or property in ["map", "cell_size"]:
			rule_brush.invalidate()  # its ground is read again


## Sets what a drag does, keeping the toolbar's buttons in step.
func set_mode(new_mode: Mode) -> void:
	mode = new_mode
	for key: Mode in _buttons:
		(_buttons[key] as Button).set_pressed_no_signal(key == mode)
	if mode == Mode.OFF:
		_remove_circle()
	elif get_circle():
		(_circle.material_override as StandardMaterial3D).albedo_color = brush_colour()


## The 3D editor's input while a field is edited: moves the brush circle; a left drag paints
## (or erases with Ctrl, or in Erase mode). True when the event was used.
func handle_input(camera: Camera3D, event: InputEvent) -> bool:
	if _field == null or not _field.is_inside_tree() or mode == Mode.OFF:
		return false
	if event is InputEventMouseMotion:
		return _on_motion(camera, event as InputEventMouseMotion)
	if event is InputEventMouseButton and (event as InputEventMouseButton).button_index == MOUSE_BUTTON_LEFT:
		return _on_left_button(camera, event as InputEventMouseButton)
	return false


func _on_motion(camera: Camera3D, motion: InputEventMouseMotion) -> bool:
	var hit: Variant = ground_point(camera, motion.position)
	_show_circle(hit)
	if _stroke and hit != null and (motion.button_mask & MOUSE_BUTTON_MASK_LEFT) != 0:
		_paint_at(hit)
	elif _stroke:
		_preview_if_due()
	return _stroke != null


func _on_left_button(camera: Camera3D, button: InputEventMouseButton) -> bool:
	if not button.pressed:
		var was_painting: bool = _stroke != null
		_end_stroke(true)
		return was_painting
	var hit: Variant = ground_point(camera, button.position)
	if hit == null or not _begin_stroke(button.ctrl_pressed or mode == Mode.ERASE):
		return false
	_paint_at(hit)
	return true


## Where the ray through [param screen_point] meets the field's ground (world space), or null: the
## colliders under the brush when the ground is made of them, else the field's plane.
func ground_point(camera: Camera3D, screen_point: Vector2) -> Variant:
	var from: Vector3 = camera.project_ray_origin(screen_point)
	var direction: Vector3 = camera.project_ray_normal(screen_point)
	if _field.ground_source == SunflowerField.GroundSource.COLLIDERS:
		var query: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.create(
			from, from + direction * 4000.0, _field.ground_collision_mask
		)
		var hit: Dictionary = _field.get_world_3d().direct_space_state.intersect_ray(query)
		if not hit.is_empty():
			return hit["position"]
	if _field.ground_source == SunflowerField.GroundSource.HEIGHT_MAP and _field.get_plant_count() > 0:
		return _height_map_point(from, direction)
	var plane: Plane = Plane(_field.global_basis.y.normalized(), _field.global_position)
	return plane.intersects_ray(from, direction)


## Where a ray meets the field's height map: marched in half-metre steps in the field's space, then
## bisected; null when it meets none within 2 km.
func _height_map_point(from: Vector3, direction: Vector3) -> Variant:
	var simulation: NativeField = NativeField.new(_field.get_simulation())
	var origin: Vector3 = _field.to_local(from)
	var along: Vector3 = (_field.global_transform.affine_inverse().basis * direction).normalized()
	var above: Callable = func(t: float) -> float:
		var at: Vector3 = origin + along * t
		return at.y - simulation.get_ground_height(Vector2(at.x, at.z))
	var previous: float = 0.0
	var t: float = 0.5
	while t < 2000.0:
		var height: float = above.call(t)
		if not is_nan(height) and height <= 0.0:
			var low: float = previous
			var high: float = t
			for i: int in 20:
				var middle: float = (low + high) * 0.5
				var h: float = above.call(middle)
				if is_nan(h) or h > 0.0:
					low = middle
				else:
					high = middle
			return _field.to_global(origin + along * high)
		previous = t
		t += 0.5
	return null


func _begin_stroke(erasing: bool) -> bool:
	_stroke = _open_map(_field)
	if _stroke == null:
		return false
	var following: String = rule_brush.begin(_field, _original)
	if not following.is_empty():
		_stroke = null
		return _fail("SunflowerField painter: " + following)
	_erasing = erasing
	_seed += 1
	return true


## A native map holding [param field]'s map (see [code]map_files.gd[/code]); remembers the map and
## its bytes as they were. Null (with [member last_error]) otherwise.
func _open_map(field: SunflowerField) -> RefCounted:
	var editor: RefCounted = map_files.open(field)
	last_error = map_files.last_error
	if editor:
		_original = field.map.text
		_original_map = field.map
	return editor


func _paint_at(world_point: Vector3) -> void:
	var local: Vector3 = _field.to_local(world_point)
	var cells: Vector2 = Vector2(local.x, local.z) / _field.cell_size
	var painted: String = "" if _erasing else symbol
	var reach: float = radius / _field.cell_size
	var changed: PackedInt32Array
	if rule_brush.is_following():
		var weights: Array = rule_brush.weights_at(cells, reach)
		changed = _stroke.paint(cells, reach, painted, density, _seed, weights[0], rule_brush.rect_cells(weights[1]))
		rule_brush.note_changed(changed, painted)
	else:
		changed = _stroke.paint(cells, reach, painted, density, _seed, PackedFloat32Array(), PackedInt32Array())
	_preview_due = _preview_due or not changed.is_empty()
	_preview_if_due()


## Shows the stroke so far once the last preview has been built (a large field builds over a few
## frames; starting another would drop it) and the interval has passed.
func _preview_if_due() -> void:
	if _preview_due and not _field.is_building() and Time.get_ticks_msec() - _last_preview_ms >= PREVIEW_INTERVAL_MS:
		_preview_due = false
		_preview()


## Shows the stroke so far: the field draws a map made from the core's text of it.
func _preview() -> void:
	_last_preview_ms = Time.get_ticks_msec()
	var preview: SunflowerFieldMap = SunflowerFieldMap.new()
	preview.source_path = _original_map.source_path
	preview.text = _stroke.write()
	_field.map = preview


## Ends the stroke: when [param commit] and the map changed, one undo/redo action writes it.
func _end_stroke(commit: bool) -> void:
	if _stroke == null:
		return
	var painted: PackedByteArray = _stroke.write()
	var path: String = _original_map.source_path
	var field: SunflowerField = _field
	_stroke = null
	_erasing = false
	rule_brush.end()
	if not commit or painted == _original:
		field.map = _original_map
		return
	_undo_redo.create_action("Paint field map", UndoRedo.MERGE_DISABLE, field)
	_undo_redo.add_do_method(map_files, &"write_map", field, path, painted)
	_undo_redo.add_undo_method(map_files, &"write_map", field, path, _original)
	_undo_redo.commit_action()


func _fail(message: String) -> bool:
	last_error = message
	push_error(message)
	return false


func _show_circle(hit: Variant) -> void:
	if hit == null:
		_remove_circle()
		return
	if _circle == null:
		_circle = MeshInstance3D.new()
		_circle.name = "PainterBrush"
		_circle.mesh = ImmediateMesh.new()
		var material: StandardMaterial3D = StandardMaterial3D.new()
		material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
		material.no_depth_test = true
		_circle.material_override = material
		_field.add_child(_circle, false, Node.INTERNAL_MODE_BACK)
	(_circle.material_override as StandardMaterial3D).albedo_color = brush_colour()
	var mesh: ImmediateMesh = _circle.mesh
	mesh.clear_surfaces()
	mesh.surface_begin(Mesh.PRIMITIVE_LINE_STRIP)
	for i: int in CIRCLE_SEGMENTS + 1:
		var angle: float = TAU * i / CIRCLE_SEGMENTS
		mesh.surface_add_vertex(Vector3(cos(angle) * radius, 0.05, sin(angle) * radius))
	mesh.surface_end()
	_circle.global_position = hit


## The brush circle's colour: yellow while a drag paints, red while it erases (Erase, or a Ctrl-drag).
func brush_colour() -> Color:
	return Color(1.0, 0.3, 0.25) if mode == Mode.ERASE or _erasing else Color(1.0, 0.85, 0.2)


## The brush circle shown now, or null (tests).
func get_circle() -> MeshInstance3D:
	return _circle if _circle and is_instance_valid(_circle) else null


func _remove_circle() -> void:
	if _circle and is_instance_valid(_circle):
		_circle.queue_free()
	_circle = null


func _spin_box(tooltip: String, low: float, high: float, step: float, value: float, suffix: String) -> SpinBox:
	var box: SpinBox = SpinBox.new()
	box.min_value = low
	box.max_value = high
	box.step = step
	box.value = value
	box.suffix = suffix
	box.tooltip_text = tooltip
	box.get_line_edit().expand_to_text_length = true  # its prefix and suffix shown whole, not cut
	toolbar.add_child(box)
	return box
