// SunflowerSimulation's registration, and the settings a field hands its simulation: layout, ground,
// plant types, wind, levels of detail, observer, threads and pushers.
#include "sunflower_simulation.h"

#include "binding/class_binder.h"
#include "convert.h"
#include "binding/error_macros.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

using namespace sunflower;

void SunflowerSimulation::bind_methods() {
	gdx::bind_method(CLASS, "load_map", &SunflowerSimulation::load_map, { "text", "source", "legend", "plant_symbols", "max_plants" });
	gdx::bind_method(CLASS, "get_species_count", &SunflowerSimulation::get_species_count);
	gdx::bind_method(CLASS, "get_map_columns", &SunflowerSimulation::get_map_columns);
	gdx::bind_method(CLASS, "get_map_rows", &SunflowerSimulation::get_map_rows);
	gdx::bind_method(CLASS, "get_map_objects", &SunflowerSimulation::get_map_objects);
	gdx::bind_method(CLASS, "set_settings", &SunflowerSimulation::set_settings, { "species", "rows", "values" });
	gdx::bind_method(CLASS, "set_layout_seed", &SunflowerSimulation::set_layout_seed, { "layout_seed", "independent_jitter" });
	gdx::bind_method(CLASS, "set_ground_flat", &SunflowerSimulation::set_ground_flat);
	gdx::bind_method(CLASS, "set_ground_height_map", &SunflowerSimulation::set_ground_height_map,
			{ "rgba", "width", "depth", "origin", "size", "height_min", "height_max", "tilt" });
	gdx::bind_method(CLASS, "set_ground_heights", &SunflowerSimulation::set_ground_heights, { "heights", "normals", "tilt" });
	gdx::bind_method(CLASS, "get_ground_points", &SunflowerSimulation::get_ground_points);
	gdx::bind_method(CLASS, "get_cells_without_ground", &SunflowerSimulation::get_cells_without_ground);
	gdx::bind_method(CLASS, "get_ground_height", &SunflowerSimulation::get_ground_height, { "point" });
	gdx::bind_method(CLASS, "get_object_heights", &SunflowerSimulation::get_object_heights);
	gdx::bind_method(CLASS, "get_wind_state", &SunflowerSimulation::get_wind_state);
	gdx::bind_method(CLASS, "set_plant_whole", &SunflowerSimulation::set_plant_whole, { "species", "whole" });
	gdx::bind_method(CLASS, "set_plant_lod_scale", &SunflowerSimulation::set_plant_lod_scale, { "species", "scale" });
	gdx::bind_method(CLASS, "set_quality", &SunflowerSimulation::set_quality, { "quality" });
	gdx::bind_method(CLASS, "get_finer_distance", &SunflowerSimulation::get_finer_distance, { "species", "switch" });
	gdx::bind_method(CLASS, "set_observer", &SunflowerSimulation::set_observer, { "position", "frustum" });
	gdx::bind_method(CLASS, "set_pushers", &SunflowerSimulation::set_pushers, { "pushers" });
	gdx::bind_method(CLASS, "get_pushed_count", &SunflowerSimulation::get_pushed_count);
	gdx::bind_method(CLASS, "get_plants_near", &SunflowerSimulation::get_plants_near, { "position", "radius", "standing_only" });
	gdx::bind_method(CLASS, "update", &SunflowerSimulation::update, { "delta" });
	gdx::bind_method(CLASS, "get_plant_count", &SunflowerSimulation::get_plant_count);
	gdx::bind_method(CLASS, "get_lod_counts", &SunflowerSimulation::get_lod_counts);
	gdx::bind_method(CLASS, "get_lod_counts_by_species", &SunflowerSimulation::get_lod_counts_by_species);
	gdx::bind_method(CLASS, "get_plant_position", &SunflowerSimulation::get_plant_position, { "plant" });
	gdx::bind_method(CLASS, "get_plant_stalk", &SunflowerSimulation::get_plant_stalk, { "plant" });
	gdx::bind_method(CLASS, "get_plant_lod", &SunflowerSimulation::get_plant_lod, { "plant" });
	gdx::bind_method(CLASS, "get_plant_tile_level", &SunflowerSimulation::get_plant_tile_level, { "plant" });
	gdx::bind_method(CLASS, "get_plant_parts", &SunflowerSimulation::get_plant_parts, { "plant" });
	gdx::bind_method(CLASS, "get_last_update_usec", &SunflowerSimulation::get_last_update_usec);
	gdx::bind_method(CLASS, "get_worker_threads", &SunflowerSimulation::get_worker_threads);
	gdx::bind_method(CLASS, "get_memory_bytes", &SunflowerSimulation::get_memory_bytes);

	gdx::bind_integer_constant(CLASS, "", "MAX_SPECIES", FieldMap::MAX_SPECIES);
}

