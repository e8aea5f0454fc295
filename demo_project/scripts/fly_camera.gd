class_name FlyCamera
extends Camera3D
## The demo's fly camera: W/S forward/back, A/D strafe, E/Space up, Q/C down, Shift faster, mouse
## look while the mouse is captured (click to capture), R back to the start. Every key is an action
## in the InputMap, so it can be rebound.

## Metres per second.
@export var speed: float = 4.0
## Speed multiplier while "move_fast" is held.
@export var fast_factor: float = 5.0
## Radians per pixel of mouse motion.
@export var mouse_sensitivity: float = 0.003
## When false the camera ignores the keyboard and mouse (the recording mode flies it).
@export var manual: bool = true
## Walk mode: the camera keeps to head height over the ground and moves level (F8).
@export var walking: bool = false:
	set(value):
		walking = value
		if walking and is_inside_tree():
			global_position.y = ground_below(global_position) + walk_height
## Eye height while walking, metres.
@export var walk_height: float = 1.7

var start_transform: Transform3D


func _ready() -> void:
	start_transform = transform


func _unhandled_input(event: InputEvent) -> void:
	if not manual:
		return
	if event is InputEventMouseButton and (event as InputEventMouseButton).pressed:
		Input.mouse_mode = Input.MOUSE_MODE_CAPTURED
	elif event is InputEventMouseMotion and Input.mouse_mode == Input.MOUSE_MODE_CAPTURED:
		var motion: Vector2 = (event as InputEventMouseMotion).relative
		rotate_y(-motion.x * mouse_sensitivity)
		rotate_object_local(Vector3.RIGHT, -motion.y * mouse_sensitivity)
	elif event.is_action_pressed("reset_view"):
		transform = start_transform


func _process(delta: float) -> void:
	if not manual:
		return
	var input: Vector2 = Input.get_vector("move_left", "move_right", "move_forward", "move_back")
	var lift: float = Input.get_axis("move_down", "move_up")
	var factor: float = fast_factor if Input.is_action_pressed("move_fast") else 1.0
	if walking:
		var level: Basis = Basis(Vector3.UP, global_rotation.y)
		global_position += level * Vector3(input.x, 0.0, input.y) * speed * 0.4 * factor * delta
		global_position.y = ground_below(global_position) + walk_height
		return
	translate(Vector3(input.x, 0.0, input.y) * speed * factor * delta)
	global_position.y += lift * speed * factor * delta


## The height of the ground (any collider on layer 1) under [param point], or 0 where there is none.
func ground_below(point: Vector3) -> float:
	var ray: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.create(
		Vector3(point.x, 500.0, point.z), Vector3(point.x, -500.0, point.z), 1
	)
	var hit: Dictionary = get_world_3d().direct_space_state.intersect_ray(ray)
	return (hit["position"] as Vector3).y if not hit.is_empty() else 0.0


## Places the camera at [param eye] looking at [param target] and makes that the start (R).
func set_start(eye: Vector3, target: Vector3) -> void:
	look_at_from_position(eye, target)
	start_transform = transform
