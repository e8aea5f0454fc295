@tool
extends RefCounted
## Runs one [SunflowerField] behind its public face: the field drawn now (a native simulation and
## its nodes), the build that will replace it, each frame's update (observer, pushers, colliders),
## and the settings the node hands on: it keeps none of the node's settings, but reads them from the
## node (field_settings.gd) for every field it draws. The node's setters and methods call in; the
## driver reports through its own signals, which the node turns into its public ones.

## A background build's progress, 0 to 1.
signal build_progress(progress: float)
## A build completed and its field is drawn.
signal built(plant_count: int)
## A map could not be used; the field drawn stays.
signal map_error(message: String)
## The frame budget moved the quality (see FieldBudget).
signal quality_changed(quality: float)

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")
const FieldBudget: GDScript = preload("field_budget.gd")
const FieldBuild: GDScript = preload("field_build.gd")
const FieldInteraction: GDScript = preload("field_interaction.gd")
const FieldPlay: GDScript = preload("../sunflower_field_play.gd")
const FieldSettings: GDScript = preload("field_settings.gd")
const ProjectKnobs: GDScript = preload("field_project_settings.gd")
const FieldNodes: GDScript = preload("field_nodes.gd")
const FieldObserver: GDScript = preload("field_observer.gd")
const ImpostorSet: GDScript = preload("impostor_set.gd")
const PartMeshes: GDScript = preload("../plant/part_meshes.gd")
## Maps of at least this many bytes (about as many cells) build in the background when the field's
## project setting sunflower_field/performance/background_build is on; smaller ones take a few
## milliseconds and build at once.
const BACKGROUND_BUILD_MIN_BYTES: int = 65536
## Near plants cast from their impostors from this far inside their switch to the level that does
## (less the hysteresis): an observer walking in between two LOD passes finds no plant without one.
const NEAR_SHADOW_MARGIN: float = 1.0

## Fields building in the background now, for progress displays.
static var building: Array[Node3D] = []

## The field drawn now (its simulation and nodes), and the build of the next one.
var drawn: FieldNodes
var build: FieldBuild
## The figures of the last build that completed.
var stats: Dictionary = {}
## The map's error that stopped the last build ("file:line:column: …"), or empty.
var last_error: String = ""
var rebuild_queued: bool = false
var interaction: FieldInteraction
## The running game's changes to the plants, their clock and events (SunflowerField.play).
var play: FieldPlay
## The far levels' look per species, shared by the field drawn and one being built.
var impostor_sets: Array[ImpostorSet] = []
## The plant types drawn (SunflowerPlant): species 0 the node's plant ('*'), then the legend's.
var plants: Array = []
var _layout_key: Array = []
var _shared: Dictionary = {}  # shader parameters every impostor set gets
var _triangles: Array[PackedInt32Array] = []  # per species, a plant's triangles at each mesh level
var _measuring_viewport: RID  # the viewport whose GPU time is measured for the budget
var _applied_quality: float = 1.0  # the quality the field is drawn at
var _bucket_count: int  # the library's near buckets per species, and each mesh level's first
var _level_buckets: PackedInt32Array = []
var _field: Node3D


func _init(field: Node3D) -> void:
	_field = field
	ProjectSettings.settings_changed.connect(_send_project_settings)
	interaction = FieldInteraction.new(field)
	play = FieldPlay.new(field, simulation, interaction.get_body_rids)
	_bucket_count = Native.constant(&"BUCKET_COUNT")
	for level: int in PartMeshes.LEVELS:
		_level_buckets.append(Native.mesh_bucket(level, 0))


## The native simulation drawn now, or null.
func simulation() -> NativeField:
	return drawn.simulation if drawn else null


## Whom the field measures distances from now, or null.
func observer_node() -> Node3D:
	return FieldObserver.resolve(_field, _field.observer)


## Plants in the field drawn now.
func plant_count() -> int:
	return drawn.simulation.get_plant_count() if drawn else 0


