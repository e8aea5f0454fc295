@tool
@icon("icons/sunflower_field.svg")
class_name SunflowerField
extends Node3D
## A field of sunflowers laid out from a plain-text map, swaying in the wind, drawn through five
## levels of detail.
##
## Give it a [member map] (a [code].field[/code] file, see [code]fields/FORMAT.md[/code]) and it
## builds the field: near plants are full 3D models in three levels of detail (each plant made of
## a bottom, a middle and a head part), farther ones crossed-quad sprites, the farthest billboards
## that turn to face the observer. The native [SunflowerSimulation] moves the plants in the wind
## and writes their transforms straight into MultiMesh buffers every frame.
## [br][br]
## Distances are measured from the [member observer] (by default the active camera; in the editor,
## the editor's camera). Keep this node's scale at 1: size the field with [member cell_size] and
## [member plant_height].

## Emitted when a field has been built from the map.
signal field_built(plant_count: int)
## Emitted when a map cannot be used; [param message] names the file, line and column.
signal map_error(message: String)
## Emitted every frame while a field builds in the background; [param progress] runs from 0 to 1.
signal build_progress(progress: float)

## The three parts of a plant, bottom to top.
enum Part { BOTTOM, MIDDLE, HEAD }
## The five representations, most detailed first.
enum Lod { MESH_1, MESH_2, MESH_3, SPRITE, BILLBOARD }

const MESH_LEVELS: int = 3
const LOD_COUNT: int = 5
const PART_NAMES: PackedStringArray = ["bottom", "middle", "head"]
## Model units from a plant's root to the top of its head (three parts of one unit each).
const MODEL_HEIGHT: float = 3.0
## The impostor quads' size in model units; the baked textures frame exactly this.
const IMPOSTOR_WIDTH: float = 1.6
const IMPOSTOR_HEIGHT: float = 3.2
## How far the sprite's top edge leans forward, like the nodding head, in model units.
const SPRITE_LEAN: float = 0.12
const ADDON_DIR: String = "res://addons/sunflower_field/"
const DEFAULT_FRONT_TEXTURE: Texture2D = preload("textures/sunflower_front.png")
const DEFAULT_SIDE_TEXTURE: Texture2D = preload("textures/sunflower_side.png")
const IMPOSTOR_SHADER: Shader = preload("shaders/impostor.gdshader")
## Maps of at least this many bytes (about as many cells) build in the background when
## [member background_build] is on; smaller ones take a few milliseconds and build at once.
const BACKGROUND_BUILD_MIN_BYTES: int = 65536
## Plants in active chunks (those near the observer) from which their per-frame work is split over
## [member worker_threads]; below it, waking threads costs more than it saves (core benchmark).
const PARALLEL_MIN_PLANTS: int = 32768

## Fields building in the background now, for progress displays.
static var _building: Array[SunflowerField] = []

@export_group("Field")
## The field map. Import a [code].field[/code] file (the plugin turns it into a
## [SunflowerFieldMap]) or call [method load_map_file].
@export var map: SunflowerFieldMap:
	set(value):
		if value == map:
			return
		map = value
		_queue_rebuild()
		update_configuration_warnings()
## The size of one map character on the ground (thesis: 0.5 m, four plants per square metre).
@export_range(0.05, 10.0, 0.01, "or_greater", "suffix:m") var cell_size: float = 0.5:
	set(value):
		if not is_finite(value) or value <= 0.0:
			push_warning("SunflowerField.cell_size: %s is not a positive size; keeping %s" % [value, cell_size])
			return
		if value != cell_size:
			cell_size = value
			_queue_rebuild()
## Seed of the per-plant randomness (position jitter α, height, facing, wind phase). The same map
## and seed give the same field.
@export var seed: int = 1:
	set(value):
		if value != seed:
			seed = value
			_queue_rebuild()
## Jitter x and z independently (the thesis used one α for both).
@export var independent_jitter: bool = false:
	set(value):
		if value != independent_jitter:
			independent_jitter = value
			_queue_rebuild()
## Height of a plant from root to head.
@export_range(0.1, 20.0, 0.01, "or_greater", "suffix:m") var plant_height: float = 2.0:
	set(value):
		if not is_finite(value) or value <= 0.0:
			push_warning("SunflowerField.plant_height: %s is not a positive height; keeping %s" % [value, plant_height])
			return
		if value != plant_height:
			plant_height = value
			_queue_rebuild()
## Scenes placed at map cells holding other symbols, e.g. [code]{"S": preload("stone.tscn")}[/code]
## for the thesis' "big stone". Keys are single characters.
@export var legend: Dictionary = {}:
	set(value):
		legend = value
		_queue_rebuild()
