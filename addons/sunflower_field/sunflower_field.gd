@tool
@icon("icons/sunflower_field.svg")
class_name SunflowerField
extends "runtime/field_node_base.gd"
## A field of sunflowers laid out from a plain-text map, swaying in the wind, drawn through five
## levels of detail.
##
## Give it a [member map] (a [code].field[/code] file, see [code]fields/FORMAT.md[/code]) and it
## builds the field: near plants are 3D models in three levels of detail (each plant made of a
## bottom, a middle and a head part), farther ones multi-view impostors baked from the plant, lit
## and swaying with the same wind, in static far tiles that merge with distance. The native
## [SunflowerSimulation] moves the near plants in the wind and writes their transforms straight into
## MultiMesh buffers every frame. The manual: [code]docs/[/code] in the addon's repository.
## [br][br]
## Distances are measured from the [member observer] (by default the active camera; in the editor,
## the editor's camera). Keep this node's scale at 1: size the field with [member cell_size] and
## the [member plant]'s height. The plant (a [SunflowerPlant]) is the built-in sunflower unless set.

## Emitted when a field has been built from the map.
signal field_built(plant_count: int)
## Emitted when a map cannot be used; [param message] names the file, line and column.
signal map_error(message: String)
## Emitted every frame while a field builds in the background; [param progress] runs from 0 to 1.
signal build_progress(progress: float)
## Emitted when the frame budget moves the quality (see [method get_quality]).
signal quality_changed(quality: float)

## Where plants stand (see [member ground_source]).
enum GroundSource {
	FLAT = FieldGround.Source.FLAT,
	COLLIDERS = FieldGround.Source.COLLIDERS,
	HEIGHT_MAP = FieldGround.Source.HEIGHT_MAP,
}

const FieldSettings: GDScript = preload("runtime/field_settings.gd")
const FieldGround: GDScript = preload("runtime/field_ground.gd")
const FieldLegend: GDScript = preload("runtime/field_legend.gd")
const FieldFace: GDScript = preload("runtime/field_face.gd")
## The thesis' switch distances, [member lod_distances]' default.
const DEFAULT_LOD_DISTANCES: PackedFloat32Array = [6.0, 10.0, 20.0, 25.0]
## The field map. Import a [code].field[/code] file (the plugin turns it into a
## [SunflowerFieldMap]) or call [method load_map_file].
@export var map: SunflowerFieldMap:
	set(value):
		if value == map:
			return
		_listen(map, value, _queue_rebuild)  # a reimport or a paint stroke changes it in place
		map = value
		_queue_rebuild()
		update_configuration_warnings()
## Rules that fill the map (grass by slope, trees by noise and away from paths, …): "Generate from
## rules" above the inspector writes what they place into the map file, keeping cells painted by
## hand since the last generation. Not read when the field builds: the map is what it draws.
@export var placement_rules: SunflowerPlacementRules
## The size of one map character on the ground (thesis: 0.5 m, four plants per square metre).
@export_range(0.05, 10.0, 0.01, "or_greater", "suffix:m") var cell_size: float = 0.5:
	set(value):
		value = Native.accept("SunflowerField.cell_size", value, cell_size)
		if value != cell_size:
			cell_size = value
			_tell(&"cell_size")
## Seed of the per-plant randomness (position jitter α, height, facing, wind phase). The same map
## and seed give the same field.
@export var seed: int = 1:
	set(value):
		if value != seed:
			seed = value
			_queue_rebuild()
## What other map symbols stand for; keys are single characters. A [PackedScene] is placed at the
## cell's centre (e.g. [code]{"S": preload("stone.tscn")}[/code], the thesis' "big stone"); a
## [SunflowerPlant] makes the cell a plant of that type (e.g. [code]{"m": preload("maize.tres")}[/code]),
## with its own levels of detail and impostors, sharing the field's LOD selection, wind and culling.
@export var legend: Dictionary = {}:
	set(value):
		if value == legend:
			return
		for old: SunflowerPlant in FieldLegend.plants(legend):
			if old.changed.is_connected(_on_plant_changed):
				old.changed.disconnect(_on_plant_changed)
		legend = value
		for grown: SunflowerPlant in FieldLegend.plants(legend):
			if not grown.changed.is_connected(_on_plant_changed):
				grown.changed.connect(_on_plant_changed)
		_driver.configure_plants(_species_plants())
		_queue_rebuild()
		update_configuration_warnings()
