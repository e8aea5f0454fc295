@tool
extends Node3D
## The run-time half of [SunflowerField], whose script holds its settings, signals and what the
## editor shows: the driver behind the node (the field drawn, the build that replaces it, each
## frame), the node's life in the scene tree, and what a game or tool asks of the field drawn —
## builds, counts, plants, figures, part meshes, the bake. A user meets both halves as one
## SunflowerField (the API reference lists them on one page); the split keeps each script to one job.

## The three parts of a plant, bottom to top (the native core's part indices).
enum Part { BOTTOM, MIDDLE, HEAD }
## The five representations, most detailed first (the native core's levels).
enum Lod { MESH_1, MESH_2, MESH_3, SPRITE, BILLBOARD }

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")
const FieldDriver: GDScript = preload("field_driver.gd")
const ProjectKnobs: GDScript = preload("field_project_settings.gd")
const PartMeshes: GDScript = preload("../plant/part_meshes.gd")

## What the running game does to the plants: cut, flatten, remove and give back plants, its events
## (trampled, changed, recovered, pushers in and out), regrowth's clock and the save (see
## [SunflowerFieldPlay]).
var play: SunflowerFieldPlay:
	get:
		return _driver.play
## The plant's height from root to head, metres: the [member plant]'s [member SunflowerPlant.height]
## (setting it gives the field its own copy of the plant).
var plant_height: float:
	get:
		return _plant().height
	set(value):
		_own_plant().height = value
## The far levels' views of the plant: the [member plant]'s [member SunflowerPlant.impostor_views]
## (setting it gives the field its own copy of the plant).
var impostor_views: Texture2D:
	get:
		return _plant().texture_drawn("views")
	set(value):
		_own_plant().impostor_views = value
## The far levels' normals: the [member plant]'s [member SunflowerPlant.impostor_normals].
var impostor_normals: Texture2D:
	get:
		return _plant().texture_drawn("normals")
	set(value):
		_own_plant().impostor_normals = value
## The far levels' depths: the [member plant]'s [member SunflowerPlant.impostor_depths].
var impostor_depths: Texture2D:
	get:
		return _plant().texture_drawn("depths")
	set(value):
		_own_plant().impostor_depths = value

# Everything behind the public face: builds, the field drawn, each frame, impostors, part meshes.
var _driver: FieldDriver = FieldDriver.new(self)
var _empty_simulation: RefCounted


## Whether a new field is due (a change waits for the next frame) or being built in the
## background; the previous field is drawn meanwhile.
func is_building() -> bool:
	return _driver.build != null or (_driver.rebuild_queued and is_inside_tree())


## How far the coming field is, from 0 to 1 (1 when no build is due or running).
func get_build_progress() -> float:
	if _driver.build == null:
		return 0.0 if is_building() else 1.0
	return _driver.build.get_progress()


## Completes a running background build now, blocking until the field is ready.
func finish_build() -> void:
	if _driver.rebuild_queued:
		_driver.rebuild()
	if _driver.build:
		_driver.step_build(-1)


## Figures of the last build: [code]total_ms[/code] (start to [signal field_built]),
## [code]worker_ms[/code] (reading and laying out the map), [code]main_thread_ms[/code] (making
## nodes and buffers), [code]longest_step_ms[/code] (the longest the build held up one frame),
## [code]frames[/code] (frames it spanned), [code]background[/code], [code]ground_ray_ms[/code]
## (main-thread time casting rays at colliders) and [code]cells_without_ground[/code] (plant cells
## with no ground under their plant, so no plant).
func get_build_stats() -> Dictionary:
	return _driver.stats.duplicate()


## Number of plants in the field.
func get_plant_count() -> int:
	return _driver.plant_count()


## Plants per representation (mesh 1, mesh 2, mesh 3, sprite, billboard). Every plant is counted
## once, whether or not it is in view.
func get_lod_counts() -> PackedInt32Array:
	if get_plant_count() == 0:
		var zeros: PackedInt32Array = PackedInt32Array()
		zeros.resize(Lod.size())
		return zeros
	return _driver.simulation().get_lod_counts()