int64_t SunflowerSimulation::set_settings(int64_t p_species, const gdx::PackedInt32Array &p_rows, const gdx::PackedFloat32Array &p_values) {
	SF_FAIL_COND_V_MSG(!is_species(p_species), -1, "set_settings: no plant type " + std::to_string(p_species));
	const int32_t *rows = p_rows.data();
	size_t needed = 0;
	for (int64_t i = 0; i < p_rows.size(); ++i) {
		SF_FAIL_COND_V_MSG(rows[i] < 0 || size_t(rows[i]) >= param::ALL.size(), -1,
				"set_settings: row " + std::to_string(rows[i]) + " is not in the parameter table (0 to " +
						std::to_string(param::ALL.size() - 1) + ")");
		needed += param::ALL[size_t(rows[i])]->components;
	}
	SF_FAIL_COND_V_MSG(needed != size_t(p_values.size()), -1,
			"set_settings: the rows take " + std::to_string(needed) + " values, got " + std::to_string(p_values.size()));
	const float *values = p_values.data();
	ParameterSpec::Cost cost = ParameterSpec::FREE;
	const LayoutParams layout = _sim.plants().get_layout_params();
	for (int64_t i = 0; i < p_rows.size(); ++i) {
		const ParameterSpec &spec = *param::ALL[size_t(rows[i])];
		cost = std::max(cost, _sim.set_setting(spec, values, uint32_t(p_species)));
		values += spec.components;
	}
	if (!(_sim.plants().get_layout_params() == layout)) {
		++_chunks_version; // the chunks changed (a field not laid out yet)
	}
	return int64_t(cost);
}

void SunflowerSimulation::set_layout_seed(int64_t p_seed, bool p_independent_jitter) {
	LayoutParams params = _sim.plants().get_layout_params();
	params.seed = static_cast<uint64_t>(p_seed);
	params.independent_jitter = p_independent_jitter;
	if (_sim.set_layout_params(params)) {
		++_chunks_version; // the chunks changed
	}
}

void SunflowerSimulation::set_ground_flat() {
	_sim.set_ground(Ground{});
	++_chunks_version; // the chunks changed
}

gdx::String SunflowerSimulation::set_ground_height_map(const gdx::PackedFloat32Array &p_rgba, int64_t p_width, int64_t p_depth,
		gdx::Vector2 p_origin, gdx::Vector2 p_size, double p_height_min, double p_height_max, double p_tilt) {
	Ground ground;
	ground.kind = Ground::GRID;
	ground.tilt = float(p_tilt);
	const std::string problem = gdx::to_core_height_grid(p_rgba, p_width, p_depth, p_origin, p_size, p_height_min, p_height_max, ground.grid);
	if (!problem.empty()) {
		return gdx::String(problem); // the field keeps its ground
	}
	_sim.set_ground(std::move(ground));
	++_chunks_version; // the chunks changed
	return gdx::String();
}

gdx::String SunflowerSimulation::set_ground_heights(const gdx::PackedFloat32Array &p_heights, const gdx::PackedFloat32Array &p_normals,
		double p_tilt) {
	const size_t points = size_t(_sim.plants().get_map().plant_count) + _sim.plants().get_map().objects.size();
	if (size_t(p_heights.size()) != points || (p_normals.size() != 0 && size_t(p_normals.size()) != 3 * points)) {
		return gdx::String("set_ground_heights: the map has " + std::to_string(points) + " ground points; got " +
				std::to_string(p_heights.size()) + " heights and " + std::to_string(p_normals.size()) +
				" normal floats (0 or 3 per point)");
	}
	Ground ground;
	ground.kind = Ground::HEIGHTS;
	ground.tilt = float(p_tilt);
	ground.heights.assign(p_heights.data(), p_heights.data() + p_heights.size());
	ground.normals.assign(p_normals.data(), p_normals.data() + p_normals.size());
	_sim.set_ground(std::move(ground));
	++_chunks_version; // the chunks changed
	return gdx::String();
}

