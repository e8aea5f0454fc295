@tool
extends RefCounted
## Runs one [SunflowerField] behind its public face: the field drawn now (a native simulation and
## its nodes), the build that will replace it, each frame's update (observer, pushers, colliders),
## and handing the node's settings to the simulation drawn. The node's setters and methods call in.

const Native: GDScript = preload("native.gd")
const NativeField: GDScript = preload("native_field.gd")
const FieldBuild: GDScript = preload("field_build.gd")
const FieldInteraction: GDScript = preload("field_interaction.gd")
const FieldNodes: GDScript = preload("field_nodes.gd")
const FieldObserver: GDScript = preload("field_observer.gd")
const ImpostorSet: GDScript = preload("impostor_set.gd")
## Maps of at least this many bytes (about as many cells) build in the background when the field's
## background_build is on; smaller ones take a few milliseconds and build at once.
const BACKGROUND_BUILD_MIN_BYTES: int = 65536

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
## The far levels' look per species, shared by the field drawn and one being built.
var impostor_sets: Array[ImpostorSet] = []
## The plant types drawn (FieldPlant): species 0 the node's plant ('*'), then the legend's.
var plants: Array = []
var _layout_key: Array = []
var _shared: Dictionary = {}  # shader parameters every impostor set gets
var _field: Node3D


func _init(field: Node3D) -> void:
	_field = field
	interaction = FieldInteraction.new(field)


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
	background = (
		background
		and _field.background_build
		and field_map.text.size() >= BACKGROUND_BUILD_MIN_BYTES
	)
	build = FieldBuild.new(_field, impostor_sets, job, background, drawn)
	if background or build.needs_frames():
		building.append(_field)
		_field.emit_signal(&"build_progress", 0.0)
	else:
		step_build(-1)


## One step of the running build within [param budget_usec] (negative: to the end); the last step
## puts the new field in place of the old.
func step_build(budget_usec: int) -> void:
	var stalks: Array[RID] = interaction.get_body_rids()
	if not build.step(budget_usec, _field.max_draw_distance, stalks):
		if build.get_progress() > 0.0:  # not while the worker reads the map
			_field.emit_signal(&"build_progress", build.get_progress())
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
	show(done.nodes)
	done.add_main_thread_time(start)
	stats = done.get_stats()
	last_error = ""
	_field.update_configuration_warnings()
	if done.background or done.needs_frames():
		_field.emit_signal(&"build_progress", 1.0)
	_field.emit_signal(&"field_built", plant_count())


## Stops a running build (waiting for its worker) and frees what it made; the current field stays.
func cancel_build() -> void:
	if build:
		build.cancel()
		build = null
	building.erase(_field)


## Draws [param nodes] (a completed build's) in place of the field drawn now; null draws nothing.
func show(nodes: FieldNodes) -> void:
	if drawn:
		drawn.free_nodes()
	drawn = nodes
	_free_foreign_children()
	if drawn == null:
		return
	var tallest: float = 0.0
	for species_plant: Resource in plants:
		tallest = maxf(tallest, species_plant.height * species_plant.scale_max)
	drawn.finish(plants, _field.legend, _field.cell_size, tallest * 0.5)
	configure_wind()
	configure_lod()
	configure_push()
	configure_threads()
	FieldObserver.push(_field, _field.observer, _field.frustum_culling, drawn.simulation)
	drawn.simulation.update(0.0)
	drawn.show_filled_buckets()
	drawn.update_masks()


## Places the far impostors where the field node stands now (their records are in its frame).
func place_impostors() -> void:
	for impostors: ImpostorSet in impostor_sets:
		impostors.place(_field.global_transform)


## Says that a map cannot be used, as an error, a signal and a configuration warning.
func report_map_error(message: String) -> void:
	last_error = message
	push_error("SunflowerField: " + message)
	_field.emit_signal(&"map_error", message)
	_field.update_configuration_warnings()


## One frame of the field drawn: observer and pushers to the core, its update, the stalk colliders.
func update_field(delta: float) -> void:
	if plant_count() == 0:
		return
	var native_simulation: NativeField = drawn.simulation
	var observer: Node3D = FieldObserver.push(
		_field, _field.observer, _field.frustum_culling, native_simulation
	)
	native_simulation.set_pushers(
		interaction.gather_pushers(_field.pusher_group, _field.pusher_radius)
	)
	native_simulation.update(delta)
	drawn.show_filled_buckets()
	drawn.update_masks()
	drawn.follow_sun()
	var wind_state: PackedFloat32Array = native_simulation.get_wind_state()
	for impostors: ImpostorSet in impostor_sets:
		impostors.sway(wind_state, _field.wind, _field.global_transform)
		if observer:
			impostors.set_shared(&"observer_position", observer.global_position)
	if not Engine.is_editor_hint():
		interaction.update_colliders(
			native_simulation,
			observer,
			_field.collision_reach,
			_field.collision_layer,
			_field.collision_mask
		)


## Draws [param species_plants] (FieldPlant per species): their impostor textures and frames, and
## their meshes on the field drawn. True when a layout value or the plant types changed, so the
## field must be rebuilt.
func configure_plants(species_plants: Array) -> bool:
	plants = species_plants
	while impostor_sets.size() < plants.size():
		var impostors: ImpostorSet = ImpostorSet.new()
		for parameter: StringName in _shared:
			impostors.set_shared(parameter, _shared[parameter])
		impostor_sets.append(impostors)
	var key: Array = []
	for species: int in plants.size():
		impostor_sets[species].configure(plants[species])
		key.append(plants[species].layout_key())
		if drawn:
			drawn.set_plant_meshes(species, plants[species])
	var changed: bool = key != _layout_key and not _layout_key.is_empty()
	_layout_key = key
	return changed


## Sets a shader parameter of every impostor material ([code]alpha_scissor[/code],
## [code]thinning_start[/code], [code]thinning_min_density[/code]).
func set_impostor_shared(parameter: StringName, value: Variant) -> void:
	_shared[parameter] = value
	for impostors: ImpostorSet in impostor_sets:
		impostors.set_shared(parameter, value)


## Hands the field's wind to the simulation drawn.
func configure_wind() -> void:
	if drawn:
		(_field.wind as SunflowerWind).apply_to(drawn.simulation)


## Hands the field's levels of detail to the simulation drawn.
func configure_lod() -> void:
	if drawn:
		drawn.simulation.set_lod(
			_field.lod_distances,
			_field.lod_hysteresis,
			_field.lod_fade,
			_field.lod_interval,
			_field.force_lod
		)


## Hands the field's push settings to the simulation drawn.
func configure_push() -> void:
	if drawn:
		drawn.simulation.set_push_params(_field.push_strength, _field.push_recovery_time)


## Hands the field's thread count to the simulation drawn.
func configure_threads() -> void:
	if drawn:
		drawn.simulation.set_worker_threads(_field.worker_threads)


## Sets the draw distance: the impostors' per-plant fade, and the chunks' visibility ranges on the
## field drawn and one being built.
func apply_ranges() -> void:
	set_impostor_shared(&"draw_distance", _field.max_draw_distance)
	set_impostor_shared(&"draw_fade", maxf(2.0, 0.1 * _field.max_draw_distance))
	for nodes: FieldNodes in [drawn, build.nodes if build else null]:
		if nodes:
			nodes.apply_ranges(_field.max_draw_distance)


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
