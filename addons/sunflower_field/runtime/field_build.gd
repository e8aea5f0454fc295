@tool
extends RefCounted
## One build of a field: its map read and laid out into a new native simulation (on a worker
## thread, or at once), on colliders after rays found the ground (main thread, budgeted, then the
## layout on the worker again), then the field's nodes made within a per-frame budget. Owns the pending
## pair (that simulation and its [code]FieldNodes[/code]) until the field takes it, so finishing a
## build swaps two pairs; cancelling frees what it made. Keeps the build's figures.

## Where a build is: the map read (worker), rays cast at colliders (main thread, only on colliders),
## the plants laid out on them (worker), nodes made (main thread).
enum Phase { READ, RAYS, NODES }

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")
const FieldGround: GDScript = preload("field_ground.gd")
const FieldLegend: GDScript = preload("field_legend.gd")
const FieldNodes: GDScript = preload("field_nodes.gd")
const FieldSettings: GDScript = preload("field_settings.gd")
const ImpostorSet: GDScript = preload("impostor_set.gd")


## What the worker reads and lays out. Holds its own copies of the inputs, so the node may change
## (or go) meanwhile; the build waits for the worker before dropping the job.
class Job:
	extends RefCounted
	var simulation: NativeField
	var text: PackedByteArray
	var source: String
	var legend: String
	## The legend as the node had it (symbol → PackedScene or SunflowerPlant): the scenes it places.
	var scenes: Dictionary
	var max_plants: int
	var cheap_shadows: bool = true
	## The rows of the core's table the field, its wind and its plant types hold (field_settings.gd).
	var settings: FieldSettings
	var cell_size: float
	var seed: int
	var independent_jitter: bool
	var plant_symbols: String
	var lod_scales: PackedFloat32Array = []  # per species: SunflowerPlant.lod_scale_used
	var whole: Array[bool] = []  # per species: drawn whole (decided on the main thread: it asks the renderer)
	var ground: FieldGround
	var error: String = ""
	var usec: int = 0

	## A job for [param field]'s map and layout properties and [param species_plants] (a SunflowerPlant
	## per species), filling [param native_simulation].
	static func for_field(field: Node3D, species_plants: Array, native_simulation: NativeField) -> Job:
		var job: Job = Job.new()
		job.simulation = native_simulation
		job.text = field.map.text
		job.source = field.map.source_path
		job.legend = FieldLegend.object_symbols(field.legend)
		job.scenes = field.legend.duplicate()
		job.max_plants = field.max_plants
		job.cheap_shadows = field.cheap_shadows
		job.settings = FieldSettings.of(field, species_plants)
		job.cell_size = field.cell_size
		job.seed = field.seed
		job.independent_jitter = field.independent_jitter
		job.plant_symbols = FieldLegend.plant_symbols(field.legend)
		for species_plant: Resource in species_plants:
			job.lod_scales.append(species_plant.lod_scale_used())
			job.whole.append(species_plant.drawn_whole())
		job.ground = FieldGround.for_field(field)
		return job

	## Reads the map and lays it out on a flat field or a height map (on colliders: on no ground
	## until the rays are in).
	func run() -> void:
		var start: int = Time.get_ticks_usec()
		simulation.set_layout_seed(seed, independent_jitter)
		settings.apply_to(simulation)
		for species: int in whole.size():
			simulation.set_plant_lod_scale(species, lod_scales[species])
			simulation.set_plant_whole(species, whole[species])
		ground.prepare(simulation)
		error = simulation.load_map(text, source, legend, plant_symbols, max_plants)
		if error.is_empty():
			error = ground.apply_height_map(simulation, cell_size)
		if error.is_empty():
			ground.prepare_rays(simulation)
		if error.is_empty() and not ground.needs_rays():
			simulation.compute_chunk_signatures()  # so the main thread compares chunks cheaply
		usec += Time.get_ticks_usec() - start

	## Lays the plants out on the ground the rays found.
	func lay_out_on_rays() -> void:
		var start: int = Time.get_ticks_usec()
		error = ground.apply_rays(simulation)
		simulation.compute_chunk_signatures()
		usec += Time.get_ticks_usec() - start


## The pending pair: the job's simulation and the nodes made for it so far.
var nodes: FieldNodes
var job: Job
var background: bool
var _field: Node3D
var _previous: FieldNodes
var _phase: Phase = Phase.READ
var _task: int = -1
var _start_usec: int = Time.get_ticks_usec()
var _frames: int = 0
var _main_thread_ms: float = 0.0
var _longest_step_ms: float = 0.0


