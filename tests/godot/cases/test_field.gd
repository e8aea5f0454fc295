extends TestCase
## SunflowerField in a scene: layout against the map, LOD against the observer, buffers in the
## RenderingServer, wind, and the exactly-once invariant reconstructed from engine state.

const FarTileTable: GDScript = preload("res://addons/sunflower_field/runtime/far_tile_table.gd")
const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
## Floats per instance in the native MultiMesh buffers (transform, then colour).
const STRIDE: int = SunflowerDrawing.FLOATS_PER_INSTANCE

var field: SunflowerField
var observer: Node3D
## Far-tile records in a fade to the next level that leaves them out, along the last path checked.
var faded: int = 0


func before_each() -> void:
	observer = Node3D.new()
	observer.name = "Observer"
	field = field_in_tree(observer, load("res://fields/demo.field") as SunflowerFieldMap)


func after_each() -> void:
	field.free()
	observer.free()


func _map_cells() -> Dictionary:
	# The demo map read independently of the addon: cells holding '*'.
	var cells: Dictionary = {}
	var lines: PackedStringArray = FileAccess.get_file_as_string("res://fields/demo.field").split("\n")
	var row: int = -1
	for line: String in lines:
		if line.begins_with("#"):
			continue
		if row == -1:
			row = 0  # the header
			continue
		for column: int in line.length():
			if line[column] == "*":
				cells[Vector2i(column, row)] = true
		row += 1
	return cells


func test_plant_count_and_positions_match_the_map() -> void:
	var cells: Dictionary = _map_cells()
	check_eq(field.get_plant_count(), cells.size(), "plant count")
	var seen: Dictionary = {}
	for i: int in field.get_plant_count():
		var position: Vector3 = field.get_plant_info(i)["position"]
		var cell: Vector2i = Vector2i(floori(position.x / 0.5), floori(position.z / 0.5))
		check(cells.has(cell), "plant %d at %s is not on a '*' cell (%s)" % [i, position, cell])
		check(not seen.has(cell), "two plants on cell %s" % cell)
		seen[cell] = true
		var alpha: float = position.x / 0.5 - cell.x
		check(alpha >= 0.0 and alpha < 0.5, "plant %d: α = %s outside [0, 0.5)" % [i, alpha])
		check_near(position.z / 0.5 - cell.y, alpha, 1e-4, "plant %d: the same α on z" % i)


func test_lod_counts_follow_the_observer() -> void:
	observer.position = Vector3(10.0, 1.7, 7.5)  # the middle of the field
	field.advance(0.3)
	var near: PackedInt32Array = field.get_lod_counts()
	check(near[0] > 100, "mesh 1 plants near the middle: %s" % near)
	check_eq(_sum(near), field.get_plant_count(), "every plant counted once")
	observer.position = Vector3(10.0, 1.7, 200.0)
	field.advance(0.3)
	var far: PackedInt32Array = field.get_lod_counts()
	check_eq(far[4], field.get_plant_count(), "all billboards from 200 m: %s" % far)
	observer.position = Vector3(10.0, 1.7, -12.0)  # 12–27 m from the rows
	field.advance(0.3)
	var edge: PackedInt32Array = field.get_lod_counts()
	check(edge[0] == 0 and edge[1] == 0, "no near meshes from 12 m away: %s" % edge)
	check(edge[2] > 0 and edge[3] + edge[4] > 0, "mesh 3 and impostors from the edge: %s" % edge)
	for i: int in field.get_plant_count():
		var info: Dictionary = field.get_plant_info(i)
		var d: float = (info["position"] + Vector3(0, 1.067, 0)).distance_to(observer.position)
		if d < 9.5 or (d > 10.5 and d < 19.5):
			check_eq(info["lod"], 0 if d < 6.0 else 1 if d < 10.0 else 2, "plant %d at %.1f m" % [i, d])


