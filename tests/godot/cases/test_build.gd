extends TestCase
## Background builds: a large map is read on a worker thread and its nodes are made over several
## frames while the previous field stays drawn; progress is reported (also by the editor's progress
## bar) and ends in one field_built; a bad large map leaves the field as it was.

const FarTileTable: GDScript = preload("res://addons/sunflower_field/runtime/far_tile_table.gd")
const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
const DEMO_MAP: SunflowerFieldMap = preload("res://fields/demo.field")
const ProgressBarScript: GDScript = preload("res://addons/sunflower_field/editor/build_progress_bar.gd")

var field: SunflowerField
var progress: Array[float] = []
var built: Array[int] = []
var errors: Array[String] = []


func before_each() -> void:
	field = SunflowerField.new()
	field.name = "BigField"
	tree.root.add_child(field)
	field.map = DEMO_MAP
	field.advance(0.0)
	field.build_progress.connect(func(value: float) -> void: progress.append(value))
	field.field_built.connect(func(plants: int) -> void: built.append(plants))
	field.map_error.connect(func(message: String) -> void: errors.append(message))
	progress.clear()
	built.clear()
	errors.clear()


func after_each() -> void:
	if is_instance_valid(field):
		field.free()


## A square map of [param side] × [param side] sunflowers, [param bad_row] (if ≥ 0) holding a '?'.
func _square_map(side: int, bad_row: int = -1) -> SunflowerFieldMap:
	var lines: PackedStringArray = ["%d %d" % [side, side]]
	for row: int in side:
		lines.append("*".repeat(side - 1) + ("?" if row == bad_row else "*"))
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "user://square_%d.field" % side
	field_map.text = "\n".join(lines).to_utf8_buffer()
	return field_map


## The internal MultiMesh nodes of the field that are drawn now.
func _visible_multimesh_nodes() -> int:
	var count: int = 0
	for node: Node in field.get_children(true):
		if node is MultiMeshInstance3D and (node as MultiMeshInstance3D).visible:
			count += 1
	return count


func test_a_large_map_builds_over_frames_while_the_old_field_is_drawn() -> void:
	var old_nodes: int = _visible_multimesh_nodes()
	set_project_setting("sunflower_field/performance/build_budget_ms", 1.0)
	field.map = _square_map(600)
	await frames(2)
	check(field.is_building(), "a 360 000-plant map builds in the background")
	check(SunflowerField.get_building_fields().has(field), "the field is listed as building")
	var frames_seen: int = 0
	while field.is_building() and frames_seen < 2000:
		check_eq(field.get_plant_count(), 1103, "the old field is the one counted during the build")
		if not check_eq(_visible_multimesh_nodes(), old_nodes, "only the old field's nodes are drawn"):
			break
		await frames(1)
		frames_seen += 1
	check(not field.is_building(), "the build completed (within 2000 frames)")
	check(frames_seen >= 3, "the build spread over several frames (%d)" % frames_seen)
	check_eq(built, [360000] as Array[int], "one field_built, with the new plant count")
	check_eq(field.get_plant_count(), 360000, "the new field is counted")
	# The sunflower is drawn whole: a node per mesh level and one of the near impostors, then the tiles.
	var expected_nodes: int = (
		SunflowerDrawing.MESH_LEVEL_COUNT + 1 + NativeField.new(field.get_simulation()).get_tile_count()
	)
	check_eq(field.get_child_count(true) - field.get_child_count(false), expected_nodes, "only the new nodes remain")
	check(progress.size() >= 3, "progress reported while building (%d times)" % progress.size())
	var monotonic: bool = true
	for i: int in range(1, progress.size()):
		monotonic = monotonic and progress[i] >= progress[i - 1]
	check(monotonic and progress[0] >= 0.0, "progress never goes back: %s" % str(progress.slice(0, 8)))
	check_eq(progress[-1], 1.0, "progress ends at 1")
	check(not SunflowerField.get_building_fields().has(field), "no longer listed as building")
	var stats: Dictionary = field.get_build_stats()
	check(stats["background"], "the stats say background")
	check(stats["frames"] >= 3, "the stats count the frames: %s" % stats)
	check(stats["longest_step_ms"] <= stats["main_thread_ms"], "no step is longer than the whole: %s" % stats)
	check(stats["total_ms"] >= stats["main_thread_ms"], "the build lasted at least its main-thread work: %s" % stats)


