extends TestCase
## The demo scene: it loads, its keys change the wind as the thesis specifies, and plant parts can
## be replaced from glTF files (a good one and a bad one).

var demo: Node3D
var field: SunflowerField


func before_each() -> void:
	demo = (load("res://main.tscn") as PackedScene).instantiate() as Node3D
	tree.root.add_child(demo)
	field = demo.get_node("Field") as SunflowerField


func after_each() -> void:
	demo.free()


func _press(action: String) -> void:
	var key: InputEventKey = InputMap.action_get_events(action)[0].duplicate() as InputEventKey
	key.pressed = true
	Input.parse_input_event(key)
	Input.flush_buffered_events()
	await frames(1)
	key = key.duplicate() as InputEventKey
	key.pressed = false
	Input.parse_input_event(key)
	Input.flush_buffered_events()
	await frames(1)


func test_the_demo_scene_builds_the_demo_field() -> void:
	await frames(3)
	check_eq(field.get_plant_count(), 1103, "plants of fields/demo.field")
	var counts: PackedInt32Array = field.get_lod_counts()
	check(counts[0] + counts[1] + counts[2] > 0, "meshes near the start position: %s" % counts)


func test_the_hud_shows_the_frame_budget_and_the_quality_it_chose() -> void:
	await frames(3)
	var line: String = demo.call("_stats_text")
	check(not line.contains("budget"), "without a budget the HUD has no budget line")
	set_project_setting("sunflower_field/frame_budget/max_primitives", 1)  # below anything: the quality goes down
	field.set_process(false)
	for frame: int in 60:
		field.advance(1.0 / 60.0)
	line = demo.call("_stats_text")
	print("     " + line.get_slice("\n", line.count("\n")))
	check(line.contains("budget: ") and line.contains("/ 0.00 M near triangles"), "the cap in the HUD")
	check(field.get_quality() < 1.0, "the quality went down (%.2f)" % field.get_quality())
	check(line.contains("quality %.2f" % field.get_quality()), "the HUD shows the quality")


func test_the_keys_change_the_wind_as_the_thesis_says() -> void:
	await frames(2)
	var power: float = field.wind_power
	check_near(field.wind_increment, 0.1, 1e-6, "the increment starts at 0.1")
	await _press("wind_more")  # F2
	check_near(field.wind_power, power + 0.1, 1e-5, "F2 adds the increment")
	await _press("wind_less")  # F3
	await _press("wind_less")
	check_near(field.wind_power, power - 0.1, 1e-5, "F3 subtracts it")
	await _press("toggle_increment")  # F6
	check_near(field.wind_increment, 10.0, 1e-6, "F6 switches the increment to 10")
	await _press("wind_more")
	check_near(field.wind_power, power + 9.9, 1e-4, "F2 now adds 10")
	await _press("toggle_increment")
	check_near(field.wind_increment, 0.1, 1e-6, "F6 switches back to 0.1")
	var direction: Vector2 = field.wind_direction
	await _press("wind_direction_x")  # F4
	check(not field.wind_direction.is_equal_approx(direction), "F4 changes the direction")
	check_near(field.wind_direction.y, direction.normalized().y, 1e-5, "F4 leaves z alone")
	direction = field.wind_direction
	await _press("wind_direction_z")  # F5
	check_near(field.wind_direction.x, direction.x, 1e-5, "F5 leaves x alone")
	check(not is_equal_approx(field.wind_direction.y, direction.y), "F5 changes z")
	var events: Array[InputEvent] = InputMap.action_get_events("wind_more")
	check(
		events.size() > 0 and (events[0] as InputEventKey).physical_keycode == KEY_F2, "wind_more is F2 in the InputMap"
	)


