extends Node3D
## The demo scene. Keys: F2 / F3 add / subtract the wind increment, Esc releases the mouse, then quits.
## Recording mode (no person needed): --frames N [--screenshot PATH] renders N frames from the
## start viewpoint, saves a screenshot, prints the field's statistics and quits.

var _frames_left: int = -1
var _screenshot: String = ""

@onready var _field: SunflowerField = $Field


func _ready() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	for i: int in args.size():
		if args[i] == "--frames" and i + 1 < args.size():
			_frames_left = args[i + 1].to_int()
		elif args[i] == "--screenshot" and i + 1 < args.size():
			_screenshot = args[i + 1]
	if _frames_left < 0 and not _screenshot.is_empty():
		_frames_left = 30


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed("wind_more"):
		_field.increase_wind()
	elif event.is_action_pressed("wind_less"):
		_field.decrease_wind()
	elif event.is_action_pressed("quit"):
		if Input.mouse_mode == Input.MOUSE_MODE_CAPTURED:
			Input.mouse_mode = Input.MOUSE_MODE_VISIBLE
		else:
			get_tree().quit()


func _process(_delta: float) -> void:
	if _frames_left < 0:
		return
	_frames_left -= 1
	if _frames_left > 0:
		return
	_frames_left = -1
	await RenderingServer.frame_post_draw
	var counts: PackedInt32Array = _field.get_lod_counts()
	var plants: int = _field.get_plant_count()
	print("demo: %d plants; per level (mesh 1, mesh 2, mesh 3, sprite, billboard): %s" % [plants, counts])
	var usec: int = _field.get_simulation().get_last_update_usec()
	print("demo: native update %d µs; %s" % [usec, RenderingServer.get_video_adapter_name()])
	if not _screenshot.is_empty():
		var image: Image = get_viewport().get_texture().get_image()
		DirAccess.make_dir_recursive_absolute(_screenshot.get_base_dir())
		var error: Error = image.save_png(_screenshot)
		print("demo: screenshot %s (%s)" % [_screenshot, error_string(error)])
	get_tree().quit()