func test_a_bad_large_map_reports_its_place_after_the_worker_and_keeps_the_field() -> void:
	allow_error("square_400.field:252:400: unexpected '?'")
	field.map = _square_map(400, 250)
	await frames(2)
	await frames_until(func() -> bool: return not field.is_building(), 200)
	check_eq(progress, [0.0] as Array[float], "the bad map was read in the background, and went no further")
	check_eq(errors.size(), 1, "one map_error")
	check(errors.size() == 1 and errors[0].contains("square_400.field:252:400"), "file:line:column in %s" % str(errors))
	check_eq(built.size(), 0, "no field_built")
	check_eq(field.get_plant_count(), 1103, "the old field stays")
	check(
		" ".join(field._get_configuration_warnings()).contains("252:400"), "the configuration warning names the place"
	)


func test_blocking_paths_complete_the_build_at_once() -> void:
	field.map = _square_map(300)
	field.advance(0.0)
	check(not field.is_building(), "advance() completes a queued build")
	check_eq(field.get_plant_count(), 90000, "built by advance()")
	set_project_setting("sunflower_field/performance/background_build", false)
	field.map = _square_map(310)
	await frames(2)
	check(not field.is_building(), "background_build off: built in the frame it started")
	check_eq(field.get_plant_count(), 96100, "the second map")
	check_eq(field.get_build_stats()["background"], false, "stats say blocking")
	set_project_setting("sunflower_field/performance/background_build", true)
	set_project_setting("sunflower_field/performance/build_budget_ms", 1.0)
	field.map = _square_map(700)
	for i: int in 5:
		if not progress.is_empty():
			break
		await frames(1)
	check(progress.size() == 1 and field.is_building(), "background again, and still building: %s" % str(progress))
	field.finish_build()
	check(not field.is_building(), "finish_build() waits for it")
	check_eq(field.get_plant_count(), 490000, "the third map")


func test_the_progress_bar_shows_running_builds_only() -> void:
	var bar: Control = ProgressBarScript.new()
	tree.root.add_child(bar)
	bar.call("refresh")
	check(not bar.visible, "hidden while nothing builds")
	set_project_setting("sunflower_field/performance/build_budget_ms", 1.0)
	field.map = _square_map(500)
	var seen: Array[float] = []
	for i: int in 2000:
		await frames(1)
		if not field.is_building():
			break
		bar.call("refresh")
		check(bar.visible, "shown while building")
		seen.append(bar.call("get_percent"))
		check_near(seen[-1], 100.0 * field.get_build_progress(), 0.01, "the bar shows the field's progress (its step)")
		check(str(bar.call("get_text")).contains("BigField"), "names the field: %s" % bar.call("get_text"))
	bar.call("refresh")
	check(not bar.visible, "hidden once built")
	check(seen.size() >= 1, "the bar was seen during the build")
	bar.free()


