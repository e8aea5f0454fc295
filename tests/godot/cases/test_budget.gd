extends TestCase
## The frame budget: the controller alone against a cost model, and a field at head height held to a
## cap on its near meshes' triangles in simulated frames (a 60th of a second each, headless).

const FieldBudget: GDScript = preload("res://addons/sunflower_field/runtime/field_budget.gd")
const ProjectKnobs: GDScript = preload("res://addons/sunflower_field/runtime/field_project_settings.gd")
const Maps: GDScript = preload("res://runner/maps.gd")
const Stage: GDScript = preload("res://runner/stage.gd")
const FRAME: float = 1.0 / 60.0

var field: SunflowerField
var camera: Camera3D


func before_each() -> void:
	camera = Camera3D.new()
	camera.name = "Eye"
	field = field_in_tree(camera, Maps.filled(120, 120, "user://budget.field"))
	field.wind_power = 0.0
	field.set_process(false)  # the test advances it
	camera.look_at_from_position(Vector3(30.0, 1.7, 45.0), Vector3(30.0, 1.4, 20.0))


func after_each() -> void:
	if is_instance_valid(field):
		field.free()
	if is_instance_valid(camera):
		camera.free()


## Advances the field [param seconds] in frames; the quality and the near triangles of each frame.
func _run(seconds: float) -> Array[PackedFloat32Array]:
	var qualities: PackedFloat32Array = []
	var costs: PackedFloat32Array = []
	for frame: int in roundi(seconds / FRAME):
		field.advance(FRAME)
		qualities.append(field.get_quality())
		costs.append(field.get_frame_stats()["near_primitives"])
	return [qualities, costs]


func test_a_plants_triangles_are_counted_per_mesh_level() -> void:
	var plant: SunflowerPlant = field.get_plant_types()[0]
	var counts: PackedInt32Array = [plant.triangle_count(0), plant.triangle_count(1), plant.triangle_count(2)]
	print("     the sunflower's triangles at mesh 1 / 2 / 3: %s" % counts)
	check(counts[0] > counts[1] and counts[1] > counts[2] and counts[2] > 0, "fewer at each level: %s" % counts)
	var box: BoxMesh = BoxMesh.new()
	var one: SunflowerPlant = SunflowerPlant.new()
	one.mesh_level_1 = [box, null, null]
	check_eq(one.triangle_count(0), 12, "a box is 12 triangles")
	check_eq(one.triangle_count(2), 12, "drawn at every level when only level 1 is set")


func test_the_field_holds_a_cap_on_its_triangles_and_settles() -> void:
	_run(1.0)
	var free_cost: int = field.get_frame_stats()["near_primitives"]
	check(free_cost > 1000000, "at head height the near meshes hold over a million triangles (%d)" % free_cost)
	check_eq(field.get_quality(), 1.0, "no budget: full quality")
	var cap: int = free_cost / 3
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, cap)
	var changes: Array[float] = []
	field.quality_changed.connect(func(quality: float) -> void: changes.append(quality))
	var reaching: Array[PackedFloat32Array] = _run(3.0)
	var last_cost: float = reaching[1][reaching[1].size() - 1]
	print(
		(
			"     cap %d (a third of %d): after 3 s quality %.3f, %d triangles, %d steps"
			% [cap, free_cost, field.get_quality(), last_cost, changes.size()]
		)
	)
	check(last_cost <= cap, "within the cap after 3 s: %d ≤ %d" % [last_cost, cap])
	check(
		field.get_quality() < 1.0 and field.get_quality() >= ProjectKnobs.budget_min_quality(), "the quality went down"
	)
	check(not changes.is_empty() and changes[-1] == field.get_quality(), "quality_changed told each step")
	var settled: Array[PackedFloat32Array] = _run(10.0)
	var low: float = Array(settled[0]).min()
	var high: float = Array(settled[0]).max()
	print("     the next 10 s: quality %.3f–%.3f, triangles at most %d" % [low, high, Array(settled[1]).max()])
	check(
		(high - low) / high < 0.05, "settled: the quality varies %.1f %% (under 5 %%)" % (100.0 * (high - low) / high)
	)
	check(Array(settled[1]).max() <= cap, "within the cap all the while")
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, int(field.get_frame_stats()["near_primitives"] * 0.8))
	_run(1.0)  # over it: a step down, and the quality that went over is a ceiling for 10 s
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, free_cost * 4)  # a new target forgets the ceiling
	var freed: Array[PackedFloat32Array] = _run(12.0)
	print("     the cap raised to 4× right after: quality %.3f after 12 s" % field.get_quality())
	check_eq(field.get_quality(), 1.0, "quality given back under a generous cap")
	var rise: PackedFloat32Array = freed[0]
	var largest: float = 0.0
	for i: int in range(1, rise.size()):
		largest = maxf(largest, rise[i] / rise[i - 1])
	check(largest <= 1.0 + FieldBudget.MAX_STEP_UP + 1e-4, "given back in small steps (largest ×%.3f)" % largest)
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, cap)
	_run(2.0)
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, 0)
	check_eq(field.get_quality(), 1.0, "no target: full quality at once")