## Near plants at mesh 1 and 2 cast their shadows from mesh 3: their nodes cast none, and each has a
## shadow-only child the library fills with the same instances, drawing the level-3 mesh. With
## cheap_shadows off, every level casts from its own mesh.
func test_near_plants_cast_shadows_from_mesh_3() -> void:
	field.impostor_shadows_from = SunflowerField.Lod.SPRITE  # every mesh level casts from a mesh
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.advance(0.3)
	var last: MultiMeshInstance3D = _node("Mesh3")
	check_eq(last.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "mesh 3 casts its own")
	check(last.get_child_count(true) == 0, "mesh 3 has no shadow twin")
	for level: int in 2:
		var node: MultiMeshInstance3D = _node("Mesh%d" % (level + 1))
		check_eq(node.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, node.name)
		var twin: MultiMeshInstance3D = node.get_child(0, true) as MultiMeshInstance3D
		if not check(twin != null, "%s has a shadow twin" % node.name):
			continue
		check_eq(twin.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY, "shadows only")
		check(twin.multimesh.mesh == last.multimesh.mesh, "%s's twin draws mesh 3" % node.name)
		var drawn: RID = node.multimesh.get_rid()
		var cast: RID = twin.multimesh.get_rid()
		var count: int = RenderingServer.multimesh_get_visible_instances(drawn)
		check(count > 0 or level == 1, "%s draws plants (%d)" % [node.name, count])
		check_eq(RenderingServer.multimesh_get_visible_instances(cast), count, "the same plants")
		check(
			RenderingServer.multimesh_get_buffer(cast) == RenderingServer.multimesh_get_buffer(drawn),
			"%s's twin has its instances" % node.name
		)
	field.cheap_shadows = false
	field.advance(0.1)
	for level: int in 3:
		var node: MultiMeshInstance3D = _node("Mesh%d" % (level + 1))
		check_eq(node.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "full: " + node.name)
		check_eq(node.get_child_count(true), 0, "full: no twin under " + node.name)


## With impostor_shadows_from at mesh 3, mesh-3 plants cast no mesh shadows, the nearer levels keep
## their twins, and the far tiles' casters draw the near plants from the switch to mesh 3 (less the
## hysteresis and a metre) on, at the plant type's scale; a plant type with impostor_shadows off and
## Never turn that off.
func test_near_plants_cast_shadows_from_their_impostors_from_a_level_on() -> void:
	check_eq(field.impostor_shadows_from, SunflowerField.Lod.MESH_3, "from mesh 3 by default")
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.advance(0.3)
	var last: MultiMeshInstance3D = _node("Mesh3")
	check_eq(last.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, "mesh 3 casts no mesh shadow")
	check_eq(last.get_child_count(true), 0, "and has no twin")
	for level: int in 2:
		check_eq(_node("Mesh%d" % (level + 1)).get_child_count(true), 1, "mesh %d keeps its twin" % (level + 1))
	var expected: float = (
		(field.lod_distances[1] - field.lod_hysteresis) * field.get_plant_types()[0].lod_scale_used() - 1.0
	)
	var casters: int = 0
	for node: MultiMeshInstance3D in _field_nodes():
		if not node.name.begins_with("FarTile"):
			continue
		var caster: MultiMeshInstance3D = node.get_child(0, true) as MultiMeshInstance3D
		var material: ShaderMaterial = caster.material_override as ShaderMaterial
		check_near(material.get_shader_parameter("near_shadow_from"), expected, 1e-4, node.name + "'s caster")
		casters += 1
	check(casters > 0, "far tiles' casters checked (%d)" % casters)
	# A plant type with its impostor shadows off casts from its meshes at every level, the field's
	# setting kept.
	var own: SunflowerPlant = SunflowerPlant.default_plant().duplicate() as SunflowerPlant
	own.impostor_shadows = false
	field.plant = own
	field.advance(0.1)
	check_eq(field.impostor_shadows_from, SunflowerField.Lod.MESH_3, "the field's setting stays")
	check_eq(_node("Mesh3").cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "its mesh 3 casts")
	for node: MultiMeshInstance3D in _field_nodes():
		if node.name.begins_with("FarTile"):
			var material: ShaderMaterial = (node.get_child(0, true) as MultiMeshInstance3D).material_override
			check_eq(material.get_shader_parameter("near_shadow_from"), -1.0, "its casters cast for no near plant")
	own.impostor_shadows = true
	field.advance(0.1)
	check_eq(_node("Mesh3").cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, "on again: from impostors")
	field.impostor_shadows_from = SunflowerField.Lod.SPRITE
	field.advance(0.1)
	check_eq(_node("Mesh3").cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "Never: mesh 3 casts")
	for node: MultiMeshInstance3D in _field_nodes():
		if node.name.begins_with("FarTile"):
			var material: ShaderMaterial = (node.get_child(0, true) as MultiMeshInstance3D).material_override
			check_eq(material.get_shader_parameter("near_shadow_from"), -1.0, "Never: " + node.name)


