extends SceneTree
## The demo's play, restored: compares two pictures of one view of the demo field, one taken after
## restarting with --load-changes (a trail walked and the scythe swung in the run before), one
## without, and the two runs' logs:
##   godot --headless --path demo_project --script res://tests/cases/check_play.gd --
##     PLAIN.png LOADED.png SAVED.log LOADED.log
## Prints "play: ok" or what is wrong; exit code 1 on failure. (tools/test.sh makes the runs.)

## A pixel counts as changed when a channel differs by more than this.
const CHANGED: float = 0.12


func _initialize() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var plain: Image = Image.load_from_file(args[0]) if args.size() == 4 else null
	var loaded: Image = Image.load_from_file(args[1]) if args.size() == 4 else null
	if plain == null or loaded == null or plain.get_size() != loaded.get_size():
		print("play: the pictures cannot be read or differ in size: %s" % [args])
		quit(1)
		return
	var saved: int = _count(FileAccess.get_file_as_string(args[2]), "saved")
	var restored: int = _count(FileAccess.get_file_as_string(args[3]), "loaded")
	var changed: int = 0
	var ground: Array[int] = [0, 0]  # bare-ground pixels without the changes, with them
	for y: int in plain.get_height():
		for x: int in plain.get_width():
			var a: Color = plain.get_pixel(x, y)
			var b: Color = loaded.get_pixel(x, y)
			if maxf(absf(a.r - b.r), maxf(absf(a.g - b.g), absf(a.b - b.b))) > CHANGED:
				changed += 1
			ground[0] += 1 if _bare(a) else 0
			ground[1] += 1 if _bare(b) else 0
	var pixels: float = plain.get_width() * plain.get_height()
	print(
		(
			"play: %d changes saved, %d loaded; %.1f %% of the pixels changed; bare ground %.1f %% without, %.1f %% with them"
			% [saved, restored, 100.0 * changed / pixels, 100.0 * ground[0] / pixels, 100.0 * ground[1] / pixels]
		)
	)
	var problems: PackedStringArray = []
	if saved < 50:
		problems.append("the walk and the scythe changed few plants (%d)" % saved)
	if restored != saved:
		problems.append("the restart restored %d of the %d changes" % [restored, saved])
	# Measured (320 × 180 and 640 × 360 alike): the trail and three scythe cuts change 4.1 % of the picture
	# and bare 2.5 % more ground.
	if changed < 0.03 * pixels:
		problems.append("the restored field looks like the map's")
	if ground[1] < ground[0] + 0.01 * pixels:
		problems.append("the scythe's cuts show no ground")
	print("play: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	quit(0 if problems.is_empty() else 1)


## The number in a log's "demo: play: N changes <verb>" line, or -1.
static func _count(log: String, verb: String) -> int:
	for line: String in log.split("\n"):
		if line.begins_with("demo: play: ") and line.contains(" changes %s " % verb):
			return line.trim_prefix("demo: play: ").to_int()
	return -1


## The demo's bare ground: brown, red above green above blue.
static func _bare(color: Color) -> bool:
	return color.r > color.g + 0.03 and color.g > color.b and color.r < 0.7
