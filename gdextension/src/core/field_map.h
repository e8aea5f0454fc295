#pragma once
// The plain-text field map (fields/FORMAT.md): a header "COLUMNS ROWS", then one line per row,
// '*' a sunflower, ' ' or '.' nothing, other characters only when the legend names them: as another
// plant type (species 1, 2, … in the order given) or as an object (a scene the addon places).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sunflower {

struct MapError {
	std::string source;
	int line = 0; // 1-based; 0 when the error concerns the whole file
	int column = 0; // 1-based character (not byte) column; 0 when it concerns the whole line
	std::string message;

	// "source:line:column: message", the form editors and compilers use.
	std::string to_string() const;
};

struct MapObject {
	int column = 0; // 0-based cell coordinates
	int row = 0;
	char32_t symbol = 0;
};

struct FieldMap {
	int columns = 0;
	int rows = 0;
	// At most this many plant types in one map: '*' and up to seven legend plants.
	static constexpr int MAX_SPECIES = 8;
	// One byte per cell, row-major: 1 + the species of the plant standing there ('*' is species 0),
	// 0 where none does.
	std::vector<uint8_t> plants;
	int species_count = 1; // '*' and the plant symbols the map was read with
	// Cells holding a legend character (e.g. the thesis' "big stone").
	std::vector<MapObject> objects;
	int64_t plant_count = 0;

	bool has_plant(int p_column, int p_row) const {
		return plants[static_cast<size_t>(p_row) * static_cast<size_t>(columns) + static_cast<size_t>(p_column)] != 0;
	}
	// The species of the plant at a cell that has one.
	int species_at(int p_column, int p_row) const {
		return plants[static_cast<size_t>(p_row) * static_cast<size_t>(columns) + static_cast<size_t>(p_column)] - 1;
	}
};

struct MapLimits {
	int64_t max_cells = int64_t(1) << 32; // columns × rows
	int64_t max_plants = 16'000'000;
	int max_side = 1'000'000;
};

// Decodes UTF-8 text into code points (legend symbols); malformed bytes become U+FFFD, one each.
std::u32string decode_utf8_text(std::string_view p_text);

// Parses p_text (raw bytes of the file). p_legend lists the extra symbols allowed in rows as objects,
// p_plant_symbols those that are plants of species 1, 2, … (at most MAX_SPECIES - 1; a symbol in
// both is a plant). On failure returns false and fills r_error; r_map is then left unspecified.
bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, std::u32string_view p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, FieldMap &r_map, MapError &r_error);
// The same with '*' as the only plant.
bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, const std::string &p_source,
		const MapLimits &p_limits, FieldMap &r_map, MapError &r_error);

} // namespace sunflower