## A frame: a due build starts, a running one takes its step within the budget, the field moves.
func process(delta: float, budget_ms: float) -> void:
	if rebuild_queued:
		rebuild(true)
	if build:
		step_build(int(1000.0 * maxf(budget_ms, minf(delta * 500.0, 100.0))))
	update_field(delta)


## Starts a build of the field from its map (in the background when asked, allowed and the map is
## large), or clears the field when there is no map (or no native library).
func rebuild(background: bool = false) -> void:
	rebuild_queued = false
	if not _field.is_inside_tree():
		rebuild_queued = true
		return
	cancel_build()
	var field_map: Resource = _field.map
	var native_simulation: NativeField = NativeField.create() if field_map else null
	if native_simulation == null:
		show(null)
		return
	var job: FieldBuild.Job = FieldBuild.Job.for_field(_field, plants, native_simulation)
	# Where the observer is now, so that the far tiles' records are ordered for it from the start.
	FieldObserver.push(_field, _field.observer, _field.frustum_culling, native_simulation)
	background = background and ProjectKnobs.background_build() and field_map.text.size() >= BACKGROUND_BUILD_MIN_BYTES
	build = FieldBuild.new(_field, impostor_sets, job, background, drawn)
	if background or build.needs_frames():
		building.append(_field)
		build_progress.emit(0.0)
	else:
		step_build(-1)


## One step of the running build within [param budget_usec] (negative: to the end); the last step
## puts the new field in place of the old.
func step_build(budget_usec: int) -> void:
	var stalks: Array[RID] = interaction.get_body_rids()
	if not build.step(budget_usec, _field.max_draw_distance * quality(), stalks):
		if build.get_progress() > 0.0:  # not while the worker reads the map
			build_progress.emit(build.get_progress())
		return
	var message: String = build.get_error()
	if not message.is_empty():
		cancel_build()
		report_map_error(message)  # the current field stays
		return
	var start: int = Time.get_ticks_usec()
	var done: FieldBuild = build
	build = null
	building.erase(_field)
	show(done.nodes, done.job.scenes, done.job.cell_size)
	done.add_main_thread_time(start)
	stats = done.get_stats()
	last_error = ""
	if done.background or done.needs_frames():
		build_progress.emit(1.0)
	built.emit(plant_count())


## Stops a running build (waiting for its worker) and frees what it made; the current field stays.
func cancel_build() -> void:
	if build:
		build.cancel()
		build = null
	building.erase(_field)


## Draws [param nodes] (a completed build's) in place of the field drawn now, the legend's
## [param scenes] placed on cells of [param cell_size] metres; null draws nothing.
func show(nodes: FieldNodes, scenes: Dictionary = {}, cell_size: float = 0.0) -> void:
	var old: NativeField = simulation()
	if drawn:
		drawn.free_nodes()
	drawn = nodes
	_free_foreign_children()
	if drawn == null:
		return
	var tallest: float = 0.0
	for species_plant: Resource in plants:
		tallest = maxf(tallest, species_plant.height * species_plant.scale_max)
	drawn.finish(plants, scenes, cell_size, tallest * 0.5)
	_configure_drawn()
	play._carry(old, drawn.simulation)
	FieldObserver.push(_field, _field.observer, _field.frustum_culling, drawn.simulation)
	drawn.simulation.update(0.0)
	drawn.simulation.draw()
	drawn.show_filled_buckets()
	drawn.update_masks()
	drawn.update_hidden_cells()


## Places the far impostors where the field node stands now (their records are in its frame).
func place_impostors() -> void:
	for impostors: ImpostorSet in impostor_sets:
		impostors.place(_field.global_transform)


## Says that a map cannot be used, as an error and a signal (the node shows it as a warning too).
func report_map_error(message: String) -> void:
	last_error = message
	push_error("SunflowerField: " + message)
	map_error.emit(message)