## Starts reading [param build_job] on a worker thread when [param in_background], else at once.
## Chunks that draw as [param previous]'s (the FieldNodes drawn now, or null) take its nodes.
func _init(
	field: Node3D, impostors: Array[ImpostorSet], build_job: Job, in_background: bool, previous: FieldNodes
) -> void:
	job = build_job
	background = in_background
	_field = field
	nodes = FieldNodes.new(field, job.simulation, impostors)
	nodes.cheap_shadows = job.cheap_shadows
	_previous = previous
	if background:
		_task = WorkerThreadPool.add_task(job.run, true, "SunflowerField: " + job.source.get_file())
	else:
		job.run()


## Whether the build waits for collider rays, which need frames: such a build is stepped even when
## the map is small.
func needs_frames() -> bool:
	return job.ground.needs_rays()


## One step: waits for the worker (unless [param budget_usec] ≥ 0 and it is still running), casts
## collider rays (which miss none of [param exclude]: the field's own stalks), then makes tile nodes
## until the budget is spent (negative: until done). True when the pending field is complete or the
## map failed ([method get_error]).
func step(budget_usec: int, max_draw_distance: float, exclude: Array[RID]) -> bool:
	var start: int = Time.get_ticks_usec()
	if _task >= 0:
		if budget_usec >= 0 and not WorkerThreadPool.is_task_completed(_task):
			_frames += 1
			return false
		WorkerThreadPool.wait_for_task_completion(_task)
		_task = -1
	if not job.error.is_empty():
		return true
	if _phase == Phase.READ:
		_phase = Phase.NODES
		if job.ground.needs_rays():
			_phase = Phase.RAYS
			job.ground.start_rays(
				_field, _field.ground_ray_above, _field.ground_ray_below, _field.ground_collision_mask
			)
	if _phase == Phase.RAYS:
		var left: int = budget_usec - (Time.get_ticks_usec() - start) if budget_usec >= 0 else -1
		var cast: bool = job.ground.cast_rays(maxi(left, 0) if budget_usec >= 0 else -1, exclude)
		_frames += 1
		add_main_thread_time(start)
		if not cast:
			return false
		_phase = Phase.NODES
		if budget_usec >= 0 and background:  # a large map: lay it out on a worker (small ones take ~1 ms)
			_task = WorkerThreadPool.add_task(job.lay_out_on_rays, true, "SunflowerField: ground")
			return false
		job.lay_out_on_rays()
		if not job.error.is_empty():
			return true
		start = Time.get_ticks_usec()
	if _previous:  # the layout is complete: match its tiles with the field drawn now, once
		nodes.reuse(_previous)
		_previous = null
	var had_tiles: bool = nodes.get_tile_progress() < 1.0
	var done: bool = nodes.make_tiles(budget_usec, max_draw_distance)
	_frames += 1
	add_main_thread_time(start)
	# The swap that follows (the near nodes, the legend's scenes, the first update) gets a frame of
	# its own when this step made tile nodes within a budget.
	return done and not (had_tiles and budget_usec >= 0)


## The map's error ("file:line:column: …"), or empty.
func get_error() -> String:
	return job.error


## How far the build is, 0 to 1: the worker's part is the first tenth; rays, when cast, the next
## four.
func get_progress() -> float:
	var rays: float = 0.4 if job.ground.needs_rays() else 0.0
	if _phase == Phase.READ:
		return 0.0 if _task >= 0 else 0.1
	if _phase == Phase.RAYS:
		return 0.1 + rays * job.ground.get_ray_progress()
	return 0.1 + rays + (0.9 - rays) * (0.0 if _task >= 0 else nodes.get_tile_progress())


## Counts main-thread time spent on this build since [param start_usec].
func add_main_thread_time(start_usec: int) -> void:
	var step_ms: float = (Time.get_ticks_usec() - start_usec) / 1000.0
	_main_thread_ms += step_ms
	_longest_step_ms = maxf(_longest_step_ms, step_ms)


## The build's figures (see [method SunflowerField.get_build_stats]).
func get_stats() -> Dictionary:
	return {
		"background": background,
		"frames": _frames,
		"longest_step_ms": _longest_step_ms,
		"main_thread_ms": _main_thread_ms,
		"worker_ms": job.usec / 1000.0,
		"ground_ray_ms": job.ground.get_ray_ms(),
		"tiles_made": nodes.tiles_made,
		"tiles_kept": nodes.tiles_kept,
		"cells_without_ground": job.simulation.get_cells_without_ground(),
		"total_ms": (Time.get_ticks_usec() - _start_usec) / 1000.0,
	}


## Stops the build, waiting for its worker, and frees what it made.
func cancel() -> void:
	if _task >= 0:
		WorkerThreadPool.wait_for_task_completion(_task)
		_task = -1
	nodes.free_nodes()