func test_a_gltf_part_replaces_a_mesh_and_a_bad_file_is_refused() -> void:
	await frames(1)
	# A good part: a 1-unit box written as glTF.
	var holder: Node3D = Node3D.new()
	var box_instance: MeshInstance3D = MeshInstance3D.new()
	var box: BoxMesh = BoxMesh.new()
	box.size = Vector3(0.2, 1.0, 0.2)
	box_instance.mesh = box
	box_instance.position.y = 0.5
	holder.add_child(box_instance)
	box_instance.owner = holder
	var document: GLTFDocument = GLTFDocument.new()
	var state: GLTFState = GLTFState.new()
	check_eq(document.append_from_scene(holder, state), OK, "exporting the test part")
	var good: String = ProjectSettings.globalize_path("user://part_box.gltf")
	check_eq(document.write_to_filesystem(state, good), OK, "writing the test part")
	holder.free()
	var before: Mesh = field.get_part_mesh(0, SunflowerField.Part.HEAD)
	check_eq(demo.call("apply_part_argument", "1,head," + good), "", "a good glTF part is accepted")
	var after: Mesh = field.get_part_mesh(0, SunflowerField.Part.HEAD)
	check(after != before and after != null, "the head of mesh 1 was replaced")
	# A bad part: bytes that are not glTF.
	var bad: String = ProjectSettings.globalize_path("user://part_bad.glb")
	var file: FileAccess = FileAccess.open(bad, FileAccess.WRITE)
	file.store_string("this is not a glTF file")
	file.close()
	allow_error("modules/gltf/")  # the engine's own report of the unreadable file
	var message: String = demo.call("apply_part_argument", "2,bottom," + bad)
	check(message.contains(bad) and message.contains("not a readable glTF"), "bad file message: " + message)
	check(field.get_part_mesh(1, SunflowerField.Part.BOTTOM) is ArrayMesh, "the part stays the default")
	check(str(demo.call("apply_part_argument", "4,head," + good)).contains("LEVEL must be 1, 2 or 3"), "a bad level")
	check(str(demo.call("apply_part_argument", "1,leaf," + good)).contains("PART must be"), "a bad part")
	check(str(demo.call("apply_part_argument", "1,head,/no/such.glb")).contains("no such file"), "a missing file")


func test_the_map_menu_builds_a_large_map_in_the_background_with_progress_shown() -> void:
	await frames(2)
	var progress: Control = null
	for node: Node in demo.get_node("Hud").get_children():
		if node.name == "SunflowerBuildProgress":
			progress = node as Control
	check(progress != null and not progress.visible, "the HUD has a hidden build progress display")
	demo.call("load_map", "res://fields/large.field")
	var shown: bool = false
	for i: int in 600:
		await frames(1)
		shown = shown or (progress != null and progress.visible)
		check(field.get_plant_count() in [1103, 113000], "one of the two fields is drawn at any time")
		if not field.is_building():
			break
	check(shown, "the progress display showed while the large map built")
	check_eq(field.get_plant_count(), 113000, "the large field replaced the demo field")
	check(field.get_build_stats()["background"], "it built in the background")
	await frames(1)
	check(progress != null and not progress.visible, "the progress display hides again")


func test_walk_mode_puts_the_camera_among_the_flowers_and_they_part() -> void:
	await frames(3)
	var camera: FlyCamera = demo.get_node("Camera") as FlyCamera
	await _press("walk_mode")  # F8
	check(camera.walking, "F8 walks")
	check_near(camera.global_position.y, camera.walk_height, 1e-4, "at head height")
	camera.global_position = field.get_plant_info(600)["position"] + Vector3(0.2, camera.walk_height, 0.0)
	await frames(30)
	check(camera.is_in_group(field.pusher_group), "a low camera is a pusher")
	check(field.get_pushed_count() > 0, "the flowers around it are pushed (%d)" % field.get_pushed_count())
	await _press("walk_mode")
	check(not camera.walking, "F8 again flies")
	await _press("wind_model")  # F9
	check_eq(field.wind.model, SunflowerWind.Model.THESIS, "F9 switches to the thesis' wind")
	await _press("wind_model")
	check_eq(field.wind.model, SunflowerWind.Model.NATURAL, "and back")


func test_x_cuts_in_front_and_v_sows_there_the_path_too() -> void:
	await frames(3)
	var camera: FlyCamera = demo.get_node("Camera") as FlyCamera
	var plants: int = field.get_plant_count()
	# Over the path (columns 19 and 20 of the map are empty), looking along it.
	camera.global_transform = field.global_transform * Transform3D(Basis(), Vector3(10.0, 1.7, 12.0))
	await frames(1)
	var ahead: PackedInt32Array = field.play.get_cells_in_circle(Vector3(10.0, 0.0, 10.0), 1.5)
	var empty: int = 0
	for cell: int in ahead:
		empty += 1 if field.play.get_cell_state(cell)["plant_type"] < 0 else 0
	check(empty > 0, "the path lies ahead (%d empty cells of %d)" % [empty, ahead.size()])
	await _press("cut_plants")  # X
	check_eq(field.play.get_change_count(), ahead.size() - empty, "X cut every plant ahead")
	await _press("sow_plants")  # V
	for cell: int in ahead:
		var state: Dictionary = field.play.get_cell_state(cell)
		check_eq([state["plant_type"], state["state"]], [0, SunflowerFieldPlay.State.STANDING], "cell %d sown" % cell)
	check_eq(field.get_plant_count(), plants + empty, "the path's cells got plants")
	check_eq(field.play.get_change_count(), empty, "the cut plants stand as the map has them again")
	check(demo.call("_stats_text").contains("%d sown (V)" % ahead.size()), "the HUD counts what was sown")