## Refuse maps with more sunflowers than this (0: the core's limit of 16 million).
@export_range(0, 100000000, 1) var max_plants: int = 4000000:
	set(value):
		if value != max_plants:
			max_plants = maxi(value, 0)
			_queue_rebuild()
## Side of the square chunks the far representations are grouped in.
@export_range(2.0, 256.0, 1.0, "suffix:m") var chunk_size: float = 16.0:
	set(value):
		if is_finite(value) and value > 0.0 and value != chunk_size:
			chunk_size = value
			_queue_rebuild()

@export_group("Wind")
## Wind power p_w: 0 is calm, 1.0 ≈ 1 m/s, at most 100. Stored in [member wind].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var wind_power: float:
	get:
		return _get_wind().power
	set(value):
		_get_wind().power = value
## Where the wind blows to, on the ground (x, z). Stored in [member wind].
@export var wind_direction: Vector2:
	get:
		return _get_wind().direction
	set(value):
		_get_wind().direction = value
## What one step of [method increase_wind] / [method decrease_wind] changes the power by.
## Stored in [member wind].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var wind_increment: float:
	get:
		return _get_wind().increment
	set(value):
		_get_wind().increment = value
## The wind resource; share one between fields to give them the same weather.
@export var wind: SunflowerWind:
	get:
		return _get_wind()
	set(value):
		if value == _wind:
			return
		if _wind and _wind.changed.is_connected(_on_wind_changed):
			_wind.changed.disconnect(_on_wind_changed)
		_wind = value if value else SunflowerWind.new()
		_wind.changed.connect(_on_wind_changed)
		_on_wind_changed()

@export_group("Plant")
## Texture of the sprite's front quad (the flower head seen from the front), with alpha.
@export var sprite_front_texture: Texture2D = DEFAULT_FRONT_TEXTURE:
	set(value):
		sprite_front_texture = value
		_update_materials()
## Texture of the sprite's side quad, with alpha.
@export var sprite_side_texture: Texture2D = DEFAULT_SIDE_TEXTURE:
	set(value):
		sprite_side_texture = value
		_update_materials()
## Texture of the billboard, with alpha.
@export var billboard_texture: Texture2D = DEFAULT_FRONT_TEXTURE:
	set(value):
		billboard_texture = value
		_update_materials()
## Alpha below which sprite and billboard pixels are discarded (thesis: 190/255).
@export_range(0.0, 1.0, 0.001) var alpha_scissor: float = 190.0 / 255.0:
	set(value):
		alpha_scissor = clampf(value, 0.0, 1.0) if is_finite(value) else 190.0 / 255.0
		_update_materials()

@export_group("Level of detail")
## Switch distances: mesh 1 → 2, mesh 2 → 3, mesh 3 → sprite, sprite → billboard (thesis:
## 6, 10, 20, 25 m). Must increase.
@export var lod_distances: PackedFloat32Array = PackedFloat32Array([6.0, 10.0, 20.0, 25.0]):
	set(value):
		var problem: String = _check_distances(value)
		if not problem.is_empty():
			push_warning("SunflowerField.lod_distances: %s; keeping %s" % [problem, lod_distances])
			return
		lod_distances = value
		_configure_lod()
		_apply_visibility_ranges()
## Hysteresis on every switch: less detail this much later, more detail this much earlier.
@export_range(0.0, 5.0, 0.05, "suffix:m") var lod_hysteresis: float = 0.5:
	set(value):
		lod_hysteresis = maxf(value, 0.0) if is_finite(value) else 0.5
		_configure_lod()
## Seconds between LOD updates (thesis: 0.25 s). Plants move every frame regardless.
@export_range(0.0, 2.0, 0.01, "suffix:s") var lod_interval: float = 0.25:
	set(value):
		lod_interval = maxf(value, 0.0) if is_finite(value) else 0.25
		_configure_lod()
## Draw every plant as one representation, whatever its distance (for benchmarks and debugging).
@export_enum("Automatic:-1", "Mesh 1:0", "Mesh 2:1", "Mesh 3:2", "Sprite:3", "Billboard:4") var force_lod: int = -1:
	set(value):
		force_lod = clampi(value, -1, LOD_COUNT - 1)
		_configure_lod()
## Skip writing plants outside the observer camera's view (the engine culls the far chunks itself).
@export var frustum_culling: bool = true
## Beyond this distance, draw only a share of the impostors, falling with the square of the
## distance (down to [member thinning_min_density]); the kept ones widen to keep the coverage.
## Done on the GPU, so it costs no CPU time. 0 turns thinning off.
@export_range(0.0, 1000.0, 1.0, "or_greater", "suffix:m") var thinning_distance: float = 0.0:
	set(value):
		thinning_distance = maxf(value, 0.0) if is_finite(value) else 0.0
		_update_materials()
