#include "sunflower_simulation.h"

#include "binding/class_binder.h"
#include "binding/convert.h"
#include "binding/error_macros.h"
#include "binding/rendering_server.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

using namespace sunflower;


void SunflowerSimulation::bind_methods() {
	const char *CLASS = "SunflowerSimulation";
	gdx::bind_method(CLASS, "load_map", &SunflowerSimulation::load_map, { "text", "source", "legend", "plant_symbols", "max_plants" });
	gdx::bind_method(CLASS, "check_map", &SunflowerSimulation::check_map,
			{ "text", "source", "legend", "plant_symbols", "max_plants", "any_symbol" });
	gdx::bind_method(CLASS, "get_map_figures", &SunflowerSimulation::get_map_figures, { "text", "max_plants" });
	gdx::bind_method(CLASS, "get_species_count", &SunflowerSimulation::get_species_count);
	gdx::bind_method(CLASS, "paint_map", &SunflowerSimulation::paint_map, { "center", "radius", "symbol", "density", "seed", "relayout" });
	gdx::bind_method(CLASS, "write_map", &SunflowerSimulation::write_map);
	gdx::bind_method(CLASS, "resize_map", &SunflowerSimulation::resize_map, { "columns", "rows" });
	gdx::bind_method(CLASS, "clear", &SunflowerSimulation::clear);
	gdx::bind_method(CLASS, "get_map_columns", &SunflowerSimulation::get_map_columns);
	gdx::bind_method(CLASS, "get_map_rows", &SunflowerSimulation::get_map_rows);
	gdx::bind_method(CLASS, "get_map_objects", &SunflowerSimulation::get_map_objects);
	gdx::bind_method(CLASS, "set_layout", &SunflowerSimulation::set_layout, { "cell_size", "seed", "independent_jitter", "chunk_size" });
	gdx::bind_method(CLASS, "set_tile_merge_distance", &SunflowerSimulation::set_tile_merge_distance, { "metres" });
	gdx::bind_method(CLASS, "set_ground_flat", &SunflowerSimulation::set_ground_flat);
	gdx::bind_method(CLASS, "set_ground_height_map", &SunflowerSimulation::set_ground_height_map,
			{ "rgba", "width", "depth", "origin", "size", "height_min", "height_max", "tilt" });
	gdx::bind_method(CLASS, "set_ground_heights", &SunflowerSimulation::set_ground_heights, { "heights", "normals", "tilt" });
	gdx::bind_method(CLASS, "get_ground_points", &SunflowerSimulation::get_ground_points);
	gdx::bind_method(CLASS, "get_cells_without_ground", &SunflowerSimulation::get_cells_without_ground);
	gdx::bind_method(CLASS, "get_ground_height", &SunflowerSimulation::get_ground_height, { "point" });
	gdx::bind_method(CLASS, "get_object_heights", &SunflowerSimulation::get_object_heights);
	gdx::bind_method(CLASS, "get_wind_state", &SunflowerSimulation::get_wind_state);
	gdx::bind_method(CLASS, "set_plant_height", &SunflowerSimulation::set_plant_height, { "species", "metres" });
	gdx::bind_method(CLASS, "set_plant_form", &SunflowerSimulation::set_plant_form,
			{ "species", "part_lengths", "middle_variation", "height_units", "cull_radius_units", "stiffness" });
	gdx::bind_method(CLASS, "set_plant_whole", &SunflowerSimulation::set_plant_whole, { "species", "whole" });
	gdx::bind_method(CLASS, "set_plant_variation", &SunflowerSimulation::set_plant_variation,
			{ "species", "yaw_range", "scale_min", "scale_max", "brightness", "tint" });
	gdx::bind_method(CLASS, "set_wind", &SunflowerSimulation::set_wind,
			{ "model", "power", "direction", "stiffness_middle", "stiffness_bottom", "bend_per_power", "max_bend", "flip_interval",
					"flip_chance", "gust_speed", "gust_share" });
	gdx::bind_method(CLASS, "set_lod", &SunflowerSimulation::set_lod, { "distances", "hysteresis", "fade", "interval", "force_level" });
	gdx::bind_method(CLASS, "set_observer", &SunflowerSimulation::set_observer, { "position", "frustum" });
	gdx::bind_method(CLASS, "set_worker_threads", &SunflowerSimulation::set_worker_threads, { "threads" });
	gdx::bind_method(CLASS, "set_pushers", &SunflowerSimulation::set_pushers, { "pushers" });
	gdx::bind_method(CLASS, "set_push_params", &SunflowerSimulation::set_push_params, { "strength", "recovery_seconds" });
	gdx::bind_method(CLASS, "get_pushed_count", &SunflowerSimulation::get_pushed_count);
	gdx::bind_method(CLASS, "get_plants_near", &SunflowerSimulation::get_plants_near, { "position", "radius" });
	gdx::bind_method(CLASS, "set_bucket_multimesh", &SunflowerSimulation::set_bucket_multimesh, { "bucket", "multimesh" });
	gdx::bind_method(CLASS, "set_tile_multimesh", &SunflowerSimulation::set_tile_multimesh, { "tile", "multimesh" });
	gdx::bind_method(CLASS, "release_multimeshes", &SunflowerSimulation::release_multimeshes);
	gdx::bind_method(CLASS, "adopt_tile_multimesh", &SunflowerSimulation::adopt_tile_multimesh, { "tile", "multimesh" });
	gdx::bind_method(CLASS, "get_tile_count", &SunflowerSimulation::get_tile_count);
	gdx::bind_method(CLASS, "get_tile_ids", &SunflowerSimulation::get_tile_ids);
	gdx::bind_method(CLASS, "get_tile_places", &SunflowerSimulation::get_tile_places);
	gdx::bind_method(CLASS, "get_tile_merge_rule", &SunflowerSimulation::get_tile_merge_rule);
	gdx::bind_method(CLASS, "choose_tile_level", &SunflowerSimulation::choose_tile_level, { "distance" });
	gdx::bind_method(CLASS, "get_active_mask", &SunflowerSimulation::get_active_mask, { "species" });
	gdx::bind_method(CLASS, "get_mask_version", &SunflowerSimulation::get_mask_version);
	gdx::bind_method(CLASS, "get_tiles_drawn", &SunflowerSimulation::get_tiles_drawn);
	gdx::bind_method(CLASS, "get_chunk_grid", &SunflowerSimulation::get_chunk_grid);
	gdx::bind_method(CLASS, "compute_chunk_signatures", &SunflowerSimulation::compute_chunk_signatures);
	gdx::bind_method(CLASS, "get_chunk_count", &SunflowerSimulation::get_chunk_count);
	gdx::bind_method(CLASS, "get_chunk_aabb", &SunflowerSimulation::get_chunk_aabb, { "chunk" });
	gdx::bind_method(CLASS, "update", &SunflowerSimulation::update, { "delta" });
	gdx::bind_method(CLASS, "get_plant_count", &SunflowerSimulation::get_plant_count);
	gdx::bind_method(CLASS, "get_lod_counts", &SunflowerSimulation::get_lod_counts);
	gdx::bind_method(CLASS, "get_lod_counts_by_species", &SunflowerSimulation::get_lod_counts_by_species);
	gdx::bind_method(CLASS, "get_plant_position", &SunflowerSimulation::get_plant_position, { "plant" });
	gdx::bind_method(CLASS, "get_plant_stalk", &SunflowerSimulation::get_plant_stalk, { "plant" });
	gdx::bind_method(CLASS, "get_plant_lod", &SunflowerSimulation::get_plant_lod, { "plant" });
	gdx::bind_method(CLASS, "get_plant_tile_level", &SunflowerSimulation::get_plant_tile_level, { "plant" });
	gdx::bind_method(CLASS, "get_plant_parts", &SunflowerSimulation::get_plant_parts, { "plant" });
	gdx::bind_method(CLASS, "get_bucket_instance_count", &SunflowerSimulation::get_bucket_instance_count, { "bucket" });
	gdx::bind_method(CLASS, "get_filled_buckets", &SunflowerSimulation::get_filled_buckets);
	gdx::bind_method(CLASS, "get_last_update_usec", &SunflowerSimulation::get_last_update_usec);
	gdx::bind_method(CLASS, "get_memory_bytes", &SunflowerSimulation::get_memory_bytes);

	gdx::bind_method(CLASS, "sanitize_parameter", &SunflowerSimulation::sanitize_parameter, { "name", "value", "current" });
	gdx::bind_method(CLASS, "explain_parameter", &SunflowerSimulation::explain_parameter, { "name", "value", "used" });
	gdx::bind_method(CLASS, "get_parameter_default", &SunflowerSimulation::get_parameter_default, { "name" });
	gdx::bind_method(CLASS, "get_parameter_names", &SunflowerSimulation::get_parameter_names);
	gdx::bind_method(CLASS, "check_lod_distances", &SunflowerSimulation::check_lod_distances, { "distances" });
	gdx::bind_method(CLASS, "sanitize_wind_direction", &SunflowerSimulation::sanitize_wind_direction, { "direction" });
	gdx::bind_method(CLASS, "mesh_bucket", &SunflowerSimulation::mesh_bucket, { "level", "part" });
	gdx::bind_method(CLASS, "get_plant_height_units", &SunflowerSimulation::get_plant_height_units);

	gdx::bind_integer_constant(CLASS, "", "PART_COUNT", PART_COUNT);
	gdx::bind_integer_constant(CLASS, "", "MESH_LEVEL_COUNT", LOD_MESH_COUNT);
	gdx::bind_integer_constant(CLASS, "", "LOD_COUNT", LOD_COUNT);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_IMPOSTOR", BUCKET_IMPOSTOR);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_COUNT", BUCKET_COUNT);
	gdx::bind_integer_constant(CLASS, "", "MAX_SPECIES", FieldMap::MAX_SPECIES);
	gdx::bind_integer_constant(CLASS, "", "TILE_IDS", TILE_IDS);
	gdx::bind_integer_constant(CLASS, "", "TILE_PLACES", TILE_PLACES);
	gdx::bind_integer_constant(CLASS, "", "FLOATS_PER_INSTANCE", FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "WHOLE_FLOATS_PER_INSTANCE", WHOLE_FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "FAR_FLOATS_PER_INSTANCE", FAR_FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "FAR_SIGNED_STEPS", far_steps::SIGNED);
	gdx::bind_integer_constant(CLASS, "", "FAR_BRIGHTNESS_STEPS", far_steps::BRIGHTNESS);
	gdx::bind_integer_constant(CLASS, "", "FAR_STEP_BITS", far_steps::STEP_BITS);
	gdx::bind_integer_constant(CLASS, "", "FAR_CELL_BITS", far_steps::CELL_BITS);
	gdx::bind_integer_constant(CLASS, "", "PARALLEL_MIN_PLANTS", NearField::PARALLEL_MIN_PLANTS);
	gdx::bind_integer_constant(CLASS, "", "MAX_AUTO_THREADS", param::MAX_AUTO_THREADS);
	gdx::bind_integer_constant(CLASS, "", "MAX_THREADS", param::MAX_THREADS);
}

