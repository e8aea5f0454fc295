// Writing and editing field maps (field_map.h): the canonical writer, cells, brush strokes.
#include "field_map.h"
#include "random_hash.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sunflower {

namespace {

void append_utf8(std::string &r_out, char32_t p_code) {
	if (p_code < 0x80) {
		r_out += static_cast<char>(p_code);
	} else if (p_code < 0x800) {
		r_out += static_cast<char>(0xC0 | (p_code >> 6));
		r_out += static_cast<char>(0x80 | (p_code & 0x3F));
	} else if (p_code < 0x10000) {
		r_out += static_cast<char>(0xE0 | (p_code >> 12));
		r_out += static_cast<char>(0x80 | ((p_code >> 6) & 0x3F));
		r_out += static_cast<char>(0x80 | (p_code & 0x3F));
	} else {
		r_out += static_cast<char>(0xF0 | (p_code >> 18));
		r_out += static_cast<char>(0x80 | ((p_code >> 12) & 0x3F));
		r_out += static_cast<char>(0x80 | ((p_code >> 6) & 0x3F));
		r_out += static_cast<char>(0x80 | (p_code & 0x3F));
	}
}

size_t cell_index(const FieldMap &p_map, int p_column, int p_row) {
	return static_cast<size_t>(p_row) * static_cast<size_t>(p_map.columns) + static_cast<size_t>(p_column);
}

} // namespace

std::string write_field_map(const FieldMap &p_map, std::u32string_view p_plant_symbols) {
	std::unordered_map<size_t, char32_t> objects;
	objects.reserve(p_map.objects.size());
	for (const MapObject &object : p_map.objects) {
		objects[cell_index(p_map, object.column, object.row)] = object.symbol;
	}
	std::string out;
	out.reserve(p_map.plants.size() + size_t(p_map.rows) + 64);
	for (const std::string &line : p_map.preamble) {
		out += line;
		out += '\n';
	}
	out += std::to_string(p_map.columns) + " " + std::to_string(p_map.rows) + "\n";
	std::string row_text;
	for (int row = 0; row < p_map.rows; ++row) {
		row_text.clear();
		size_t kept = 0; // bytes up to the last cell that is not empty
		for (int column = 0; column < p_map.columns; ++column) {
			const size_t cell = cell_index(p_map, column, row);
			const uint8_t plant = p_map.plants[cell];
			if (plant == 1) {
				row_text += '*';
			} else if (plant > 1 && size_t(plant - 2) < p_plant_symbols.size()) {
				append_utf8(row_text, p_plant_symbols[plant - 2]);
			} else if (const auto found = objects.find(cell); found != objects.end()) {
				append_utf8(row_text, found->second);
			} else {
				row_text += p_map.empty_symbol;
				continue;
			}
			kept = row_text.size();
		}
		out.append(row_text, 0, kept);
		out += '\n';
	}
	return out;
}

CellContent get_cell(const FieldMap &p_map, int p_column, int p_row) {
	CellContent content;
	if (p_column < 0 || p_row < 0 || p_column >= p_map.columns || p_row >= p_map.rows) {
		return content;
	}
	const uint8_t plant = p_map.plants[cell_index(p_map, p_column, p_row)];
	if (plant != 0) {
		content.kind = CellContent::PLANT;
		content.species = plant - 1;
		return content;
	}
	for (const MapObject &object : p_map.objects) {
		if (object.column == p_column && object.row == p_row) {
			content.kind = CellContent::OBJECT;
			content.symbol = object.symbol;
			break;
		}
	}
	return content;
}

bool set_cell(FieldMap &r_map, int p_column, int p_row, const CellContent &p_content) {
	if (p_column < 0 || p_row < 0 || p_column >= r_map.columns || p_row >= r_map.rows) {
		return false;
	}
	const CellContent current = get_cell(r_map, p_column, p_row);
	if (current == p_content) {
		return false;
	}
	uint8_t &plant = r_map.plants[cell_index(r_map, p_column, p_row)];
	if (current.kind == CellContent::PLANT) {
		--r_map.plant_count;
	} else if (current.kind == CellContent::OBJECT) {
		r_map.objects.erase(std::find_if(r_map.objects.begin(), r_map.objects.end(),
				[&](const MapObject &p_object) { return p_object.column == p_column && p_object.row == p_row; }));
	}
	plant = 0;
	if (p_content.kind == CellContent::PLANT) {
		plant = static_cast<uint8_t>(1 + std::clamp(p_content.species, 0, FieldMap::MAX_SPECIES - 1));
		r_map.species_count = std::max(r_map.species_count, int(plant));
		++r_map.plant_count;
	} else if (p_content.kind == CellContent::OBJECT) {
		// Objects stay in map order (row by row), as the parser lists them.
		const auto at = std::find_if(r_map.objects.begin(), r_map.objects.end(), [&](const MapObject &p_object) {
			return p_object.row > p_row || (p_object.row == p_row && p_object.column > p_column);
		});
		r_map.objects.insert(at, MapObject{ p_column, p_row, p_content.symbol });
	}
	return true;
}

