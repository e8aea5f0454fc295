// SunflowerMap's registration and its reading, checking and editing of one map.
#include "sunflower_map.h"

#include "binding/class_binder.h"
#include "convert.h"
#include "binding/error_macros.h"

#include <vector>

using namespace sunflower;

void SunflowerMap::bind_methods() {
	gdx::bind_method(CLASS, "load", &SunflowerMap::load, { "text", "source", "legend", "plant_symbols", "max_plants" });
	gdx::bind_method(CLASS, "check", &SunflowerMap::check, { "text", "source", "legend", "plant_symbols", "max_plants", "any_symbol" });
	gdx::bind_method(CLASS, "get_figures", &SunflowerMap::get_figures, { "text", "max_plants" });
	gdx::bind_method(CLASS, "paint", &SunflowerMap::paint, { "center", "radius", "symbol", "density", "seed", "weights", "weights_rect" });
	gdx::bind_method(CLASS, "resize", &SunflowerMap::resize, { "columns", "rows" });
	gdx::bind_method(CLASS, "write", &SunflowerMap::write);
	gdx::bind_method(CLASS, "get_columns", &SunflowerMap::get_columns);
	gdx::bind_method(CLASS, "get_rows", &SunflowerMap::get_rows);
	gdx::bind_method(CLASS, "get_objects", &SunflowerMap::get_objects);
}

MapLimits SunflowerMap::limits_for(int64_t p_max_plants) {
	MapLimits limits;
	if (p_max_plants > 0) {
		limits.max_plants = p_max_plants;
	}
	return limits;
}

gdx::PackedInt32Array SunflowerMap::objects_of(const FieldMap &p_map) {
	std::vector<int32_t> flat;
	for (const MapObject &object : p_map.objects) {
		flat.insert(flat.end(), { object.column, object.row, static_cast<int32_t>(object.symbol) });
	}
	gdx::PackedInt32Array out;
	out.assign(flat.data(), flat.size());
	return out;
}

gdx::String SunflowerMap::load(const gdx::PackedByteArray &p_text, const gdx::String &p_source, const gdx::String &p_legend,
		const gdx::String &p_plant_symbols, int64_t p_max_plants) {
	FieldMap parsed;
	MapError error;
	const std::u32string plant_symbols = decode_utf8_text(p_plant_symbols.utf8());
	if (!parse_field_map(gdx::to_core(p_text), decode_utf8_text(p_legend.utf8()), plant_symbols, p_source.utf8(),
				limits_for(p_max_plants), parsed, error)) {
		return gdx::String(error.to_string());
	}
	_map = std::move(parsed);
	_plant_symbols = plant_symbols;
	return gdx::String();
}

gdx::String SunflowerMap::check(const gdx::PackedByteArray &p_text, const gdx::String &p_source, const gdx::String &p_legend,
		const gdx::String &p_plant_symbols, int64_t p_max_plants, bool p_any_symbol) {
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

gdx::PackedInt32Array SunflowerMap::get_figures(const gdx::PackedByteArray &p_text, int64_t p_max_plants) {
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

gdx::PackedInt32Array SunflowerMap::paint(gdx::Vector2 p_center, double p_radius, const gdx::String &p_symbol, double p_density,
		int64_t p_seed, const gdx::PackedFloat32Array &p_weights, const gdx::PackedInt32Array &p_weights_rect) {
	const std::u32string symbol = decode_utf8_text(p_symbol.utf8());
	SF_FAIL_COND_V_MSG(symbol.size() > 1, gdx::PackedInt32Array(),
			"paint: the symbol must be one character ('*', a legend symbol) or empty to erase; got \"" + p_symbol.utf8() + "\"");
	CellContent content;
	if (!symbol.empty() && symbol[0] != U' ' && symbol[0] != U'.') {
		const size_t plant = _plant_symbols.find(symbol[0]);
		if (symbol[0] == U'*') {
			content = CellContent{ CellContent::PLANT, 0, 0 };
		} else if (plant != std::u32string::npos) {
			content = CellContent{ CellContent::PLANT, int(plant) + 1, 0 };
		} else {
			content = CellContent{ CellContent::OBJECT, 0, symbol[0] };
		}
	}
	CellWeights weights;
	const bool weighted = p_weights.size() > 0;
	if (weighted) {
		SF_FAIL_COND_V_MSG(p_weights_rect.size() != 4 || p_weights_rect.data()[2] < 0 || p_weights_rect.data()[3] < 0 ||
						int64_t(p_weights_rect.data()[2]) * p_weights_rect.data()[3] != p_weights.size(),
				gdx::PackedInt32Array(),
				"paint: weights_rect must be column, row, columns, rows of the weights' " + std::to_string(p_weights.size()) +
						" cells");
		const int32_t *rect = p_weights_rect.data();
		weights.column = rect[0];
		weights.row = rect[1];
		weights.columns = rect[2];
		weights.rows = rect[3];
		weights.values.assign(p_weights.data(), p_weights.data() + p_weights.size());
	}
	std::vector<int> changed;
	const glm::vec2 center = gdx::to_core(p_center);
	paint_cells(_map, center.x, center.y, float(p_radius), content, float(p_density), uint64_t(p_seed), changed,
			weighted ? &weights : nullptr);
	gdx::PackedInt32Array out;
	out.assign(changed.data(), changed.size());
	return out;
}

bool SunflowerMap::resize(int64_t p_columns, int64_t p_rows) {
	const MapLimits limits;
	SF_FAIL_COND_V_MSG(p_columns < 1 || p_rows < 1 || p_columns > limits.max_side || p_rows > limits.max_side ||
					p_columns * p_rows > limits.max_cells,
			false,
			"resize: " + std::to_string(p_columns) + " x " + std::to_string(p_rows) + " is not a map size (1 to " +
					std::to_string(limits.max_side) + " a side, at most " + std::to_string(limits.max_cells) + " cells)");
	return resize_field_map(_map, int(p_columns), int(p_rows), limits);
}

gdx::PackedByteArray SunflowerMap::write() const {
	const std::string text = write_field_map(_map, _plant_symbols);
	gdx::PackedByteArray out;
	out.assign(reinterpret_cast<const uint8_t *>(text.data()), text.size());
	return out;
}

gdx::PackedInt32Array SunflowerMap::get_objects() const {
	return objects_of(_map);
}