static MapLimits limits_for(int64_t p_max_plants) {
	MapLimits limits;
	if (p_max_plants > 0) {
		limits.max_plants = p_max_plants;
	}
	return limits;
}

gdx::String SunflowerSimulation::load_map(const gdx::PackedByteArray &p_text, const gdx::String &p_source,
		const gdx::String &p_legend, const gdx::String &p_plant_symbols, int64_t p_max_plants) {
	const MapLimits limits = limits_for(p_max_plants);
	MapError error;
	if (!_sim.load_map(gdx::to_core(p_text), decode_utf8_text(p_legend.utf8()), decode_utf8_text(p_plant_symbols.utf8()),
				p_source.utf8(), limits, error)) {
		return gdx::String(error.to_string());
	}
	release_multimeshes(); // the old field's chunks no longer exist
	return gdx::String();
}

gdx::String SunflowerSimulation::check_map(const gdx::PackedByteArray &p_text, const gdx::String &p_source,
		const gdx::String &p_legend, const gdx::String &p_plant_symbols, int64_t p_max_plants, bool p_any_symbol) {
	FieldMap parsed;
	MapError error;
	MapLimits limits = limits_for(p_max_plants);
	limits.any_object_symbol = p_any_symbol;
	if (!parse_field_map(gdx::to_core(p_text), decode_utf8_text(p_legend.utf8()), decode_utf8_text(p_plant_symbols.utf8()),
				p_source.utf8(), limits, parsed, error)) {
		return gdx::String(error.to_string());
	}
	return gdx::String();
}