## The least share of impostors drawn far away, with thinning on.
@export_range(0.01, 1.0, 0.01) var thinning_min_density: float = 0.25:
	set(value):
		thinning_min_density = clampf(value, 0.01, 1.0) if is_finite(value) else 0.25
		_update_materials()
## Billboards beyond this distance are not drawn (0: no limit).
@export_range(0.0, 10000.0, 1.0, "or_greater", "suffix:m") var max_draw_distance: float = 0.0:
	set(value):
		max_draw_distance = maxf(value, 0.0) if is_finite(value) else 0.0
		_apply_visibility_ranges()

@export_group("Performance")
## Build large maps without stalling: the map is read and laid out on a worker thread, then the
## field's nodes are made a few at a time, at most [member build_budget_ms] per frame. The previous
## field stays drawn until the new one is complete ([signal build_progress] reports, the editor shows
## a progress bar). Off: every build completes in the frame it starts, like
## [method load_map_file] and [method advance] always do.
@export var background_build: bool = true
## Main-thread time a background build may take per frame. When frames are slower than twice this
## anyway (software rendering), a step may take up to half the last frame's time, at most 100 ms.
@export_range(1.0, 100.0, 0.5, "suffix:ms") var build_budget_ms: float = 8.0:
	set(value):
		build_budget_ms = clampf(value, 1.0, 100.0) if is_finite(value) else 8.0
## Threads that move the plants near the observer, the main thread included: 0 uses the machine's
## cores (at most 4), 1 keeps the work on the main thread. The work is split only when at least
## [constant PARALLEL_MIN_PLANTS] plants are near; the result is the same either way.
@export_range(0, 16) var worker_threads: int = 0:
	set(value):
		worker_threads = clampi(value, 0, 16)
		if _built_plants >= 0:
			_simulation.set_worker_threads(worker_threads, PARALLEL_MIN_PLANTS)

@export_group("Observer")
## The node distances are measured from. Empty: the viewport's active camera (in the editor, the
## editor camera). A [Camera3D] also culls plants outside its view.
@export var observer: NodePath:
	set(value):
		observer = value
		update_configuration_warnings()

var _wind: SunflowerWind
var _simulation: SunflowerSimulation
## Part meshes by [code]level * 3 + part[/code]; null entries use the default models.
var _part_meshes: Array[Mesh] = []
var _built_plants: int = -1
var _rebuild_queued: bool = false
var _dynamic_nodes: Array[MultiMeshInstance3D] = []
var _chunk_nodes: Array[MultiMeshInstance3D] = []
var _object_nodes: Array[Node] = []
var _materials: Dictionary = {}
var _impostor_meshes: Dictionary = {}
var _last_error: String = ""
## The field being built (drawn once complete), the worker's job, and the chunk nodes made so far.
var _pending: SunflowerSimulation
var _pending_job: BuildJob
var _pending_task: int = -1
var _pending_nodes: Array[MultiMeshInstance3D] = []
var _build_stats: Dictionary = {}


## A field's map read and laid out, on a worker thread or not. Holds its own copies of the inputs,
## so the node may change (or go) meanwhile; the node waits for the task before dropping the job.
class BuildJob:
	extends RefCounted
	var simulation: SunflowerSimulation = SunflowerSimulation.new()
	var text: PackedByteArray
	var source: String
	var legend: String
	var max_plants: int
	var cell_size: float
	var seed: int
	var independent_jitter: bool
	var chunk_size: float
	var part_scale: float
	var error: String = ""
	var usec: int = 0

	func run() -> void:
		var start: int = Time.get_ticks_usec()
		error = simulation.load_map(text, source, legend, max_plants)
		if error.is_empty():
			simulation.set_layout(cell_size, seed, independent_jitter, chunk_size)
			simulation.set_plant_shape(part_scale, 1.9, 3.2)
		usec = Time.get_ticks_usec() - start


func _init() -> void:
	_simulation = SunflowerSimulation.new()  # empty until the first build is put in its place
	_part_meshes.resize(MESH_LEVELS * 3)
	_get_wind()


func _ready() -> void:
	_queue_rebuild()


func _notification(what: int) -> void:
	if what == NOTIFICATION_PREDELETE:
		_cancel_build()
		_clear_field()


func _process(delta: float) -> void:
	if _rebuild_queued:
		_rebuild(true)
	if _pending:
		_step_build(int(1000.0 * maxf(build_budget_ms, minf(delta * 500.0, 100.0))))
	if _built_plants > 0:
		_push_observer()
		_simulation.update(delta)