## What the budget adds to a frame's main-thread time (printed, not checked: a measurement): the
## median of 600 updates at head height with a cap the field is within and without a budget.
func test_the_budget_costs_little_a_frame() -> void:
	_run(0.5)
	var medians: Array[float] = []
	for cap: int in [0, 100000000]:
		set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, cap)
		var times: Array[float] = []
		for frame: int in 600:
			var start: int = Time.get_ticks_usec()
			field.advance(FRAME)
			times.append(Time.get_ticks_usec() - start)
		times.sort()
		medians.append(times[300])
	print("     a frame's update, median of 600: %.0f µs without a budget, %.0f µs with one" % medians)
	check_eq(field.get_quality(), 1.0, "a cap the field is within keeps full quality")


func test_the_quality_scales_the_distances_the_plants_switch_at() -> void:
	_run(0.5)
	var full: PackedInt32Array = field.get_lod_counts()
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, 1)  # far below anything: down to the least quality
	set_project_setting(ProjectKnobs.BUDGET_MIN_QUALITY, 0.5)
	_run(3.0)
	check_eq(field.get_quality(), 0.5, "at the least quality")
	var halved: PackedInt32Array = field.get_lod_counts()
	print("     plants per level at quality 1: %s, at 0.5: %s" % [full, halved])
	check(halved[0] < full[0] and halved[0] > 0, "fewer plants at mesh 1")
	check(halved[0] + halved[1] + halved[2] < (full[0] + full[1] + full[2]) / 2, "under half as many meshes")
	set_project_setting(ProjectKnobs.BUDGET_MIN_QUALITY, 0.8)
	check_eq(field.get_quality(), 0.8, "raising the least quality lifts it at once")


## The controller alone, against a cost that grows with the square of the quality (the near
## meshes') and a fixed part, in steps of a 60th of a second: it reaches the target from 4× over
## within 3 s and then holds one quality; the GPU target works the same way.
## Every field drawn in one viewport shares one budget: the project's targets against their near
## triangles summed, stepped once a round (every field has told its triangles), so that two fields do
## not both answer one overrun (each did, with a budget of its own per node). Two fields of 600 000
## triangles under a cap of 1 000 000: each alone is within it, together they are over.
func test_fields_in_one_viewport_share_its_budget() -> void:
	set_project_setting(ProjectKnobs.BUDGET_PRIMITIVES, 1000000)
	var viewport: RID = RenderingServer.viewport_create()
	var shared: RefCounted = FieldBudget.governor_of(viewport)
	check(FieldBudget.governor_of(viewport) == shared, "one budget per viewport")
	check(FieldBudget.governor_of(tree.root.get_viewport_rid()) != shared, "another for another viewport")
	var first: RefCounted = RefCounted.new()  # two fields, as the budget tells them apart
	var second: RefCounted = RefCounted.new()
	var other: RID = RenderingServer.viewport_create()
	var alone: RefCounted = FieldBudget.governor_of(other)
	for round: int in 3:
		shared.step_shared(0.3, first, 600000, 0.0)
		shared.step_shared(0.3, second, 600000, 0.0)
		alone.step_shared(0.3, first, 600000, 0.0)
	check(shared.quality < 1.0, "together over the cap: it went down (%.3f)" % shared.quality)
	check_eq(alone.quality, 1.0, "one field alone is within it")
	var before: float = shared.quality
	shared.step_shared(0.3, first, 600000, 0.0)  # a new round: one step for the two fields' last round
	check(shared.quality < before, "a step a round (%.3f after %.3f)" % [shared.quality, before])
	var stepped: float = shared.quality
	shared.step_shared(0.3, second, 600000, 0.0)  # the same round: no second step
	check_eq(shared.quality, stepped, "one step a round, whichever field comes first")
	RenderingServer.free_rid(viewport)
	RenderingServer.free_rid(other)


func test_the_controller_reaches_a_target_and_holds_it() -> void:
	for target: String in ["primitives", "gpu"]:
		var budget: RefCounted = FieldBudget.new()
		if target == "primitives":
			budget.max_primitives = 1000000
		else:
			budget.gpu_ms = 4.0
		var full_cost: float = 4.0  # times the target, at quality 1
		var qualities: PackedFloat32Array = []
		var share: float = 0.0
		for frame: int in 600:
			var q: float = budget.quality
			share = 0.2 + (full_cost - 0.2) * q * q
			budget.step(FRAME, int(share * 1000000.0), share * 4.0)
			qualities.append(budget.quality)
			if frame == 179:
				check(
					budget.load_share() <= 1.0, "%s: within the target after 3 s (%.2f)" % [target, budget.load_share()]
				)
		var tail: Array = Array(qualities.slice(300))
		print(
			(
				"     %s: quality %.3f, load %.2f; the last 5 s %.3f–%.3f"
				% [target, budget.quality, share, tail.min(), tail.max()]
			)
		)
		check(tail.min() == tail.max(), "%s: one quality once settled" % target)
		check(share > 0.5, "%s: not far below the target (%.2f)" % [target, share])


