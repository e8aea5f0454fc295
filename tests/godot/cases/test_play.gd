extends TestCase
## Plants a game changes at run time (SunflowerField.play): pushers trample a trail that recovers,
## cells cut and given back, the events of each exactly once, colliders and queries that follow, and
## the save: a round trip cell for cell, written atomically, a corrupt or another map's refused.

const Maps: GDScript = preload("res://runner/maps.gd")

var field: SunflowerField
var observer: Node3D
var pusher: Node3D
var events: Array[Array] = []  # [signal name, cells or node, extra]


func before_each() -> void:
	events.clear()
	pusher = Node3D.new()
	pusher.name = "Pusher"
	pusher.position = Vector3(-3.0, 0.5, 5.0)  # off the map
	tree.root.add_child(pusher)
	observer = Node3D.new()
	observer.name = "Observer"
	observer.position = Vector3(5.0, 1.7, 5.0)
	field = field_in_tree(observer, Maps.filled(40, 20, "res://play_test.field"))  # 20 × 10 m
	field.wind_power = 0.0
	field.play.plants_trampled.connect(
		func(cells: PackedInt32Array, by: Node3D) -> void: events.append(["trampled", cells, by])
	)
	field.play.plants_changed.connect(
		func(cells: PackedInt32Array, change: int) -> void: events.append(["changed", cells, change])
	)
	field.play.plants_recovered.connect(
		func(cells: PackedInt32Array) -> void: events.append(["recovered", cells, null])
	)
	field.play.pusher_entered.connect(func(node: Node3D) -> void: events.append(["entered", node, null]))
	field.play.pusher_exited.connect(func(node: Node3D) -> void: events.append(["exited", node, null]))


func after_each() -> void:
	field.free()
	observer.free()
	pusher.free()


## Every cell named by events of [param kind], with repeats.
func _cells_of(kind: String) -> PackedInt32Array:
	var cells: PackedInt32Array = []
	for event: Array in events:
		if event[0] == kind:
			cells.append_array(event[1])
	return cells


func _count(kind: String) -> int:
	return events.filter(func(event: Array) -> bool: return event[0] == kind).size()


func _state(cell: int) -> int:
	return field.play.get_cell_state(cell)["state"]


func test_a_walking_pusher_tramples_a_trail_once_per_plant_which_recovers() -> void:
	var plant: SunflowerPlant = field.get_plant_types()[0]
	plant = plant.duplicate()
	plant.recover_after = 3.0
	field.plant = plant
	field.finish_build()
	field.trample_share = 0.6
	field.collision_reach = 3.0
	pusher.add_to_group(&"sunflower_pushers")
	for step: int in 120:  # across the field, 24 m in 2 s
		pusher.position.x = -2.0 + step * 0.2
		field.advance(1.0 / 60.0)
	var trampled: PackedInt32Array = _cells_of("trampled")
	check(trampled.size() > 40, "a trail was trampled (%d plants)" % trampled.size())
	var unique: Dictionary = {}
	for cell: int in trampled:
		unique[cell] = true
	check_eq(unique.size(), trampled.size(), "each plant told once")
	for event: Array in events:
		if event[0] == "trampled":
			check(event[2] == pusher, "the pusher named")
	var expected: Dictionary = {}  # every plant whose root the pusher's 0.6 × 0.6 m passed within
	for step: int in 120:
		var at: Vector3 = Vector3(-2.0 + step * 0.2, 0.0, 5.0)
		for near: int in field.get_simulation().get_plants_near(at, 0.36 - 0.01, false):
			expected[field.play.get_cell_of_plant(near)] = true
	for cell: int in expected:
		check(unique.has(cell), "cell %d within reach of the path was trampled" % cell)
	check_eq(_state(trampled[0]), SunflowerFieldPlay.State.FLATTENED, "a trampled plant lies")
	check_eq(_count("entered"), 1, "the pusher came over the field once")
	check_eq(_count("exited"), 1, "and left it once")
	# Flattened plants are no obstacles: no collider stands on them.
	var by_observer: int = field.get_simulation().get_plants_near(observer.position, 3.0, false).size()
	check(
		field.get_simulation().get_plants_near(observer.position, 3.0, true).size() < by_observer,
		"the trail passes the observer"
	)
	var colliders: int = field.get_collider_count()
	var standing_near: int = field.get_simulation().get_plants_near(pusher.position, 3.0, true).size()
	check_eq(
		colliders,
		(
			field.get_simulation().get_plants_near(observer.position, 3.0, true).size()
			+ standing_near
			- _shared(pusher.position, observer.position, 3.0)
		),
		"colliders only on standing plants"
	)
	events.clear()
	for i: int in 60:  # 1 s more: 2.x s since the first were trampled
		field.advance(1.0 / 60.0)
	check(_cells_of("recovered").size() < trampled.size(), "not all recovered yet at about 1 s after the last")
	for i: int in 150:
		field.advance(1.0 / 60.0)
	var recovered: PackedInt32Array = _cells_of("recovered")
	recovered.sort()
	trampled.sort()
	check_eq(recovered, trampled, "every trampled plant stood again after 3 s, told once")
	check_eq(_state(trampled[0]), SunflowerFieldPlay.State.STANDING, "standing")
	check_eq(field.play.get_change_count(), 0, "no change left")