func test_parameter_changes_during_a_build_reach_the_new_field() -> void:
	set_project_setting("sunflower_field/performance/build_budget_ms", 1.0)
	field.map = _square_map(600)
	await frames(2)
	while field.is_building() and field.get_build_progress() <= 0.1:
		await frames(1)
	check(
		field.is_building(),
		"some tile nodes are made, not all: %s %s" % [field.get_build_progress(), field.get_build_stats()]
	)
	field.max_draw_distance = 123.0
	field.lod_distances = PackedFloat32Array([5.0, 9.0, 18.0, 30.0])
	field.wind_power = 4.0
	await frames_until(func() -> bool: return not field.is_building(), 2000)
	# Each tile ends once its nearest plant may be past the draw distance (the engine measures to the
	# box's centre); its plants dither out one after another before that, in the impostor shader. A
	# merged tile's range begins where its nearest plant may be its level's, and its children's
	# nodes (and their shadow casters) have its node as visibility parent.
	var begins: Dictionary = {}  # node name → where its tile is shown from
	var parents: Dictionary = {}  # node name → its tile's parent's node name ("" for none)
	var simulation: NativeField = NativeField.new(field.get_simulation())
	for tile: int in simulation.get_tile_count():
		var parent: int = FarTileTable.new(simulation).parent(tile)
		var node_name: String = "FarTile%d" % FarTileTable.new(simulation).key(tile)
		begins[node_name] = FarTileTable.new(simulation).shown_from(tile)
		parents[node_name] = ("FarTile%d" % FarTileTable.new(simulation).key(parent) if parent >= 0 else "")
	check(begins.values().any(func(begin: float) -> bool: return begin > 0.0), "the field has merged tiles")
	var wrong_ranges: int = 0
	var wrong_parents: int = 0
	var impostor_material: ShaderMaterial = null
	for node: Node in field.get_children(true):
		var instance: MultiMeshInstance3D = node as MultiMeshInstance3D
		if instance and instance.name.begins_with("FarTile"):
			var end: float = 123.0 + 0.5 * instance.custom_aabb.size.length()
			var begin: float = begins.get(str(instance.name), -1.0)
			wrong_ranges += (
				0
				if instance.visibility_range_begin == begin and is_equal_approx(instance.visibility_range_end, end)
				else 1
			)
			for drawn: GeometryInstance3D in [instance, instance.get_child(0, true)]:
				var parent: Node = (
					null if drawn.visibility_parent.is_empty() else drawn.get_node(drawn.visibility_parent)
				)
				wrong_parents += 0 if (str(parent.name) if parent else "") == parents[str(instance.name)] else 1
			impostor_material = instance.multimesh.mesh.surface_get_material(0) as ShaderMaterial
	check_eq(wrong_ranges, 0, "every tile's range follows the draw distance set during the build")
	check_eq(wrong_parents, 0, "every tile's node and shadow caster hide where its parent tile is drawn")
	if check(impostor_material != null, "tiles draw the impostor material"):
		check_eq(impostor_material.get_shader_parameter("draw_distance"), 123.0, "the plants fade out at it")
		check_near(impostor_material.get_shader_parameter("draw_fade"), 12.3, 1e-4, "over its last tenth")
	check_eq(field.get_simulation().get_lod_counts().size(), 5, "the new simulation answers")
	# Wind set during the build moves the new field's plants (drawn as meshes to see them sway).
	field.force_lod = SunflowerField.Lod.MESH_1
	field.advance(0.0)
	var before: Transform3D = field.get_plant_info(0)["parts"][2]
	for i: int in 10:
		field.advance(0.1)
	var after: Transform3D = field.get_plant_info(0)["parts"][2]
	check(not after.is_equal_approx(before), "the wind set during the build sways the new field")


## Whether the impostor [param node]'s shadows are drawn: it casts none itself; its caster child,
## drawing from the same MultiMesh, casts them (and nothing else) while it is visible.
func _casts(node: Node) -> bool:
	var caster: GeometryInstance3D = node.get_child(0, true) as GeometryInstance3D
	if not check(caster != null and caster.name == "ShadowCaster", "%s has a shadow caster" % node.name):
		return false
	check_eq(
		(node as GeometryInstance3D).cast_shadow,
		GeometryInstance3D.SHADOW_CASTING_SETTING_OFF,
		"%s casts none itself" % node.name
	)
	check_eq(caster.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY, "its caster only casts")
	check(
		(caster as MultiMeshInstance3D).multimesh == (node as MultiMeshInstance3D).multimesh, "from the same MultiMesh"
	)
	return caster.visible


