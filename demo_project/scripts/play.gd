class_name DemoPlay
extends Node
## The demo's play with the field (SunflowerField.play): walking low tramples a trail that stands
## up again, X cuts what stands in front of you (a scythe), V sows there (the map's plant type, in
## cut and empty cells alike), the HUD counts the events, and the changes are saved when the demo
## quits; --load-changes restores them at the next start.

## Plants within this share of the walker's push radius are trampled.
const TRAMPLE_SHARE: float = 0.45
## Below this eye height (a walker's: 1.7 m) the camera tramples; higher it only parts the plants.
const TRAMPLE_HEIGHT: float = 2.0
## Seconds until a trampled plant stands again, and until a cut one has grown again.
const RECOVER_AFTER: float = 60.0
const REGROW_AFTER: float = 180.0
## The scythe: what stands within this radius, this far ahead of the camera on the ground, metres.
const SCYTHE_RADIUS: float = 1.5
const SCYTHE_AHEAD: float = 2.0

var trampled: int = 0
var cut: int = 0
var recovered: int = 0
var sown: int = 0
var _field: SunflowerField
var _played: bool = false  # the field changed (or changes were loaded) in this run
var _camera: Node3D


## Plays with [param field] from [param camera]'s place.
func setup(field: SunflowerField, camera: Node3D) -> void:
	_field = field
	_camera = camera
	_field.play.plants_trampled.connect(_on_trampled)
	_field.play.plants_changed.connect(_on_changed)
	_field.play.plants_recovered.connect(_on_recovered)
	_field.play.plants_put.connect(_on_put)
	_field.field_built.connect(_on_built)


## Each frame: the camera tramples while it is as low as a walker's eyes.
func _process(_delta: float) -> void:
	var walking: bool = _camera.global_position.y < TRAMPLE_HEIGHT
	if walking != (_field.trample_share > 0.0):
		_field.trample_share = TRAMPLE_SHARE if walking else 0.0


## Cuts what stands within SCYTHE_RADIUS of the ground SCYTHE_AHEAD metres in front of the camera;
## returns how many plants.
func swing_scythe() -> int:
	return _field.play.change_plants(_cells_ahead(), SunflowerFieldPlay.Change.CUT).size()


## Sows the cells the scythe reaches with the map's plant type (0): cut plants stand again, empty
## cells (the path, the clearing) get a plant; returns how many cells changed.
func sow() -> int:
	return _field.play.put_plants(_cells_ahead(), 0).size()


func _cells_ahead() -> PackedInt32Array:
	var ahead: Vector3 = -_camera.global_basis.z
	ahead.y = 0.0
	var centre: Vector3 = _camera.global_position + ahead.normalized() * SCYTHE_AHEAD
	return _field.play.get_cells_in_circle(_field.to_local(centre), SCYTHE_RADIUS)


## The HUD's words on play.
func stats_text() -> String:
	return (
		"%d trampled, %d cut (X), %d sown (V), %d stood again, %d changed"
		% [trampled, cut, sown, recovered, _field.play.get_change_count()]
	)


## Where the changes of the map at [param map_path] are kept between runs.
static func save_path(map_path: String) -> String:
	return "user://changes/%s.changes" % map_path.get_file()


## Writes the field's changes for [param map_path] when it changed in this run (all of them undone:
## the old save goes; a run that changed nothing leaves it).
func save(map_path: String) -> void:
	if not _played:
		return
	var path: String = save_path(map_path)
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	if _field.play.get_change_count() == 0:
		DirAccess.remove_absolute(path)
		return
	if _field.play.save_changes_to_file(path) == OK:
		print("demo: play: %d changes saved to %s" % [_field.play.get_change_count(), path])


## Loads the changes saved for [param map_path]; returns "" or what went wrong.
func load_saved(map_path: String) -> String:
	var path: String = save_path(map_path)
	if not FileAccess.file_exists(path):
		return "no changes were saved for %s (%s)" % [map_path.get_file(), path]
	if _field.play.load_changes_from_file(path) != OK:
		return "the changes in %s cannot be loaded (the log says why)" % path
	print("demo: play: %d changes loaded from %s" % [_field.play.get_change_count(), path])
	_played = true
	return ""


func _on_trampled(cells: PackedInt32Array, _by: Node3D) -> void:
	trampled += cells.size()
	_played = true


func _on_changed(cells: PackedInt32Array, change: int) -> void:
	if change == SunflowerFieldPlay.Change.CUT:
		cut += cells.size()
	_played = true


func _on_put(cells: PackedInt32Array, _plant_type: int) -> void:
	sown += cells.size()
	_played = true


func _on_recovered(cells: PackedInt32Array) -> void:
	recovered += cells.size()
	_played = true


func _on_built(_plants: int) -> void:
	for plant: SunflowerPlant in _field.get_plant_types():
		plant.recover_after = RECOVER_AFTER
		plant.regrow_after = REGROW_AFTER