## The share of its distances the field draws with now: 1 unless a frame budget
## lowered it. The frame budget is the project's (Project Settings, [code]sunflower_field/frame_budget/[/code]:
## [code]max_primitives[/code], the most triangles the near meshes of a viewport's fields may hold in a
## frame together, the main view's; [code]gpu_ms[/code], the milliseconds the viewport may take on the
## GPU, as the engine measures it, smoothed over about 0.15 s; [code]min_quality[/code]), held by one
## quality per viewport that every field there draws at: a scalar scaling [member lod_distances],
## [member lod_fade], [member thinning_distance] and [member max_draw_distance] together, lowered in
## steps of at most 30 % four times a second and given back in steps of at most 10 % after a second
## with 30 % headroom, never straight back to a quality that went over in the last 10 s (unless a
## target changed), so it settles instead of pumping. Off in the editor.
func get_quality() -> float:
	return _driver.quality()


## What the field drawn costs now, for a HUD or a benchmark: [code]update_ms[/code] (the native
## update and draw of the last frame), [code]worker_threads[/code] (the threads it ran on: the project
## setting [code]sunflower_field/performance/worker_threads[/code] resolved), [code]memory_bytes[/code]
## (CPU memory the native field holds),
## [code]near_meshes[/code] (plants written at each mesh level last frame, after culling: three
## counts, every plant type together), [code]near_primitives[/code] (their triangles, what
## the frame budget's [code]max_primitives[/code] caps, with the viewport's other fields'),
## [code]gpu_ms[/code] (the smoothed GPU time the budget saw, 0 without a GPU target) and
## [code]quality[/code] ([method get_quality]). Zeros before a
## field is drawn.
func get_frame_stats() -> Dictionary:
	return _driver.frame_stats()


## Plants per representation for each plant type of [method get_plant_types] (five counts each, as
## [method get_lod_counts]).
func get_lod_counts_by_species() -> Array[PackedInt32Array]:
	var counts: Array[PackedInt32Array] = []
	var flat: PackedInt32Array = _driver.simulation().get_lod_counts_by_species() if get_plant_count() > 0 else []
	for species: int in _driver.plants.size():
		var own: PackedInt32Array = flat.slice(species * Lod.size(), (species + 1) * Lod.size())
		own.resize(Lod.size())
		counts.append(own)
	return counts


## A plant's state in the field's space: [code]position[/code] (Vector3, its root),
## [code]lod[/code] (0–4, see [enum Lod]) and [code]parts[/code] (three [Transform3D], bottom to
## top, as drawn now; upright for sprites and billboards).
func get_plant_info(index: int) -> Dictionary:
	if index < 0 or index >= get_plant_count():
		push_error("SunflowerField.get_plant_info: index %d is out of range (%d plants)" % [index, get_plant_count()])
		return {}
	return {
		"position": _driver.simulation().get_plant_position(index),
		"lod": _driver.simulation().get_plant_lod(index),
		"parts": Native.unpack_transforms(_driver.simulation().get_plant_parts(index)),
	}


## Runs one update now, [param delta] seconds long (for tools and tests; the node also updates
## itself every frame).
func advance(delta: float) -> void:
	finish_build()
	_driver.update_field(delta)


## Plants pushed by bodies now or still springing back.
func get_pushed_count() -> int:
	return _driver.simulation().get_pushed_count() if _driver.drawn else 0


## The plant whose root is nearest to [param point] (field space, on the ground) within
## [param max_distance] metres, or -1. A plant cut or removed at run time is not there; a flattened
## one is (see [method SunflowerFieldPlay.get_cell_state]).
func get_plant_at(point: Vector3, max_distance: float = 0.5) -> int:
	return _driver.nearest_plant(point, max_distance)


## The plant whose stalk collider is [param body] (a ray cast's or a collision's [code]rid[/code],
## see [member collision_reach]), or -1; -1 too for a plant flattened, cut or removed since (its
## collider goes at the field's next frame).
func get_plant_for_body(body: RID) -> int:
	var plant: int = _driver.interaction.get_plant_of_body(body)
	if plant < 0 or play.get_cell_state(play.get_cell_of_plant(plant))["state"] != SunflowerFieldPlay.State.STANDING:
		return -1
	return plant


