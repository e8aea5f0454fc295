extends TestCase
## Bad input and odd lifecycles: every malformed map is refused with file, line and column while
## the field keeps what it had; bad values are rejected or clamped with a warning naming the
## property; adding, removing, re-parenting, duplicating and freeing leave nothing behind.

const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
const DEMO_MAP: SunflowerFieldMap = preload("res://fields/demo.field")
const LARGE_MAP: SunflowerFieldMap = preload("res://fields/large.field")

var field: SunflowerField


func before_each() -> void:
	field = SunflowerField.new()
	tree.root.add_child(field)
	field.map = DEMO_MAP
	field.advance(0.0)


func after_each() -> void:
	if is_instance_valid(field):
		field.free()


func _write(file_name: String, bytes: PackedByteArray) -> String:
	var path: String = "user://robustness/" + file_name
	DirAccess.make_dir_recursive_absolute("user://robustness")
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	file.store_buffer(bytes)
	file.close()
	return path


func test_every_malformed_map_is_refused_with_its_place_and_the_field_stays() -> void:
	var random: RandomNumberGenerator = RandomNumberGenerator.new()
	random.seed = 7
	var garbage: PackedByteArray = []
	for i: int in 4096:
		garbage.append(random.randi_range(0, 255))
	var huge_row: String = "*".repeat(2100) + "\n"
	var cases: Array[Array] = [
		["missing_header.field", "***\n***\n".to_utf8_buffer(), ":1:1: expected a whole number for COLUMNS"],
		["garbled_header.field", "4x3\n****\n".to_utf8_buffer(), ":1:2: expected a whole number for COLUMNS"],
		["zero.field", "0 3\n".to_utf8_buffer(), ":1:1: COLUMNS must be positive"],
		["negative.field", "3 -2\n".to_utf8_buffer(), ":1:3: ROWS must be positive"],
		["words.field", "wide tall\n".to_utf8_buffer(), ":1:1: expected a whole number"],
		["enormous.field", "100000 100000\n*\n".to_utf8_buffer(), ":1:1: a 100000 x 100000 map has"],
		["long_row.field", "3 1\n****\n".to_utf8_buffer(), ":2:4: row 1 is longer than the 3 columns"],
		["extra_rows.field", "3 1\n***\n***\n".to_utf8_buffer(), ":3:1: more rows than the 1"],
		["unknown.field", "3 1\n*x*\n".to_utf8_buffer(), ":2:2: unexpected 'x'"],
		["tab.field", "3 1\n*\t*\n".to_utf8_buffer(), ":2:2: unexpected tab character"],
		["nul.field", PackedByteArray([51, 32, 49, 10, 42, 0, 42, 10]), ":2:2: unexpected NUL byte"],
		["garbage.field", garbage, ":1:"],
		["empty.field", PackedByteArray(), ": the file is empty"],
		["huge.field", ("2100 2000\n" + huge_row.repeat(2000)).to_utf8_buffer(), "more than 4000000 sunflowers"],
	]
	var before: int = field.get_plant_count()
	var messages: Array[String] = []
	field.map_error.connect(func(message: String) -> void: messages.append(message))
	for entry: Array in cases:
		var path: String = _write(entry[0], entry[1])
		allow_error(entry[0])
		messages.clear()
		check_eq(field.load_map_file(path), ERR_PARSE_ERROR, entry[0])
		if check_eq(messages.size(), 1, entry[0] + ": map_error emitted once"):
			check(messages[0].begins_with(path) and messages[0].contains(entry[2]), "%s: %s" % [entry[0], messages[0]])
			check(
				" ".join(field._get_configuration_warnings()).contains(messages[0]),
				entry[0] + ": configuration warning"
			)
		check_eq(field.get_plant_count(), before, entry[0] + ": the previous field stays")
	field.max_plants = 5
	allow_error("six.field")
	check_eq(
		field.load_map_file(_write("six.field", "6 1\n******\n".to_utf8_buffer())), ERR_PARSE_ERROR, "max_plants guard"
	)
	check(messages.back().contains("more than 5 sunflowers"), "the guard says the limit: %s" % messages.back())


