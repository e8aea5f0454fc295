@tool
@icon("icons/sunflower_field_play.svg")
class_name SunflowerFieldPlay
extends RefCounted
## What a running game does to a [SunflowerField]'s plants: cut, flatten, remove and give back
## plants at run time, the events of it, regrowth, and a save that remembers.
##
## Every field has one, as [member SunflowerField.play]. Changes show at once at every level of
## detail, without a rebuild, and never change the map file; a rebuild of the same map keeps them, a
## new map forgets them. Cells are the map's (row × columns + column): find them with
## [method get_cells_in_circle], [method get_cells_in_rect], [method get_cell_at] or, for a plant a ray
## or a body hit, [method get_cell_of_plant]. The manual: [code]docs/play.md[/code].
## [codeblock]
## # A scythe: cut what stands within 1.5 m in front of the player.
## var centre: Vector3 = field.to_local(player.global_position - player.global_basis.z * 1.5)
## field.play.change_plants(field.play.get_cells_in_circle(centre, 1.5), SunflowerFieldPlay.Change.CUT)
## [/codeblock]

## Emitted when [param pusher] pushed over the standing plants of [param cells] this frame (see
## [member SunflowerField.trample_share]); each plant once each time it is trampled.
signal plants_trampled(cells: PackedInt32Array, pusher: Node3D)
## Emitted when [method change_plants] changed the plants of [param cells] by [param change] (a
## [enum Change]).
signal plants_changed(cells: PackedInt32Array, change: int)
## Emitted when [method put_plants] put plants of type [param plant_type] in [param cells].
signal plants_put(cells: PackedInt32Array, plant_type: int)
## Emitted when flattened or cut plants of [param cells] stood again by their plant type's regrowth
## ([member SunflowerPlant.recover_after], [member SunflowerPlant.regrow_after]).
signal plants_recovered(cells: PackedInt32Array)
## Emitted when a pusher (see [member SunflowerField.pusher_group]) comes over the field's map.
signal pusher_entered(pusher: Node3D)
## Emitted when a pusher leaves the field's map or its group.
signal pusher_exited(pusher: Node3D)

## What [method change_plants] does to a cell's plant.
enum Change {
	STAND,  ## A flattened or cut plant stands again.
	FLATTEN,  ## It lies bent (until its type's [member SunflowerPlant.recover_after], if any).
	CUT,  ## It is drawn nowhere (until its type's [member SunflowerPlant.regrow_after], if any).
	REMOVE,  ## No plant there any more; nothing grows back.
	RESTORE,  ## The cell as the map has it.
}
## A cell's plant after play ([method get_cell_state]).
enum State {
	STANDING,  ## It stands (as the map has it, or stood up again).
	FLATTENED,  ## It lies bent: trampled or flattened.
	CUT,  ## It is cut down.
	NONE,  ## The cell holds no plant: none in the map, or removed.
}

## A save file's suffix while it is written (renamed over the save once complete).
const PARTIAL_SUFFIX: String = ".partial"
const NativeField: GDScript = preload("native/native_field.gd")
const FieldGround: GDScript = preload("runtime/field_ground.gd")

var _field: Node3D
var _simulation: Callable  # the field's NativeField drawn now, or null
var _own_bodies: Callable  # the field's stalk colliders (Array[RID]), which rays for the ground miss
var _clock: float = 0.0
var _over_field: Dictionary = {}  # pusher node -> true while it stands over the field's map


func _init(field: Node3D, simulation: Callable, own_bodies: Callable) -> void:
	_field = field
	_simulation = simulation
	_own_bodies = own_bodies


## Applies [param change] to the plants of [param cells] at once; returns the cells whose plant
## changed (a cell with no plant, or in that state already, is not) and tells
## [signal plants_changed]. A cell that is not the map's is an error, and nothing changes.
func change_plants(cells: PackedInt32Array, change: Change) -> PackedInt32Array:
	var simulation: NativeField = _drawn()
	if simulation == null:
		return PackedInt32Array()
	var changed: PackedInt32Array = simulation.change_cells(cells, change, _clock)
	if not changed.is_empty():
		plants_changed.emit(changed, change)
	return changed


## Puts a standing plant of type [param plant_type] (its index in [method SunflowerField.get_plant_types])
## in each of [param cells], over what is there, at once; returns the cells changed and tells
## [signal plants_put]. The plant stands where the map would have stood one of that cell (its place,
## turn and size follow the cell), on the ground the field stands on; the map's own type puts the
## map's plant back. A cell or plant type that is not the field's is an error, and nothing changes; a
## cell with no ground under it (a hole, a ray that hits no collider) is left empty with a warning.
## [codeblock]
## # Sow a row of the second plant type along the field's tenth row of cells.
## var row: PackedInt32Array = field.play.get_cells_in_rect(Rect2(0.0, 4.5, 20.0, 0.5))
## field.play.put_plants(row, 1)
## [/codeblock]
func put_plants(cells: PackedInt32Array, plant_type: int) -> PackedInt32Array:
	var simulation: NativeField = _drawn()
	if simulation == null:
		return PackedInt32Array()
	var changed: PackedInt32Array = simulation.put_cells(cells, plant_type)
	_place_unplaced(simulation)
	if not changed.is_empty():
		plants_put.emit(changed, plant_type)
	return changed