## How many stalk colliders stand now (see [member collision_reach]).
func get_collider_count() -> int:
	return _driver.interaction.get_collider_count()


## The native simulation behind the field drawn now ([code]SunflowerSimulation[/code], for tools and
## tests); an empty one before the first field is built, null without the native library.
func get_simulation() -> RefCounted:
	if _driver.drawn:
		return _driver.simulation().native
	if _empty_simulation == null:
		_empty_simulation = Native.create_simulation()
	return _empty_simulation


func _ready() -> void:
	if not Native.is_available():
		Native.report_missing()  # once per run, however many fields
	_queue_rebuild()


func _notification(what: int) -> void:
	if what == NOTIFICATION_PREDELETE:
		_driver.cancel_build()
		_driver.show(null)
		_driver.interaction.free_colliders()
	elif what == NOTIFICATION_EXIT_TREE:
		_driver.interaction.free_colliders()  # they stand in this world's physics space
	elif what == NOTIFICATION_TRANSFORM_CHANGED or what == NOTIFICATION_ENTER_TREE:
		_driver.place_impostors()


func _process(delta: float) -> void:
	_driver.process(delta, ProjectKnobs.build_budget_ms())


func _queue_rebuild() -> void:
	_driver.rebuild_queued = true


## [param action] follows the [signal Resource.changed] of [param new] instead of [param old]'s.
static func _listen(old: Resource, new: Resource, action: Callable) -> void:
	if old and old.changed.is_connected(action):
		old.changed.disconnect(action)
	if new and not new.changed.is_connected(action):
		new.changed.connect(action)


## Tells the field drawn that [param property], a row of the core's table, changed (the core says
## what that costs: field_settings.gd).
func _tell(property: StringName) -> void:
	_driver.send_settings({"SunflowerField." + property: get(property)})


## The plant types grown, species by species: [member plant] (the map's '*'), then the legend's
## plants in its order. [method get_lod_counts_by_species] follows this order.
func get_plant_types() -> Array[SunflowerPlant]:
	var types: Array[SunflowerPlant] = []
	types.assign(_driver.plants)
	return types


## Replaces one part mesh, like the thesis' [code]setSunflower[/code]: [param lod] 0–2 (mesh level),
## [param part] 0–2 (see [enum Part]). [code]null[/code] empties the slot (it draws nothing). Parts
## are modelled with their root at the origin, growing along +y.
func set_part_mesh(lod: int, part: int, mesh: Mesh) -> void:
	if PartMeshes.check(lod, part, "set_part_mesh"):
		_own_plant().set_part_mesh(lod, part, mesh)


## The mesh drawn for a part (the built-in sunflower's where the plant has none).
func get_part_mesh(lod: int, part: int) -> Mesh:
	return _plant().mesh_drawn(lod, part) if PartMeshes.check(lod, part, "get_part_mesh") else null


## Renders the field's plant's impostor textures from its level-1 parts (after [method set_part_mesh]
## at run time, say) and draws them; await it. A field growing the built-in sunflower gets its own
## copy first. Files go beside the plant's resource, else to [code]user://[/code]. Needs a renderer.
func bake_impostors() -> Error:
	return await _own_plant().bake_impostors(self)


# --- The plant ------------------------------------------------------------------------------------


## The plant grown: the node's [code]plant[/code], else the built-in sunflower (species 0 of the
## plant types the driver draws, told by the node whenever they change).
func _plant() -> SunflowerPlant:
	return _driver.plants[0]


## The plant, made this field's own first when it is the shared built-in sunflower (so changing it
## through the node's proxies changes no other field): a copy set as the node's [code]plant[/code].
func _own_plant() -> SunflowerPlant:
	if _plant() == SunflowerPlant.default_plant():
		set(&"plant", SunflowerPlant.default_plant().duplicate())
	return _plant()
