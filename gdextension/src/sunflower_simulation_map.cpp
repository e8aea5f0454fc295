// SunflowerSimulation's map: reading, checking and editing it.
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

gdx::PackedInt32Array SunflowerSimulation::paint_map(gdx::Vector2 p_center, double p_radius, const gdx::String &p_symbol,
		double p_density, int64_t p_seed, bool p_relayout, const gdx::PackedFloat32Array &p_weights,
		const gdx::PackedInt32Array &p_weights_rect) {
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
	CellWeights weights;
	const bool weighted = p_weights.size() > 0;
	if (weighted) {
		SF_FAIL_COND_V_MSG(p_weights_rect.size() != 4 || p_weights_rect.data()[2] < 0 || p_weights_rect.data()[3] < 0 ||
						int64_t(p_weights_rect.data()[2]) * p_weights_rect.data()[3] != p_weights.size(),
				gdx::PackedInt32Array(),
				"paint_map: weights_rect must be column, row, columns, rows of the weights' " + std::to_string(p_weights.size()) +
						" cells");
		const int32_t *rect = p_weights_rect.data();
		weights.column = rect[0];
		weights.row = rect[1];
		weights.columns = rect[2];
		weights.rows = rect[3];
		weights.values.assign(p_weights.data(), p_weights.data() + p_weights.size());
	}
	std::vector<int> changed;
	_sim.paint_map(gdx::to_core(p_center), float(p_radius), content, float(p_density), uint64_t(p_seed), p_relayout, changed,
			weighted ? &weights : nullptr);
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