## The map cells whose centres lie within [param radius] metres of [param center] (the field's space;
## its height ignored).
func get_cells_in_circle(center: Vector3, radius: float) -> PackedInt32Array:
	var simulation: NativeField = _drawn()
	return simulation.get_cells_in_circle(Vector2(center.x, center.z), radius) if simulation else PackedInt32Array()


## The map cells whose centres lie in [param area] (the field's x, z: position and size in metres).
func get_cells_in_rect(area: Rect2) -> PackedInt32Array:
	var simulation: NativeField = _drawn()
	return simulation.get_cells_in_rect(area.position, area.end) if simulation else PackedInt32Array()


## The map cell under [param point] (the field's space), or -1 off the map.
func get_cell_at(point: Vector3) -> int:
	var simulation: NativeField = _drawn()
	var cell_size: float = _field.cell_size
	if simulation == null or cell_size <= 0.0:
		return -1
	var column: int = floori(point.x / cell_size)
	var row: int = floori(point.z / cell_size)
	if column < 0 or row < 0 or column >= simulation.get_map_columns() or row >= simulation.get_map_rows():
		return -1
	return row * simulation.get_map_columns() + column


## The map cell of plant [param plant] (as [method SunflowerField.get_plant_at] and
## [method SunflowerField.get_plant_for_body] give), or -1.
func get_cell_of_plant(plant: int) -> int:
	var simulation: NativeField = _drawn()
	return simulation.get_plant_cell(plant) if simulation else -1


## What a cell holds after play: [code]plant_type[/code] (its index in
## [method SunflowerField.get_plant_types], -1 for none), [code]state[/code] (a [enum State]) and
## [code]since[/code] (the clock, [method get_clock], when it took that state).
func get_cell_state(cell: int) -> Dictionary:
	var simulation: NativeField = _drawn()
	var change: Vector3 = simulation.get_cell_change(cell) if simulation else Vector3.ZERO
	var plant_type: int = int(change.x) - 1
	var state: State = State.NONE if plant_type < 0 else int(change.y) as State
	return {"plant_type": plant_type, "state": state, "since": change.z}


## How many cells differ from the map by play.
func get_change_count() -> int:
	var simulation: NativeField = _drawn()
	return simulation.get_change_count() if simulation else 0


## Seconds the field's play clock has run: it runs while the game does; regrowth follows it and a
## save keeps it.
func get_clock() -> float:
	return _clock


## The changes and the clock, compact (3–7 bytes a changed cell), versioned and bound to the map: put
## them in your game's save and give them back to [method load_changes].
func save_changes() -> PackedByteArray:
	var simulation: NativeField = _drawn()
	return simulation.save_changes(_clock) if simulation else PackedByteArray()


## Replaces the changes and the clock by a save of [method save_changes], shown at once. A save of
## another map, a corrupt or a newer one is refused with an error naming what does not match, and
## nothing changes ([constant ERR_INVALID_DATA]).
func load_changes(bytes: PackedByteArray) -> Error:
	return _load(bytes, "the changes")


## [method save_changes] written to the file [param path] so that a crash midway leaves the save it
## replaces whole: the bytes go to a file beside it first ([constant PARTIAL_SUFFIX]), which is then
## renamed over it.
func save_changes_to_file(path: String) -> Error:
	var written: Error = write_atomically(path, save_changes())
	if written != OK:
		push_error(
			"SunflowerField '%s': cannot write the changes to %s: %s" % [_field.name, path, error_string(written)]
		)
	return written


## [method load_changes] from the file [param path]. When it is missing but its partial file is
## there (a crash between a rename's removing the old save and placing the new, where a platform's
## rename does both), the partial one is read: its checksum says whether it is whole.
func load_changes_from_file(path: String) -> Error:
	if not FileAccess.file_exists(path) and FileAccess.file_exists(path + PARTIAL_SUFFIX):
		path += PARTIAL_SUFFIX
	var bytes: PackedByteArray = FileAccess.get_file_as_bytes(path)
	var opened: Error = FileAccess.get_open_error()
	if opened != OK:
		push_error(
			"SunflowerField '%s': cannot read the changes from %s: %s" % [_field.name, path, error_string(opened)]
		)
		return opened
	return _load(bytes, "the changes in " + path)


