#include "sunflower_placement.h"

#include "binding/class_binder.h"
#include "core/field_map.h"

#include <algorithm>
#include <thread>

namespace {

template <class T, class P>
std::vector<T> to_vector(const P &p_array) {
	const T *data = p_array.data();
	return data ? std::vector<T>(data, data + p_array.size()) : std::vector<T>();
}

// The rectangle of cells (p_column, p_row, p_columns, p_rows) GDScript asks for, when every number is
// a map side's or less (the core checks it lies in the field).
bool rect_from(int64_t p_column, int64_t p_row, int64_t p_columns, int64_t p_rows, sunflower::CellRect &r_rect) {
	const int64_t limit = sunflower::MapLimits{}.max_side;
	if (std::min({ p_column, p_row, p_columns, p_rows }) < 0 || std::max({ p_column, p_row, p_columns, p_rows }) > limit) {
		return false;
	}
	r_rect = sunflower::CellRect{ static_cast<int>(p_column), static_cast<int>(p_row), static_cast<int>(p_columns),
		static_cast<int>(p_rows) };
	return true;
}

} // namespace

void SunflowerPlacement::bind_methods() {
	gdx::bind_method(CLASS, "get_layer_fields", &SunflowerPlacement::get_layer_fields);
	gdx::bind_method(CLASS, "set_field", &SunflowerPlacement::set_field, { "columns", "rows", "cell_size", "seed" });
	gdx::bind_method(CLASS, "set_heights", &SunflowerPlacement::set_heights, { "heights" });
	gdx::bind_method(CLASS, "clear_layers", &SunflowerPlacement::clear_layers);
	gdx::bind_method(CLASS, "add_layer", &SunflowerPlacement::add_layer, { "row", "lines", "footprints", "mask" });
	gdx::bind_method(CLASS, "check", &SunflowerPlacement::check);
	gdx::bind_method(CLASS, "generate", &SunflowerPlacement::generate, { "column", "row", "columns", "rows", "threads" });
	gdx::bind_method(CLASS, "layer_weights", &SunflowerPlacement::layer_weights,
			{ "layer", "column", "row", "columns", "rows", "map" });
	gdx::bind_method(CLASS, "cancel", &SunflowerPlacement::cancel);
	gdx::bind_method(CLASS, "write_map", &SunflowerPlacement::write_map,
			{ "cells", "columns", "rows", "plant_symbols", "header", "previous" });
	gdx::bind_method(CLASS, "read_map_cells", &SunflowerPlacement::read_map_cells, { "text", "plant_symbols" });
	gdx::bind_method(CLASS, "keep_hand_edits", &SunflowerPlacement::keep_hand_edits, { "generated_before", "edited", "generated_now" });
}

gdx::String SunflowerPlacement::get_layer_fields() {
	std::string names;
	for (const std::string &name : sunflower::placement_layer_fields()) {
		names += (names.empty() ? "" : ",") + name;
	}
	return gdx::String(names);
}

void SunflowerPlacement::set_field(int64_t p_columns, int64_t p_rows, double p_cell_size, int64_t p_seed) {
	_rules.columns = static_cast<int>(std::clamp<int64_t>(p_columns, 0, sunflower::MapLimits{}.max_side));
	_rules.rows = static_cast<int>(std::clamp<int64_t>(p_rows, 0, sunflower::MapLimits{}.max_side));
	_rules.cell_size = static_cast<float>(p_cell_size);
	_rules.seed = static_cast<uint64_t>(p_seed);
}

void SunflowerPlacement::set_heights(const gdx::PackedFloat32Array &p_heights) {
	_rules.heights = to_vector<float>(p_heights);
}

void SunflowerPlacement::clear_layers() {
	_rules.layers.clear();
}

gdx::String SunflowerPlacement::add_layer(const gdx::PackedFloat32Array &p_row, const gdx::PackedFloat32Array &p_lines,
		const gdx::PackedFloat32Array &p_footprints, const gdx::PackedByteArray &p_mask) {
	sunflower::PlacementLayer layer;
	const std::string problem = sunflower::placement_layer_from(to_vector<float>(p_row), to_vector<float>(p_lines),
			to_vector<float>(p_footprints), to_vector<uint8_t>(p_mask), layer);
	if (problem.empty()) {
		_rules.layers.push_back(std::move(layer));
	}
	return gdx::String(problem);
}

gdx::String SunflowerPlacement::check() const {
	return gdx::String(sunflower::check_placement(_rules));
}

gdx::PackedByteArray SunflowerPlacement::generate(int64_t p_column, int64_t p_row, int64_t p_columns, int64_t p_rows, int64_t p_threads) {
	gdx::PackedByteArray out;
	_cancel = false;
	sunflower::CellRect rect;
	if (!rect_from(p_column, p_row, p_columns, p_rows, rect)) {
		return out;
	}
	const uint32_t cores = std::max(1u, std::thread::hardware_concurrency());
	sunflower::WorkerPool pool(p_threads > 0 ? static_cast<uint32_t>(std::min<int64_t>(p_threads, 64)) : std::min(cores, 8u));
	std::vector<uint8_t> cells;
	if (sunflower::generate_placement(_rules, rect, &pool, cells, &_cancel)) {
		out.assign(cells.data(), cells.size());
	}
	return out;
}

