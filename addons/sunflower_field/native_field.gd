# gdlint: disable=max-public-methods, function-arguments-number
# (one method per native method the addon calls, with its signature)
@tool
extends RefCounted
## The one script that calls the native simulation ([code]SunflowerSimulation[/code]), with typed
## signatures: every other script of the addon holds a NativeField, so it parses (and its calls are
## checked) where no library fits the platform. Each method is the native one of the same name; the
## class reference of [code]SunflowerSimulation[/code] says more.

const Native: GDScript = preload("native.gd")

## The native simulation itself, for tools and tests ([method SunflowerField.get_simulation]).
var native: RefCounted


## A new simulation, or null (with the one missing-library error) when there is no library.
static func create() -> RefCounted:
	var simulation: RefCounted = Native.create_simulation()
	return new(simulation) if simulation != null else null


func _init(simulation: RefCounted) -> void:
	native = simulation


## Parses a field map (see [code]fields/FORMAT.md[/code]) and lays out its plants.
func load_map(text: PackedByteArray, source: String, legend: String, plant_symbols: String, max_plants: int) -> String:
	return native.load_map(text, source, legend, plant_symbols, max_plants)


## The plant types of the map read.
func get_species_count() -> int:
	return native.get_species_count()


## Columns of the loaded map.
func get_map_columns() -> int:
	return native.get_map_columns()


## Rows of the loaded map.
func get_map_rows() -> int:
	return native.get_map_rows()


## Cells holding legend symbols, as triples (column, row, unicode code point).
func get_map_objects() -> PackedInt32Array:
	return native.get_map_objects()


## Settings by their rows of the core's table ([code]field_settings.gd[/code] sends them): the
## largest cost (0 free, 1 a rebuild: those rows were not applied), -1 when refused.
func set_settings(species: int, rows: PackedInt32Array, values: PackedFloat32Array) -> int:
	return native.set_settings(species, rows, values)


## The random seed and whether x and z get independent jitter (the thesis uses one α for both).
func set_layout_seed(layout_seed: int, independent_jitter: bool) -> void:
	native.set_layout_seed(layout_seed, independent_jitter)


## Stands the plants on the plane y = 0 of the field's space (the default).
func set_ground_flat() -> void:
	native.set_ground_flat()


## Stands the plants on a height map.
func set_ground_height_map(
	rgba: PackedFloat32Array,
	width: int,
	depth: int,
	origin: Vector2,
	size: Vector2,
	height_min: float,
	height_max: float,
	tilt: float
) -> String:
	return native.set_ground_height_map(rgba, width, depth, origin, size, height_min, height_max, tilt)


## Stands the plants on heights measured elsewhere (rays at colliders).
func set_ground_heights(heights: PackedFloat32Array, normals: PackedFloat32Array, tilt: float) -> String:
	return native.set_ground_heights(heights, normals, tilt)


## Where the ground is asked for, x and z in the field's space.
func get_ground_points() -> PackedFloat32Array:
	return native.get_ground_points()


## Plant cells of the map with no ground under their plant, which therefore have no plant.
func get_cells_without_ground() -> int:
	return native.get_cells_without_ground()


## The ground's height at [param point] (x, z of the field's space).
func get_ground_height(point: Vector2) -> float:
	return native.get_ground_height(point)


## The ground's height under each legend object of the map (its cell's centre), in map order.
func get_object_heights() -> PackedFloat32Array:
	return native.get_object_heights()


## The field-wide wind the impostor shader sways far plants with, after the last update.
func get_wind_state() -> PackedFloat32Array:
	return native.get_wind_state()


## Whether a species' near plants are drawn whole.
func set_plant_whole(species: int, whole: bool) -> void:
	native.set_plant_whole(species, whole)


## A species' switch distances are the field's times [param scale] (not positive: unchanged).
func set_plant_lod_scale(species: int, scale: float) -> void:
	native.set_plant_lod_scale(species, scale)


## The observer's position and view frustum in the field's space.
func set_observer(position: Vector3, frustum: PackedFloat32Array) -> void:
	native.set_observer(position, frustum)


## The frame budget's quality the switch distances and fade are drawn at (0–1].
func set_quality(quality: float) -> void:
	native.set_quality(quality)