func test_buffers_reach_the_rendering_server() -> void:
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.advance(0.3)
	var simulation: NativeField = NativeField.new(field.get_simulation())
	# The built-in sunflower is drawn whole: one instance per mesh-1 plant, in the level's first bucket.
	var heads: MultiMeshInstance3D = _node("Mesh1")
	var rid: RID = heads.multimesh.get_rid()
	var count: int = simulation.get_bucket_instance_count(SunflowerDrawing.mesh_bucket(0, 0))
	var whole: int = SunflowerDrawing.WHOLE_FLOATS_PER_INSTANCE
	check(count > 100, "mesh-1 plants written: %d" % count)
	check_eq(simulation.get_bucket_instance_count(SunflowerDrawing.mesh_bucket(0, 2)), 0, "no instances per part")
	check_eq(RenderingServer.multimesh_get_visible_instances(rid), count, "visible instances")
	var buffer: PackedFloat32Array = RenderingServer.multimesh_get_buffer(rid)
	check(buffer.size() >= count * whole, "buffer holds the instances")
	# Each instance stands at some mesh-1 plant's root, at its size, as get_plant_info reports it.
	var heads_by_origin: Dictionary = {}
	var bottoms: Dictionary = {}
	for i: int in field.get_plant_count():
		var info: Dictionary = field.get_plant_info(i)
		if info["lod"] == 0:
			var bottom: Transform3D = info["parts"][0]
			heads_by_origin[_key(bottom.origin)] = info["parts"][2]
			bottoms[_key(bottom.origin)] = bottom
	check_eq(heads_by_origin.size(), count, "mesh-1 plants vs instances")
	for k: int in count:
		var origin: Vector3 = Vector3(buffer[k * whole + 3], buffer[k * whole + 7], buffer[k * whole + 11])
		var expected: Variant = bottoms.get(_key(origin))
		if not check(expected != null, "instance %d at %s is no plant's root" % [k, origin]):
			break
		var up: Vector3 = Vector3(buffer[k * whole + 1], buffer[k * whole + 5], buffer[k * whole + 9])
		check_near(up.length(), (expected as Transform3D).basis.y.length(), 1e-4, "size of instance %d" % k)
	# The renderer culls the bucket by the box of the plants it holds (and the node adds none of its
	# own): every head lies in it, and it is smaller than the field's.
	var box: AABB = RenderingServer.multimesh_get_aabb(rid)
	check(heads.custom_aabb == AABB(), "the bucket's node has no box of its own")
	for origin_key: Vector2i in heads_by_origin:
		var origin: Vector3 = (heads_by_origin[origin_key] as Transform3D).origin
		if not check(box.grow(1e-3).has_point(origin), "head at %s inside the bucket's box %s" % [origin, box]):
			break
	var field_box: AABB = FarTileTable.new(NativeField.new(field.get_simulation())).aabb(0)
	check(
		box.size.x * box.size.z < 0.5 * field_box.size.x * field_box.size.z,
		"%s smaller than the field's %s" % [box, field_box]
	)


func test_wind_moves_the_plants_and_calm_keeps_them_upright() -> void:
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.wind_power = 0.0
	for i: int in 40:  # natural wind eases a change in over half a second
		field.advance(0.05)
	var plant: int = _a_plant_at_lod(0)
	var before: Array = field.get_plant_info(plant)["parts"]
	for i: int in 20:
		field.advance(0.05)
	var after: Array = field.get_plant_info(plant)["parts"]
	for part: int in 3:
		check(after[part].is_equal_approx(before[part]), "calm: part %d moved" % part)
		check_near((after[part] as Transform3D).basis.y.normalized().y, 1.0, 1e-5, "calm: part %d upright" % part)
	field.wind_power = 4.0
	field.wind_direction = Vector2(0.0, 1.0)
	for i: int in 40:
		field.advance(0.05)
	var tips: Array[Vector3] = []
	for i: int in 12:
		field.advance(0.05)
		var head: Transform3D = field.get_plant_info(plant)["parts"][2]
		tips.append(head.origin)
	var moved: float = 0.0
	for i: int in range(1, tips.size()):
		moved += tips[i].distance_to(tips[i - 1])
		check_near(tips[i].x, tips[0].x, 1e-3, "the wind blows along z: the head keeps its x")
	check(moved > 0.01, "windy: the head moved %s m" % moved)