## How many plants stand within [param reach] of both points.
func _shared(a: Vector3, b: Vector3, reach: float) -> int:
	var near_b: Dictionary = {}
	for plant: int in field.get_simulation().get_plants_near(b, reach, true):
		near_b[plant] = true
	var both: int = 0
	for plant: int in field.get_simulation().get_plants_near(a, reach, true):
		both += 1 if near_b.has(plant) else 0
	return both


func test_cut_plants_are_gone_from_queries_and_colliders_and_come_back() -> void:
	field.collision_reach = 2.0
	field.advance(1.0 / 60.0)
	var before: int = field.get_collider_count()
	var cells: PackedInt32Array = field.play.get_cells_in_circle(observer.position, 1.0)
	check(cells.size() >= 8, "cells around the observer (%d)" % cells.size())
	var near_plant: int = field.get_plant_at(observer.position, 0.6)
	check(near_plant >= 0, "a plant stands by the observer")
	var changed: PackedInt32Array = field.play.change_plants(cells, SunflowerFieldPlay.Change.CUT)
	check_eq(changed, cells, "every cell held a plant, now cut")
	check_eq(_count("changed"), 1, "one event")
	check_eq(events[0][2], SunflowerFieldPlay.Change.CUT, "a cut")
	check_eq(field.play.change_plants(cells, SunflowerFieldPlay.Change.CUT).size(), 0, "a second cut cuts nothing")
	check_eq(_count("changed"), 1, "and tells nothing")
	check_eq(field.get_plant_at(observer.position, 0.6), -1, "no plant found where they were cut")
	field.advance(1.0 / 60.0)
	check_eq(field.get_collider_count(), before - cells.size(), "their colliders went")
	check_eq(field.play.get_cell_of_plant(near_plant) in cells, true, "the plant by the observer was one of them")
	var state: Dictionary = field.play.get_cell_state(cells[0])
	check_eq([state["plant_type"], state["state"]], [0, SunflowerFieldPlay.State.CUT], "its plant type and state")
	check_near(state["since"], field.play.get_clock() - 1.0 / 60.0, 1e-4, "cut a frame ago on the field's clock")
	field.play.change_plants(cells, SunflowerFieldPlay.Change.REMOVE)
	check_eq(field.play.get_cell_state(cells[0])["state"], SunflowerFieldPlay.State.NONE, "removed: no plant")
	check_eq(field.play.get_cell_of_plant(near_plant), -1, "a removed plant has no cell")
	field.play.change_plants(cells, SunflowerFieldPlay.Change.RESTORE)
	field.advance(1.0 / 60.0)
	check_eq(field.get_plant_at(observer.position, 0.6), near_plant, "given back as the map has it")
	check_eq(field.get_collider_count(), before, "with its colliders")
	check_eq(field.play.get_change_count(), 0, "nothing differs from the map")
	allow_error("is not one of the map's")
	check_eq(
		field.play.change_plants(PackedInt32Array([cells[0], 800]), SunflowerFieldPlay.Change.CUT).size(),
		0,
		"a cell off the map is an error"
	)
	check_eq(_state(cells[0]), SunflowerFieldPlay.State.STANDING, "and nothing changed")