## The plant the field grows: its parts, form, variety and impostor textures. Empty: the built-in
## sunflower. A plant shared by several fields changes them all.
@export var plant: SunflowerPlant:
	set(value):
		if value == plant:
			return
		_listen(plant, value, _on_plant_changed)
		plant = value
		_on_plant_changed()
		if Engine.is_editor_hint():
			notify_property_list_changed()  # the inspector offers Bake impostors for a plant of its own
## The wind resource; share one between fields to give them the same weather. A field's own wind
## is saved with its scene only once a setting differs from the defaults.
@export var wind: SunflowerWind = SunflowerWind.new():
	set(value):
		if value == null:
			value = SunflowerWind.new()
		if value == wind:
			return
		_listen(wind, value, _tell_wind)
		wind = value
		_tell_wind()
## Wind power p_w: 0 is calm, 1.0 ≈ 1 m/s, at most 100. Stored in [member wind].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var wind_power: float:
	get:
		return wind.power
	set(value):
		wind.power = value
## Where the wind blows to, on the ground (x, z). Stored in [member wind].
@export var wind_direction: Vector2:
	get:
		return wind.direction
	set(value):
		wind.direction = value
## What one step of [method increase_wind] / [method decrease_wind] changes the power by.
## Stored in [member wind].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var wind_increment: float:
	get:
		return wind.increment
	set(value):
		wind.increment = value
## Where the plants stand. [b]Flat[/b]: on the node's plane (y = 0). [b]Colliders[/b]: where a ray
## straight down hits a physics body in [member ground_collision_mask], between
## [member ground_ray_above] and [member ground_ray_below] of the node — any terrain with collision
## (a HeightMapShape3D, a trimesh, a terrain plugin's). The rays run on the main thread, a
## share per frame (Project Settings: [code]sunflower_field/performance/build_budget_ms[/code]),
## from the physics frame after the build starts.
## [b]Height Map[/b]: on [member height_map], read on the build's worker thread. Cells with no
## ground under their plant (a hole, past the colliders or the map) get no plant; legend objects
## stand on the ground too.
@export var ground_source: GroundSource = GroundSource.FLAT:
	set(value):
		if value != ground_source:
			ground_source = value
			_queue_rebuild()
			notify_property_list_changed()  # its own settings show
## Colliders: the physics layers that are ground.
@export_flags_3d_physics var ground_collision_mask: int = 1:
	set(value):
		if value != ground_collision_mask:
			ground_collision_mask = value
			_queue_rebuild()
## Height Map: its red channel (0 to 1) is the height from [code]height_range.x[/code] to
## [code]height_range.y[/code] — as [method HeightMapShape3D.update_map_data_from_image] reads it, so
## one image can make both the collision and the field. Pixels with alpha below 0.5 are holes.
## Sampled bilinearly; the first and last pixels lie on [member height_map_rect]'s edges.
@export var height_map: Texture2D:
	set(value):
		if value != height_map:
			height_map = value
			_queue_rebuild()
## Height Map: the rectangle it covers in the node's space, x and z (an empty one: the whole map,
## from (0, 0) to columns × rows cells). A HeightMapShape3D of w × d heights at the node's origin
## spans [code]Rect2(-(w - 1) / 2, -(d - 1) / 2, w - 1, d - 1)[/code].
@export var height_map_rect: Rect2 = Rect2():
	set(value):
		if value != height_map_rect:
			height_map_rect = value
			_queue_rebuild()
## Height Map: the heights of red 0 and red 1.
@export var height_range: Vector2 = Vector2(0.0, 10.0):
	set(value):
		if value != height_range:
			height_range = value
			_queue_rebuild()