func test_the_hills_map_stands_the_field_on_the_terrain() -> void:
	await frames(2)
	demo.call("load_map", "res://fields/hills.field")
	await frames_until(func() -> bool: return field.get_plant_count() == 55008 and not field.is_building(), 600)
	check_eq(field.get_plant_count(), 55008, "the hills field is built")
	# Two plant types: the map's 'r' cells are the addon's red sunflower (the demo's legend).
	var types: Array[SunflowerPlant] = field.get_plant_types()
	check_eq(types.size(), 2, "sunflowers and red sunflowers")
	if types.size() == 2:
		check_eq(types[1].name, "Red sunflower")
		var by_species: Array[PackedInt32Array] = field.get_lod_counts_by_species()
		var sums: Array[int] = []
		for counts: PackedInt32Array in by_species:
			var total: int = 0
			for count: int in counts:
				total += count
			sums.append(total)
		check_eq(sums, [47167, 7841], "plants per type")
	check_eq(field.ground_source, SunflowerField.GroundSource.COLLIDERS, "on the terrain's collision")
	check((demo.get_node("Hills") as Node3D).visible and not (demo.get_node("Ground") as Node3D).visible)
	var camera: FlyCamera = demo.get_node("Camera") as FlyCamera
	var worst: float = 0.0
	var lowest: float = INF
	var highest: float = -INF
	for i: int in range(0, 55008, 97):
		var root: Vector3 = field.to_global(field.get_plant_info(i)["position"])
		worst = maxf(worst, absf(root.y - camera.ground_below(root)))
		lowest = minf(lowest, root.y)
		highest = maxf(highest, root.y)
	check(worst < 0.001, "plants stand on the terrain (worst %.4f m)" % worst)
	check(highest - lowest > 3.0, "the terrain is hilly (%.1f m)" % (highest - lowest))
	await _press("walk_mode")  # F8 walks over the hills at head height
	check_near(camera.global_position.y - camera.ground_below(camera.global_position), camera.walk_height, 0.01)
	demo.call("load_map", "res://fields/demo.field")
	await frames_until(func() -> bool: return field.get_plant_count() == 1103 and not field.is_building(), 600)
	check_eq(field.ground_source, SunflowerField.GroundSource.FLAT, "the demo field lies flat again")
	check(not (demo.get_node("Hills") as Node3D).visible and (demo.get_node("Ground") as Node3D).visible)


## Atlases an earlier run baked, loaded again, come with what the bake measures on its views: a
## plant whose views are specks of a texel is thin from mip 0.5 and has a cut for each level, as it
## had when it was baked (loaded without them, the maple's far impostors lost a third of their cover).
func test_the_plants_maps_baked_atlases_load_with_their_measures() -> void:
	await frames(3)
	var views: Image = Image.create_empty(64, 64, false, Image.FORMAT_RGBA8)
	for y: int in range(0, 64, 2):
		for x: int in range(0, 64, 2):
			views.set_pixel(x, y, Color.WHITE)
	DirAccess.make_dir_recursive_absolute(DemoPlants.FOLDER)
	var baked_name: String = "measured_test_000000000000"
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		views.save_png(DemoPlants.FOLDER.path_join("%s_%s.png" % [baked_name, kind]))
	var plant: SunflowerPlant = SunflowerPlant.new()
	check(DemoPlants._load_baked(plant, baked_name), "loaded")
	check_near(plant.impostor_thin_from, 0.5, 0.01, "thin from where its views say")
	check_eq(plant.impostor_alpha_cuts.size(), 7, "a cut for each of its views' 7 mip levels")
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		DirAccess.remove_absolute(DemoPlants.FOLDER.path_join("%s_%s.png" % [baked_name, kind]))


## The Plants map's baked impostors are kept under a name that follows what the bake depends on:
## each test plant's is its own and the same from run to run, and a name nothing was baked under
## loads nothing (so a changed scene or baker is baked again, not drawn from old atlases).
func test_the_plants_maps_bakes_are_named_by_what_they_depend_on() -> void:
	await frames(3)  # the demo's start (its field's build) done before it is freed
	var names: Dictionary = {}
	for symbol: String in DemoPlants.SCENES:
		var code: String = DemoPlants._fingerprint(DemoPlants.SCENES[symbol])
		check_eq(DemoPlants._fingerprint(DemoPlants.SCENES[symbol]), code, "%s: the same code twice" % symbol)
		names[code] = symbol
	check_eq(names.size(), DemoPlants.SCENES.size(), "each plant's code is its own")
	check(not DemoPlants._load_baked(SunflowerPlant.new(), "never_baked_000000000000"), "nothing baked: nothing loaded")