## Reads a map from [param path] ([code]res://[/code], [code]user://[/code] or an absolute path)
## and builds the field. On error the current field stays, [signal map_error] is emitted and the
## error is returned. The build completes before this returns, unless [param background] is true
## (and [member background_build] on): then [signal field_built] tells when it is ready.
func load_map_file(path: String, background: bool = false) -> Error:
	var errors: Array[String] = []
	var field_map: SunflowerFieldMap = SunflowerFieldMap.from_file(path, errors)
	if field_map == null:
		_report_map_error(errors[0])
		return ERR_FILE_CANT_OPEN
	var message: String = field_map.check(_legend_symbols(), max_plants)
	if not message.is_empty():
		_report_map_error(message)
		return ERR_PARSE_ERROR
	map = field_map
	_rebuild(background)
	return OK


## Whether a new field is due (a change waits for the next frame) or being built in the
## background; the previous field is drawn meanwhile.
func is_building() -> bool:
	return _pending != null or (_rebuild_queued and is_inside_tree())


## How far the coming field is, from 0 to 1 (1 when no build is due or running).
func get_build_progress() -> float:
	if _pending == null:
		return 0.0 if is_building() else 1.0
	if _pending_task >= 0:
		return 0.0
	return 0.1 + 0.9 * _pending_nodes.size() / maxf(2.0 * _pending.get_chunk_count(), 1.0)


## Completes a running background build now, blocking until the field is ready.
func finish_build() -> void:
	if _rebuild_queued:
		_rebuild()
	if _pending:
		_step_build(-1)


## Figures of the last build: [code]total_ms[/code] (start to [signal field_built]),
## [code]worker_ms[/code] (reading and laying out the map), [code]main_thread_ms[/code] (making
## nodes and buffers), [code]longest_step_ms[/code] (the longest the build held up one frame),
## [code]frames[/code] (frames it spanned) and [code]background[/code].
func get_build_stats() -> Dictionary:
	return _build_stats.duplicate()


## The fields building in the background now (for progress displays such as the editor's).
static func get_building_fields() -> Array[SunflowerField]:
	var fields: Array[SunflowerField] = []
	for field: SunflowerField in _building:
		if is_instance_valid(field) and field.is_inside_tree():
			fields.append(field)
	return fields


## Number of plants in the field.
func get_plant_count() -> int:
	return maxi(_built_plants, 0)


## Plants per representation (mesh 1, mesh 2, mesh 3, sprite, billboard). Every plant is counted
## once, whether or not it is in view.
func get_lod_counts() -> PackedInt32Array:
	if _built_plants <= 0:
		return PackedInt32Array([0, 0, 0, 0, 0])
	return _simulation.get_lod_counts()


## A plant's state in the field's space: [code]position[/code] (Vector3, its root),
## [code]lod[/code] (0–4, see [enum Lod]) and [code]parts[/code] (three [Transform3D], bottom to
## top, as drawn now; upright for sprites and billboards).
func get_plant_info(index: int) -> Dictionary:
	if index < 0 or index >= get_plant_count():
		push_error("SunflowerField.get_plant_info: index %d is out of range (%d plants)" % [index, get_plant_count()])
		return {}
	var flat: PackedFloat32Array = _simulation.get_plant_parts(index)
	var parts: Array[Transform3D] = []
	for part: int in 3:
		var o: int = part * 12
		parts.append(
			Transform3D(
				Vector3(flat[o], flat[o + 4], flat[o + 8]),
				Vector3(flat[o + 1], flat[o + 5], flat[o + 9]),
				Vector3(flat[o + 2], flat[o + 6], flat[o + 10]),
				Vector3(flat[o + 3], flat[o + 7], flat[o + 11])
			)
		)
	return {
		"position": _simulation.get_plant_position(index),
		"lod": _simulation.get_plant_lod(index),
		"parts": parts,
	}


## Runs one update now, [param delta] seconds long (for tools and tests; the node also updates
## itself every frame).
func advance(delta: float) -> void:
	finish_build()
	if _built_plants > 0:
		_push_observer()
		_simulation.update(delta)


## Replaces one part mesh, like the thesis' [code]setSunflower[/code]: [param lod] 0–2 (mesh level),
## [param part] 0–2 (see [enum Part]). [code]null[/code] restores the default model. Parts are
## modelled with their root at the origin and height 1 along +y.
func set_part_mesh(lod: int, part: int, mesh: Mesh) -> void:
	if lod < 0 or lod >= MESH_LEVELS or part < 0 or part >= 3:
		push_error("SunflowerField.set_part_mesh: lod %d / part %d is out of range (0–2 each)" % [lod, part])
		return
	_part_meshes[lod * 3 + part] = mesh
	if lod * 3 + part < _dynamic_nodes.size():
		_dynamic_nodes[lod * 3 + part].multimesh.mesh = get_part_mesh(lod, part)