## The viewport's GPU time at full quality (the target far above it), the middle two of four frames.
func _gpu_ms_at_full_quality() -> float:
	set_project_setting(ProjectKnobs.BUDGET_GPU_MS, 9000.0)  # measured, never reached
	await frames(2)  # (the viewport's GPU time is measured from the frame after a budget is set)
	var measured: Array = []
	for frame: int in 4:
		await frames(1)
		measured.append(field.get_frame_stats()["gpu_ms"])
	measured.sort()
	return (measured[1] + measured[2]) * 0.5


## The GPU-time target under lavapipe (its "GPU" is the CPU, so only convergence and stability are
## checked): real frames at head height, the sun's shadows off (so that the near meshes are most of
## the frame), the target 70 % of the field's GPU time at full quality.
func test_the_field_holds_a_gpu_time_target_on_the_software_renderer() -> void:
	field.free()
	camera.free()
	var stage: RefCounted = Stage.new(tree.root, 400.0, Vector3(30.0, 0.0, 30.0))
	for sun: Node in stage.root.find_children("*", "DirectionalLight3D", true, false):
		(sun as DirectionalLight3D).shadow_enabled = false
	field = SunflowerField.new()
	stage.root.add_child(field)
	field.map = Maps.filled(60, 60, "user://budget.field")  # 30 × 30 m: the near meshes are most of a frame
	field.wind_power = 0.0
	field.finish_build()
	camera = Camera3D.new()
	stage.root.add_child(camera)
	camera.make_current()
	camera.look_at_from_position(Vector3(15.0, 1.7, 25.0), Vector3(15.0, 1.4, 0.0))
	set_project_setting(ProjectKnobs.BUDGET_GPU_MS, 9000.0)
	await frames(4)  # the first frames compile shaders
	# The software "GPU" is the CPU: under the test command's second lane its time swings with that
	# lane's load. When the frames after the measurement all come in under the target (the load fell
	# meanwhile: 3 618 ms measured, then 2 359–2 527 ms for a target of 2 533 ms in one run), the
	# controller is right to keep full quality and the field is measured again, up to three times.
	var full_ms: float = 0.0
	var qualities: PackedFloat32Array = []
	var times: PackedFloat32Array = []
	for attempt: int in 3:
		full_ms = await _gpu_ms_at_full_quality()
		if not check(full_ms > 0.0, "the engine measures the viewport's GPU time (%.2f ms)" % full_ms):
			stage.root.free()
			return
		set_project_setting(ProjectKnobs.BUDGET_GPU_MS, full_ms * 0.7)
		qualities.clear()
		times.clear()
		# 30 frames: under the second lane, after 12 frames the quality was still stepping down to the
		# target once (0.830 → 0.723, at 1 818–2 039 ms for a target of 1 879 ms), and after 20 once
		# near the least quality (0.272–0.309), where the software GPU time hardly follows the quality;
		# alone it settles within 6.
		for frame: int in 30:
			await frames(1)
			qualities.append(field.get_quality())
			times.append(field.get_frame_stats()["gpu_ms"])
		if field.get_quality() < 1.0 or Array(times).max() > ProjectKnobs.budget_gpu_ms():
			break
		print("     every frame under the target (%.1f ms) at full quality: measured again" % Array(times).max())
	var last: Array = Array(qualities.slice(-6))
	var last_times: Array = Array(times.slice(-6))
	var figures: Array = [full_ms, ProjectKnobs.budget_gpu_ms(), qualities.size(), field.get_quality()]
	figures.append_array([last.min(), last.max(), last_times.min(), last_times.max()])
	var line: String = "     GPU time at full quality %.1f ms, target %.1f ms: after %d frames quality %.3f"
	print((line + " (last 6: %.3f–%.3f), %.1f–%.1f ms") % figures)
	check(field.get_quality() < 1.0, "the quality went down")
	# Settled: the quality follows the software GPU time, which under the second lane swings by about
	# ±10 % frame to frame (1 652–2 021 ms at quality 0.705–0.752 in one run, a 6 % spread); a
	# controller that oscillates or keeps falling moves it by more.
	check((last.max() - last.min()) / last.max() < 0.1, "settled over the last 6 frames")
	check(last_times.min() < full_ms * 0.8, "the GPU time fell (%.1f of %.1f ms)" % [last_times.min(), full_ms])
	stage.root.free()