func test_accepted_oddities_load_correctly() -> void:
	var cases: Array[Array] = [
		["bom.field", PackedByteArray([0xEF, 0xBB, 0xBF]) + "2 1\n**\n".to_utf8_buffer(), 2],
		["crlf.field", "3 2\r\n***\r\n* *\r\n".to_utf8_buffer(), 5],
		["trailing_blank.field", "2 2\n**\n**\n\n\n   \n".to_utf8_buffer(), 4],
		["short_rows.field", "5 3\n*\n**\n".to_utf8_buffer(), 3],
		["comments.field", "# a field\n  # indented\n\n2 1\n*.\n".to_utf8_buffer(), 1],
	]
	for entry: Array in cases:
		check_eq(field.load_map_file(_write(entry[0], entry[1])), OK, entry[0])
		check_eq(field.get_plant_count(), entry[2], entry[0] + " plants")


func test_bad_values_are_rejected_or_clamped_with_a_warning() -> void:
	take_warnings()
	field.wind_power = NAN
	check_eq(field.wind_power, 0.0, "NaN power")
	check(warned("SunflowerWind.power: nan"), "NaN power warns")
	field.wind_power = INF
	check_eq(field.wind_power, 0.0, "infinite power")
	check(warned("SunflowerWind.power: inf"), "infinite power warns")
	field.wind_power = -3.0
	check_eq(field.wind_power, 0.0, "negative power")
	check(warned("outside 0–100"), "negative power warns")
	field.wind_direction = Vector2.ZERO
	check_eq(field.wind_direction, Vector2(1.0, 0.0), "a zero direction")
	check(warned("SunflowerWind.direction"), "zero direction warns")
	field.cell_size = 0.0
	check_eq(field.cell_size, 0.5, "zero cell size is rejected")
	check(warned("SunflowerField.cell_size"), "zero cell size warns")
	field.cell_size = -1.0
	check_eq(field.cell_size, 0.5, "negative cell size is rejected")
	field.impostor_shadows_from = 7
	check_eq(field.impostor_shadows_from, SunflowerField.Lod.SPRITE, "a level past Never is Never")
	check(warned("SunflowerField.impostor_shadows_from: 7"), "and warns")
	var knobs: GDScript = load("res://addons/sunflower_field/runtime/field_project_settings.gd")
	set_project_setting(knobs.BUDGET_GPU_MS, NAN)
	check_eq(knobs.budget_gpu_ms(), 0.0, "a NaN GPU budget in Project Settings keeps none")
	check(warned("sunflower_field/frame_budget/gpu_ms: nan is not a finite number"), "and warns, naming it")
	set_project_setting(knobs.BUDGET_PRIMITIVES, -5)
	check_eq(knobs.budget_primitives(), 0, "a negative cap is none")
	check(warned("sunflower_field/frame_budget/max_primitives"), "and warns")
	field.plant_height = NAN
	check_eq(field.plant_height, 2.0, "NaN plant height is rejected")
	check(warned("SunflowerPlant.height"), "bad height warns")
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.impostor_shadow_shift = NAN
	check_near(plant.impostor_shadow_shift, 0.03, 1e-6, "a NaN shadow shift is the default")
	check(warned("SunflowerPlant.impostor_shadow_shift: nan"), "a NaN shadow shift warns")
	plant.impostor_shadow_shift = 2.0
	check_eq(plant.impostor_shadow_shift, 0.5, "a shadow shift past its range is clamped")
	plant.impostor_emission_range = NAN
	check_eq(plant.impostor_emission_range, 8.0, "a NaN emission range is the default")
	check(warned("SunflowerPlant.impostor_emission_range: nan"), "a NaN emission range warns")
	plant.impostor_emission_range = 0.0
	check_eq(plant.impostor_emission_range, 1.0, "an emission range below 1 is clamped (no division by 0)")
	field.lod_distances = PackedFloat32Array([6.0, 5.0, 20.0, 25.0])
	check_eq(field.lod_distances, PackedFloat32Array([6.0, 10.0, 20.0, 25.0]), "decreasing distances are rejected")
	check(warned("distances must increase"), "decreasing distances warn")
	field.lod_distances = PackedFloat32Array([6.0, 10.0])
	check(warned("needs 4 distances"), "too few distances warn")
	field.set("part_meshes/mesh_1/head", Texture2D.new())
	check(warned("is not a Mesh"), "a non-mesh part warns")
	check(field.get_part_mesh(0, SunflowerField.Part.HEAD) == null, "the slot is left empty, no default part")
	field.impostor_views = null
	field.advance(0.016)
	check(warned("no impostor views texture"), "a missing texture warns")
	field.wind_power = 5.0
	for i: int in 5:
		field.advance(0.016)
	check_eq(field.get_plant_count(), 1103, "the field still works")