func test_a_save_loads_back_cell_for_cell_and_a_bad_one_changes_nothing() -> void:
	var cut: PackedInt32Array = field.play.get_cells_in_rect(Rect2(2.0, 2.0, 3.0, 2.0))
	var flat: PackedInt32Array = field.play.get_cells_in_circle(Vector3(12.0, 0.0, 6.0), 1.5)
	field.play.change_plants(cut, SunflowerFieldPlay.Change.CUT)
	field.advance(0.5)
	field.play.change_plants(flat, SunflowerFieldPlay.Change.FLATTEN)
	field.advance(0.25)
	var path: String = "user://play_test.changes"
	check_eq(field.play.save_changes_to_file(path), OK, "saved")
	check(not FileAccess.file_exists(path + SunflowerFieldPlay.PARTIAL_SUFFIX), "no partial file left")
	var states: Array[Dictionary] = []
	for cell: int in 800:
		states.append(field.play.get_cell_state(cell))
	var clock: float = field.play.get_clock()
	var count: int = field.play.get_change_count()
	check_eq(count, cut.size() + flat.size(), "what differs from the map")
	# A crash while writing the next save: its partial file holds half a save, the save stands.
	var saved: PackedByteArray = FileAccess.get_file_as_bytes(path)
	var partial: FileAccess = FileAccess.open(path + SunflowerFieldPlay.PARTIAL_SUFFIX, FileAccess.WRITE)
	partial.store_buffer(saved.slice(0, saved.size() / 2))
	partial.close()
	field.play.change_plants(field.play.get_cells_in_rect(Rect2(0, 0, 20, 10)), SunflowerFieldPlay.Change.RESTORE)
	field.play.change_plants(
		field.play.get_cells_in_circle(Vector3(3.0, 0.0, 8.0), 1.0), SunflowerFieldPlay.Change.REMOVE
	)
	field.advance(2.0)
	check_eq(field.play.load_changes_from_file(path), OK, "loaded")
	check_eq(field.play.get_clock(), clock, "the clock as saved")
	check_eq(field.play.get_change_count(), count, "as many changes")
	var equal: bool = true
	for cell: int in 800:
		equal = equal and field.play.get_cell_state(cell) == states[cell]
	check(equal, "every cell as saved")
	# A corrupt save and another map's: refused, naming why, nothing changed.
	var corrupt: PackedByteArray = saved.duplicate()
	corrupt[corrupt.size() / 2] ^= 0x10
	allow_error("cannot be loaded")
	check_eq(field.play.load_changes(corrupt), ERR_INVALID_DATA, "a corrupt save is refused")
	var other: SunflowerField = field_in_tree(Node3D.new(), Maps.filled(40, 21, "res://other.field"))
	check_eq(other.play.load_changes(saved), ERR_INVALID_DATA, "another map's save is refused")
	other.free()
	check_eq(field.play.get_change_count(), count, "nothing changed")
	check_eq(field.play.get_cell_state(cut[0]), states[cut[0]], "the cut cell as it was")
	# A crash between the rename's removing the save and placing the new one: the partial file is read.
	field.play.change_plants(cut, SunflowerFieldPlay.Change.RESTORE)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))
	partial = FileAccess.open(path + SunflowerFieldPlay.PARTIAL_SUFFIX, FileAccess.WRITE)
	partial.store_buffer(saved)
	partial.close()
	check_eq(field.play.load_changes_from_file(path), OK, "the whole partial file read in the save's place")
	check_eq(field.play.get_change_count(), count, "with every change")
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path + SunflowerFieldPlay.PARTIAL_SUFFIX))


func test_changes_stay_through_a_rebuild_of_the_same_map_and_go_with_another() -> void:
	var cells: PackedInt32Array = field.play.get_cells_in_circle(Vector3(8.0, 0.0, 5.0), 1.0)
	field.play.change_plants(cells, SunflowerFieldPlay.Change.CUT)
	field.seed = field.seed + 1  # a new layout of the same map
	field.finish_build()
	check_eq(field.play.get_change_count(), cells.size(), "kept through the rebuild")
	check_eq(_state(cells[0]), SunflowerFieldPlay.State.CUT, "the cell still cut")
	field.map = Maps.filled(41, 20, "res://play_test_2.field")
	field.finish_build()
	check_eq(field.play.get_change_count(), 0, "forgotten with another map")


## A 40 × 20 map (20 × 10 m) whose row 10 (z 5 to 5.5 m) is empty.
func _map_with_an_empty_row(path: String) -> SunflowerFieldMap:
	var field_map: SunflowerFieldMap = Maps.filled(40, 20, path)
	var lines: PackedStringArray = field_map.text.get_string_from_utf8().split("\n")
	lines[11] = ".".repeat(40)
	field_map.text = "\n".join(lines).to_utf8_buffer()
	return field_map