## The mesh drawn for a part (the default model where none was set).
func get_part_mesh(lod: int, part: int) -> Mesh:
	if lod < 0 or lod >= MESH_LEVELS or part < 0 or part >= 3:
		push_error("SunflowerField.get_part_mesh: lod %d / part %d is out of range (0–2 each)" % [lod, part])
		return null
	var mesh: Mesh = _part_meshes[lod * 3 + part]
	if mesh:
		return mesh
	return load("%smeshes/sunflower_lod%d_%s.res" % [ADDON_DIR, lod + 1, PART_NAMES[part]]) as Mesh


## Adds [member wind_increment] to the wind power.
func increase_wind() -> void:
	wind_power = wind_power + wind_increment


## Subtracts [member wind_increment] from the wind power.
func decrease_wind() -> void:
	wind_power = wind_power - wind_increment


## The native simulation behind the field (for tools and tests).
func get_simulation() -> SunflowerSimulation:
	return _simulation


func _get_configuration_warnings() -> PackedStringArray:
	var warnings: PackedStringArray = []
	if map == null:
		warnings.append("No map: import a .field file and assign it to 'map', or call load_map_file().")
	elif _last_error != "":
		warnings.append("The map cannot be used: " + _last_error)
	if not observer.is_empty() and not (get_node_or_null(observer) is Node3D):
		warnings.append("'observer' does not point to a Node3D; the active camera is used instead.")
	if is_inside_tree() and not Engine.is_editor_hint() and _resolve_observer() == null:
		warnings.append("No observer: set 'observer' or add a current Camera3D; the field keeps its last LOD.")
	if not scale.is_equal_approx(Vector3.ONE):
		warnings.append("Keep the field's scale at 1; size it with 'cell_size' and 'plant_height'.")
	return warnings


func _get_property_list() -> Array[Dictionary]:
	var properties: Array[Dictionary] = []
	properties.append(
		{"name": "Part meshes", "type": TYPE_NIL, "usage": PROPERTY_USAGE_GROUP, "hint_string": "part_meshes/"}
	)
	for lod: int in MESH_LEVELS:
		for part: int in 3:
			(
				properties
				. append(
					{
						"name": "part_meshes/mesh_%d/%s" % [lod + 1, PART_NAMES[part]],
						"type": TYPE_OBJECT,
						"hint": PROPERTY_HINT_RESOURCE_TYPE,
						"hint_string": "Mesh",
						"usage": PROPERTY_USAGE_DEFAULT,
					}
				)
			)
	return properties


func _get(property: StringName) -> Variant:
	var slot: int = _part_slot(property)
	if slot >= 0:
		return _part_meshes[slot]
	return null


func _set(property: StringName, value: Variant) -> bool:
	var slot: int = _part_slot(property)
	if slot < 0:
		return false
	if value != null and not (value is Mesh):
		push_warning("SunflowerField.%s: %s is not a Mesh; using the default part" % [property, value])
		value = null
	set_part_mesh(slot / 3, slot % 3, value as Mesh)
	return true


func _property_can_revert(property: StringName) -> bool:
	return _part_slot(property) >= 0


func _property_get_revert(_property: StringName) -> Variant:
	return null  # the default model


# --- Building ---------------------------------------------------------------------------------


func _part_slot(property: StringName) -> int:
	var text: String = property
	if not text.begins_with("part_meshes/mesh_"):
		return -1
	var pieces: PackedStringArray = text.trim_prefix("part_meshes/mesh_").split("/")
	if pieces.size() != 2 or not pieces[0].is_valid_int():
		return -1
	var lod: int = pieces[0].to_int() - 1
	var part: int = PART_NAMES.find(pieces[1])
	if lod < 0 or lod >= MESH_LEVELS or part < 0:
		return -1
	return lod * 3 + part


func _get_wind() -> SunflowerWind:
	if _wind == null:
		_wind = SunflowerWind.new()
		_wind.changed.connect(_on_wind_changed)
	return _wind


func _on_wind_changed() -> void:
	if _simulation:
		_simulation.set_wind(_wind.power, _wind.direction)
		_simulation.set_wind_dynamics(_wind.get_dynamics())


func _configure_lod() -> void:
	if _simulation:
		_simulation.set_lod(lod_distances, lod_hysteresis, lod_interval, force_lod)


func _check_distances(distances: PackedFloat32Array) -> String:
	if distances.size() != 4:
		return "needs 4 distances, got %d" % distances.size()
	for i: int in 4:
		if not is_finite(distances[i]) or distances[i] <= 0.0:
			return "distance %d (%s) is not a positive number" % [i + 1, distances[i]]
		if i > 0 and distances[i] <= distances[i - 1]:
			return "distances must increase (%s after %s)" % [distances[i], distances[i - 1]]
	return ""


func _legend_symbols() -> String:
	var symbols: String = ""
	for key: Variant in legend:
		var symbol: String = str(key)
		if symbol.length() != 1 or symbol in ["*", " ", "."]:
			push_warning("SunflowerField.legend: key '%s' must be one character other than '*', ' ' and '.'" % symbol)
			continue
		symbols += symbol
	return symbols