func test_every_plant_is_drawn_exactly_once_along_a_camera_path() -> void:
	# Reconstruct, from the RenderingServer's buffers and the visibility ranges, where each plant
	# is drawn; a plain Node3D observer has no frustum, so every plant must appear exactly once, or, in
	# the mesh 3 → impostor cross-fade, as mesh 3 and as an impostor whose shares (the instance
	# colours' alpha) add up to one.
	var path: Array[Vector3] = [
		Vector3(-40, 1.7, -40),
		Vector3(-8, 1.7, 7),
		Vector3(0, 1.7, 0),
		Vector3(5, 1.7, 3),
		Vector3(10, 1.7, 7.5),
		Vector3(14, 1.7, 12),
		Vector3(19.5, 1.7, 14.5),
		Vector3(26, 1.7, 20),
		Vector3(30, 30, 10),
		Vector3(10, 60, 7),
	]
	var counted: Vector2i = _check_drawn_once_along(path)
	check(counted.x > 0, "some plants were in the cross-fade along the path")
	check_eq(counted.y, 0, "no merged tile is drawn on the demo field's 16 m chunks")


func test_merged_far_tiles_draw_each_place_once_across_levels() -> void:
	# 1 m chunks make 8 m tiles, 16 m merged ones and one of 32 m over the demo field; with a 10 m
	# merge distance plants turn to them at 10 m and 20 m from the observer, fading over the half
	# octave before. Each plant is drawn at the level its distance gives it, or left out by that
	# level, by the one tile over it that the engine draws: the tiles' ranges and visibility parents
	# cut the tree of tiles so that each place is drawn by one tile, whose plants are all at its level
	# or a higher one.
	field.chunk_size = 1.0
	field.tile_merge_distance = 10.0
	field.lod_distances = PackedFloat32Array([1.0, 2.0, 3.0, 4.0])  # the far tiles draw nearly all
	field.finish_build()
	var simulation: NativeField = NativeField.new(field.get_simulation())
	var levels: Dictionary = {}
	for tile: int in simulation.get_tile_count():
		levels[FarTileTable.new(simulation).level(tile)] = true
	check_eq(levels.keys(), [0, 1, 2], "three tile levels")
	var path: Array[Vector3] = [Vector3(10, 1.7, 7), Vector3(-25, 1.7, 7), Vector3(-30, 20, -30), Vector3(-70, 10, 7)]
	var counted: Vector2i = _check_drawn_once_along(path)
	check(counted.y > 0, "merged tiles left plants out along the path")
	check(faded > 0, "plants the next level leaves out were fading along the path")
	field.tile_merge_distance = 0.0
	field.finish_build()
	check_eq(_check_drawn_once_along(path).y, 0, "without merging every plant is drawn")


## The far tiles' records reach the engine nearest the observer first and are written again as it
## moves: with 1 m chunks (8 m tiles) each tile's buffer holds the same records (roots and cells)
## before and after a walk across the field, some tiles' in a new order, and each tile's first record
## is nearer the observer than its last at both places.
func test_far_tiles_are_written_again_nearest_the_observer_first_as_it_moves() -> void:
	field.chunk_size = 1.0
	field.tile_merge_distance = 0.0
	var ends: Array[Vector3] = [Vector3(-30.0, 1.7, -30.0), Vector3(60.0, 1.7, 50.0)]
	var before: Dictionary = {}  # tile node name → its records' keys in order
	var reordered: int = 0
	for stop: int in ends.size():
		observer.position = ends[stop]
		if stop == 0:
			field.finish_build()  # the tiles written for the observer there
		for i: int in 60:  # one tile at a time, 1 024 plants an update
			field.advance(1.0 / 60.0)
		var nearer_first: int = 0
		var tiles: int = 0
		for node: MultiMeshInstance3D in _field_nodes():
			if not node.name.begins_with("FarTile"):
				continue
			var buffer: PackedFloat32Array = RenderingServer.multimesh_get_buffer(node.multimesh.get_rid())
			var far: int = SunflowerDrawing.FAR_FLOATS_PER_INSTANCE
			var count: int = buffer.size() / far
			if count < 2:
				continue
			tiles += 1
			var keys: Array[Vector3i] = []
			for k: int in count:
				var root: Vector3 = _root(buffer, k, true, far)
				keys.append(Vector3i(roundi(root.x * 1000.0), roundi(root.z * 1000.0), roundi(buffer[k * far + 6])))
			var first: Vector3 = _root(buffer, 0, true, far)
			var last: Vector3 = _root(buffer, count - 1, true, far)
			nearer_first += 1 if first.distance_to(ends[stop]) < last.distance_to(ends[stop]) else 0
			if stop == 0:
				before[node.name] = keys
			elif check(before.has(node.name), "%s was there before the walk" % node.name):
				reordered += 1 if keys != before[node.name] else 0
				var sorted_now: Array[Vector3i] = keys.duplicate()
				var sorted_then: Array[Vector3i] = (before[node.name] as Array[Vector3i]).duplicate()
				sorted_now.sort()
				sorted_then.sort()
				check(sorted_now == sorted_then, "%s holds the same records after the walk" % node.name)
		check(tiles >= 4, "far tiles to look at (%d)" % tiles)
		check_eq(nearer_first, tiles, "from %s each tile's first record is nearer than its last" % ends[stop])
	check(reordered > 0, "tiles were written again in a new order after the walk (%d)" % reordered)


