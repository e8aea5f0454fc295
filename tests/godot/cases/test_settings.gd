extends TestCase
## The settings path (field_settings.gd): the node's, its wind's and its plant types' settings reach
## the simulation drawn by their rows of the core's table, the core says what a change costs, and
## the driver keeps no copy of them (a field built meanwhile gets what the node holds).

const ProjectKnobs: GDScript = preload("res://addons/sunflower_field/runtime/field_project_settings.gd")

var field: SunflowerField
var observer: Node3D


func before_each() -> void:
	observer = Node3D.new()
	observer.name = "Observer"
	observer.position = Vector3(10.0, 1.7, 7.5)  # the middle of the demo field
	field = field_in_tree(observer, load("res://fields/demo.field") as SunflowerFieldMap)
	field.advance(0.3)


func after_each() -> void:
	field.free()
	observer.free()


## A change the next update takes (switch distances, the wind) reaches the field drawn: no new field.
func test_a_setting_the_next_update_takes_reaches_the_field_drawn_without_a_build() -> void:
	var simulation: RefCounted = field.get_simulation()
	var near: PackedInt32Array = field.get_lod_counts()
	check(near[0] > 100, "mesh 1 near the middle at first: %s" % near)
	field.lod_distances = PackedFloat32Array([0.5, 1.0, 2.0, 3.0])
	check(not field.is_building(), "no build for switch distances")
	field.advance(0.3)
	check(field.get_simulation() == simulation, "the same field drawn")
	var after: PackedInt32Array = field.get_lod_counts()
	check(after[0] < 5 and after[4] > near[4], "switch distances of 0.5–3 m: mostly billboards: %s" % after)
	var calm: SunflowerWind = SunflowerWind.new()
	calm.model = SunflowerWind.Model.THESIS  # (natural wind eases a change in over seconds)
	calm.power = 0.0
	field.wind = calm
	field.advance(0.3)
	check_near(field.get_simulation().get_wind_state()[2], 0.0, 1e-6, "calm: no sway amplitude")
	calm.power = 8.0
	field.advance(0.3)
	check(field.get_simulation().get_wind_state()[2] > 0.01, "a wind's change reaches the field drawn")
	check(field.get_simulation() == simulation, "still the same field")


## A change the layout depends on (the cell size, a plant type's variety) builds the field anew; the
## field drawn keeps its own until the new one replaces it.
func test_a_setting_the_layout_depends_on_builds_the_field_anew() -> void:
	var simulation: RefCounted = field.get_simulation()
	var before: Vector3 = field.get_plant_info(0)["position"]
	field.cell_size = 1.0
	check(field.is_building(), "a new cell size builds the field anew")
	check(field.get_simulation() == simulation, "the field drawn stays until then")
	check_eq(field.get_plant_info(0)["position"], before, "and keeps its layout")
	field.advance(0.0)
	check(field.get_simulation() != simulation, "a new field drawn")
	check_near(field.get_plant_info(0)["position"].x, before.x * 2.0, 1e-3, "the first plant at twice the distance")
	var grown: SunflowerPlant = SunflowerPlant.default_plant().duplicate()
	field.plant = grown
	field.advance(0.0)
	simulation = field.get_simulation()
	grown.recover_after = 5.0  # taken by the field drawn
	check(not field.is_building(), "a plant type's recovery needs no build")
	grown.yaw_range = 0.1
	check(field.is_building(), "its variety does")
	field.advance(0.0)
	check(field.get_simulation() != simulation, "built anew")


## A setting changed while a field builds in the background reaches that field once it is drawn,
## although the build began before (the driver reads the node; it keeps no copy).
func test_a_setting_changed_while_a_field_builds_reaches_it() -> void:
	set_project_setting("sunflower_field/performance/build_budget_ms", 1.0)
	var lines: PackedStringArray = ["400 400"]
	for row: int in 400:
		lines.append("*".repeat(400))
	var big: SunflowerFieldMap = SunflowerFieldMap.new()
	big.source_path = "user://settings_400.field"
	big.text = "\n".join(lines).to_utf8_buffer()
	field.map = big
	await frames_until(func() -> bool: return field.get_build_progress() > 0.0, 200)
	check(field.is_building(), "building in the background")
	field.lod_distances = PackedFloat32Array([0.5, 1.0, 2.0, 3.0])
	field.finish_build()
	field.advance(0.3)
	check_eq(field.get_plant_count(), 160000, "the new field")
	var counts: PackedInt32Array = field.get_lod_counts()
	check(counts[0] < 5, "the switch distances set during the build: %s" % counts)


## The frame budget's quality scales the switch distances in the core, and the core says where a type
## turns finer (what its impostor shadows follow).
func test_the_quality_scales_the_switch_distances_in_the_core() -> void:
	var simulation: RefCounted = field.get_simulation()
	var sprite: float = simulation.get_finer_distance(0, 2)
	check_near(
		sprite,
		(20.0 - 0.5) * SunflowerPlant.default_plant().lod_scale_used(),
		1e-3,
		"mesh 3 ↔ sprite less the hysteresis"
	)
	simulation.set_quality(0.5)
	check_near(
		simulation.get_finer_distance(0, 2),
		(10.0 - 0.5) * SunflowerPlant.default_plant().lod_scale_used(),
		1e-3,
		"at half quality"
	)
	simulation.set_quality(2.0)  # refused: the quality stays
	check_near(
		simulation.get_finer_distance(0, 2),
		(10.0 - 0.5) * SunflowerPlant.default_plant().lod_scale_used(),
		1e-3,
		"kept"
	)


## The machine-wide settings live in Project Settings (field_project_settings.gd): a field takes
## their changes at run time, a bad value is warned about naming the setting, and a scene saved with
## one of them as a node property loads with a warning saying where it went.
func test_machine_wide_settings_live_in_project_settings() -> void:
	set_project_setting("sunflower_field/performance/worker_threads", 1)
	await frames(1)  # (Project Settings tell their changes at the end of the frame)
	check_eq(field.get_frame_stats()["worker_threads"], 1, "one thread, as the project says")
	set_project_setting("sunflower_field/performance/worker_threads", 2)
	await frames(1)
	check_eq(field.get_frame_stats()["worker_threads"], 2, "two, without a build")
	set_project_setting("sunflower_field/performance/worker_threads", 99)
	await frames(1)
	check_eq(field.get_frame_stats()["worker_threads"], 16, "held to the table's 16")
	check(warned("sunflower_field/performance/worker_threads: 99 is outside 0–16; using 16"), "and warned, naming it")
	set_project_setting("sunflower_field/performance/build_budget_ms", "fast")
	check_eq(ProjectKnobs.build_budget_ms(), 8.0, "a budget that is no number: the default")
	check(warned("sunflower_field/performance/build_budget_ms"), "and warned")
	var old: Node3D = SunflowerField.new()
	old.set("background_build", false)  # what a scene saved before carries
	check(warned("background_build is a project setting now (sunflower_field/performance/background_build"), "said")
	check_eq(old.get("background_build"), null, "and not kept on the node")
	old.free()