gdx::PackedInt32Array SunflowerSimulation::get_map_figures(const gdx::PackedByteArray &p_text, int64_t p_max_plants) {
	FieldMap parsed;
	MapError error;
	MapLimits limits = limits_for(p_max_plants);
	limits.any_object_symbol = true;
	gdx::PackedInt32Array out;
	if (parse_field_map(gdx::to_core(p_text), std::u32string_view(), std::string(), limits, parsed, error)) {
		const int32_t figures[] = { parsed.columns, parsed.rows, static_cast<int32_t>(parsed.plant_count) };
		out.assign(figures, 3);
	}
	return out;
}

void SunflowerSimulation::clear() {
	_sim.clear();
	release_multimeshes();
}

int64_t SunflowerSimulation::get_map_columns() const {
	return _sim.plants().get_map().columns;
}

int64_t SunflowerSimulation::get_map_rows() const {
	return _sim.plants().get_map().rows;
}

gdx::PackedInt32Array SunflowerSimulation::get_map_objects() const {
	std::vector<int32_t> flat;
	for (const MapObject &object : _sim.plants().get_map().objects) {
		flat.insert(flat.end(), { object.column, object.row, static_cast<int32_t>(object.symbol) });
	}
	gdx::PackedInt32Array out;
	out.assign(flat.data(), flat.size());
	return out;
}

void SunflowerSimulation::set_layout(double p_cell_size, int64_t p_seed, bool p_independent_jitter, double p_chunk_size) {
	LayoutParams params = _sim.plants().get_layout_params();
	params.cell_size = static_cast<float>(p_cell_size);
	params.seed = static_cast<uint64_t>(p_seed);
	params.independent_jitter = p_independent_jitter;
	params.chunk_size = static_cast<float>(p_chunk_size);
	if (_sim.set_layout_params(params)) {
		release_multimeshes(); // the chunks changed
	}
}