func test_no_observer_is_a_configuration_warning_and_no_crash() -> void:
	field.advance(0.1)
	check(" ".join(field._get_configuration_warnings()).contains("No observer"), "warning without a camera")
	field.observer = NodePath("../Nowhere")
	field.advance(0.1)
	check(
		" ".join(field._get_configuration_warnings()).contains("does not point to a Node3D"), "warning for a bad path"
	)


func test_lifecycles_leave_nothing_behind() -> void:
	field.free()
	var killer_script: GDScript = _frame_killer_script()
	# The first round warms engine caches up; the second must leave exactly what it found.
	await _lifecycle_round(killer_script)
	await frames(2)
	var objects_before: int = Performance.get_monitor(Performance.OBJECT_COUNT) as int
	var memory_before: int = RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_BUFFER_MEM_USED)
	await _lifecycle_round(killer_script)
	await frames(3)
	check_eq(Performance.get_monitor(Performance.OBJECT_COUNT) as int, objects_before, "objects after a round")
	var memory_after: int = RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_BUFFER_MEM_USED)
	check(memory_after <= memory_before, "GPU buffer memory back to %d bytes, is %d" % [memory_before, memory_after])


## Adds, removes, re-adds, re-parents, duplicates, swaps maps and frees a field mid-frame.
func _lifecycle_round(killer_script: GDScript) -> void:
	var holder: Node3D = Node3D.new()
	tree.root.add_child(holder)
	var other: Node3D = Node3D.new()
	tree.root.add_child(other)
	var subject: SunflowerField = SunflowerField.new()
	subject.map = DEMO_MAP
	holder.add_child(subject)
	await frames(2)
	check_eq(subject.get_plant_count(), 1103, "built when added")
	holder.remove_child(subject)
	await frames(1)
	holder.add_child(subject)
	await frames(2)
	check_eq(subject.get_plant_count(), 1103, "rebuilt when re-added")
	subject.reparent(other)
	await frames(2)
	check_eq(subject.get_plant_count(), 1103, "works after reparenting")
	var copy: SunflowerField = subject.duplicate() as SunflowerField
	other.add_child(copy)
	await frames(2)
	check_eq(copy.get_plant_count(), 1103, "a duplicate builds its own field")
	var internal: int = copy.get_child_count(true) - copy.get_child_count(false)
	# The sunflower is drawn whole: a node per mesh level and one of the near impostors, then the tiles.
	var expected: int = SunflowerDrawing.MESH_LEVEL_COUNT + 1 + NativeField.new(copy.get_simulation()).get_tile_count()
	check_eq(internal, expected, "the duplicate holds its own nodes only, not copies of the original's")
	subject.map = null
	await frames(1)
	check_eq(subject.get_plant_count(), 0, "no map, no field")
	subject.map = LARGE_MAP
	await frames(1)
	check(subject.is_building(), "a large map builds in the background")
	var waited: int = await frames_until(func() -> bool: return not subject.is_building(), 600)
	check(waited < 600, "the background build completed within 600 frames")
	check_eq(subject.get_plant_count(), 113000, "a map swap at run time")
	# Drop a background build half way by changing the map, then free a field while it builds.
	# (A slow frame gives a build up to 100 ms, which may finish it at once: then start another.)
	for attempt: int in 3:
		subject.map = DEMO_MAP.duplicate()
		subject.map = LARGE_MAP.duplicate()
		await frames(1)
		if subject.is_building():
			break
	check(subject.is_building(), "the second large map is building")
	subject.map = DEMO_MAP
	await frames(1)
	check(not subject.is_building(), "a map change drops the running build")
	check_eq(subject.get_plant_count(), 1103, "and the new map is built")
	copy.map = LARGE_MAP
	await frames(1)
	check(copy.is_building(), "the field about to be freed is building")
	# Free a field in the middle of a frame, from another node's _process.
	var killer: Node = Node.new()
	killer.set_script(killer_script)
	killer.set("victim", copy)
	tree.root.add_child(killer)
	await frames(3)
	check(not is_instance_valid(copy), "freed mid-frame")
	killer.free()
	holder.free()
	other.free()


