extends SceneTree
## Runs the drop-in project's scenes (which have no code of their own) and checks that the field is
## built, drawn in several representations and swaying, and that in the terrain scene it stands on
## the hills' collision. Prints "dropin: ok" or what failed.


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
	scene.free()
	problems.append_array(await _check_terrain())
	print("dropin: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	await create_timer(3.0).timeout  # no pipeline left compiling at exit (godot#117064 deadlocks it)
	quit(0 if problems.is_empty() else 1)


## The terrain scene: a HeightMapShape3D and a field on Colliders; every root on the hills.
func _check_terrain() -> PackedStringArray:
	var scene: Node = (load("res://terrain.tscn") as PackedScene).instantiate()
	root.add_child(scene)
	var field: Node3D = scene.get_node("SunflowerField")
	for i: int in 60:
		await process_frame
		if not field.call("is_building"):
			break
	var problems: PackedStringArray = []
	var plants: int = field.call("get_plant_count")
	if plants != 1103:
		problems.append("terrain: expected 1103 plants, got %d" % plants)
	var space: PhysicsDirectSpaceState3D = (field as Node3D).get_world_3d().direct_space_state
	var worst: float = 0.0
	var highest: float = -INF
	for i: int in plants:
		var at: Vector3 = (field.call("get_plant_info", i) as Dictionary)["position"]
		var ray: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.create(
			at + Vector3.UP * 50.0, at + Vector3.DOWN * 50.0
		)
		var hit: Dictionary = space.intersect_ray(ray)
		worst = maxf(worst, absf(at.y - (hit["position"] as Vector3).y) if not hit.is_empty() else INF)
		highest = maxf(highest, at.y)
	if worst > 0.001 or highest < 1.0:
		problems.append("terrain: roots off the hills by up to %.3f m (highest %.2f m)" % [worst, highest])
	print("dropin: terrain scene, %d plants on the hills (highest root %.2f m)" % [plants, highest])
	scene.free()
	return problems