## Plants beyond this distance are not drawn (0: no limit); each dithers out over the last tenth
## of it (at least 2 m) by its own distance, so no chunk of plants vanishes at once.
@export_range(0.0, 10000.0, 1.0, "or_greater", "suffix:m") var max_draw_distance: float = 0.0:
	set(value):
		value = Native.accept("SunflowerField.max_draw_distance", value, max_draw_distance)
		if value != max_draw_distance:
			max_draw_distance = value
			_driver.set_draw_distance()
## The node distances are measured from. Empty: the viewport's active camera (in the editor, the
## editor camera). A [Camera3D] also culls plants outside its view.
@export var observer: NodePath:
	set(value):
		observer = value
		update_configuration_warnings()
## Nodes in this group part the plants around them, like a body walking through the field: near
## plants within the pusher's radius bend away from it and spring back once it has gone. A pusher's
## [code]push_radius[/code] meta sets its own radius. Empty: no pushers.
@export var pusher_group: StringName = &"sunflower_pushers"
@export_group("Advanced: layout")
## Jitter x and z independently (the thesis used one α for both).
@export var independent_jitter: bool = false:
	set(value):
		if value != independent_jitter:
			independent_jitter = value
			_queue_rebuild()
## Refuse maps with more sunflowers than this (0: the core's limit of 16 million).
@export_range(0, 100000000, 1) var max_plants: int = 4000000:
	set(value):
		value = Native.accept_int("SunflowerField.max_plants", value, max_plants)
		if value != max_plants:
			max_plants = value
			_tell(&"max_plants")
## Side of the square chunks the field is cut into: a chunk's plants turn near (each with its own
## level of detail and sway) or far together; far plants are drawn in tiles of 8 × 8 chunks, one
## draw call each. (A field of more than 65 536 chunks gets larger ones.)
@export_range(2.0, 256.0, 1.0, "or_greater", "suffix:m") var chunk_size: float = 16.0:
	set(value):
		value = Native.accept("SunflowerField.chunk_size", value, chunk_size)
		if value != chunk_size:
			chunk_size = value
			_tell(&"chunk_size")
## Far tiles merge with distance, so a wide field costs few draw calls: plants this far from the
## observer are drawn by merged tiles, 2 × 2 tiles as one MultiMesh holding a quarter of their
## plants, each drawn twice as wide to keep the field's cover; from twice it, 4 × 4 tiles with a
## sixteenth; and so on, until one tile covers the field. Over the half octave before each of these
## distances the plants the next level leaves out dither away one after another, each over a few
## metres, and the others widen, so no tile of plants switches at once and no plant vanishes in a
## frame. Each place is drawn by one tile: a merged tile once all its plants are at its distance,
## its children nearer (the tile draws each plant as its own distance says). A merged level that begins beyond the
## sun's shadows casts none: beyond the farthest [member DirectionalLight3D.directional_shadow_max_distance]
## of the shadow-casting directional lights in the field's viewport (100 m, Godot's default, without
## one), followed from frame to frame when a light changes. The merged tiles' copies of their
## plants add a third to the far plants' GPU memory on a field large enough to have them. 0: tiles
## never merge.
@export_range(0.0, 2000.0, 1.0, "or_greater", "suffix:m") var tile_merge_distance: float = 200.0:
	set(value):
		value = Native.accept("SunflowerField.tile_merge_distance", value, tile_merge_distance)
		if value != tile_merge_distance:
			tile_merge_distance = value
			_tell(&"tile_merge_distance")
@export_group("Advanced: ground")
## Colliders: how far above the node the rays start.
@export_range(0.0, 1000.0, 0.1, "or_greater", "suffix:m") var ground_ray_above: float = 100.0:
	set(value):
		value = Native.accept("SunflowerField.ground_ray_above", value, ground_ray_above)
		if value != ground_ray_above:
			ground_ray_above = value
			_tell(&"ground_ray_above")
## Colliders: how far below the node the rays end.
@export_range(0.0, 1000.0, 0.1, "or_greater", "suffix:m") var ground_ray_below: float = 100.0:
	set(value):
		value = Native.accept("SunflowerField.ground_ray_below", value, ground_ray_below)
		if value != ground_ray_below:
			ground_ray_below = value
			_tell(&"ground_ray_below")