## Checks, at each of [param path]'s stops, that every plant is drawn once (or twice in a cross-fade,
## shares adding up to one) or left out where a merged level stands in for it; returns the plants
## seen in cross-fades and those left out, summed over the stops. A far tile the engine draws (in its
## range, and its visibility parents not) draws each plant it holds at the level the simulation's
## choose_tile_level gives the plant, if that level keeps it (the impostor shader's rule); a plant
## given to a level below the tile's would vanish, as would one under no drawn tile.
func _check_drawn_once_along(path: Array[Vector3]) -> Vector2i:
	var positions: Dictionary = {}
	for i: int in field.get_plant_count():
		positions[_key(field.get_plant_info(i)["position"])] = i
	var simulation: NativeField = NativeField.new(field.get_simulation())
	var tile_of_node: Dictionary = {}  # node name → tile
	for tile: int in simulation.get_tile_count():
		tile_of_node["FarTile%d" % FarTileTable.new(simulation).key(tile)] = tile
	var crossfades: int = 0
	var left_out: int = 0
	faded = 0
	for stop: Vector3 in path:
		observer.position = stop
		field.advance(0.3)
		var drawn: PackedInt32Array = PackedInt32Array()
		drawn.resize(field.get_plant_count())
		var shares: PackedFloat32Array = PackedFloat32Array()
		shares.resize(field.get_plant_count())
		var fading: PackedInt32Array = PackedInt32Array()  # representations drawn in a cross-fade
		fading.resize(field.get_plant_count())
		var below: int = 0  # plants a drawn tile holds whose distance gives them a level below it
		for node: MultiMeshInstance3D in _field_nodes():
			var rid: RID = node.multimesh.get_rid()
			var instances: int = _drawn(node)
			var tile: bool = node.name.begins_with("FarTile")
			var shown: bool = node.visible and _in_visibility_range(node, stop) and not _hidden_by_parent(node, stop)
			if instances == 0 or not (shown or tile):
				continue
			if node.name.contains("Middle") or node.name.contains("Head"):
				continue  # one part per plant: the bottom part's origin is the plant's root
			var buffer: PackedFloat32Array = RenderingServer.multimesh_get_buffer(rid)
			# The format the library allocated, from the floats per instance: impostors are 8-float
			# records (a far tile's carry their chunk's cell, the near bucket's a share); near plants
			# drawn whole are one instance each, with custom data.
			var stride: int = buffer.size() / RenderingServer.multimesh_get_instance_count(rid)
			var compact: bool = stride == SunflowerDrawing.FAR_FLOATS_PER_INSTANCE
			check(
				stride in [STRIDE, SunflowerDrawing.WHOLE_FLOATS_PER_INSTANCE] or compact,
				"%s's records are of a known layout (%d floats)" % [node.name, stride]
			)
			# A tile skips the plants of the chunks its material's mask marks (the near buckets draw them).
			var mask: PackedByteArray = _mask_of(node) if tile else PackedByteArray()
			var merge: Vector4 = node.get_instance_shader_parameter(&"tile_merge") if tile else Vector4()
			if tile:
				var expected: Vector4 = FarTileTable.new(simulation).merge(tile_of_node[str(node.name)])
				check_eq(merge, expected, "%s's merge" % node.name)
			var far: int = SunflowerDrawing.FAR_FLOATS_PER_INSTANCE
			for k: int in instances:
				var root: Vector3 = _root(buffer, k, compact, stride)
				var share: float = 1.0
				if tile:
					if not shown:
						continue
					# The cell + 65 536 × the levels above the tile's that keep the plant (instance_buffer.h).
					var stored: int = roundi(buffer[k * far + 6])
					if mask[stored & 65535] != 0:
						continue
					var plant_level: int = int(merge.x) + (stored >> 16)
					# Its level from here (the top level keeps every plant beyond it).
					var choice: Vector2 = simulation.choose_tile_level(stop.distance_to(root))
					if int(choice.x) < int(merge.x):
						below += 1  # the shader leaves it out: its level's tile is not drawn
						continue
					if plant_level < int(choice.x):
						continue  # its level leaves it out
					# In the fade to the next level a plant it leaves out is drawn or not by its own
					# random (the widened others stand in): counted as drawn.
					faded += 1 if choice.y > 0.0 and plant_level == int(choice.x) else 0
				else:
					# The instance colour's alpha: the share of the pixels drawn (negative: the other
					# pixels, a coarser mesh fading in).
					share = absf(buffer[k * far + 6] if compact else buffer[k * stride + 15])
				var index: int = positions.get(_key(root), -1)
				if check(index >= 0, "%s instance %d at %s is no plant" % [node.name, k, root]):
					drawn[index] += 1
					shares[index] += share
					fading[index] += 1 if not tile and share < 1.0 else 0
		check_eq(below, 0, "from %s no drawn tile holds a plant given to a level below its own" % stop)
		var wrong: int = 0
		var crossfading: int = 0
		for i: int in drawn.size():
			var once: bool = drawn[i] == 1 and is_equal_approx(shares[i], 1.0)
			var complementary: bool = drawn[i] == 2 and fading[i] == 2 and absf(shares[i] - 1.0) < 1e-4
			crossfading += 1 if complementary else 0
			var position: Vector3 = field.get_plant_info(i)["position"]
			var level: int = int(simulation.choose_tile_level(stop.distance_to(position)).x)
			if drawn[i] == 0 and simulation.get_plant_tile_level(i) < level:
				left_out += 1  # a merged level draws where it stands, and leaves it out
				continue
			if not once and not complementary:
				wrong += 1
				if wrong <= 3:
					check(false, "from %s plant %d is drawn %d times, shares %.4f" % [stop, i, drawn[i], shares[i]])
		check_eq(wrong, 0, "from %s plants not drawn once (or twice complementarily)" % stop)
		crossfades += crossfading
		check_eq(_sum(field.get_lod_counts()), field.get_plant_count(), "LOD counts from %s" % stop)
	return Vector2i(crossfades, left_out)