func test_plants_put_in_empty_cells_stand_there_found_by_queries_colliders_and_saves() -> void:
	var sown: Array[Array] = []
	field.play.plants_put.connect(func(cells: PackedInt32Array, type: int) -> void: sown.append([cells, type]))
	field.map = _map_with_an_empty_row("res://play_put.field")
	field.collision_reach = 2.0
	field.advance(1.0 / 60.0)
	var plants: int = field.get_plant_count()
	check_eq(plants, 40 * 19, "the row is empty")
	var colliders: int = field.get_collider_count()
	var cells: PackedInt32Array = field.play.get_cells_in_rect(Rect2(3.0, 5.0, 4.0, 0.5))  # 8 cells of row 10
	check_eq(cells.size(), 8, "eight cells of the empty row")
	var spot: Vector3 = Vector3(5.1, 0.0, 5.1)  # in cell (10, 10), by the observer
	check_eq(field.get_plant_at(spot, 0.2), -1, "no plant there yet")
	var put: PackedInt32Array = field.play.put_plants(cells, 0)
	check_eq(put, cells, "every cell given a plant")
	check_eq(sown.size(), 1, "told once")
	check_eq(sown[0], [cells, 0], "with the cells and the plant type")
	check_eq(field.play.put_plants(cells, 0).size(), 0, "a second put puts nothing")
	check_eq(sown.size(), 1, "and tells nothing")
	check_eq(field.get_plant_count(), plants + 8, "eight plants added, none laid out again")
	var found: int = field.get_plant_at(spot, 0.4)
	check(found >= plants, "the plant put is found where it stands (plant %d)" % found)
	check_eq(field.play.get_cell_of_plant(found), 10 * 40 + 10, "in its cell")
	var state: Dictionary = field.play.get_cell_state(10 * 40 + 10)
	check_eq([state["plant_type"], state["state"]], [0, SunflowerFieldPlay.State.STANDING], "standing, of type 0")
	var info: Dictionary = field.get_plant_info(found)
	check_near((info["position"] as Vector3).y, 0.0, 1e-5, "on the flat ground")
	check_eq(info["position"].x >= 5.0 and info["position"].x < 5.25, true, "in the first half of its cell")
	field.advance(1.0 / 60.0)
	check(field.get_collider_count() > colliders, "stalk colliders for the plants put near the observer")
	var bytes: PackedByteArray = field.play.save_changes()
	field.play.change_plants(cells, SunflowerFieldPlay.Change.RESTORE)
	field.advance(1.0 / 60.0)
	check_eq(field.get_plant_at(spot, 0.4), -1, "given back as the map has it: no plant")
	check_eq(field.get_collider_count(), colliders, "nor its collider")
	check_eq(field.play.load_changes(bytes), OK, "the save with the plants put loads")
	check_eq(field.play.get_cell_of_plant(field.get_plant_at(spot, 0.4)), 10 * 40 + 10, "and they stand again")
	allow_error("has no plant type 3")
	check_eq(field.play.put_plants(cells, 3).size(), 0, "a plant type the field does not grow is an error")


func test_a_plant_put_on_a_field_on_colliders_stands_on_the_collider() -> void:
	var body: StaticBody3D = StaticBody3D.new()
	var shape: CollisionShape3D = CollisionShape3D.new()
	var box: BoxShape3D = BoxShape3D.new()
	box.size = Vector3(40.0, 1.0, 40.0)
	shape.shape = box
	body.add_child(shape)
	body.position = Vector3(10.0, 0.2, 5.0)  # its top at 0.7 m
	tree.root.add_child(body)
	field.ground_source = SunflowerField.GroundSource.COLLIDERS
	field.map = _map_with_an_empty_row("res://play_put_colliders.field")
	check(await frames_until(func() -> bool: return not field.is_building(), 300) < 300, "built on the collider")
	var cell: int = 10 * 40 + 10
	check_eq(field.play.put_plants(PackedInt32Array([cell]), 0), PackedInt32Array([cell]), "a plant put")
	var found: int = field.get_plant_at(Vector3(5.1, 0.7, 5.1), 0.4)
	check(found >= 0, "it stands")
	if found >= 0:
		check_near((field.get_plant_info(found)["position"] as Vector3).y, 0.7, 1e-3, "on the collider's top")
	body.free()


func test_a_field_whose_map_has_no_plant_takes_plants_put() -> void:
	field.map = Maps.filled(20, 10, "res://play_empty.field", ".")
	field.advance(1.0 / 60.0)
	check_eq(field.get_plant_count(), 0, "no plant in the map")
	var cells: PackedInt32Array = field.play.get_cells_in_circle(Vector3(5.0, 0.0, 2.5), 1.0)
	check(cells.size() > 10, "cells by the observer (%d)" % cells.size())
	check_eq(field.play.put_plants(cells, 0), cells, "every cell sown")
	field.advance(1.0 / 60.0)
	check_eq(field.get_plant_count(), cells.size(), "the plants put are the field's")
	var counts: PackedInt32Array = field.get_lod_counts()
	check_eq(counts[0] + counts[1] + counts[2] + counts[3] + counts[4], cells.size(), "each drawn: %s" % counts)
	check(field.get_plant_at(Vector3(5.1, 0.0, 2.6), 0.5) >= 0, "and found where it stands")