func test_reloading_the_scene_rebuilds_the_field() -> void:
	var scene_root: Node3D = Node3D.new()
	var inner: SunflowerField = SunflowerField.new()
	inner.name = "Field"
	inner.map = DEMO_MAP
	inner.wind_power = 2.5
	scene_root.add_child(inner)
	inner.owner = scene_root
	var packed: PackedScene = PackedScene.new()
	check_eq(packed.pack(scene_root), OK, "packing")
	scene_root.free()
	var scene_path: String = "user://robustness_scene.tscn"
	check_eq(ResourceSaver.save(packed, scene_path), OK, "saving the scene")
	check_eq(tree.change_scene_to_file(scene_path), OK, "changing scene")
	await frames(3)
	var loaded: SunflowerField = tree.current_scene.get_node("Field") as SunflowerField
	check_eq(loaded.get_plant_count(), 1103, "built in the scene")
	check_near(loaded.wind_power, 2.5, 1e-6, "the wind was saved with the scene")
	var internal_saved: int = 0
	var instance: Node = packed.instantiate()
	for node: Node in instance.get_node("Field").get_children(true):
		internal_saved += 1 if node is MultiMeshInstance3D else 0
	instance.free()
	check_eq(internal_saved, 0, "the generated nodes are not saved in the user's scene")
	check_eq(tree.reload_current_scene(), OK, "reloading")
	await frames(3)
	check_eq((tree.current_scene.get_node("Field") as SunflowerField).get_plant_count(), 1103, "rebuilt after reload")
	tree.unload_current_scene()
	await frames(2)


func test_soak_10000_frames_with_jumps_wind_changes_and_map_swaps() -> void:
	var random: RandomNumberGenerator = RandomNumberGenerator.new()
	random.seed = 11
	var observer: Node3D = Node3D.new()
	observer.name = "SoakObserver"
	tree.root.add_child(observer)
	field.observer = field.get_path_to(observer)
	var maps: Array[SunflowerFieldMap] = [
		DEMO_MAP,
		SunflowerFieldMap.from_file(_write("soak_small.field", "10 10\n**********\n* * * * *\n".to_utf8_buffer())),
	]
	var memory_start: int = 0
	for frame: int in 10000:
		if frame % 37 == 0:
			observer.position = Vector3(
				random.randf_range(-30, 50), random.randf_range(0.5, 40), random.randf_range(-30, 50)
			)
		if frame % 101 == 0:
			field.wind_power = random.randf_range(0.0, 30.0)
			field.wind_direction = Vector2(random.randf_range(-1, 1), random.randf_range(-1, 1))
		if frame % 1000 == 500:
			field.map = maps[(frame / 1000) % 2]
		field.advance(1.0 / 60.0)
		if frame % 250 == 0:
			await frames(1)
		if frame == 999:
			memory_start = OS.get_static_memory_usage()
	var memory_end: int = OS.get_static_memory_usage()
	print("     soak memory: %.1f MB after 1 000 frames, %.1f MB after 10 000" % [memory_start / 1e6, memory_end / 1e6])
	check(memory_end < memory_start + 2_000_000, "memory stays flat (%d → %d bytes)" % [memory_start, memory_end])
	check(field.get_plant_count() > 0, "still a field")
	observer.free()


func _frame_killer_script() -> GDScript:
	var script: GDScript = GDScript.new()
	script.source_code = """extends Node
var victim: Node
func _process(_delta: float) -> void:
	if is_instance_valid(victim):
		victim.free()
"""
	script.reload()
	return script
