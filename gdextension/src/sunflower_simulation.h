#pragma once
// SunflowerSimulation: the engine-facing face of the core FieldSimulation: its map, settings, ground,
// observer and pushers, the frame's update and the queries on its plants. Configured by the
// SunflowerField node, updated once per frame. What it draws goes to the renderer through a
// SunflowerDrawing attached to it; play's changes to its plants through a SunflowerChanges.
#include "binding/godot_api.h"
#include "core/field_simulation.h"

#include <vector>

class SunflowerSimulation {
public:
	static constexpr const char *CLASS = "SunflowerSimulation";
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

	void update(double p_delta);

	int64_t get_plant_count() const;
	gdx::PackedInt32Array get_lod_counts() const;
	gdx::PackedInt32Array get_lod_counts_by_species() const;
	gdx::Vector3 get_plant_position(int64_t p_plant) const;
	gdx::Vector2 get_plant_stalk(int64_t p_plant) const;
	int64_t get_plant_lod(int64_t p_plant) const;
	int64_t get_plant_tile_level(int64_t p_plant) const;
	gdx::PackedFloat32Array get_plant_parts(int64_t p_plant) const;
	int64_t get_last_update_usec() const;
	// The threads the near plants are moved on (the caller included), as the setting resolved them.
	int64_t get_worker_threads() const { return _sim.near().get_worker_threads(); }
	int64_t get_memory_bytes() const;

	// The core, for the classes attached to this simulation (SunflowerDrawing, SunflowerChanges).
	sunflower::FieldSimulation &core() { return _sim; }
	const sunflower::FieldSimulation &core() const { return _sim; }
	// Changes whenever the plants' chunks do (a map read, a ground or layout given): the MultiMeshes
	// a drawing was given for the old ones are let go.
	uint64_t get_chunks_version() const { return _chunks_version; }
	// Whether p_species can name a plant type (with an error when not).
	static bool is_species(int64_t p_species);

private:
	bool _is_plant(int64_t p_plant) const;

	sunflower::FieldSimulation _sim;
	uint64_t _chunks_version = 0;
	std::vector<sunflower::Pusher> _pushers; // reused between frames
	int64_t _last_update_usec = 0;
};
