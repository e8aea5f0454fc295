extends SceneTree
## Runs the drop-in project's main scene (which has no code of its own) and checks that the field
## is built, drawn in several representations and swaying. Prints "dropin: ok" or what failed.


func _initialize() -> void:
	_check.call_deferred()


func _check() -> void:
	var scene: Node = (load("res://main.tscn") as PackedScene).instantiate()
	root.add_child(scene)
	var field: Node3D = scene.get_node("SunflowerField")
	for i: int in 10:
		await process_frame
	var problems: PackedStringArray = []
	var plants: int = field.call("get_plant_count")
	if plants != 1103:
		problems.append("expected 1103 plants, got %d" % plants)
	var counts: PackedInt32Array = field.call("get_lod_counts")
	if counts[0] + counts[1] + counts[2] == 0:
		problems.append("no plant near enough for a mesh: %s" % counts)
	var moved: bool = false
	var plant: int = -1
	for i: int in plants:
		if (field.call("get_plant_info", i) as Dictionary)["lod"] < 3:
			plant = i
			break
	if plant >= 0:
		var before: Transform3D = (field.call("get_plant_info", plant) as Dictionary)["parts"][2]
		for i: int in 10:
			await process_frame
		var after: Transform3D = (field.call("get_plant_info", plant) as Dictionary)["parts"][2]
		moved = not before.is_equal_approx(after)
	if not moved:
		problems.append("the plants do not sway")
	print("dropin: %d plants, per level %s" % [plants, counts])
	print("dropin: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	quit(0 if problems.is_empty() else 1)
