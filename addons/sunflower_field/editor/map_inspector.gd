@tool
extends EditorInspectorPlugin
## The map buttons at the top of a [SunflowerField]'s inspector: "New map…" (columns × rows, filled
## or empty, saved as a new .field beside the scene) and "Resize map…" (keeps the cells both sizes
## share), each one undo/redo action through the painter; and, for a field with placement rules,
## "Generate from rules" (placement_generator.gd; pressed again while it runs, it cancels) with a
## progress bar under it while it runs.

const GENERATE: String = "Generate from rules"
const GENERATING: String = "Generating… (press to cancel)"

var _painter: RefCounted
var _generator: RefCounted


func _init(painter: RefCounted, generator: RefCounted) -> void:
	_painter = painter
	_generator = generator


func _can_handle(object: Object) -> bool:
	return object is SunflowerField


func _parse_begin(object: Object) -> void:
	var field: SunflowerField = object as SunflowerField
	var row: HBoxContainer = HBoxContainer.new()
	for entry: Array in [["New map…", false], ["Resize map…", true]]:
		var button: Button = Button.new()
		button.text = entry[0]
		button.size_flags_horizontal = Control.SIZE_EXPAND_FILL
		button.pressed.connect(_ask_size.bind(field, entry[1]))
		row.add_child(button)
	add_custom_control(row)
	if field.placement_rules:
		var generate: Button = Button.new()
		generate.text = GENERATING if _generator.is_running(field) else GENERATE
		generate.tooltip_text = (
			"Writes what the placement rules place into the map file (cells painted by hand since the last "
			+ "generation are kept)"
		)
		var bar: ProgressBar = ProgressBar.new()
		bar.name = "GenerateProgress"
		bar.max_value = 1.0
		bar.visible = _generator.is_running(field)
		bar.indeterminate = true
		generate.pressed.connect(_on_generate.bind(field, generate, bar))
		add_custom_control(generate)
		add_custom_control(bar)


func _on_generate(field: SunflowerField, button: Button, bar: ProgressBar) -> void:
	if _generator.is_running(field):
		_generator.cancel(field)
		return
	button.text = GENERATING
	bar.visible = true
	# (The inspector may build its controls anew meanwhile: progress goes to the controls pressed.)
	var show: Callable = func(step: String, share: float) -> void:
		if is_instance_valid(button):
			button.text = "Generating: %s… (press to cancel)" % step
		if is_instance_valid(bar):
			bar.indeterminate = share < 0.0
			bar.value = maxf(share, 0.0)
	await _generator.generate(field, show)
	if is_instance_valid(button):
		button.text = GENERATE
	if is_instance_valid(bar):
		bar.visible = false


## A dialog asking for columns and rows (and, for a new map, whether it starts planted).
func _ask_size(field: SunflowerField, resizing: bool) -> void:
	var dialog: ConfirmationDialog = ConfirmationDialog.new()
	dialog.title = "Resize the field map" if resizing else "New field map"
	var box: VBoxContainer = VBoxContainer.new()
	var columns: SpinBox = _size_box(box, "Columns", field.map.columns if resizing and field.map else 40)
	var rows: SpinBox = _size_box(box, "Rows", field.map.rows if resizing and field.map else 30)
	var filled: CheckBox = CheckBox.new()
	filled.text = "Every cell a sunflower"
	filled.visible = not resizing
	box.add_child(filled)
	dialog.add_child(box)
	dialog.confirmed.connect(
		func() -> void:
			if resizing:
				_painter.map_files.resize_map(field, int(columns.value), int(rows.value))
			else:
				_painter.map_files.new_map(field, int(columns.value), int(rows.value), filled.button_pressed)
			dialog.queue_free()
	)
	dialog.canceled.connect(dialog.queue_free)
	EditorInterface.get_base_control().add_child(dialog)
	dialog.popup_centered()


func _size_box(parent: VBoxContainer, label: String, value: int) -> SpinBox:
	var box: SpinBox = SpinBox.new()
	box.prefix = label
	box.min_value = 1
	box.max_value = 100000
	box.value = maxi(value, 1)
	parent.add_child(box)
	return box