gdx::PackedFloat32Array SunflowerSimulation::get_ground_points() const {
	std::vector<glm::vec2> points;
	ground_points(_sim.plants().get_map(), _sim.plants().get_layout_params(), points);
	gdx::PackedFloat32Array out;
	out.assign(reinterpret_cast<const float *>(points.data()), points.size() * 2);
	return out;
}

double SunflowerSimulation::get_ground_height(gdx::Vector2 p_point) const {
	const Ground &ground = _sim.plants().get_ground();
	if (ground.kind == Ground::FLAT) {
		return 0.0;
	}
	return ground.kind == Ground::GRID ? double(ground.grid.sample(gdx::to_core(p_point))) : double(NAN);
}

int64_t SunflowerSimulation::get_cells_without_ground() const {
	return _sim.plants().get_layout().cells_without_ground;
}

gdx::PackedFloat32Array SunflowerSimulation::get_object_heights() const {
	const std::vector<float> &heights = _sim.plants().get_layout().object_ground;
	gdx::PackedFloat32Array out;
	out.assign(heights.data(), heights.size());
	return out;
}

gdx::PackedFloat32Array SunflowerSimulation::get_wind_state() const {
	const WindModel::ShaderState state = _sim.near().get_wind().shader_state();
	const float values[] = { state.lean.x, state.lean.y, state.amplitude, state.bend_limit, state.gust_share,
		state.gust_scroll, state.sway, state.moving };
	gdx::PackedFloat32Array out;
	out.assign(values, std::size(values));
	return out;
}

int64_t SunflowerSimulation::get_species_count() const {
	return _sim.plants().get_species_count();
}

bool SunflowerSimulation::is_species(int64_t p_species) {
	SF_FAIL_COND_V_MSG(p_species < 0 || p_species >= FieldMap::MAX_SPECIES, false,
			"species " + std::to_string(p_species) + " is out of range (0 to " + std::to_string(FieldMap::MAX_SPECIES - 1) + ")");
	return true;
}

void SunflowerSimulation::set_plant_lod_scale(int64_t p_species, double p_scale) {
	if (!is_species(p_species)) {
		return;
	}
	PlantShape shape = _sim.plants().get_shape(uint32_t(p_species));
	shape.lod_scale = float(p_scale); // not positive or not finite: set_shape keeps the current one
	_sim.set_shape(shape, uint32_t(p_species));
}

void SunflowerSimulation::set_plant_whole(int64_t p_species, bool p_whole) {
	if (!is_species(p_species)) {
		return;
	}
	PlantShape shape = _sim.plants().get_shape(uint32_t(p_species));
	shape.whole = p_whole;
	_sim.set_shape(shape, uint32_t(p_species));
}

void SunflowerSimulation::set_observer(gdx::Vector3 p_position, const gdx::PackedFloat32Array &p_frustum) {
	_sim.near().set_observer(gdx::to_core(p_position));
	const int64_t count = p_frustum.size() / 4;
	if (count > 0) {
		_sim.near().get_frustum().set_planes(gdx::to_core_planes(p_frustum), static_cast<size_t>(count));
	} else {
		_sim.near().get_frustum().clear();
	}
}

void SunflowerSimulation::set_quality(double p_quality) {
	_sim.near().set_quality(float(p_quality));
}

double SunflowerSimulation::get_finer_distance(int64_t p_species, int64_t p_switch) const {
	return is_species(p_species) && p_switch >= 0 ? double(_sim.near().get_finer_distance(uint32_t(p_species), uint32_t(p_switch))) : -1.0;
}

void SunflowerSimulation::set_pushers(const gdx::PackedFloat32Array &p_pushers) {
	SF_FAIL_COND_MSG(p_pushers.size() % 4 != 0,
			"set_pushers takes 4 floats per pusher (x, y, z, radius), got " + std::to_string(p_pushers.size()));
	gdx::to_core_pushers(p_pushers, _pushers);
	_sim.near().get_pushes().set_pushers(_pushers.data(), _pushers.size());
}

void SunflowerSimulation::update(double p_delta) {
	const auto start = std::chrono::steady_clock::now();
	_sim.update(static_cast<float>(p_delta));
	_last_update_usec = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
}