## Where a plant of [param species] turns finer at [param switch] (0: mesh 1 → 2 … 3: sprite →
## billboard), coming nearer: the switch at the quality less the hysteresis, at the type's scale.
func get_finer_distance(species: int, switch: int) -> float:
	return native.get_finer_distance(species, switch)


## Bodies the plants part around, four floats each (x, y, z, radius) in the field's space, from the
## next [method update] on.
func set_pushers(pushers: PackedFloat32Array) -> void:
	native.set_pushers(pushers)


## Plants pushed now or still springing back (only these hold push state).
func get_pushed_count() -> int:
	return native.get_pushed_count()


## The plants whose roots lie within [param radius] metres of [param position] on the ground (its
## height ignored): not one cut or removed at run time, nor, with [param standing_only], one flattened.
func get_plants_near(position: Vector3, radius: float, standing_only: bool = false) -> PackedInt32Array:
	return native.get_plants_near(position, radius, standing_only)


## The MultiMesh that receives a dynamic bucket.
func set_bucket_multimesh(bucket: int, multimesh: RID) -> void:
	native.set_bucket_multimesh(bucket, multimesh)


## A second MultiMesh for a bucket, given the same instances every update (a shadow-only node).
func set_bucket_shadow_multimesh(bucket: int, multimesh: RID) -> void:
	native.set_bucket_shadow_multimesh(bucket, multimesh)


## The static MultiMesh of a far tile's impostors (sprites and billboards are one multi-view
## impostor).
func set_tile_multimesh(tile: int, multimesh: RID) -> void:
	native.set_tile_multimesh(tile, multimesh)


## Like [method set_tile_multimesh] for a MultiMesh that already holds this tile's instances
## (another simulation's tile of equal key and signature in [method get_tile_ids]).
func adopt_tile_multimesh(tile: int, multimesh: RID) -> void:
	native.adopt_tile_multimesh(tile, multimesh)


## Number of far tiles.
func get_tile_count() -> int:
	return native.get_tile_count()


## The far tiles' identities, read once per build.
func get_tile_ids() -> PackedInt64Array:
	return native.get_tile_ids()


## The far tiles' places, read once per build.
func get_tile_places() -> PackedFloat32Array:
	return native.get_tile_places()


## The field's merge rule, for the impostor shader's [code]tile_merge[/code] after a tile's own
## level.
func get_tile_merge_rule() -> PackedFloat32Array:
	return native.get_tile_merge_rule()


## Which of a species' chunks are active now.
func get_active_mask(species: int) -> PackedByteArray:
	return native.get_active_mask(species)


## Play's [param action] (0 stand, 1 flatten, 2 cut, 3 remove, 4 as the map) on map cells at the
## field's clock [param now]; the cells changed.
func change_cells(cells: PackedInt32Array, action: int, now: float) -> PackedInt32Array:
	return native.change_cells(cells, action, now)


## Puts a standing plant of type [param species] in each of [param cells]; the cells changed. Those
## with no ground height known wait: [method get_unplaced_cells].
func put_cells(cells: PackedInt32Array, species: int) -> PackedInt32Array:
	return native.put_cells(cells, species)


## Cells given a plant that stands nowhere yet for want of a ground height, in cell order.
func get_unplaced_cells() -> PackedInt32Array:
	return native.get_unplaced_cells()


## Where the plants of [param cells] stand: x, z pairs in the field's space.
func get_cell_roots(cells: PackedInt32Array) -> PackedFloat32Array:
	return native.get_cell_roots(cells)


## The ground's [param heights] under [param cells] (NaN: not known); their plants put stand there.
func set_cell_heights(cells: PackedInt32Array, heights: PackedFloat32Array) -> void:
	native.set_cell_heights(cells, heights)


## The clock moved to [param now]: the cells whose plants stood again by regrowth.
func advance_changes(now: float) -> PackedInt32Array:
	return native.advance_changes(now)


## A cell after play: x its plant (0 none, 1 + type), y its state, z the clock when it took it.
func get_cell_change(cell: int) -> Vector3:
	return native.get_cell_change(cell)


## How many cells differ from the map.
func get_change_count() -> int:
	return native.get_change_count()