func test_a_small_change_of_a_large_map_makes_nodes_only_for_the_tiles_it_touched() -> void:
	field.chunk_size = 8.0
	field.map = _square_map(200)  # 100 × 100 m: 13 × 13 chunks of 8 m, 2 × 2 tiles of 8 × 8 chunks
	field.finish_build()
	var simulation: NativeField = NativeField.new(field.get_simulation())
	check_eq(simulation.get_chunk_count(), 169)
	check_eq(simulation.get_tile_count(), 5, "2 × 2 tiles and the merged tile over them")
	check_eq(field.get_build_stats().tiles_made, 5, "a new map makes every tile")
	# The same map with a 10 × 10-cell hole in the north-west corner: one tile touched, and the
	# merged tile that holds its plants too.
	var lines: PackedStringArray = field.map.text.get_string_from_utf8().split("\n")
	for row: int in range(1, 11):
		lines[row] = " ".repeat(10) + lines[row].substr(10)
	var holed: SunflowerFieldMap = SunflowerFieldMap.new()
	holed.source_path = "user://holed.field"
	holed.text = "\n".join(lines).to_utf8_buffer()
	field.map = holed
	field.finish_build()
	simulation = NativeField.new(field.get_simulation())
	var stats: Dictionary = field.get_build_stats()
	check_eq(field.get_plant_count(), 40000 - 100, "the hole's plants are gone")
	check_eq(stats.tiles_made, 2, "nodes made only for the touched tile and the merged one")
	check_eq(stats.tiles_kept, 3, "the others kept their nodes and buffers")
	# Every plant is still in exactly one level-0 buffer: the kept ones hold what the new field says;
	# the merged tile holds its share. Each node tells the shader its tile's place among the levels.
	var by_name: Dictionary = {}
	for tile: int in simulation.get_tile_count():
		by_name["FarTile%d" % FarTileTable.new(simulation).key(tile)] = tile
	var instances: PackedInt32Array = [0, 0]  # per level
	for node: Node in field.get_children(true):
		if not node.name.begins_with("FarTile"):
			continue
		var tile: int = by_name[str(node.name)]
		var level: int = FarTileTable.new(simulation).level(tile)
		var buffer: PackedFloat32Array = RenderingServer.multimesh_get_buffer(
			(node as MultiMeshInstance3D).multimesh.get_rid()
		)
		instances[level] += buffer.size() / SunflowerDrawing.FAR_FLOATS_PER_INSTANCE
		var merge: Vector4 = FarTileTable.new(simulation).merge(tile)
		check_eq(
			(node as GeometryInstance3D).get_instance_shader_parameter(&"tile_merge"),
			merge,
			"%s's place among the levels" % node.name
		)
		check_eq(merge.y, 1.0, "%s knows the field's top level" % node.name)
		# The merged level begins 200 m away, beyond the sun's shadows: it casts none.
		check_eq(_casts(node), level == 0, "%s's shadows" % node.name)
	check_eq(instances[0], field.get_plant_count(), "far buffers hold every plant once")
	# A new merge distance keeps every tile's node and buffer, and moves where the merged one begins.
	field.tile_merge_distance = 500.0
	field.finish_build()
	check_eq(field.get_build_stats().tiles_kept, 5, "the same tiles: all kept")
	simulation = NativeField.new(field.get_simulation())
	var merged: int = simulation.get_tile_count() - 1
	check_eq(FarTileTable.new(simulation).begin(merged), 500.0, "the merged tile begins at the new distance")
	var merged_node: GeometryInstance3D = null
	for node: Node in field.get_children(true):
		if node.name == "FarTile%d" % FarTileTable.new(simulation).key(merged):
			merged_node = node
	if check(merged_node != null, "the merged tile's node"):
		# From where all its plants are at least 500 m away.
		var reach: float = 0.5 * merged_node.custom_aabb.size.length()
		check_near(merged_node.visibility_range_begin, 500.0 + reach, 1e-3, "its node's range begins there")
		check_eq(merged_node.get_instance_shader_parameter(&"tile_merge").z, 500.0, "its shader knows the distance")
		check(not _casts(merged_node), "beyond the sun's shadows")
		# The tiles follow the sun's shadows from frame to frame, without a rebuild: a sun added whose
		# shadows reach past where the merged level begins lets it cast; shorter shadows, shadows
		# turned off or the sun gone take them away again.
		var sun: DirectionalLight3D = DirectionalLight3D.new()
		sun.shadow_enabled = true
		sun.directional_shadow_max_distance = 600.0
		tree.root.add_child(sun)
		await frames(2)
		check(_casts(merged_node), "a merged tile within a sun's 600 m of shadows casts them")
		sun.directional_shadow_max_distance = 300.0
		await frames(2)
		check(not _casts(merged_node), "the sun's shadows shortened to 300 m")
		sun.directional_shadow_max_distance = 600.0
		sun.shadow_enabled = false
		await frames(2)
		check(not _casts(merged_node), "the sun's shadows turned off")
		sun.shadow_enabled = true
		await frames(2)
		check(_casts(merged_node), "and on again")
		# A build with the sun there sets it from the start.
		field.tile_merge_distance = 450.0
		field.finish_build()
		for node: Node in field.get_children(true):
			if node.name == "FarTile%d" % FarTileTable.new(simulation).key(merged):
				merged_node = node
				check(_casts(merged_node), "a merged tile built within a sun's shadows casts them")
		sun.free()
		await frames(2)
		check(not _casts(merged_node), "the sun gone")
	var quarter: float = field.get_plant_count() / 4.0
	check_near(instances[1], quarter, 5.0 * sqrt(quarter), "the merged tile holds about a quarter")
