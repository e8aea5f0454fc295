extends SceneTree
## Checks the recording mode's outputs: godot --headless --script res://tests/cases/check_recording.gd
##   -- STATS.json SHOT.png FRAMES. Prints "recording: ok" or what is wrong; exit code 1 on failure.


func _initialize() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var problems: PackedStringArray = []
	var stats: Variant = JSON.parse_string(FileAccess.get_file_as_string(args[0]))
	if not (stats is Dictionary):
		problems.append("%s is not a JSON object" % args[0])
	else:
		var data: Dictionary = stats
		for key: String in [
			"plants", "frames", "frame_ms", "native_update_ms", "lod_counts_final", "engine", "renderer", "driver"
		]:
			if not data.has(key):
				problems.append("stats lack '%s'" % key)
		if data.get("plants", 0) != 1103.0:
			problems.append("stats: plants %s, expected 1103" % data.get("plants"))
		if data.get("frames", 0) != float(args[2].to_int() - 1):
			problems.append("stats: %s frames timed, expected %d" % [data.get("frames"), args[2].to_int() - 1])
		var counts: Array = data.get("lod_counts_final", [])
		var total: float = 0.0
		for c: Variant in counts:
			total += float(c)
		if counts.size() != 5 or total != 1103.0:
			problems.append("stats: LOD counts %s do not add up to 1103" % [counts])
	var image: Image = Image.load_from_file(args[1])
	if image == null or image.is_empty():
		problems.append("%s is not an image" % args[1])
	else:
		var yellow: int = 0
		var green: int = 0
		var samples: int = 0
		for y: int in range(0, image.get_height(), 3):
			for x: int in range(0, image.get_width(), 3):
				var c: Color = image.get_pixel(x, y)
				samples += 1
				yellow += 1 if (c.r > 0.55 and c.g > 0.42 and c.b < 0.45 * minf(c.r, c.g)) else 0
				green += 1 if (c.g > c.r * 1.1 and c.g > c.b * 1.3 and c.g > 0.12) else 0
		print(
			(
				"recording: %s, %d x %d, %.1f%% petal yellow, %.1f%% leaf green"
				% [args[1], image.get_width(), image.get_height(), 100.0 * yellow / samples, 100.0 * green / samples]
			)
		)
		# The flight ends beside the field, seeing most heads from the side and behind: with every plant
		# as mesh 1 the last frame is 0.6 % petal yellow and 3.4 % leaf green (the far levels, drawn
		# from the direction they are seen, show the same).
		if yellow < samples / 400:
			problems.append("the screenshot shows almost no sunflower yellow")
		if green < samples / 100:
			problems.append("the screenshot shows almost no leaf green")
	print("recording: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	quit(0 if problems.is_empty() else 1)