## How far plants lean from upright towards the ground's normal: 0 keeps them upright (sunflowers
## do), 1 stands them along it.
@export_range(0.0, 1.0, 0.01) var ground_tilt: float = 0.0:
	set(value):
		value = Native.accept("SunflowerField.ground_tilt", value, ground_tilt)
		if value != ground_tilt:
			ground_tilt = value
			_tell(&"ground_tilt")
@export_group("Advanced: look")
## Alpha below which sprite and billboard pixels are discarded (thesis: 190/255).
@export_range(0.0, 1.0, 0.001) var alpha_scissor: float = 190.0 / 255.0:
	set(value):
		alpha_scissor = Native.accept("SunflowerField.alpha_scissor", value, alpha_scissor)
		_driver.set_impostor_shared(&"alpha_scissor", alpha_scissor)
## Near plants at mesh level 1 or 2 cast their shadows from their mesh 3 (the shadow of a plant a
## few shadow-map texels wide looks the same, at a quarter of the triangles); off: each casts from the
## mesh it is drawn with.
@export var cheap_shadows: bool = true:
	set(value):
		if value != cheap_shadows:
			cheap_shadows = value
			_queue_rebuild()
## Near plants drawn at this level or coarser cast their shadows from their impostors (two
## triangles each: the plant's silhouette seen from the sun, each pixel at the depth the plant has
## there) instead of a mesh, from the distance where they switch to it (less [member lod_hysteresis]
## and a metre) on; nearer levels cast from their meshes (from mesh 3 with [member cheap_shadows]).
## From mesh 3 (the default) the million-plant field at head height draws 0.47× the primitives of
## full-detail shadows. Never, with [member cheap_shadows] off: every plant casts from the mesh it is
## drawn with.
@export_enum("Mesh 2:1", "Mesh 3:2", "Never:3") var impostor_shadows_from: int = 2:
	set(value):
		var used: int = clampi(value, SunflowerField.Lod.MESH_2, SunflowerField.Lod.SPRITE)
		if used != value:
			push_warning(
				"SunflowerField.impostor_shadows_from: %d is not 1–3 (Mesh 2, Mesh 3, Never); using %d" % [value, used]
			)
			value = used
		if value != impostor_shadows_from:
			impostor_shadows_from = value
			_driver.send_near_shadows()
@export_group("Advanced: levels of detail")
## Switch distances: mesh 1 → 2, mesh 2 → 3, mesh 3 → sprite, sprite → billboard (thesis:
## 6, 10, 20, 25 m) for a plant of the sunflower's 2 m; each plant type switches at these times its
## [method SunflowerPlant.lod_scale_used] (its size over 2 m unless its [member SunflowerPlant.lod_scale]
## says otherwise). Must increase.
@export var lod_distances: PackedFloat32Array = DEFAULT_LOD_DISTANCES:
	set(value):
		var problem: String = Native.check_lod_distances(value)
		if not problem.is_empty():
			push_warning("SunflowerField.lod_distances: %s; keeping %s" % [problem, lod_distances])
			return
		if value != lod_distances:
			lod_distances = value
			_tell(&"lod_distances")
## Hysteresis on every switch: less detail this much later, more detail this much earlier.
@export_range(0.0, 5.0, 0.05, "or_greater", "suffix:m") var lod_hysteresis: float = 0.5:
	set(value):
		value = Native.accept("SunflowerField.lod_hysteresis", value, lod_hysteresis)
		if value != lod_hysteresis:
			lod_hysteresis = value
			_tell(&"lod_hysteresis")
## Metres over which a plant leaving mesh 3 dithers into its impostor (both drawn, complementary
## screen-door patterns), ending at the sprite switch less [member lod_hysteresis]: no plant pops
## from mesh to impostor. Plants drawn whole ([member SunflowerPlant.draw_whole]) also dither from mesh 1
## into 2 and from 2 into 3, over as large a share of this as the switch distance is of the sprite
## switch's. Plant materials fade when they dither by the instance colour's alpha, as the addon's
## [code]shaders/plant_parts.gdshader[/code] does (the built-in plants use it, and plain
## StandardMaterial3D parts are drawn with it); a ShaderMaterial of your own fades with one line,
## [code]plant_fade_discards[/code] of [code]shaders/screen_door.gdshaderinc[/code]; other materials
## switch at once. 0 turns the fades off.
@export_range(0.0, 10.0, 0.1, "or_greater", "suffix:m") var lod_fade: float = 3.0:
	set(value):
		value = Native.accept("SunflowerField.lod_fade", value, lod_fade)
		if value != lod_fade:
			lod_fade = value
			_tell(&"lod_fade")