func _report_map_error(message: String) -> void:
	_last_error = message
	push_error("SunflowerField: " + message)
	map_error.emit(message)
	update_configuration_warnings()


func _queue_rebuild() -> void:
	_rebuild_queued = true


func _rebuild(background: bool = false) -> void:
	_rebuild_queued = false
	if not is_inside_tree():
		_rebuild_queued = true
		return
	_cancel_build()
	if map == null:
		_clear_field()
		_simulation.clear()
		return
	var job: BuildJob = BuildJob.new()
	job.text = map.text
	job.source = map.source_path
	job.legend = _legend_symbols()
	job.max_plants = max_plants
	job.cell_size = cell_size
	job.seed = seed
	job.independent_jitter = independent_jitter
	job.chunk_size = chunk_size
	job.part_scale = plant_height / MODEL_HEIGHT
	_pending_job = job
	_pending = job.simulation
	background = background and background_build and map.text.size() >= BACKGROUND_BUILD_MIN_BYTES
	_build_stats = {
		"background": background,
		"frames": 0,
		"longest_step_ms": 0.0,
		"main_thread_ms": 0.0,
		"worker_ms": 0.0,
		"start_usec": Time.get_ticks_usec(),
	}
	if background:
		_pending_task = WorkerThreadPool.add_task(job.run, false, "SunflowerField: " + job.source.get_file())
		_building.append(self)
		build_progress.emit(0.0)
	else:
		job.run()
		_step_build(-1)


## One step of a build: waits for the worker (unless [param budget_usec] ≥ 0 and it is still
## running), then makes chunk nodes until the budget is spent; the last step puts the new field in
## place of the old. A negative budget completes the build.
func _step_build(budget_usec: int) -> void:
	var start: int = Time.get_ticks_usec()
	if _pending_task >= 0:
		if budget_usec >= 0 and not WorkerThreadPool.is_task_completed(_pending_task):
			_build_stats["frames"] += 1
			return
		WorkerThreadPool.wait_for_task_completion(_pending_task)
		_pending_task = -1
	if not _pending_job.error.is_empty():
		var message: String = _pending_job.error
		_cancel_build()
		_report_map_error(message)  # the current field stays
		return
	var switch_distance: float = lod_distances[3]
	var chunk_count: int = _pending.get_chunk_count()
	while _pending_nodes.size() < 2 * chunk_count:
		var chunk: int = _pending_nodes.size() / 2
		var aabb: AABB = _pending.get_chunk_aabb(chunk)
		var sprite: MultiMeshInstance3D = _make_multimesh_node("ChunkSprites%d" % chunk, _impostor_mesh("sprite"), aabb)
		var billboard: MultiMeshInstance3D = _make_multimesh_node(
			"ChunkBillboards%d" % chunk, _impostor_mesh("billboard"), aabb
		)
		billboard.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		sprite.visible = false  # shown when the whole field is ready
		billboard.visible = false
		_pending_nodes.append_array([sprite, billboard])
		_set_chunk_ranges(sprite, billboard, switch_distance)
		_pending.set_chunk_multimeshes(chunk, sprite.multimesh.get_rid(), billboard.multimesh.get_rid())
		if budget_usec >= 0 and Time.get_ticks_usec() - start >= budget_usec:
			break
	var step_ms: float = (Time.get_ticks_usec() - start) / 1000.0
	_build_stats["frames"] += 1
	_build_stats["main_thread_ms"] += step_ms
	_build_stats["longest_step_ms"] = maxf(_build_stats["longest_step_ms"], step_ms)
	if _pending_nodes.size() < 2 * chunk_count:
		build_progress.emit(get_build_progress())
		return
	_put_in_place()


## Replaces the drawn field by the built one.
func _put_in_place() -> void:
	var start: int = Time.get_ticks_usec()
	var chunk_nodes: Array[MultiMeshInstance3D] = _pending_nodes.duplicate()
	_pending_nodes.clear()
	_clear_field(chunk_nodes)
	_simulation = _pending
	_build_stats["worker_ms"] = _pending_job.usec / 1000.0
	_pending = null
	_pending_job = null
	_building.erase(self)
	_last_error = ""
	_chunk_nodes = chunk_nodes
	for node: MultiMeshInstance3D in _chunk_nodes:
		node.visible = true
	_on_wind_changed()
	_configure_lod()
	_simulation.set_worker_threads(worker_threads, PARALLEL_MIN_PLANTS)
	_build_dynamic_nodes()
	_build_objects()
	_built_plants = _simulation.get_plant_count()
	_push_observer()
	_simulation.update(0.0)
	var step_ms: float = (Time.get_ticks_usec() - start) / 1000.0
	_build_stats["main_thread_ms"] += step_ms
	_build_stats["longest_step_ms"] = maxf(_build_stats["longest_step_ms"], step_ms)
	_build_stats["total_ms"] = (Time.get_ticks_usec() - _build_stats["start_usec"]) / 1000.0
	_build_stats.erase("start_usec")
	update_configuration_warnings()
	if _build_stats["background"]:
		build_progress.emit(1.0)
	field_built.emit(_built_plants)


