extends SceneTree
## Forest benchmark (numbers, not pass/fail; tools/bench.sh runs it under Xvfb, Vulkan lavapipe): a
## field of each Sapling test plant, as Plant from scene… makes it (cells as wide as the plant, the
## field three times as deep as its impostors begin), calm, seen from head height in it and from 40 m
## outside; for each view the median software frame time of FRAMES frames and the primitives drawn,
## with the plant's generated levels (thinned) and with every mesh level its level 1 (what a plant
## from a scene without variants drew before its levels thinned), the two alternating frame by frame.

const Maps: GDScript = preload("res://runner/maps.gd")
const PLANTS: PackedStringArray = ["maple_tree", "bottlebrush_bush"]
const FRAMES: int = 15


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	print("| field | view | frame ms, levels thinned | every level mesh 1 | primitives, thinned | every level mesh 1 |")
	print("|---|---|---|---|---|---|")
	for plant_name: String in PLANTS:
		var plant: SunflowerPlant = SunflowerPlant.from_scene(
			load("res://test_plants/%s.glb" % plant_name) as PackedScene
		)
		if plant == null or await plant.bake_impostors(root, "user://forest_bench", plant_name) != OK:
			print("| %s | the plant could not be made or baked | | | | |" % plant_name)
			continue
		var unthinned: SunflowerPlant = plant.duplicate() as SunflowerPlant
		unthinned.mesh_level_2 = plant.mesh_level_1.duplicate()
		unthinned.mesh_level_3 = plant.mesh_level_1.duplicate()
		var cell: float = maxf(0.5, plant.spacing_metres())
		var cells: int = ceili(
			maxf(60.0, 3.0 * plant.lod_scale_used() * SunflowerField.DEFAULT_LOD_DISTANCES[2]) / cell
		)
		var side: float = cells * cell
		var fields: Array[SunflowerField] = []
		for drawn: SunflowerPlant in [plant, unthinned]:
			var field: SunflowerField = SunflowerField.new()
			field.plant = drawn
			field.cell_size = cell
			field.map = Maps.filled(cells, cells, "user://forest_bench_%s.field" % plant_name)
			field.wind_power = 0.0
			root.add_child(field)
			field.finish_build()
			fields.append(field)
		var sun: DirectionalLight3D = DirectionalLight3D.new()
		sun.rotation_degrees = Vector3(-50.0, 30.0, 0.0)
		sun.shadow_enabled = true
		root.add_child(sun)
		var camera: Camera3D = Camera3D.new()
		camera.far = side * 4.0
		root.add_child(camera)
		camera.make_current()
		var middle: float = side * 0.5
		var views: Dictionary = {
			"head height inside": [Vector3(middle, 1.7, side * 0.75), Vector3(middle, 1.4, side * 0.75 - 25.0)],
			"40 m outside": [Vector3(middle, 1.7, side + 40.0), Vector3(middle, 1.0, side - 30.0)],
		}
		for view: String in views:
			camera.look_at_from_position(views[view][0], views[view][1])
			var times: Array[PackedFloat64Array] = [PackedFloat64Array(), PackedFloat64Array()]
			var primitives: PackedInt64Array = [0, 0]
			for frame: int in FRAMES + 2:
				for k: int in 2:
					fields[k].visible = true
					fields[1 - k].visible = false
					fields[k].advance(0.0)
					await process_frame  # the other field's last frame, and this one's first
					var start: int = Time.get_ticks_usec()
					await process_frame
					if frame >= 2:  # the first frames warm the shaders
						times[k].append((Time.get_ticks_usec() - start) / 1000.0)
						primitives[k] = int(Performance.get_monitor(Performance.RENDER_TOTAL_PRIMITIVES_IN_FRAME))
			print(
				(
					"| %s (%d × %d cells of %.2f m) | %s | %.1f | %.1f | %d | %d |"
					% [
						plant_name,
						cells,
						cells,
						cell,
						view,
						_median(times[0]),
						_median(times[1]),
						primitives[0],
						primitives[1]
					]
				)
			)
		for node: Node in fields + [sun, camera]:
			node.free()
	quit(0)


static func _median(values: PackedFloat64Array) -> float:
	var sorted: PackedFloat64Array = values.duplicate()
	sorted.sort()
	return sorted[sorted.size() / 2]