## Seconds between LOD updates (thesis: 0.25 s). Plants move every frame regardless.
@export_range(0.0, 2.0, 0.01, "or_greater", "suffix:s") var lod_interval: float = 0.25:
	set(value):
		value = Native.accept("SunflowerField.lod_interval", value, lod_interval)
		if value != lod_interval:
			lod_interval = value
			_tell(&"lod_interval")
## Draw every plant as one representation, whatever its distance (for benchmarks and debugging).
@export_enum("Automatic:-1", "Mesh 1:0", "Mesh 2:1", "Mesh 3:2", "Sprite:3", "Billboard:4") var force_lod: int = -1:
	set(value):
		value = Native.accept_int("SunflowerField.force_lod", value, force_lod)
		if value != force_lod:
			force_lod = value
			_tell(&"force_lod")
## Skip writing plants outside the observer camera's view (the engine culls the far chunks itself).
@export var frustum_culling: bool = true
## Beyond this distance, draw only a share of the impostors, falling with the square of the
## distance (down to [member thinning_min_density]); the kept ones widen to keep the coverage.
## Done on the GPU, so it costs no CPU time. 0 turns thinning off.
@export_range(0.0, 1000.0, 1.0, "or_greater", "suffix:m") var thinning_distance: float = 0.0:
	set(value):
		thinning_distance = Native.accept("SunflowerField.thinning_distance", value, thinning_distance)
		_driver.set_thinning_start()
## The least share of impostors drawn far away, with thinning on.
@export_range(0.01, 1.0, 0.01) var thinning_min_density: float = 0.25:
	set(value):
		thinning_min_density = Native.accept("SunflowerField.thinning_min_density", value, thinning_min_density)
		_driver.set_impostor_shared(&"thinning_min_density", thinning_min_density)
@export_group("Advanced: interaction")
## A pusher's radius when it sets none.
@export_range(0.01, 20.0, 0.01, "or_greater", "suffix:m") var pusher_radius: float = 0.6:
	set(value):
		pusher_radius = Native.accept("SunflowerField.pusher_radius", value, pusher_radius)
## A pusher pushes over (tramples: flattens) the standing plants whose roots lie within this share of
## its radius, and [signal SunflowerFieldPlay.plants_trampled] tells which (running game only). Trampled plants lie bent
## until their type's [member SunflowerPlant.recover_after]. 0: pushers only bend plants.
@export_range(0.0, 1.0, 0.01) var trample_share: float = 0.0:
	set(value):
		trample_share = Native.accept("SunflowerField.trample_share", value, trample_share)
## How far a pusher bends the plants at its centre (a bend, like the wind's: 0.8 tilts a plant about
## 45°); it falls to 0 at the pusher's radius.
@export_range(0.0, 10.0, 0.01) var push_strength: float = 1.2:
	set(value):
		value = Native.accept("SunflowerField.push_strength", value, push_strength)
		if value != push_strength:
			push_strength = value
			_tell(&"push_strength")
## Seconds a plant takes to spring back upright once the pusher has gone.
@export_range(0.05, 60.0, 0.05, "suffix:s") var push_recovery_time: float = 1.5:
	set(value):
		value = Native.accept("SunflowerField.push_recovery_time", value, push_recovery_time)
		if value != push_recovery_time:
			push_recovery_time = value
			_tell(&"push_recovery_time")
## Stalks within this distance of a pusher or the observer get capsule colliders (running game
## only), so characters bump into them and ray casts hit them ([method get_plant_for_body]). 0: none.
@export_range(0.0, 100.0, 0.1, "or_greater", "suffix:m") var collision_reach: float = 0.0:
	set(value):
		collision_reach = Native.accept("SunflowerField.collision_reach", value, collision_reach)