## The map cells whose centres lie within [param radius] of [param center] (x, z).
func get_cells_in_circle(center: Vector2, radius: float) -> PackedInt32Array:
	return native.get_cells_in_circle(center, radius)


## The map cells whose centres lie between [param min] and [param max] (x, z).
func get_cells_in_rect(min: Vector2, max: Vector2) -> PackedInt32Array:
	return native.get_cells_in_rect(min, max)


## The pushers push over the standing plants within [param share] of their radius: cell and pusher
## index, two ints a plant.
func trample(share: float, now: float) -> PackedInt32Array:
	return native.trample(share, now)


## A plant's map cell, or -1.
func get_plant_cell(plant: int) -> int:
	return native.get_plant_cell(plant)


## The save of the changes at the clock [param now].
func save_changes(now: float) -> PackedByteArray:
	return native.save_changes(now)


## Loads a save of [method save_changes]: "" or what is wrong (nothing changed then).
func load_changes(bytes: PackedByteArray) -> String:
	return native.load_changes(bytes)


## The clock of the save loaded last.
func get_loaded_clock() -> float:
	return native.get_loaded_clock()


## The cells whose plant play took down, a bit each: rows of ceil(columns / 8) bytes (empty until
## the first change); the impostors hide their plants.
func get_hidden_cells() -> PackedByteArray:
	return native.get_hidden_cells()


## Changes whenever a bit of [method get_hidden_cells] does.
func get_hidden_version() -> int:
	return native.get_hidden_version()


## Per tile, 1 when it has a plant to draw now, 0 when all its chunks are active (hide its node.
func get_tiles_drawn() -> PackedByteArray:
	return native.get_tiles_drawn()


## Changes whenever a chunk turns active or static, or the field is rebuilt.
func get_mask_version() -> int:
	return native.get_mask_version()


## The chunk grid's size in cells (x, z).
func get_chunk_grid() -> PackedInt32Array:
	return native.get_chunk_grid()


## Computes every chunk's signature now (a build's worker does it, so comparisons on the main
## thread are cheap).
func compute_chunk_signatures() -> void:
	native.compute_chunk_signatures()


## Forgets every MultiMesh RID, before the MultiMeshes are freed.
func release_multimeshes() -> void:
	native.release_multimeshes()


## Advances the field by [param delta] seconds and writes the MultiMesh buffers.
func update(delta: float) -> void:
	native.update(delta)


## Number of plants.
func get_plant_count() -> int:
	return native.get_plant_count()


## Plants per representation (mesh 1, mesh 2, mesh 3, sprite, billboard).
func get_lod_counts() -> PackedInt32Array:
	return native.get_lod_counts()


## Plants per representation for each species in turn ([constant LOD_COUNT] counts each).
func get_lod_counts_by_species() -> PackedInt32Array:
	return native.get_lod_counts_by_species()


## A plant's root in the field's space.
func get_plant_position(plant: int) -> Vector3:
	return native.get_plant_position(plant)


## A plant's stalk in metres, upright, for its collider: x its radius, y the height from its root to
## its head.
func get_plant_stalk(plant: int) -> Vector2:
	return native.get_plant_stalk(plant)


## The representation a plant is drawn in (0–4).
func get_plant_lod(plant: int) -> int:
	return native.get_plant_lod(plant)


## The three part transforms (bottom, middle, head) as 3 × 12 floats, each a row-major 3×4 matrix
## as in MultiMesh buffers.
func get_plant_parts(plant: int) -> PackedFloat32Array:
	return native.get_plant_parts(plant)


## Which dynamic buckets hold instances after the last [method update], one byte per bucket
## ([constant BUCKET_COUNT] per species, species by species).
func get_filled_buckets() -> PackedByteArray:
	return native.get_filled_buckets()


## Instances written into a dynamic bucket last frame.
func get_bucket_instance_count(bucket: int) -> int:
	return native.get_bucket_instance_count(bucket)


## The threads the near plants are moved on, the caller included.
func get_worker_threads() -> int:
	return native.get_worker_threads()


## How long the last update took, microseconds.
func get_last_update_usec() -> int:
	return native.get_last_update_usec()


## CPU memory held for the field, in bytes.
func get_memory_bytes() -> int:
	return native.get_memory_bytes()