gdx::PackedFloat32Array SunflowerPlacement::layer_weights(int64_t p_layer, int64_t p_column, int64_t p_row, int64_t p_columns,
		int64_t p_rows, const gdx::PackedByteArray &p_map) const {
	gdx::PackedFloat32Array out;
	sunflower::CellRect rect;
	if (p_layer < 0 || !rect_from(p_column, p_row, p_columns, p_rows, rect)) {
		return out;
	}
	std::vector<float> weights;
	if (sunflower::placement_layer_weights(_rules, static_cast<size_t>(p_layer), rect, to_vector<uint8_t>(p_map), weights)) {
		out.assign(weights.data(), weights.size());
	}
	return out;
}

void SunflowerPlacement::cancel() {
	_cancel = true;
}

// p_text parsed with any printable symbol an object; false when it does not parse.
static bool parse_any(const gdx::PackedByteArray &p_text, const std::u32string &p_plant_symbols, sunflower::FieldMap &r_map) {
	const uint8_t *bytes = p_text.data();
	const std::string_view text(reinterpret_cast<const char *>(bytes ? bytes : reinterpret_cast<const uint8_t *>("")),
			static_cast<size_t>(p_text.size()));
	sunflower::MapLimits limits;
	limits.any_object_symbol = true;
	sunflower::MapError error;
	return sunflower::parse_field_map(text, U"", p_plant_symbols, "previous", limits, r_map, error);
}

gdx::PackedByteArray SunflowerPlacement::write_map(const gdx::PackedByteArray &p_cells, int64_t p_columns, int64_t p_rows,
		const gdx::String &p_plant_symbols, const gdx::String &p_header, const gdx::PackedByteArray &p_previous) {
	gdx::PackedByteArray out;
	const std::u32string symbols = sunflower::decode_utf8_text(p_plant_symbols.utf8());
	if (p_columns < 1 || p_rows < 1 || p_cells.size() != p_columns * p_rows ||
			symbols.size() >= static_cast<size_t>(sunflower::FieldMap::MAX_SPECIES)) {
		return out;
	}
	sunflower::FieldMap previous;
	if (p_previous.size() > 0 && !parse_any(p_previous, symbols, previous)) {
		return out;
	}
	sunflower::FieldMap map;
	map.columns = static_cast<int>(p_columns);
	map.rows = static_cast<int>(p_rows);
	map.plants = to_vector<uint8_t>(p_cells);
	map.species_count = 1 + static_cast<int>(symbols.size());
	map.empty_symbol = '.';
	for (uint8_t &cell : map.plants) {
		if (cell > map.species_count) {
			cell = 0; // a plant type the symbols do not name: no plant (the caller checks the count)
		}
		map.plant_count += cell != 0 ? 1 : 0;
	}
	for (const sunflower::MapObject &object : previous.objects) {
		if (object.column < map.columns && object.row < map.rows) {
			uint8_t &cell = map.plants[static_cast<size_t>(object.row) * static_cast<size_t>(map.columns) + static_cast<size_t>(object.column)];
			map.plant_count -= cell != 0 ? 1 : 0;
			cell = 0;
			map.objects.push_back(object);
		}
	}
	map.preamble = previous.preamble;
	const std::string header = map.preamble.empty() ? p_header.utf8() : std::string();
	size_t start = 0;
	while (start < header.size()) {
		const size_t end = header.find('\n', start);
		map.preamble.push_back(header.substr(start, end == std::string::npos ? std::string::npos : end - start));
		start = end == std::string::npos ? header.size() : end + 1;
	}
	const std::string text = sunflower::write_field_map(map, symbols);
	out.assign(reinterpret_cast<const uint8_t *>(text.data()), text.size());
	return out;
}

gdx::PackedByteArray SunflowerPlacement::read_map_cells(const gdx::PackedByteArray &p_text, const gdx::String &p_plant_symbols) {
	gdx::PackedByteArray out;
	sunflower::FieldMap map;
	if (parse_any(p_text, sunflower::decode_utf8_text(p_plant_symbols.utf8()), map)) {
		out.assign(map.plants.data(), map.plants.size());
	}
	return out;
}

gdx::PackedByteArray SunflowerPlacement::keep_hand_edits(const gdx::PackedByteArray &p_generated_before,
		const gdx::PackedByteArray &p_edited, const gdx::PackedByteArray &p_generated_now) {
	gdx::PackedByteArray out;
	if (p_generated_before.size() != p_edited.size() || p_edited.size() != p_generated_now.size()) {
		return out;
	}
	const std::vector<uint8_t> kept = sunflower::keep_hand_edits(to_vector<uint8_t>(p_generated_before),
			to_vector<uint8_t>(p_edited), to_vector<uint8_t>(p_generated_now));
	out.assign(kept.data(), kept.size());
	return out;
}
