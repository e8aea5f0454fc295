class_name DemoHud
extends CanvasLayer
## The demo's heads-up display: frame rate, plants per level of detail, a triangle estimate, the
## wind, a map menu, messages and a key help that F10 (or H) hides.

signal map_chosen(path: String)

const HELP: String = """W/S forward/back   A/D strafe   E/Space up   Q/C down   Shift faster
Mouse look (click to capture)   R start position   F1 wireframe
F2/F3 wind +/- increment   F4/F5 wind direction x/z   F6 increment 0.1 <-> 10
F7 load a part mesh (glTF)   F8 walk among the flowers   F9 wind model (natural/thesis)
X scythe   V sow   M next map   F10/H hide this help   Esc quit (saves the field: --load-changes)"""
## How long a message stays, in wall time (a recording's frames are slow: 6 s of them were minutes).
const MESSAGE_MSEC: int = 6000

var _stats: Label
var _help: Label
var _message: Label
var _maps: OptionButton
var _map_paths: PackedStringArray = []
var _message_until: int = 0  # Time.get_ticks_msec() when the message goes


func _ready() -> void:
	var panel: PanelContainer = PanelContainer.new()
	panel.position = Vector2(8, 8)
	add_child(panel)
	var box: VBoxContainer = VBoxContainer.new()
	panel.add_child(box)
	_stats = Label.new()
	box.add_child(_stats)
	_message = Label.new()
	_message.modulate = Color(1.0, 0.85, 0.4)
	box.add_child(_message)
	_help = Label.new()
	_help.text = HELP
	_help.anchor_top = 1.0
	_help.anchor_bottom = 1.0
	_help.offset_top = -80.0
	_help.offset_left = 8.0
	add_child(_help)
	_maps = OptionButton.new()
	_maps.anchor_left = 1.0
	_maps.anchor_right = 1.0
	_maps.offset_left = -260.0
	_maps.offset_top = 8.0
	_maps.offset_right = -8.0
	_maps.item_selected.connect(func(index: int) -> void: map_chosen.emit(_map_paths[index]))
	add_child(_maps)
	# The addon's own progress display, shown while a large map builds in the background.
	var progress: Control = preload("res://addons/sunflower_field/editor/build_progress_bar.gd").new()
	progress.anchor_left = 1.0
	progress.anchor_right = 1.0
	progress.offset_left = -260.0
	progress.offset_top = 44.0
	progress.offset_right = -8.0
	add_child(progress)


func _process(_delta: float) -> void:
	if not _message.text.is_empty() and Time.get_ticks_msec() >= _message_until:
		_message.text = ""


## Lists the maps of the menu; [param current] is selected.
func set_maps(names: PackedStringArray, paths: PackedStringArray, current: String) -> void:
	_maps.clear()
	_map_paths = paths
	for name: String in names:
		_maps.add_item(name)
	var index: int = paths.find(current)
	if index < 0:
		_maps.add_item(current.get_file())
		_map_paths.append(current)
		index = _map_paths.size() - 1
	_maps.select(index)


func toggle_help() -> void:
	_help.visible = not _help.visible


func is_help_visible() -> bool:
	return _help.visible


## Shows a message for a few seconds (and prints it).
func show_message(text: String) -> void:
	print("demo: " + text)
	_message.text = text
	_message_until = Time.get_ticks_msec() + MESSAGE_MSEC


## Takes the message away (what it said is done).
func clear_message() -> void:
	_message.text = ""


func set_stats(text: String) -> void:
	_stats.text = text