## The physics layers the stalk colliders are in.
@export_flags_3d_physics var collision_layer: int = 1
## The physics layers the stalk colliders scan.
@export_flags_3d_physics var collision_mask: int = 1

var _own_wind: SunflowerWind  # the wind the node made itself, saved only once it is changed


func _init() -> void:
	_own_wind = wind
	_driver.build_progress.connect(build_progress.emit)
	_driver.built.connect(_on_built)
	_driver.map_error.connect(_on_map_error)
	_driver.quality_changed.connect(quality_changed.emit)
	wind.changed.connect(_tell_wind)
	_driver.configure_plants(_species_plants())
	_driver.set_impostor_shared(&"alpha_scissor", alpha_scissor)
	_driver.set_thinning_start()
	_driver.set_impostor_shared(&"thinning_min_density", thinning_min_density)
	set_notify_transform(true)  # the far impostors are placed through the field's transform


func _tell_wind() -> void:
	_driver.send_settings(FieldSettings.rows_of(wind, "SunflowerWind"))


func _on_built(plants: int) -> void:
	update_configuration_warnings()
	field_built.emit(plants)


func _on_map_error(message: String) -> void:
	map_error.emit(message)
	update_configuration_warnings()


func _validate_property(property: Dictionary) -> void:
	FieldFace.validate_property(self, property, _own_wind)


func _property_can_revert(property: StringName) -> bool:
	return FieldFace.can_revert(self, property, _own_wind)


func _property_get_revert(property: StringName) -> Variant:
	return FieldFace.revert_value(self, property, _own_wind)


## Reads a map from [param path] ([code]res://[/code], [code]user://[/code] or an absolute path)
## and builds the field. On error the current field stays, [signal map_error] is emitted and the
## error is returned. The build completes before this returns, unless [param background] is true
## (and the project setting [code]sunflower_field/performance/background_build[/code] on): then
## [signal field_built] tells when it is ready.
func load_map_file(path: String, background: bool = false) -> Error:
	var errors: Array[String] = []
	var field_map: SunflowerFieldMap = SunflowerFieldMap.from_file(path, errors)
	if field_map == null:
		_driver.report_map_error(errors[0])
		return ERR_FILE_CANT_OPEN
	var message: String = field_map.check(
		FieldLegend.object_symbols(legend) + FieldLegend.plant_symbols(legend), max_plants
	)
	if not message.is_empty():
		_driver.report_map_error(message)
		return ERR_PARSE_ERROR
	map = field_map
	_driver.rebuild(background)
	return OK


## The fields building in the background now (for progress displays such as the editor's).
static func get_building_fields() -> Array[SunflowerField]:
	var fields: Array[SunflowerField] = []
	for field: Node3D in FieldDriver.building:
		if is_instance_valid(field) and field.is_inside_tree():
			fields.append(field as SunflowerField)
	return fields


## Adds [member wind_increment] to the wind power.
func increase_wind() -> void:
	wind_power = wind_power + wind_increment


## Subtracts [member wind_increment] from the wind power.
func decrease_wind() -> void:
	wind_power = wind_power - wind_increment


func _get_configuration_warnings() -> PackedStringArray:
	return FieldFace.configuration_warnings(self, _driver.last_error, _driver.observer_node())


# --- The plant ------------------------------------------------------------------------------------


## The plant types grown, species by species: the [member plant] ('*'), then the legend's.
func _species_plants() -> Array:
	var plants: Array = [plant if plant else SunflowerPlant.default_plant()]
	plants.append_array(FieldLegend.plants(legend))
	return plants


func _on_plant_changed() -> void:
	if _driver.configure_plants(_species_plants()):
		_queue_rebuild()
	update_configuration_warnings()


# Scenes saved by older versions carry names that are gone (field_face.gd takes them).
func _get(property: StringName) -> Variant:
	return FieldFace.former_value(self, property)


func _set(property: StringName, value: Variant) -> bool:
	return FieldFace.set_former(self, property, value)
