#pragma once
// SunflowerSimulation: the engine-facing face of the core FieldSimulation. Configured once by the
// SunflowerField node, updated once per frame; pushes the instance buffers to the RenderingServer
// itself, so no per-frame arrays travel through GDScript.
#include "binding/godot_api.h"
#include "core/field_simulation.h"
#include "core/tile_reorder.h"

#include <vector>

class SunflowerSimulation {
public:
	static void bind_methods();

	gdx::String load_map(const gdx::PackedByteArray &p_text, const gdx::String &p_source, const gdx::String &p_legend,
			const gdx::String &p_plant_symbols, int64_t p_max_plants);
	int64_t get_species_count() const;
	int64_t get_map_columns() const;
	int64_t get_map_rows() const;
	gdx::PackedInt32Array get_map_objects() const;

	// Settings by their rows of the core's table (get_parameter_names' order): p_values holds each
	// row's components in turn (get_parameter_components); a plant type's rows are p_species'. The
	// core routes each to the unit that owns it (FieldSimulation::set_setting). Returns the largest
	// cost (0 free, 1 a rebuild: those rows were not applied, the caller builds anew), or -1 with an
	// error and nothing set when the rows and values do not match.
	int64_t set_settings(int64_t p_species, const gdx::PackedInt32Array &p_rows, const gdx::PackedFloat32Array &p_values);
	// The layout's seed and jitter, which are not the table's (a seed is any 64-bit integer).
	void set_layout_seed(int64_t p_seed, bool p_independent_jitter);
	void set_ground_flat();
	gdx::String set_ground_height_map(const gdx::PackedFloat32Array &p_rgba, int64_t p_width, int64_t p_depth, gdx::Vector2 p_origin,
			gdx::Vector2 p_size, double p_height_min, double p_height_max, double p_tilt);
	gdx::String set_ground_heights(const gdx::PackedFloat32Array &p_heights, const gdx::PackedFloat32Array &p_normals, double p_tilt);
	gdx::PackedFloat32Array get_ground_points() const;
	int64_t get_cells_without_ground() const;
	double get_ground_height(gdx::Vector2 p_point) const;
	gdx::PackedFloat32Array get_object_heights() const;
	gdx::PackedFloat32Array get_wind_state() const;
	// Whether the species' near plants are drawn whole: one instance per plant in its level's first
	// mesh bucket (WHOLE_FLOATS_PER_INSTANCE floats, with custom data), their parts placed by the
	// shader, instead of one per part.
	void set_plant_whole(int64_t p_species, bool p_whole);
	void set_plant_lod_scale(int64_t p_species, double p_scale);
	void set_observer(gdx::Vector3 p_position, const gdx::PackedFloat32Array &p_frustum);
	// The frame budget's quality the levels are drawn at (NearField::set_quality), and where a plant
	// type turns finer at a switch (NearField::get_finer_distance): what its impostor shadows follow.
	void set_quality(double p_quality);
	double get_finer_distance(int64_t p_species, int64_t p_switch) const;
	void set_pushers(const gdx::PackedFloat32Array &p_pushers);
	int64_t get_pushed_count() const;
	gdx::PackedInt32Array get_plants_near(gdx::Vector3 p_position, double p_radius, bool p_standing_only) const;