## Writes [param bytes] to [param path] so that a crash midway leaves the previous file whole.
static func write_atomically(path: String, bytes: PackedByteArray) -> Error:
	var partial: String = path + PARTIAL_SUFFIX
	var file: FileAccess = FileAccess.open(partial, FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_buffer(bytes)
	file.flush()
	var written: Error = file.get_error()
	file.close()
	if written != OK:
		DirAccess.remove_absolute(partial)
		return written
	return DirAccess.rename_absolute(partial, path)


## (The field calls this.) One frame of play on [param simulation]: the clock moves
## by [param delta], plants due recover, the [param pushers] trample within [param trample_share] of
## their radius and are followed in and out of the field.
func _step(simulation: NativeField, delta: float, pushers: Array[Node3D], trample_share: float) -> void:
	if simulation == null:
		return
	_clock += delta
	var recovered: PackedInt32Array = simulation.advance_changes(_clock)
	if not recovered.is_empty():
		plants_recovered.emit(recovered)
	if trample_share > 0.0 and not pushers.is_empty():
		_tell_trampled(simulation.trample(trample_share, _clock), pushers)
	_follow_pushers(simulation, pushers)


## (The field calls this.) The changes of [param old] carried to [param new] (a rebuild): kept when
## both read the same map, forgotten for another map.
func _carry(old: NativeField, new: NativeField) -> void:
	if old == null or new == null or old == new or old.get_change_count() == 0:
		return
	new.load_changes(old.save_changes(_clock))  # another map's save is refused: forgotten
	_place_unplaced(new)


func _drawn() -> NativeField:  # the field's simulation, once its map is built (with plants or none)
	var simulation: NativeField = _simulation.call()
	return simulation if simulation and simulation.get_map_columns() > 0 else null


func _load(bytes: PackedByteArray, what: String) -> Error:
	var simulation: NativeField = _drawn()
	var message: String = (
		simulation.load_changes(bytes)
		if simulation
		else "the field has no plants drawn yet (load changes once it is built: see field_built)"
	)
	if message.is_empty():
		_clock = simulation.get_loaded_clock()
		_place_unplaced(simulation)
		return OK
	push_error("SunflowerField '%s': %s cannot be loaded: %s" % [_field.name, what, message])
	return ERR_INVALID_DATA


func _tell_trampled(pairs: PackedInt32Array, pushers: Array[Node3D]) -> void:
	var by_pusher: Dictionary = {}  # pusher index -> its cells
	for i: int in range(0, pairs.size(), 2):
		if not by_pusher.has(pairs[i + 1]):
			by_pusher[pairs[i + 1]] = PackedInt32Array()
		by_pusher[pairs[i + 1]].append(pairs[i])
	for index: int in by_pusher:
		plants_trampled.emit(by_pusher[index], pushers[index] if index < pushers.size() else null)


func _follow_pushers(simulation: NativeField, pushers: Array[Node3D]) -> void:
	if pushers.is_empty() and _over_field.is_empty():
		return
	var size: Vector2 = Vector2(simulation.get_map_columns(), simulation.get_map_rows()) * _field.cell_size
	var now: Dictionary = {}
	for pusher: Node3D in pushers:
		var local: Vector3 = _field.to_local(pusher.global_position)
		if local.x >= 0.0 and local.z >= 0.0 and local.x < size.x and local.z < size.y:
			now[pusher] = true
	for pusher: Variant in _over_field.keys():  # (a pusher freed since is no Node3D)
		if not now.has(pusher):
			_over_field.erase(pusher)
			if is_instance_valid(pusher):
				pusher_exited.emit(pusher)
	for pusher: Node3D in now:
		if not _over_field.has(pusher):
			_over_field[pusher] = true
			pusher_entered.emit(pusher)


# Plants put where the ground's height is not known (a field on colliders knows it only under the
# map's plants): rays cast now under their roots give it; a cell no ray finds ground under is told.
func _place_unplaced(simulation: NativeField) -> void:
	var cells: PackedInt32Array = simulation.get_unplaced_cells()
	if cells.is_empty():
		return
	var ground: RefCounted = FieldGround.for_field(_field)
	if ground.needs_rays() and _field.is_inside_tree():
		ground.set_ray_points(simulation.get_cell_roots(cells))
		ground.start_rays(_field, _field.ground_ray_above, _field.ground_ray_below, _field.ground_collision_mask)
		ground.cast_rays(-1, _own_bodies.call())
		simulation.set_cell_heights(cells, ground.get_ray_heights())
		cells = simulation.get_unplaced_cells()
	if not cells.is_empty():
		var columns: int = simulation.get_map_columns()
		push_warning(
			(
				(
					"SunflowerField '%s': no ground under %d cell(s) given a plant (the first: column %d, row %d); "
					+ "they stay empty until the field is built on ground there"
				)
				% [_field.name, cells.size(), cells[0] % columns, cells[0] / columns]
			)
		)