## One frame of the field drawn: observer and pushers to the core, its update, the stalk colliders.
func update_field(delta: float) -> void:
	if plant_count() == 0:
		return
	var native_simulation: NativeField = drawn.simulation
	var observer: Node3D = FieldObserver.push(_field, _field.observer, _field.frustum_culling, native_simulation)
	native_simulation.set_pushers(interaction.gather_pushers(_field.pusher_group, _field.pusher_radius))
	if not Engine.is_editor_hint():
		play._step(native_simulation, delta, interaction.pusher_nodes, _field.trample_share)
	native_simulation.update(delta)
	native_simulation.draw()
	drawn.show_filled_buckets()
	drawn.update_masks()
	drawn.update_hidden_cells()
	drawn.follow_sun()
	if not Engine.is_editor_hint():
		_step_budgets(delta)
	var wind_state: PackedFloat32Array = native_simulation.get_wind_state()
	for impostors: ImpostorSet in impostor_sets:
		impostors.sway(wind_state, _field.wind, _field.global_transform)
		if observer:
			impostors.set_shared(&"observer_position", observer.global_position)
	if not Engine.is_editor_hint():
		interaction.update_colliders(
			native_simulation, observer, _field.collision_reach, _field.collision_layer, _field.collision_mask
		)


## Draws [param species_plants] (SunflowerPlant per species): their impostor textures and frames,
## their meshes and their rows of the core's table on the field drawn. True when the field must be
## built anew: the core says a row changed that the layout depends on, the plant types changed, or
## what the layout takes beyond the rows (a plant's switch scale, drawing whole) did; while a
## build runs with no field drawn yet, any change.
func configure_plants(species_plants: Array) -> bool:
	plants = species_plants
	while impostor_sets.size() < plants.size():
		var impostors: ImpostorSet = ImpostorSet.new()
		for parameter: StringName in _shared:
			impostors.set_shared(parameter, _shared[parameter])
		impostor_sets.append(impostors)
	var key: Array = []
	var cost: int = FieldSettings.FREE
	_triangles.clear()
	for species: int in plants.size():
		impostor_sets[species].configure(plants[species])
		var levels: PackedInt32Array = []
		for level: int in PartMeshes.LEVELS:
			levels.append(plants[species].triangle_count(level))
		_triangles.append(levels)
		key.append(plants[species].layout_key())
		if drawn:
			drawn.set_plant_meshes(species, plants[species])
			var rows: Dictionary = FieldSettings.rows_of(plants[species], "SunflowerPlant")
			cost = maxi(cost, FieldSettings.send(drawn.simulation, rows, species))
	send_near_shadows()
	var changed: bool = key != _layout_key and not _layout_key.is_empty()
	_layout_key = key
	return changed or cost == FieldSettings.REBUILD or (build != null and drawn == null)


## Sets a shader parameter of every impostor material ([code]alpha_scissor[/code],
## [code]thinning_start[/code], [code]thinning_min_density[/code]).
func set_impostor_shared(parameter: StringName, value: Variant) -> void:
	_shared[parameter] = value
	for impostors: ImpostorSet in impostor_sets:
		impostors.set_shared(parameter, value)


## Sends changed settings of the node or its wind ([param rows]: their rows of the core's table and
## values, field_settings.gd) to the field drawn. A change the field's layout depends on (the core
## says which: the field drawn does not take it) builds the field anew; with no field drawn, the
## table's cost says whether the coming field must be built again.
func send_settings(rows: Dictionary) -> void:
	var cost: int = FieldSettings.FREE
	if drawn:
		cost = FieldSettings.send(drawn.simulation, rows)
	else:
		for row: String in rows:
			cost = maxi(cost, Native.parameter_cost(row))
	if cost == FieldSettings.REBUILD:
		rebuild_queued = true
	send_near_shadows()