## Stops a running build (waiting for its worker) and frees what it made; the current field stays.
func _cancel_build() -> void:
	if _pending_task >= 0:
		WorkerThreadPool.wait_for_task_completion(_pending_task)
		_pending_task = -1
	for node: MultiMeshInstance3D in _pending_nodes:
		if is_instance_valid(node):
			node.free()
	_pending_nodes.clear()
	if _pending:
		_pending.release_multimeshes()
	_pending = null
	_pending_job = null
	_building.erase(self)


## Frees the drawn field's nodes (and any internal child other than [param keep]).
func _clear_field(keep: Array[MultiMeshInstance3D] = []) -> void:
	if _simulation:
		_simulation.release_multimeshes()
	# Every internal child is ours; this also drops copies made by duplicate().
	var spared: Dictionary = {}
	for node: Node in get_children(false):
		spared[node] = true
	for node: Node in keep:
		spared[node] = true
	for node: Node in get_children(true):
		if not spared.has(node):
			node.free()
	_dynamic_nodes.clear()
	_chunk_nodes.clear()
	_object_nodes.clear()
	_built_plants = -1


## Makes the impostor materials once; they are shared by the drawn field and one being built.
func _build_materials() -> void:
	if not _materials.is_empty():
		return
	for key: String in ["front", "side", "billboard"]:
		var material: ShaderMaterial = ShaderMaterial.new()
		material.shader = IMPOSTOR_SHADER
		_materials[key] = material
	_update_materials()


func _update_materials() -> void:
	var textures: Dictionary = {
		"front": sprite_front_texture, "side": sprite_side_texture, "billboard": billboard_texture
	}
	for key: String in _materials:
		var material: ShaderMaterial = _materials[key]
		if textures[key] == null:
			push_warning("SunflowerField: no %s texture; that impostor is drawn untextured" % key)
		material.set_shader_parameter("albedo_texture", textures[key])
		material.set_shader_parameter("alpha_scissor", alpha_scissor)
		material.set_shader_parameter("face_observer", key == "billboard")
		material.set_shader_parameter("thinning_start", thinning_distance)
		material.set_shader_parameter("thinning_min_density", thinning_min_density)


func _field_aabb() -> AABB:
	var box: AABB = AABB()
	for chunk: int in _simulation.get_chunk_count():
		var chunk_box: AABB = _simulation.get_chunk_aabb(chunk)
		box = chunk_box if chunk == 0 else box.merge(chunk_box)
	return box.grow(plant_height * 0.5)


func _make_multimesh_node(node_name: String, mesh: Mesh, aabb: AABB) -> MultiMeshInstance3D:
	var multimesh: MultiMesh = MultiMesh.new()
	multimesh.transform_format = MultiMesh.TRANSFORM_3D
	multimesh.mesh = mesh
	multimesh.custom_aabb = aabb
	var node: MultiMeshInstance3D = MultiMeshInstance3D.new()
	node.name = node_name
	node.multimesh = multimesh
	node.custom_aabb = aabb
	add_child(node, false, Node.INTERNAL_MODE_BACK)
	return node


func _build_dynamic_nodes() -> void:
	var aabb: AABB = _field_aabb()
	for lod: int in MESH_LEVELS:
		for part: int in 3:
			var node: MultiMeshInstance3D = _make_multimesh_node(
				"Mesh%d%s" % [lod + 1, PART_NAMES[part].capitalize()], get_part_mesh(lod, part), aabb
			)
			_dynamic_nodes.append(node)
	var sprite: MultiMeshInstance3D = _make_multimesh_node("Sprites", _impostor_mesh("sprite"), aabb)
	var billboard: MultiMeshInstance3D = _make_multimesh_node("Billboards", _impostor_mesh("billboard"), aabb)
	billboard.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	_dynamic_nodes.append_array([sprite, billboard])
	for bucket: int in _dynamic_nodes.size():
		_simulation.set_bucket_multimesh(bucket, _dynamic_nodes[bucket].multimesh.get_rid())


func _set_chunk_ranges(sprite: MultiMeshInstance3D, billboard: MultiMeshInstance3D, switch_distance: float) -> void:
	sprite.visibility_range_end = switch_distance
	billboard.visibility_range_begin = switch_distance
	billboard.visibility_range_end = max_draw_distance


