class_name CameraPath
extends RefCounted
## A scripted camera path for the recording mode: waypoints (eye, target) flown through in equal
## shares of the frames, eased in and out.
##
## A waypoint file has one waypoint per line, "x y z tx ty tz" (eye, then the point looked at);
## blank lines and lines starting with # are ignored.

var eyes: PackedVector3Array = []
var targets: PackedVector3Array = []


## The built-in flight over a field of [param size] metres (x, z): in at head height from the south,
## up over the middle, high over the north edge looking back, then low along the west side. Heights
## are above [param ground] (a Callable giving the ground's height under a point), when given.
static func built_in(size: Vector2, ground: Callable = Callable()) -> CameraPath:
	var path: CameraPath = CameraPath.new()
	var w: float = size.x
	var h: float = size.y
	path.add(Vector3(0.6 * w, 2.4, h + 3.5), Vector3(0.45 * w, 1.0, h - 11.0))
	path.add(Vector3(0.5 * w, 1.7, h - 2.0), Vector3(0.5 * w, 1.4, h - 16.0))
	path.add(Vector3(0.5 * w, 8.0, 0.5 * h), Vector3(0.5 * w, 0.0, 0.2 * h))
	path.add(Vector3(0.3 * w, 25.0, -12.0), Vector3(0.5 * w, 0.0, 0.5 * h))
	path.add(Vector3(-12.0, 3.0, 0.5 * h), Vector3(0.5 * w, 1.5, 0.5 * h))
	if ground.is_valid():
		for i: int in path.eyes.size():
			path.eyes[i].y += ground.call(path.eyes[i])
			path.targets[i].y += ground.call(path.targets[i])
	return path


## A still camera at one of the fixed views the GPU-side benchmark compares, over a field of
## [param size] metres (x, z): "inside" (head height in the middle, looking north), "outside40"
## (head height 40 m south of the field, looking at its middle), "above45" (25 m up, looking down
## at 45° to the middle) or "down60" (60 m straight down on the middle). Null for another name.
static func view(view_name: String, size: Vector2) -> CameraPath:
	var middle: Vector3 = Vector3(0.5 * size.x, 0.0, 0.5 * size.y)
	var eye: Vector3
	var target: Vector3
	match view_name:
		"inside":
			eye = middle + Vector3(0.0, 1.7, 0.0)
			target = middle + Vector3(0.0, 1.7, -10.0)
		"outside40":
			eye = Vector3(middle.x, 1.7, size.y + 40.0)
			target = middle + Vector3(0.0, 1.0, 0.0)
		"above45":
			eye = middle + Vector3(0.0, 25.0, 25.0)
			target = middle
		"down60":
			eye = middle + Vector3(0.0, 60.0, 0.0)
			target = middle + Vector3(0.0, 0.0, -0.01)  # not straight along the up axis
		_:
			return null
	var path: CameraPath = CameraPath.new()
	path.add(eye, target)
	path.add(eye, target)
	return path


## Reads a waypoint file; returns null and fills [param r_error] on a bad line.
static func from_file(file_path: String, r_error: Array[String]) -> CameraPath:
	var text: String = FileAccess.get_file_as_string(file_path)
	if text.is_empty() and FileAccess.get_open_error() != OK:
		r_error.append("%s: cannot read the path file" % file_path)
		return null
	var path: CameraPath = CameraPath.new()
	var line_number: int = 0
	for line: String in text.split("\n"):
		line_number += 1
		var stripped: String = line.strip_edges()
		if stripped.is_empty() or stripped.begins_with("#"):
			continue
		var numbers: PackedFloat64Array = []
		for word: String in stripped.split(" ", false):
			if not word.is_valid_float():
				r_error.append("%s:%d: '%s' is not a number" % [file_path, line_number, word])
				return null
			numbers.append(word.to_float())
		if numbers.size() != 6:
			r_error.append(
				"%s:%d: expected 6 numbers (x y z tx ty tz), found %d" % [file_path, line_number, numbers.size()]
			)
			return null
		path.add(Vector3(numbers[0], numbers[1], numbers[2]), Vector3(numbers[3], numbers[4], numbers[5]))
	if path.eyes.size() < 2:
		r_error.append("%s: a path needs at least 2 waypoints" % file_path)
		return null
	return path


func add(eye: Vector3, target: Vector3) -> void:
	eyes.append(eye)
	targets.append(target)


## The camera transform at [param t] in [0, 1].
func sample(t: float) -> Transform3D:
	var segments: int = eyes.size() - 1
	var scaled: float = clampf(t, 0.0, 1.0) * segments
	var index: int = mini(int(scaled), segments - 1)
	var local: float = smoothstep(0.0, 1.0, scaled - index)
	var eye: Vector3 = eyes[index].lerp(eyes[index + 1], local)
	var target: Vector3 = targets[index].lerp(targets[index + 1], local)
	return Transform3D.IDENTITY.looking_at(target - eye, Vector3.UP).translated(eye)