void SunflowerSimulation::set_tile_merge_distance(double p_metres) {
	LayoutParams params = _sim.plants().get_layout_params();
	params.tile_merge_distance = static_cast<float>(p_metres);
	if (_sim.set_layout_params(params)) {
		release_multimeshes(); // the tiles changed
	}
}

void SunflowerSimulation::set_ground_flat() {
	_sim.set_ground(Ground{});
	release_multimeshes(); // the chunks changed
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
	release_multimeshes();
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
	release_multimeshes();
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

gdx::PackedInt32Array SunflowerSimulation::paint_map(gdx::Vector2 p_center, double p_radius, const gdx::String &p_symbol,
		double p_density, int64_t p_seed, bool p_relayout) {
	const std::u32string symbol = decode_utf8_text(p_symbol.utf8());
	SF_FAIL_COND_V_MSG(symbol.size() > 1, gdx::PackedInt32Array(),
			"paint_map: the symbol must be one character ('*', a legend symbol) or empty to erase; got \"" + p_symbol.utf8() +
					"\"");
	CellContent content;
	if (!symbol.empty() && symbol[0] != U' ' && symbol[0] != U'.') {
		const size_t plant = _sim.plants().get_plant_symbols().find(symbol[0]);
		if (symbol[0] == U'*') {
			content = CellContent{ CellContent::PLANT, 0, 0 };
		} else if (plant != std::u32string::npos) {
			content = CellContent{ CellContent::PLANT, int(plant) + 1, 0 };
		} else {
			content = CellContent{ CellContent::OBJECT, 0, symbol[0] };
		}
	}
	std::vector<int> changed;
	_sim.paint_map(gdx::to_core(p_center), float(p_radius), content, float(p_density), uint64_t(p_seed), p_relayout, changed);
	if (p_relayout && !changed.empty()) {
		release_multimeshes(); // the layout changed
	}
	gdx::PackedInt32Array out;
	out.assign(changed.data(), changed.size());
	return out;
}

bool SunflowerSimulation::resize_map(int64_t p_columns, int64_t p_rows) {
	const MapLimits limits;
	SF_FAIL_COND_V_MSG(p_columns < 1 || p_rows < 1 || p_columns > limits.max_side || p_rows > limits.max_side ||
					p_columns * p_rows > limits.max_cells,
			false,
			"resize_map: " + std::to_string(p_columns) + " x " + std::to_string(p_rows) + " is not a map size (1 to " +
					std::to_string(limits.max_side) + " a side, at most " + std::to_string(limits.max_cells) + " cells)");
	FieldMap map = _sim.plants().get_map();
	resize_field_map(map, int(p_columns), int(p_rows), limits);
	_sim.replace_map(std::move(map));
	release_multimeshes(); // the layout changed
	return true;
}

gdx::PackedByteArray SunflowerSimulation::write_map() const {
	const std::string text = write_field_map(_sim.plants().get_map(), _sim.plants().get_plant_symbols());
	gdx::PackedByteArray out;
	out.assign(reinterpret_cast<const uint8_t *>(text.data()), text.size());
	return out;
}

int64_t SunflowerSimulation::get_species_count() const {
	return _sim.plants().get_species_count();
}

bool SunflowerSimulation::_is_species(int64_t p_species) const {
	SF_FAIL_COND_V_MSG(p_species < 0 || p_species >= FieldMap::MAX_SPECIES, false,
			"species " + std::to_string(p_species) + " is out of range (0 to " + std::to_string(FieldMap::MAX_SPECIES - 1) + ")");
	return true;
}

void SunflowerSimulation::set_plant_height(int64_t p_species, double p_metres) {
	if (_is_species(p_species)) {
		_sim.set_plant_height(float(p_metres), uint32_t(p_species));
	}
}

void SunflowerSimulation::set_plant_form(int64_t p_species, gdx::Vector3 p_part_lengths, double p_middle_variation,
		double p_height_units, double p_cull_radius_units, double p_stiffness) {
	if (!_is_species(p_species)) {
		return;
	}
	const uint32_t species = uint32_t(p_species);
	PlantShape shape = _sim.plants().get_shape(species);
	const float metres = shape.part_scale * shape.parts_height(); // the plant keeps its height
	shape.part_lengths = gdx::to_core(p_part_lengths);
	shape.middle_variation = float(p_middle_variation);
	shape.height = float(p_height_units);
	shape.cull_radius = float(p_cull_radius_units);
	shape.stiffness = float(p_stiffness);
	_sim.set_shape(shape, species);
	_sim.set_plant_height(metres, species);
}

void SunflowerSimulation::set_plant_whole(int64_t p_species, bool p_whole) {
	if (!_is_species(p_species)) {
		return;
	}
	PlantShape shape = _sim.plants().get_shape(uint32_t(p_species));
	shape.whole = p_whole;
	_sim.set_shape(shape, uint32_t(p_species));
}

void SunflowerSimulation::set_plant_variation(int64_t p_species, double p_yaw_range, double p_scale_min, double p_scale_max,
		double p_brightness, double p_tint) {
	if (!_is_species(p_species)) {
		return;
	}
	LayoutParams params = _sim.plants().get_layout_params();
	PlantVariety &variety = params.varieties[size_t(p_species)];
	variety.yaw_range = float(p_yaw_range);
	variety.scale_min = float(p_scale_min);
	variety.scale_max = float(p_scale_max);
	variety.brightness = float(p_brightness);
	variety.tint = float(p_tint);
	if (_sim.set_layout_params(params)) {
		release_multimeshes(); // the chunks changed
	}
}

void SunflowerSimulation::set_wind(int64_t p_model, double p_power, gdx::Vector2 p_direction, double p_stiffness_middle, double p_stiffness_bottom,
		double p_bend_per_power, double p_max_bend, double p_flip_interval, double p_flip_chance, double p_gust_speed,
		double p_gust_share) {
	WindParams params;
	params.model = int(std::clamp<int64_t>(p_model, INT32_MIN, INT32_MAX)); // the core clamps
	params.power = float(p_power);
	params.direction = gdx::to_core(p_direction);
	params.d1 = float(p_stiffness_middle);
	params.d2 = float(p_stiffness_bottom);
	params.h = float(p_bend_per_power);
	params.max_bend = float(p_max_bend);
	params.flip_interval = float(p_flip_interval);
	params.flip_chance = float(p_flip_chance);
	params.gust_speed = float(p_gust_speed);
	params.gust_share = float(p_gust_share);
	_sim.near().set_wind(params); // the core applies the param:: rules
}

void SunflowerSimulation::set_lod(const gdx::PackedFloat32Array &p_distances, double p_hysteresis, double p_fade, double p_interval,
		int64_t p_force_level) {
	const std::string problem = sunflower::check_lod_distances(p_distances.data(), size_t(p_distances.size()));
	SF_FAIL_COND_MSG(!problem.empty(), "set_lod: " + problem);
	LodParams params;
	std::copy_n(p_distances.data(), 4, params.distances.begin());
	params.hysteresis = float(p_hysteresis);
	params.fade = float(p_fade);
	params.interval = float(p_interval);
	params.force_level = int(std::clamp<int64_t>(p_force_level, INT32_MIN, INT32_MAX)); // the core clamps
	_sim.near().set_lod(params);
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

void SunflowerSimulation::set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
	SF_FAIL_COND_MSG(p_bucket < 0 || p_bucket >= int64_t(_buckets.size()),
			"bucket " + std::to_string(p_bucket) + " is out of range (0 to " + std::to_string(_buckets.size() - 1) + ": " +
					std::to_string(BUCKET_COUNT) + " per species)");
	if (!gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	BucketTarget &target = _buckets[static_cast<size_t>(p_bucket)];
	target.multimesh = p_multimesh;
	target.allocated = 0;
	target.last_count = 0;
}

void SunflowerSimulation::set_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	if (!_is_tile(p_tile) || !gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	_tiles.resize(_sim.tiles().get_tile_count());
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh;
	_upload_tile(static_cast<uint32_t>(p_tile));
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // allocating the data drew every instance
}

void SunflowerSimulation::adopt_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	if (!_is_tile(p_tile)) {
		return;
	}
	_tiles.resize(_sim.tiles().get_tile_count());
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh; // its data is this tile's already
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // its count is the previous field's
}

int64_t SunflowerSimulation::get_tile_count() const {
	return _sim.tiles().get_tile_count();
}

gdx::PackedInt64Array SunflowerSimulation::get_tile_ids() const {
	const FarTiles &tiles = _sim.tiles();
	gdx::PackedInt64Array out;
	out.resize(int64_t(tiles.get_tile_count()) * TILE_IDS);
	int64_t *row = out.data();
	for (uint32_t t = 0; t < tiles.get_tile_count(); ++t, row += TILE_IDS) {
		const FarTiles::Tile &tile = tiles.get_tile(t);
		row[0] = int64_t(tile.key);
		row[1] = int64_t(tiles.get_tile_signature(t));
		row[2] = tile.species;
		row[3] = tile.level;
		row[4] = tile.is_top() ? -1 : int64_t(tile.parent);
	}
	return out;
}

gdx::PackedFloat32Array SunflowerSimulation::get_tile_places() const {
	const FarTiles &tiles = _sim.tiles();
	gdx::PackedFloat32Array out;
	out.resize(int64_t(tiles.get_tile_count()) * TILE_PLACES);
	float *row = out.data();
	for (uint32_t t = 0; t < tiles.get_tile_count(); ++t, row += TILE_PLACES) {
		const ChunkBounds bounds = tiles.get_tile_bounds(t);
		const float values[TILE_PLACES] = { bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x - bounds.min.x,
			bounds.max.y - bounds.min.y, bounds.max.z - bounds.min.z, tiles.get_tile_begin(t), tiles.get_tile_shown_from(t) };
		std::copy(values, values + TILE_PLACES, row);
	}
	return out;
}

gdx::PackedFloat32Array SunflowerSimulation::get_tile_merge_rule() const {
	// The impostor shader's tile_merge after the tile's own level: the field's top level, where
	// level 1 begins, the fade's share of an octave.
	const float values[] = { float(_sim.tiles().get_top_tile_level()), _sim.tiles().merge_distance(1), FarTiles::TILE_MERGE_FADE };
	gdx::PackedFloat32Array out;
	out.assign(values, std::size(values));
	return out;
}










gdx::Vector2 SunflowerSimulation::choose_tile_level(double p_distance) const {
	const FarTiles::TileChoice choice = _sim.tiles().choose_tile_level(float(p_distance));
	return gdx::Vector2{ float(choice.level), choice.fade };
}

gdx::PackedByteArray SunflowerSimulation::get_active_mask(int64_t p_species) const {
	gdx::PackedByteArray out;
	if (!_is_species(p_species)) {
		return out;
	}
	const FieldLayout &layout = _sim.plants().get_layout();
	out.resize(int64_t(layout.grid_x) * layout.grid_z);
	_sim.near().write_active_mask(uint32_t(p_species), out.data());
	return out;
}

gdx::PackedByteArray SunflowerSimulation::get_tiles_drawn() const {
	gdx::PackedByteArray out;
	out.resize(_sim.tiles().get_tile_count());
	for (uint32_t tile = 0; tile < _sim.tiles().get_tile_count(); ++tile) {
		out.data()[tile] = _sim.is_tile_drawn(tile) ? 1 : 0;
	}
	return out;
}

int64_t SunflowerSimulation::get_mask_version() const {
	return _sim.get_mask_version();
}

gdx::PackedInt32Array SunflowerSimulation::get_chunk_grid() const {
	gdx::PackedInt32Array out;
	out.resize(2);
	out.data()[0] = _sim.plants().get_layout().grid_x;
	out.data()[1] = _sim.plants().get_layout().grid_z;
	return out;
}



void SunflowerSimulation::compute_chunk_signatures() {
	_sim.compute_chunk_signatures();
}

void SunflowerSimulation::release_multimeshes() {
	_buckets.assign(_sim.near().get_bucket_count(), BucketTarget{});
	_tiles.clear();
	_tile_visible.clear();
}

int64_t SunflowerSimulation::get_chunk_count() const {
	return _sim.plants().get_chunk_count();
}

gdx::AABB SunflowerSimulation::get_chunk_aabb(int64_t p_chunk) const {
	if (!_is_chunk(p_chunk)) {
		return gdx::AABB{};
	}
	const ChunkBounds bounds = _sim.plants().get_chunk_bounds(static_cast<uint32_t>(p_chunk));
	return gdx::to_godot_aabb(bounds.min, bounds.max);
}

void SunflowerSimulation::_upload_tile(uint32_t p_tile) {
	const uint32_t count = _sim.tiles().get_tile(p_tile).plants;
	gdx::PackedFloat32Array buffer;
	buffer.resize(int64_t(count) * FAR_FLOATS_PER_INSTANCE);
	_sim.tiles().write_tile_instances(p_tile, buffer.data());
	if (_tiles[p_tile].is_valid()) {
		gdx::RenderingServer::multimesh_allocate_data(_tiles[p_tile], count, gdx::RenderingServer::COMPACT);
		gdx::RenderingServer::multimesh_set_buffer(_tiles[p_tile], buffer);
	}
}

void SunflowerSimulation::_push_bucket(uint32_t p_bucket) {
	BucketTarget &target = _buckets[p_bucket];
	const InstanceBuffer &bucket = _sim.near().get_bucket(p_bucket);
	const uint32_t count = bucket.get_count();
	if (!target.multimesh.is_valid() || (count == 0 && target.last_count == 0)) {
		return;
	}
	const uint32_t stride = bucket.get_stride();
	if (count > target.allocated || stride != target.stride) {
		target.allocated = std::max(bucket.get_capacity(), count);
		target.stride = stride;
		// Whole plants' records carry custom data; the impostors' are compact (2D transforms only).
		gdx::RenderingServer::Format format = gdx::RenderingServer::TRANSFORM_AND_COLOUR;
		if (stride == WHOLE_FLOATS_PER_INSTANCE) {
			format = gdx::RenderingServer::TRANSFORM_COLOUR_AND_CUSTOM;
		} else if (stride == FAR_FLOATS_PER_INSTANCE) {
			format = gdx::RenderingServer::COMPACT;
		}
		gdx::RenderingServer::multimesh_allocate_data(target.multimesh, target.allocated, format);
		target.staging.resize(int64_t(target.allocated) * stride);
	}
	if (count > 0) {
		std::copy_n(bucket.get_data(), size_t(count) * stride, target.staging.data());
		gdx::RenderingServer::multimesh_set_buffer(target.multimesh, target.staging);
		// The box of this frame's plants, so that each pass (a shadow cascade, the camera) draws the
		// bucket only when they reach into it.
		if (bucket.get_bounds_low() != target.bounds_low || bucket.get_bounds_high() != target.bounds_high) {
			target.bounds_low = bucket.get_bounds_low();
			target.bounds_high = bucket.get_bounds_high();
			gdx::RenderingServer::multimesh_set_custom_aabb(target.multimesh, gdx::to_godot_aabb(target.bounds_low, target.bounds_high));
		}
	}
	gdx::RenderingServer::multimesh_set_visible_instances(target.multimesh, count);
	target.last_count = count;
}

void SunflowerSimulation::update(double p_delta) {
	const auto start = std::chrono::steady_clock::now();
	_sim.update(static_cast<float>(p_delta));
	for (uint32_t b = 0; b < _buckets.size(); ++b) {
		_push_bucket(b);
	}
	// Each tile draws only its records kept at the nearest level its plants may be given.
	for (size_t t = 0; t < _tiles.size() && t < _tile_visible.size(); ++t) {
		const int64_t visible = _sim.tiles().get_tile_visible_count(uint32_t(t));
		if (_tiles[t].is_valid() && visible != _tile_visible[t]) {
			gdx::RenderingServer::multimesh_set_visible_instances(_tiles[t], visible);
			_tile_visible[t] = visible;
		}
	}
	_last_update_usec = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
}

bool SunflowerSimulation::_is_plant(int64_t p_plant) const {
	SF_FAIL_COND_V_MSG(p_plant < 0 || p_plant >= int64_t(_sim.plants().get_plant_count()), false,
			"plant index " + std::to_string(p_plant) + " is out of range (the field has " +
					std::to_string(_sim.plants().get_plant_count()) + " plants)");
	return true;
}

bool SunflowerSimulation::_is_tile(int64_t p_tile) const {
	SF_FAIL_COND_V_MSG(p_tile < 0 || p_tile >= int64_t(_sim.tiles().get_tile_count()), false,
			"tile " + std::to_string(p_tile) + " is out of range (the field has " + std::to_string(_sim.tiles().get_tile_count()) +
					" tiles)");
	return true;
}

bool SunflowerSimulation::_is_chunk(int64_t p_chunk) const {
	SF_FAIL_COND_V_MSG(p_chunk < 0 || p_chunk >= int64_t(_sim.plants().get_chunk_count()), false,
			"chunk " + std::to_string(p_chunk) + " is out of range (the field has " +
					std::to_string(_sim.plants().get_chunk_count()) + " chunks)");
	return true;
}

int64_t SunflowerSimulation::get_plant_count() const {
	return _sim.plants().get_plant_count();
}

gdx::PackedInt32Array SunflowerSimulation::get_lod_counts_by_species() const {
	std::vector<int32_t> values;
	for (uint32_t species = 0; species < _sim.plants().get_species_count(); ++species) {
		for (int64_t count : _sim.near().get_lod_counts(species)) {
			values.push_back(static_cast<int32_t>(count));
		}
	}
	gdx::PackedInt32Array out;
	out.assign(values.data(), values.size());
	return out;
}


gdx::PackedInt32Array SunflowerSimulation::get_lod_counts() const {
	const auto counts = _sim.near().get_lod_counts();
	int32_t values[LOD_COUNT];
	for (size_t i = 0; i < LOD_COUNT; ++i) {
		values[i] = static_cast<int32_t>(counts[i]);
	}
	gdx::PackedInt32Array out;
	out.assign(values, LOD_COUNT);
	return out;
}

gdx::Vector3 SunflowerSimulation::get_plant_position(int64_t p_plant) const {
	if (!_is_plant(p_plant)) {
		return gdx::Vector3{};
	}
	return gdx::to_godot(_sim.plants().get_layout().plants[size_t(p_plant)].root());
}

gdx::Vector2 SunflowerSimulation::get_plant_stalk(int64_t p_plant) const {
	return _is_plant(p_plant) ? gdx::to_godot(_sim.plants().get_stalk(uint32_t(p_plant))) : gdx::Vector2{};
}

int64_t SunflowerSimulation::get_plant_lod(int64_t p_plant) const {
	return _is_plant(p_plant) ? _sim.near().get_plant_lod(uint32_t(p_plant)) : -1;
}

int64_t SunflowerSimulation::get_plant_tile_level(int64_t p_plant) const {
	return _is_plant(p_plant) ? int64_t(_sim.tiles().plant_tile_level(_sim.plants().get_layout().plants[size_t(p_plant)])) : -1;
}

gdx::PackedFloat32Array SunflowerSimulation::get_plant_parts(int64_t p_plant) const {
	gdx::PackedFloat32Array out;
	if (!_is_plant(p_plant)) {
		return out;
	}
	PartTransforms parts;
	_sim.near().get_plant_parts(uint32_t(p_plant), parts);
	out.resize(PART_COUNT * TRANSFORM_FLOATS);
	float *data = out.data();
	for (uint32_t part = 0; part < PART_COUNT; ++part) {
		write_transform(data + part * TRANSFORM_FLOATS, parts.basis[part], parts.origin[part]);
	}
	return out;
}

int64_t SunflowerSimulation::get_bucket_instance_count(int64_t p_bucket) const {
	return p_bucket >= 0 && p_bucket < int64_t(_sim.near().get_bucket_count()) ? _sim.near().get_bucket(uint32_t(p_bucket)).get_count() : 0;
}

gdx::PackedByteArray SunflowerSimulation::get_filled_buckets() const {
	gdx::PackedByteArray out;
	out.resize(_sim.near().get_bucket_count());
	uint8_t *filled = out.data();
	for (uint32_t b = 0; b < _sim.near().get_bucket_count(); ++b) {
		filled[b] = _sim.near().get_bucket(b).get_count() > 0 ? 1 : 0;
	}
	return out;
}

int64_t SunflowerSimulation::get_last_update_usec() const {
	return _last_update_usec;
}

void SunflowerSimulation::set_worker_threads(int64_t p_threads) {
	SF_FAIL_COND_MSG(p_threads < 0 || p_threads > param::MAX_THREADS,
			"worker threads " + std::to_string(p_threads) + " is out of range (0 to " + std::to_string(param::MAX_THREADS) + ")");
	_sim.near().set_worker_threads(static_cast<uint32_t>(p_threads));
}

void SunflowerSimulation::set_pushers(const gdx::PackedFloat32Array &p_pushers) {
	SF_FAIL_COND_MSG(p_pushers.size() % 4 != 0,
			"set_pushers takes 4 floats per pusher (x, y, z, radius), got " + std::to_string(p_pushers.size()));
	gdx::to_core_pushers(p_pushers, _pushers);
	_sim.near().get_pushes().set_pushers(_pushers.data(), _pushers.size());
}

void SunflowerSimulation::set_push_params(double p_strength, double p_recovery_seconds) {
	_sim.near().get_pushes().set_params(float(p_strength), float(p_recovery_seconds)); // the core applies param::PUSH_*
}

int64_t SunflowerSimulation::get_pushed_count() const {
	return _sim.near().get_pushes().get_pushed_count();
}

gdx::PackedInt32Array SunflowerSimulation::get_plants_near(gdx::Vector3 p_position, double p_radius) const {
	std::vector<uint32_t> plants;
	_sim.plants().find_plants_near(gdx::to_core_ground(p_position), float(p_radius), plants);
	return gdx::to_godot_indices(plants);
}



int64_t SunflowerSimulation::get_memory_bytes() const {
	return static_cast<int64_t>(_sim.get_memory_bytes());
}


// --- The parameter table, for the node's setters -------------------------------------------------

double SunflowerSimulation::sanitize_parameter(const gdx::String &p_name, double p_value, double p_current) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, p_value, "no parameter is called '" + p_name.utf8() + "'");
	return sanitize(*spec, p_value, p_current);
}