## Gives the field drawn every setting of the node, its wind and its plant types as they are now,
## and the quality it is drawn at (what changed while it was built included).
func _configure_drawn() -> void:
	FieldSettings.of(_field, plants).apply_to(drawn.simulation)  # its cost: the build had these rows
	_send_project_settings()
	drawn.simulation.set_quality(quality())
	send_near_shadows()


## Gives the field drawn the machine-wide settings the core uses (Project Settings: its threads).
func _send_project_settings() -> void:
	if drawn:
		var threads: String = ProjectKnobs.row(ProjectKnobs.WORKER_THREADS)
		FieldSettings.send(drawn.simulation, {threads: ProjectKnobs.worker_threads()})


## Tells each plant type's far tiles from where they cast the near plants' shadows
## (SunflowerField.impostor_shadows_from, for a type whose SunflowerPlant.impostor_shadows is on:
## where the type turns finer than that level, as the core says, less NEAR_SHADOW_MARGIN; −1:
## never), and the field drawn which mesh levels cast from meshes. With force_lod every plant casts
## from what it is drawn with.
func send_near_shadows() -> void:
	if not drawn:
		return  # (the field drawn next gets them)
	var field_level: int = _field.impostor_shadows_from if _field.force_lod < 0 else PartMeshes.LEVELS
	var levels: PackedInt32Array = []
	for species: int in mini(impostor_sets.size(), plants.size()):
		var level: int = field_level if plants[species].impostor_shadows else PartMeshes.LEVELS
		levels.append(level)
		var from: float = -1.0
		if level < PartMeshes.LEVELS:
			from = maxf(0.0, drawn.simulation.get_finer_distance(species, level - 1) - NEAR_SHADOW_MARGIN)
		impostor_sets[species].set_shared(&"near_shadow_from", from)
	drawn.set_impostor_shadows_from(levels)


## Draws the node's draw distance (0: none) at the budget's quality: the impostors' per-plant fade,
## and the chunks' visibility ranges on the field drawn and one being built.
func set_draw_distance() -> void:
	var distance: float = _field.max_draw_distance * quality()
	set_impostor_shared(&"draw_distance", distance)
	set_impostor_shared(&"draw_fade", maxf(2.0, 0.1 * distance))
	for nodes: FieldNodes in [drawn, build.nodes if build else null]:
		if nodes:
			nodes.apply_ranges(distance)


## Draws where the node's thinning starts (0: no thinning) at the budget's quality.
func set_thinning_start() -> void:
	set_impostor_shared(&"thinning_start", _field.thinning_distance * quality())


## The share of its distances the field draws with: its viewport's frame budget's quality (the
## project's least quality at least), 1 without a budget.
func quality() -> float:
	var governor: FieldBudget = governor()
	if governor == null or not ProjectKnobs.has_frame_budget():
		return 1.0
	return maxf(governor.quality, ProjectKnobs.budget_min_quality())


## The frame budget of the field's viewport, which every field there shares (at full quality while
## Project Settings set none); null in the editor (a budget holds a running game) or out of the tree.
func governor() -> FieldBudget:
	if Engine.is_editor_hint() or not _field.is_inside_tree():
		return null
	return FieldBudget.governor_of(_field.get_viewport().get_viewport_rid())


## A frame of the viewport's budget, while Project Settings set one (stepped once a round of its
## fields' frames; a budget set again starts afresh, FieldBudget.step_shared); the field is drawn anew
## when its quality moved, or went back to 1 with the budget gone.
func _step_budgets(delta: float) -> void:
	var governor: FieldBudget = governor()
	if governor and ProjectKnobs.has_frame_budget():
		governor.step_shared(delta, _field, near_primitives(), _gpu_ms())
	_requalify()


## Draws the field at its quality and says so, when that moved.
func _requalify() -> void:
	var now: float = quality()
	if not is_equal_approx(now, _applied_quality):
		_applied_quality = now
		_apply_quality()
		quality_changed.emit(now)