bool resize_field_map(FieldMap &r_map, int p_columns, int p_rows, const MapLimits &p_limits) {
	if (p_columns < 1 || p_rows < 1 || p_columns > p_limits.max_side || p_rows > p_limits.max_side ||
			int64_t(p_columns) * int64_t(p_rows) > p_limits.max_cells) {
		return false;
	}
	std::vector<uint8_t> plants(size_t(p_columns) * size_t(p_rows), 0);
	int64_t count = 0;
	for (int row = 0; row < std::min(p_rows, r_map.rows); ++row) {
		for (int column = 0; column < std::min(p_columns, r_map.columns); ++column) {
			const uint8_t plant = r_map.plants[cell_index(r_map, column, row)];
			plants[size_t(row) * size_t(p_columns) + size_t(column)] = plant;
			count += plant != 0 ? 1 : 0;
		}
	}
	r_map.objects.erase(std::remove_if(r_map.objects.begin(), r_map.objects.end(),
								[&](const MapObject &p_object) { return p_object.column >= p_columns || p_object.row >= p_rows; }),
			r_map.objects.end());
	r_map.plants = std::move(plants);
	r_map.columns = p_columns;
	r_map.rows = p_rows;
	r_map.plant_count = count;
	return true;
}

float CellWeights::at(int p_column, int p_row) const {
	const int c = p_column - column;
	const int r = p_row - row;
	if (c < 0 || r < 0 || c >= columns || r >= rows) {
		return 0.0f;
	}
	const size_t index = static_cast<size_t>(r) * static_cast<size_t>(columns) + static_cast<size_t>(c);
	if (index >= values.size()) {
		return 0.0f;
	}
	const float weight = values[index];
	return std::isfinite(weight) ? std::clamp(weight, 0.0f, 1.0f) : 0.0f;
}

void paint_cells(FieldMap &r_map, float p_center_x, float p_center_y, float p_radius, const CellContent &p_content,
		float p_density, uint64_t p_seed, std::vector<int> &r_changed, const CellWeights *p_weights) {
	if (!(p_radius >= 0.0f) || !std::isfinite(p_radius) || !std::isfinite(p_center_x) || !std::isfinite(p_center_y)) {
		return;
	}
	const float density = std::isfinite(p_density) ? std::clamp(p_density, 0.0f, 1.0f) : 0.0f;
	const int column0 = std::max(0, static_cast<int>(std::floor(p_center_x - p_radius)));
	const int column1 = std::min(r_map.columns - 1, static_cast<int>(std::floor(p_center_x + p_radius)));
	const int row0 = std::max(0, static_cast<int>(std::floor(p_center_y - p_radius)));
	const int row1 = std::min(r_map.rows - 1, static_cast<int>(std::floor(p_center_y + p_radius)));
	const bool erase = p_content.kind == CellContent::EMPTY;
	for (int row = row0; row <= row1; ++row) {
		for (int column = column0; column <= column1; ++column) {
			const float dx = float(column) + 0.5f - p_center_x;
			const float dy = float(row) + 0.5f - p_center_y;
			if (dx * dx + dy * dy > p_radius * p_radius) {
				continue;
			}
			const float weight = p_weights ? p_weights->at(column, row) : 1.0f;
			const float chance = erase ? weight : density * weight;
			if (chance < 1.0f && unit_float(hash_plant(p_seed, cell_index(r_map, column, row), STREAM_PAINT)) >= chance) {
				continue;
			}
			if (set_cell(r_map, column, row, p_content)) {
				r_changed.push_back(column);
				r_changed.push_back(row);
			}
		}
	}
}

} // namespace sunflower