func test_a_bad_map_keeps_the_field_and_reports_file_line_column() -> void:
	allow_error("bad_map.field:3:2")
	allow_error("no_such_map.field")
	var messages: Array[String] = []
	field.map_error.connect(func(message: String) -> void: messages.append(message))
	var before: int = field.get_plant_count()
	var path: String = "user://bad_map.field"
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	file.store_string("3 2\n***\n*x*\n")
	file.close()
	var error: Error = field.load_map_file(path)
	check_eq(error, ERR_PARSE_ERROR, "load_map_file result")
	check_eq(messages.size(), 1, "map_error emitted once")
	if messages.size() == 1:
		check(messages[0].begins_with(path + ":3:2: unexpected 'x'"), "message: " + messages[0])
	check_eq(field.get_plant_count(), before, "the old field stays")
	check(
		" ".join(field._get_configuration_warnings()).contains("bad_map.field:3:2"),
		"a configuration warning names the error"
	)
	check_eq(field.load_map_file("user://no_such_map.field"), ERR_FILE_CANT_OPEN, "missing file")
	check_eq(field.get_plant_count(), before, "the old field stays after a missing file")
	var good: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	good.store_string("3 2\n***\n* *\n")
	good.close()
	check_eq(field.load_map_file(path), OK, "a good map loads")
	check_eq(field.get_plant_count(), 5, "the new field")
	# The check before the build only parses; its figures are the built field's.
	check_eq([field.map.columns, field.map.rows, field.map.plant_count], [3, 2, 5], "the checked map's size and plants")


# --- helpers ---


func _sum(values: PackedInt32Array) -> int:
	var total: int = 0
	for v: int in values:
		total += v
	return total


## The active-chunk mask a far tile's shader reads (its material's texture), which must be the
## simulation's for the tile's species.
func _mask_of(node: MultiMeshInstance3D) -> PackedByteArray:
	var material: ShaderMaterial = node.multimesh.mesh.surface_get_material(0) as ShaderMaterial
	var texture: Texture2D = material.get_shader_parameter("active_chunks")
	var bytes: PackedByteArray = texture.get_image().get_data() if texture else PackedByteArray()
	check_eq(
		bytes, NativeField.new(field.get_simulation()).get_active_mask(0), "%s's mask is the simulation's" % node.name
	)
	return bytes


## The root of instance [param k] of a buffer: a 3D transform's origin, or a static chunk's compact
## record's (instance_buffer.h: floats 3, 7 and 2 of 8).
func _root(buffer: PackedFloat32Array, k: int, compact: bool, stride: int) -> Vector3:
	if compact:
		var far: int = SunflowerDrawing.FAR_FLOATS_PER_INSTANCE
		return Vector3(buffer[k * far + 3], buffer[k * far + 7], buffer[k * far + 2])
	return Vector3(buffer[k * stride + 3], buffer[k * stride + 7], buffer[k * stride + 11])