	void set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh);
	// A second MultiMesh for a bucket that gets the same instances every frame: the node that casts
	// the bucket's shadows with another mesh (an invalid RID: none).
	void set_bucket_shadow_multimesh(int64_t p_bucket, gdx::Rid p_multimesh);
	void set_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh);
	void adopt_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh);
	int64_t get_tile_count() const;
	// The far-tile table, read once per build. Per tile, TILE_IDS integers: its key (where it lies),
	// signature (what it draws), species, level and parent (−1: none); TILE_PLACES floats: its box
	// (position x, y, z, size x, y, z), the distance its level begins and the camera distance it is
	// shown from (FarTiles).
	static constexpr int64_t TILE_IDS = 5;
	static constexpr int64_t TILE_PLACES = 8;
	gdx::PackedInt64Array get_tile_ids() const;
	gdx::PackedFloat32Array get_tile_places() const;
	// The rest of the impostor shader's tile_merge (the tile's level first): the top level, the
	// distance level 1 begins, the fade's share of an octave.
	gdx::PackedFloat32Array get_tile_merge_rule() const;
	gdx::Vector2 choose_tile_level(double p_distance) const;
	gdx::PackedByteArray get_active_mask(int64_t p_species) const;
	gdx::PackedByteArray get_tiles_drawn() const;
	int64_t get_mask_version() const;
	gdx::PackedInt32Array get_chunk_grid() const;
	void compute_chunk_signatures();
	void release_multimeshes();
	int64_t get_chunk_count() const;
	gdx::AABB get_chunk_aabb(int64_t p_chunk) const;

	void update(double p_delta);

	// Play's changes (core field_changes.h, FieldSimulation::change_cells): p_action (0 stand, 1
	// flatten, 2 cut, 3 remove, 4 as the map has it) on map cells (row × columns + column) at the
	// field's clock p_now; returns the cells changed. Shown at the next update, without a rebuild.
	gdx::PackedInt32Array change_cells(const gdx::PackedInt32Array &p_cells, int64_t p_action, double p_now);
	// Puts a standing plant of type p_species in each of p_cells (FieldSimulation::put_cells); returns
	// the cells changed. Cells whose ground height is not known wait: get_unplaced_cells, whose roots
	// (get_cell_roots: x, z pairs in the field's space) a caller casts rays under and hands back to
	// set_cell_heights.
	gdx::PackedInt32Array put_cells(const gdx::PackedInt32Array &p_cells, int64_t p_species);
	gdx::PackedInt32Array get_unplaced_cells() const;
	gdx::PackedFloat32Array get_cell_roots(const gdx::PackedInt32Array &p_cells) const;
	void set_cell_heights(const gdx::PackedInt32Array &p_cells, const gdx::PackedFloat32Array &p_heights);
	// Moves the changes' clock: returns the cells whose plants stood again.
	gdx::PackedInt32Array advance_changes(double p_now);
	// A cell after play: x its plant (0 none, 1 + plant type), y its state (0 standing, 1 flattened,
	// 2 cut), z the clock when it took it.
	gdx::Vector3 get_cell_change(int64_t p_cell) const;
	int64_t get_change_count() const;
	gdx::PackedInt32Array get_cells_in_circle(gdx::Vector2 p_center, double p_radius) const;
	gdx::PackedInt32Array get_cells_in_rect(gdx::Vector2 p_min, gdx::Vector2 p_max) const;
	// The pushers flatten the standing plants within p_share of their radius (FieldSimulation::trample):
	// two ints each trampled plant, its cell and the pusher's index in set_pushers' order.
	gdx::PackedInt32Array trample(double p_share, double p_now);
	// A plant's map cell, or -1 (also for a plant gone: removed, or under a plant of another type).
	int64_t get_plant_cell(int64_t p_plant) const;
	gdx::PackedByteArray save_changes(double p_now);
	// "" (and get_loaded_clock() the save's clock) or what is wrong, nothing changed.
	gdx::String load_changes(const gdx::PackedByteArray &p_bytes);
	double get_loaded_clock() const { return _loaded_clock; }
	// The cells whose plant play took down, a bit each (FieldSimulation::get_hidden_cells), and the
	// version that changes with them.
	gdx::PackedByteArray get_hidden_cells() const;
	int64_t get_hidden_version() const { return _sim.get_hidden_version(); }

	int64_t get_plant_count() const;
	gdx::PackedInt32Array get_lod_counts() const;
	gdx::PackedInt32Array get_lod_counts_by_species() const;
	gdx::Vector3 get_plant_position(int64_t p_plant) const;
	gdx::Vector2 get_plant_stalk(int64_t p_plant) const;
	int64_t get_plant_lod(int64_t p_plant) const;
	int64_t get_plant_tile_level(int64_t p_plant) const;
	gdx::PackedFloat32Array get_plant_parts(int64_t p_plant) const;
	int64_t get_bucket_instance_count(int64_t p_bucket) const;
	gdx::PackedByteArray get_filled_buckets() const;
	int64_t get_last_update_usec() const;
	// The threads the near plants are moved on (the caller included), as the setting resolved them.
	int64_t get_worker_threads() const { return _sim.near().get_worker_threads(); }
	int64_t get_memory_bytes() const;

	// The core's parameter table (parameters.h), for the node's setters: one validator per value.
	static double sanitize_parameter(const gdx::String &p_name, double p_value, double p_current);
	static gdx::String explain_parameter(const gdx::String &p_name, double p_value, double p_used);
	// A row's cost column (0 free, 1 a rebuild: ParameterSpec::Cost) and its count of values; -1
	// for a name not in the table.
	static int64_t get_parameter_cost(const gdx::String &p_name);
	static int64_t get_parameter_components(const gdx::String &p_name);
	static double get_parameter_default(const gdx::String &p_name);
	static double get_parameter_limit(const gdx::String &p_name, bool p_upper);
	static gdx::String get_parameter_names();
	static gdx::String check_lod_distances(const gdx::PackedFloat32Array &p_distances);
	static gdx::Vector2 sanitize_wind_direction(gdx::Vector2 p_direction);
	static int64_t mesh_bucket(int64_t p_level, int64_t p_part);

private:
	bool _is_plant(int64_t p_plant) const;
	bool _is_chunk(int64_t p_chunk) const;
	bool _is_tile(int64_t p_tile) const;
	bool _is_species(int64_t p_species) const;
	void _push_bucket(uint32_t p_bucket);
	// Writes the tile's records (nearest the observer first) into its MultiMesh.
	void _upload_tile(uint32_t p_tile);

	struct BucketTarget {
		gdx::Rid multimesh;
		// A MultiMesh that draws the same instances with a cheaper mesh into the shadow passes only
		// (set_bucket_shadow_multimesh), or none.
		gdx::Rid shadow;
		gdx::PackedFloat32Array staging;
		uint32_t allocated = 0;
		uint32_t stride = 0; // floats per instance allocated (the bucket's)
		uint32_t last_count = 0;
		glm::vec3 bounds_low{ 0.0f }; // the box last given to the renderer
		glm::vec3 bounds_high{ 0.0f };
	};

	sunflower::FieldSimulation _sim;
	std::vector<BucketTarget> _buckets; // BUCKET_COUNT per species of the map
	std::vector<gdx::Rid> _tiles; // each tile's impostors (sprite and billboard are one multi-view impostor)
	std::vector<int64_t> _tile_visible; // each tile's MultiMesh's visible instances as last set (−1: not yet)
	std::vector<uint32_t> _tile_counts; // each tile's MultiMesh's instances as allocated (or adopted)
	// The tiles' records written again nearest the observer first, TILE_ORDER_PLANTS_PER_FRAME plants a
	// frame into _reorder_buffer, and given to the tile's MultiMesh when complete; given up if the
	// field's records change meanwhile (_reorder_version: theirs when it began).
	sunflower::TileReorder _reorder;
	gdx::PackedFloat32Array _reorder_buffer;
	uint32_t _reorder_version = 0;
	static constexpr uint32_t TILE_ORDER_PLANTS_PER_FRAME = 1024;
	void _order_tiles();
	std::vector<sunflower::Pusher> _pushers; // reused between frames
	int64_t _last_update_usec = 0;
	double _loaded_clock = 0.0;
};