func _apply_visibility_ranges() -> void:
	for nodes: Array[MultiMeshInstance3D] in [_chunk_nodes, _pending_nodes]:
		for i: int in range(0, nodes.size() - 1, 2):
			_set_chunk_ranges(nodes[i], nodes[i + 1], lod_distances[3])


func _build_objects() -> void:
	var objects: PackedInt32Array = _simulation.get_map_objects()
	for i: int in range(0, objects.size(), 3):
		var symbol: String = String.chr(objects[i + 2])
		var scene: PackedScene = legend.get(symbol) as PackedScene
		if scene == null:
			push_warning(
				(
					"SunflowerField.legend: '%s' has no PackedScene; cell (%d, %d) stays empty"
					% [symbol, objects[i], objects[i + 1]]
				)
			)
			continue
		var instance: Node = scene.instantiate()
		instance.name = "%s_%d_%d" % [instance.name, objects[i], objects[i + 1]]
		if instance is Node3D:
			(instance as Node3D).position = Vector3(
				(objects[i] + 0.5) * cell_size, 0.0, (objects[i + 1] + 0.5) * cell_size
			)
		add_child(instance, false, Node.INTERNAL_MODE_BACK)
		_object_nodes.append(instance)


## The sprite or billboard mesh, made once per field.
func _impostor_mesh(kind: String) -> ArrayMesh:
	if not _impostor_meshes.has(kind):
		_build_materials()
		_impostor_meshes[kind] = _sprite_mesh() if kind == "sprite" else _billboard_mesh()
	return _impostor_meshes[kind]


## Two crossed quads (front texture facing +z, side texture facing +x); the top edge leans
## forward like the nodding head (thesis 3.2.3).
func _sprite_mesh() -> ArrayMesh:
	var w: float = IMPOSTOR_WIDTH * 0.5
	var h: float = IMPOSTOR_HEIGHT
	var mesh: ArrayMesh = ArrayMesh.new()
	_add_quad(
		mesh,
		[Vector3(-w, 0, 0), Vector3(w, 0, 0), Vector3(w, h, SPRITE_LEAN), Vector3(-w, h, SPRITE_LEAN)],
		Vector3(0, 0, 1),
		_materials["front"]
	)
	_add_quad(
		mesh,
		[Vector3(0, 0, w), Vector3(0, 0, -w), Vector3(SPRITE_LEAN, h, -w), Vector3(SPRITE_LEAN, h, w)],
		Vector3(1, 0, 0),
		_materials["side"]
	)
	return mesh


## One quad; the shader turns it about y to face the observer.
func _billboard_mesh() -> ArrayMesh:
	var w: float = IMPOSTOR_WIDTH * 0.5
	var h: float = IMPOSTOR_HEIGHT
	var mesh: ArrayMesh = ArrayMesh.new()
	_add_quad(
		mesh,
		[Vector3(-w, 0, 0), Vector3(w, 0, 0), Vector3(w, h, 0), Vector3(-w, h, 0)],
		Vector3(0, 0, 1),
		_materials["billboard"]
	)
	return mesh


func _add_quad(mesh: ArrayMesh, corners: Array, normal: Vector3, material: Material) -> void:
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array(corners)
	arrays[Mesh.ARRAY_NORMAL] = PackedVector3Array([normal, normal, normal, normal])
	arrays[Mesh.ARRAY_TEX_UV] = PackedVector2Array([Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)])
	arrays[Mesh.ARRAY_INDEX] = PackedInt32Array([0, 2, 1, 0, 3, 2])
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	mesh.surface_set_material(mesh.get_surface_count() - 1, material)


# --- Per frame --------------------------------------------------------------------------------


func _resolve_observer() -> Node3D:
	if not observer.is_empty():
		var node: Node3D = get_node_or_null(observer) as Node3D
		if node:
			return node
	if Engine.is_editor_hint():
		var editor: Object = Engine.get_singleton("EditorInterface")
		if editor:
			var viewport: Viewport = editor.call("get_editor_viewport_3d", 0)
			if viewport and viewport.get_camera_3d():
				return viewport.get_camera_3d()
	var own_viewport: Viewport = get_viewport()
	return own_viewport.get_camera_3d() if own_viewport else null


func _push_observer() -> void:
	var node: Node3D = _resolve_observer()
	if node == null:
		return
	var to_local: Transform3D = global_transform.affine_inverse()
	var frustum: PackedFloat32Array = PackedFloat32Array()
	var camera: Camera3D = node as Camera3D
	if frustum_culling and camera and camera.is_inside_tree():
		for plane: Plane in camera.get_frustum():
			var local_plane: Plane = to_local * plane
			frustum.append_array([local_plane.normal.x, local_plane.normal.y, local_plane.normal.z, local_plane.d])
	_simulation.set_observer(to_local * node.global_position, frustum)