func _key(v: Vector3) -> Vector2i:
	return Vector2i(roundi(v.x * 1000.0), roundi(v.z * 1000.0))


func _field_nodes() -> Array[MultiMeshInstance3D]:
	var nodes: Array[MultiMeshInstance3D] = []
	for child: Node in field.get_children(true):
		if child is MultiMeshInstance3D:
			nodes.append(child)
	return nodes


func _node(node_name: String) -> MultiMeshInstance3D:
	for node: MultiMeshInstance3D in _field_nodes():
		if node.name == node_name:
			return node
	check(false, "no node " + node_name)
	return null


## The engine's rule: shown while begin ≤ distance ≤ end, the distance measured from the camera
## to the centre of the instance's world-space bounding box (0 disables a bound).
func _distance_to_box(node: GeometryInstance3D, camera: Vector3) -> float:
	return camera.distance_to(node.global_transform * node.custom_aabb.get_center())


## Whether a tile's node is hidden from [param camera] by its visibility parents: the engine draws a
## node only while the camera is nearer to its parent than the parent's range begins, and that
## parent drawn by the same rule (a hidden parent's node leaves the tile to its own range).
func _hidden_by_parent(node: GeometryInstance3D, camera: Vector3) -> bool:
	var parent: GeometryInstance3D = _visibility_parent_of(node)
	while parent and parent.visible:
		if not (
			parent.visibility_range_begin > 0.0 and _distance_to_box(parent, camera) < parent.visibility_range_begin
		):
			return true
		parent = _visibility_parent_of(parent)
	return false


static func _visibility_parent_of(node: GeometryInstance3D) -> GeometryInstance3D:
	if node.visibility_parent.is_empty():
		return null
	return node.get_node_or_null(node.visibility_parent) as GeometryInstance3D


func _in_visibility_range(node: GeometryInstance3D, camera: Vector3) -> bool:
	var distance: float = _distance_to_box(node, camera)
	if node.visibility_range_end > 0.0 and distance > node.visibility_range_end:
		return false
	return not (node.visibility_range_begin > 0.0 and distance < node.visibility_range_begin)


func _a_plant_at_lod(lod: int) -> int:
	for i: int in field.get_plant_count():
		if field.get_plant_info(i)["lod"] == lod:
			return i
	check(false, "no plant at LOD %d" % lod)
	return 0


## A field drawn part by part takes a plant of fewer parts (as Plant from scene… gives the field of a
## plant of several parts one of one): the slots it leaves empty draw no mesh, with no engine error
## (the renderer refuses a mesh of nothing under the instances drawn there: one error a slot and
## level before); given its plant back, the field draws every part again.
func test_a_plant_of_fewer_parts_takes_the_place_of_one_of_more() -> void:
	var three: SunflowerPlant = _box_plant(3)
	field.plant = three
	field.finish_build()
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.advance(0.3)
	check(not three.drawn_whole() and _drawn(_node("Mesh1Head")) > 0, "the third part's near plants are drawn")
	field.plant = _box_plant(1)
	field.advance(0.3)
	check(_node("Mesh1Head").multimesh.mesh == null, "the slot the plant leaves empty draws nothing")
	field.plant = three
	field.advance(0.3)
	check(_drawn(_node("Mesh1Head")) > 0, "given back, the third part's near plants are drawn again")


## A plant of [param parts] boxes at mesh level 1 (a box does not merge: drawn part by part).
static func _box_plant(parts: int) -> SunflowerPlant:
	var plant: SunflowerPlant = SunflowerPlant.new()
	var boxes: Array[Mesh] = []
	for part: int in parts:
		boxes.append(BoxMesh.new())
	plant.mesh_level_1 = boxes
	return plant


## The instances [param node]'s MultiMesh draws.
static func _drawn(node: MultiMeshInstance3D) -> int:
	var rid: RID = node.multimesh.get_rid()
	var visible: int = RenderingServer.multimesh_get_visible_instances(rid)
	return visible if visible >= 0 else RenderingServer.multimesh_get_instance_count(rid)