## The triangles of the near meshes written this frame: plants at each mesh level, after culling,
## times a plant's triangles there (the main view's; each shadow pass draws its own).
func near_primitives() -> int:
	var total: int = 0
	for species: int in _triangles.size():
		for level: int in PartMeshes.LEVELS:
			total += near_count(species, level) * _triangles[species][level]
	return total


## Plants of [param species] written at mesh [param level] (0–2) last frame, after culling; 0 with
## no field drawn.
func near_count(species: int, level: int) -> int:
	return drawn.simulation.get_bucket_instance_count(species * _bucket_count + _level_buckets[level]) if drawn else 0


## What the field drawn costs now (SunflowerField.get_frame_stats): the native update and draw, its
## threads and memory, the plants written at each mesh level and their triangles, the budget's GPU
## time and quality; zeros before a field is drawn.
func frame_stats() -> Dictionary:
	var near: PackedInt32Array = PackedInt32Array()
	near.resize(PartMeshes.LEVELS)
	var stats: Dictionary = {
		"update_ms": 0.0,
		"worker_threads": 0,
		"memory_bytes": 0,
		"near_meshes": near,
		"near_primitives": 0,
		"gpu_ms": 0.0,
		"quality": quality(),
	}
	var native_field: NativeField = simulation()
	if native_field == null:
		return stats
	for species: int in plants.size():
		for level: int in PartMeshes.LEVELS:
			near[level] += near_count(species, level)
	var budget: FieldBudget = governor()
	stats["update_ms"] = (native_field.get_last_update_usec() + native_field.get_last_draw_usec()) / 1000.0
	stats["worker_threads"] = native_field.get_worker_threads()
	stats["memory_bytes"] = native_field.get_memory_bytes()
	stats["near_primitives"] = near_primitives()
	stats["gpu_ms"] = budget.smoothed_gpu_ms if budget and ProjectKnobs.budget_gpu_ms() > 0.0 else 0.0
	return stats


## The plant of the field drawn whose root is nearest to [param point] (field space) on the ground
## within [param max_distance] metres, or -1.
func nearest_plant(point: Vector3, max_distance: float) -> int:
	var nearest: int = -1
	var best: float = INF
	var native_field: NativeField = simulation()
	for plant: int in native_field.get_plants_near(point, max_distance, false) if native_field else PackedInt32Array():
		var root: Vector3 = native_field.get_plant_position(plant)
		var distance: float = Vector2(root.x, root.z).distance_squared_to(Vector2(point.x, point.z))
		if distance < best:
			best = distance
			nearest = plant
	return nearest


## The field's viewport's GPU time last frame in milliseconds, measured only with a GPU target.
func _gpu_ms() -> float:
	if ProjectKnobs.budget_gpu_ms() <= 0.0 or not _field.is_inside_tree():
		return 0.0
	var viewport: RID = _field.get_viewport().get_viewport_rid()
	if viewport != _measuring_viewport:
		_measuring_viewport = viewport
		RenderingServer.viewport_set_measure_render_time(viewport, true)
		return 0.0
	return RenderingServer.viewport_get_measured_render_time_gpu(viewport)


## Draws at the budget's quality: distances, thinning and draw distance.
func _apply_quality() -> void:
	if drawn:
		drawn.simulation.set_quality(quality())
	send_near_shadows()
	set_thinning_start()
	if _field.max_draw_distance > 0.0:
		set_draw_distance()


## Frees internal children that belong to no field of this node: copies that duplicate() made of
## another field's nodes.
func _free_foreign_children() -> void:
	var spared: Dictionary = {}
	for node: Node in _field.get_children(false):
		spared[node] = true  # the user's own children
	for nodes: FieldNodes in [drawn, build.nodes if build else null]:
		if nodes:
			nodes.collect(spared)
	for node: Node in _field.get_children(true):
		if not spared.has(node):
			node.free()
