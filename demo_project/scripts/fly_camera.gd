extends Camera3D
## A simple fly camera: W/S forward/back, A/D strafe, mouse look while the mouse is captured
## (click to capture, Esc releases), R back to the start.

## Metres per second.
@export var speed: float = 4.0
## Radians per pixel of mouse motion.
@export var mouse_sensitivity: float = 0.003

var _start: Transform3D


func _ready() -> void:
	_start = transform


func _unhandled_input(event: InputEvent) -> void:
	if event is InputEventMouseButton and (event as InputEventMouseButton).pressed:
		Input.mouse_mode = Input.MOUSE_MODE_CAPTURED
	elif event is InputEventMouseMotion and Input.mouse_mode == Input.MOUSE_MODE_CAPTURED:
		var motion: Vector2 = (event as InputEventMouseMotion).relative
		rotate_y(-motion.x * mouse_sensitivity)
		rotate_object_local(Vector3.RIGHT, -motion.y * mouse_sensitivity)
	elif event.is_action_pressed("reset_view"):
		transform = _start


func _process(delta: float) -> void:
	var input: Vector2 = Input.get_vector("move_left", "move_right", "move_forward", "move_back")
	translate(Vector3(input.x, 0.0, input.y) * speed * delta)