func test_legend_symbols_place_scenes_and_unknown_symbols_fail() -> void:
	var stone: Node3D = Node3D.new()
	stone.name = "Stone"
	var packed: PackedScene = PackedScene.new()
	packed.pack(stone)
	stone.free()
	field.legend = {"S": packed}
	var path: String = "user://legend.field"
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	file.store_string("4 2\n*S**\n**S*\n")
	file.close()
	check_eq(field.load_map_file(path), OK, "a map with legend symbols loads")
	check_eq(field.get_plant_count(), 6, "plants besides the stones")
	var stones: Array[Vector3] = []
	for child: Node in field.get_children(true):
		if child.name.begins_with("Stone"):
			stones.append((child as Node3D).position)
	check_eq(stones.size(), 2, "two stones placed")
	check(stones.has(Vector3(0.75, 0.0, 0.25)), "a stone at the centre of cell (1, 0): %s" % [stones])
	field.legend = {}
	allow_error("legend.field:2:2: unexpected 'S'")
	check_eq(field.load_map_file(path), ERR_PARSE_ERROR, "without the legend 'S' is an error")


## The user's path: symbols in a map file the editor imported with no option, a legend on the node.
## The import keeps any printable symbol; the legend gives them their meaning; a field without that
## legend reports the first symbol it lacks with the file, line and column.
func test_an_imported_map_uses_any_symbol_its_fields_legend_defines() -> void:
	var imported: SunflowerFieldMap = load("res://maps/stones.field") as SunflowerFieldMap
	if not check(imported != null, "the map with S and r imported without any import option"):
		return
	check_eq([imported.columns, imported.rows, imported.plant_count], [6, 3, 14], "the import counted it")
	var stone: Node3D = Node3D.new()
	stone.name = "Stone"
	var packed: PackedScene = PackedScene.new()
	packed.pack(stone)
	stone.free()
	var red: SunflowerPlant = load("res://addons/sunflower_field/plants/red_sunflower.tres")
	field.legend = {"S": packed, "r": red}
	field.map = imported
	field.finish_build()
	check_eq(field.get_plant_count(), 16, "14 sunflowers and 2 red ones")
	check_eq(field.get_plant_types().size(), 2, "two plant types")
	var stones: int = 0
	for child: Node in field.get_children(true):
		stones += 1 if child.name.begins_with("Stone") else 0
	check_eq(stones, 2, "two stones placed")
	var messages: Array[String] = []
	field.map_error.connect(func(message: String) -> void: messages.append(message))
	allow_error("res://maps/stones.field:3:2: unexpected 'S'")
	field.legend = {"r": red}
	field.finish_build()
	check_eq(messages.size(), 1, "map_error emitted once")
	var warnings: String = " ".join(field._get_configuration_warnings())
	check(
		warnings.contains("res://maps/stones.field:3:2: unexpected 'S'"), "the warning names the place: %s" % warnings
	)


func test_part_meshes_can_be_swapped_at_run_time() -> void:
	observer.position = Vector3(10.0, 1.7, 7.5)
	field.advance(0.3)
	var box: BoxMesh = BoxMesh.new()
	# A box cannot be merged with the other parts: the plant is drawn part by part from then on.
	field.set_part_mesh(0, SunflowerField.Part.HEAD, box)
	field.finish_build()
	check(_node("Mesh1Head").multimesh.mesh == box, "the head multimesh draws the new mesh")
	check(field.get_part_mesh(0, SunflowerField.Part.HEAD) == box, "get_part_mesh returns it")
	var sphere: SphereMesh = SphereMesh.new()
	field.set_part_mesh(0, SunflowerField.Part.HEAD, sphere)  # drawn as before: swapped in place
	check(_node("Mesh1Head").multimesh.mesh == sphere, "the head multimesh draws the other new mesh")
	field.set("part_meshes/mesh_1/head", null)
	field.finish_build()
	check(field.get_part_mesh(0, SunflowerField.Part.HEAD) == null, "null empties the slot: no default part")
	check(_node("Mesh1").multimesh.mesh.get_surface_count() == 1, "the bottom and middle are drawn whole")
	check(
		(
			_node("Mesh1").multimesh.mesh.get_faces().size()
			< SunflowerPlant.default_plant().whole_mesh(0).get_faces().size()
		),
		"without a head"
	)
	allow_error("out of range")
	field.set_part_mesh(3, 0, box)
	for level: int in 3:
		for part: int in 3:
			check(
				field.get_part_mesh(level, part) != box,
				"an out-of-range slot changes nothing (%d / %d)" % [level, part]
			)
	allow_error("is not a Mesh")
	field.set("part_meshes/mesh_2/bottom", Texture2D.new())
	check(field.get_part_mesh(1, 0) == null, "a non-mesh resource leaves the slot empty (no default part)")