gdx::String SunflowerSimulation::explain_parameter(const gdx::String &p_name, double p_value, double p_used) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, gdx::String(), "no parameter is called '" + p_name.utf8() + "'");
	return gdx::String(explain_sanitized(*spec, p_value, p_used));
}

double SunflowerSimulation::get_parameter_default(const gdx::String &p_name) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, 0.0, "no parameter is called '" + p_name.utf8() + "'");
	return spec->default_value;
}

gdx::String SunflowerSimulation::get_parameter_names() {
	std::string names;
	for (const ParameterSpec *spec : param::ALL) {
		names += (names.empty() ? "" : ",") + std::string(spec->name);
	}
	return gdx::String(names);
}

gdx::String SunflowerSimulation::check_lod_distances(const gdx::PackedFloat32Array &p_distances) {
	return gdx::String(sunflower::check_lod_distances(p_distances.data(), size_t(p_distances.size())));
}

gdx::Vector2 SunflowerSimulation::sanitize_wind_direction(gdx::Vector2 p_direction) {
	return gdx::to_godot(sunflower::sanitize_wind_direction(gdx::to_core(p_direction)));
}

int64_t SunflowerSimulation::mesh_bucket(int64_t p_level, int64_t p_part) {
	SF_FAIL_COND_V_MSG(p_level < 0 || p_level >= LOD_MESH_COUNT || p_part < 0 || p_part >= PART_COUNT, -1,
			"mesh level " + std::to_string(p_level) + " / part " + std::to_string(p_part) + " is out of range (0–2 each)");
	return sunflower::mesh_bucket(uint32_t(p_level), uint32_t(p_part));
}

double SunflowerSimulation::get_plant_height_units() {
	return PlantShape::HEIGHT;
}
