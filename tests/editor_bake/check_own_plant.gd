extends SceneTree
## After the editor baked res://my_plant.tres: runs own_plant_terrain.tscn (no code of its own: a
## HeightMapShape3D and a field on Colliders growing that plant) and checks the field grows the
## plant with its baked impostors, on the hills. Prints "own plant: ok" or what failed.


func _initialize() -> void:
	_check.call_deferred()


func _check() -> void:
	var scene: Node = (load("res://own_plant_terrain.tscn") as PackedScene).instantiate()
	root.add_child(scene)
	var field: Node3D = scene.get_node("SunflowerField")
	for i: int in 60:
		await process_frame
		if not field.call("is_building"):
			break
	var problems: PackedStringArray = []
	var plant: Resource = field.get("plant")
	if plant == null or plant.resource_path != "res://my_plant.tres":
		problems.append("the field does not grow my_plant.tres")
	var views: Texture2D = field.get("impostor_views")
	if views == null or views.resource_path != "res://my_plant_views.png":
		problems.append("the field's impostors do not show the baked atlas: %s" % views)
	var plants: int = field.call("get_plant_count")
	var highest: float = -INF
	for i: int in plants:
		highest = maxf(highest, (field.call("get_plant_info", i) as Dictionary)["position"].y)
	if plants != 1103 or highest < 1.0:
		problems.append("%d plants, highest root %.2f m: not the field on the hills" % [plants, highest])
	var counts: PackedInt32Array = field.call("get_lod_counts")
	print("own plant: %d plants on the hills, per level %s" % [plants, counts])
	print("own plant: " + ("ok" if problems.is_empty() else "; ".join(problems)))
	scene.free()
	await create_timer(3.0).timeout  # no pipeline left compiling at exit (godot#117064 deadlocks it)
	quit(0 if problems.is_empty() else 1)
