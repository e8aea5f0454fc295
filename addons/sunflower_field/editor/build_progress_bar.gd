@tool
extends HBoxContainer
## Shows the [SunflowerField]s building in the background: a label naming them and a bar with their
## mean progress, hidden while no field builds. The plugin puts one in the 3D editor's toolbar; a
## game may add one to its loading screen.

var _label: Label = Label.new()
var _bar: ProgressBar = ProgressBar.new()


func _init() -> void:
	name = "SunflowerBuildProgress"
	_bar.custom_minimum_size = Vector2(120.0, 0.0)
	_bar.size_flags_vertical = Control.SIZE_SHRINK_CENTER
	add_child(_label)
	add_child(_bar)
	visible = false


func _process(_delta: float) -> void:
	refresh()


## Reads the running builds now (also done every frame).
func refresh() -> void:
	var fields: Array[SunflowerField] = SunflowerField.get_building_fields()
	visible = not fields.is_empty()
	if fields.is_empty():
		return
	var total: float = 0.0
	var names: PackedStringArray = []
	for field: SunflowerField in fields:
		total += field.get_build_progress()
		names.append(field.name)
	_bar.value = 100.0 * total / fields.size()
	_label.text = "Building sunflowers"
	tooltip_text = ("Building in the background: %s (the previous field is drawn meanwhile)" % ", ".join(names))


## What the display says, with the names of the fields building, e.g.
## [code]"Building sunflowers — Building in the background: Field (…)"[/code].
func get_text() -> String:
	return "%s — %s" % [_label.text, tooltip_text]


## The bar's value, 0 to 100.
func get_percent() -> float:
	return _bar.value
