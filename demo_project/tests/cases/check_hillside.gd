extends SceneTree
## The Hillside's render test: checks a picture of fields/hillside.field taken by the demo's recording
## mode (its stats give the camera), that the track the rules keep clear shows bare ground and the
## meadows beside it show plants:
##   godot --headless --path demo_project --script res://tests/cases/check_hillside.gd -- STATS.json SHOT.png
## Prints "hillside: ok" or what is wrong; exit code 1 on failure, and saves SHOT_checked.png with the
## pixels read marked (track red, meadows blue). (tools/test.sh takes the picture with --view down60,
## 60 m straight above the middle.)

## Metres beside the track's centre line where the meadow samples are taken (the track keeps 1.5 m
## clear either side, and grass falls off over 1 m more).
const BESIDE: float = 7.0


func _initialize() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var stats: Variant = JSON.parse_string(FileAccess.get_file_as_string(args[0]))
	var image: Image = Image.load_from_file(args[1])
	if not (stats is Dictionary) or not (stats as Dictionary).has("camera_transform") or image == null:
		print("hillside: %s or %s cannot be read (the recording's stats and picture)" % [args[0], args[1]])
		quit(1)
		return
	var camera: Dictionary = stats
	var eye: Transform3D = str_to_var(camera["camera_transform"])
	var size: Vector2 = Vector2(image.get_width(), image.get_height())
	var projection: Projection = Projection.create_perspective(
		camera["camera_fov"], size.x / size.y, camera["camera_near"], camera["camera_far"]
	)
	var to_pixel: Callable = func(point: Vector3) -> Variant:
		var seen: Vector3 = eye.affine_inverse() * point
		var clip: Vector4 = projection * Vector4(seen.x, seen.y, seen.z, 1.0)
		if clip.w <= 0.0:
			return null
		var pixel: Vector2 = Vector2((clip.x / clip.w * 0.5 + 0.5) * size.x, (0.5 - clip.y / clip.w * 0.5) * size.y)
		return pixel if Rect2(Vector2(2, 2), size - Vector2(4, 4)).has_point(pixel) else null
	var marks: Image = image.duplicate()
	var heights: Image = DemoHills.height_image()
	var track: Curve3D = DemoHillside.track().curve
	var on_track: Array[int] = [0, 0]  # [plant pixels, pixels]
	var beside: Array[int] = [0, 0]
	var length: float = track.get_baked_length()
	for step: int in int(length / 0.5):
		var centre: Vector3 = track.sample_baked(step * 0.5)
		var ahead: Vector3 = track.sample_baked(minf(step * 0.5 + 0.5, length))
		var across: Vector3 = Vector3(-(ahead - centre).z, 0.0, (ahead - centre).x).normalized()
		if centre.x < 3.0 or centre.x > 117.0:
			continue
		_count(image, to_pixel.call(_on_ground(heights, centre)), on_track, marks, Color.RED)
		for side: float in [-BESIDE, BESIDE]:
			var point: Vector3 = centre + across * side
			if _track_distance(track, point) > BESIDE - 0.5 and point.x > 1.0 and point.x < 119.0:
				_count(image, to_pixel.call(_on_ground(heights, point)), beside, marks, Color.BLUE)
	marks.save_png(args[1].get_basename() + "_checked.png")
	var track_share: float = float(on_track[0]) / maxi(on_track[1], 1)
	var beside_share: float = float(beside[0]) / maxi(beside[1], 1)
	print(
		(
			"hillside: %s: plants on %.1f %% of %d track pixels, on %.1f %% of %d pixels %.0f m beside it"
			% [args[1], 100.0 * track_share, on_track[1], 100.0 * beside_share, beside[1], BESIDE]
		)
	)
	var problems: PackedStringArray = []
	if on_track[1] < 500 or beside[1] < 500:
		problems.append("the track is not in the picture (the view changed?)")
	# Measured on the committed map at 640 × 360: plants on 4.6 % of the track's pixels and 16.8 % of
	# the meadows' (thin grass seen from 60 m up); with 60 % of the track's cells given grass, 17.4 %.
	if beside_share < 0.1:
		problems.append("the meadows beside the track show few plants")
	if track_share > 0.5 * beside_share:
		problems.append("plants stand on the track the rules keep clear")
	print("hillside: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	quit(0 if problems.is_empty() else 1)


## The point on the hills' surface above or below [param point] (the field stands at the origin, the
## hills centred at 60, 60: their image's pixel x is the field's x + 20).
static func _on_ground(heights: Image, point: Vector3) -> Vector3:
	var at: Vector2 = Vector2(point.x + 20.0, point.z + 20.0)
	var low: Vector2i = Vector2i(floori(at.x), floori(at.y)).clamp(
		Vector2i.ZERO, Vector2i(DemoHills.SIDE - 2, DemoHills.SIDE - 2)
	)
	var f: Vector2 = at - Vector2(low)
	var red: float = lerpf(
		lerpf(heights.get_pixel(low.x, low.y).r, heights.get_pixel(low.x + 1, low.y).r, f.x),
		lerpf(heights.get_pixel(low.x, low.y + 1).r, heights.get_pixel(low.x + 1, low.y + 1).r, f.x),
		f.y
	)
	return Vector3(point.x, lerpf(DemoHills.LOW, DemoHills.HIGH, red), point.z)


## Counts the pixels of a 3 × 3 patch at [param pixel] (null: none) into [param counts]: how many show a
## plant (not the brown of bare ground: red over green over blue) and how many there are; marks them
## in [param marks] with [param mark].
static func _count(image: Image, pixel: Variant, counts: Array[int], marks: Image, mark: Color) -> void:
	if pixel == null:
		return
	for dy: int in range(-1, 2):
		for dx: int in range(-1, 2):
			var c: Color = image.get_pixel(int(pixel.x) + dx, int(pixel.y) + dy)
			var ground: bool = c.r >= c.g and c.g >= c.b and c.r - c.b > 0.06
			counts[0] += 0 if ground else 1
			counts[1] += 1
			marks.set_pixel(int(pixel.x) + dx, int(pixel.y) + dy, mark)


static func _track_distance(track: Curve3D, point: Vector3) -> float:
	var nearest: Vector3 = track.get_closest_point(point)
	return Vector2(point.x - nearest.x, point.z - nearest.z).length()
