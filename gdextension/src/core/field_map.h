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
	// The lines before the header (comments and blank lines), without their line ends: written back.
	std::vector<std::string> preamble;
	// How the file writes an empty cell inside a row, ' ' or '.' (whichever it used more).
	char empty_symbol = ' ';
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
	// Every printable symbol that is not a plant is kept as an object, whatever the legend says: how
	// the importer reads a map, which is checked against its field's legend when the field loads it.
	bool any_object_symbol = false;
};

// Whether a map may hold p_symbol as a legend symbol at all: a printable character (no control
// character, no U+FFFD standing for bytes that are not UTF-8).
bool is_printable_symbol(char32_t p_symbol);

// Decodes UTF-8 text into code points (legend symbols); malformed bytes become U+FFFD, one each.
std::u32string decode_utf8_text(std::string_view p_text);

// Parses p_text (raw bytes of the file). p_legend lists the extra symbols allowed in rows as objects,
// p_plant_symbols those that are plants of species 1, 2, … (at most MAX_SPECIES - 1; a symbol in
// both is a plant). On failure returns false and fills r_error; r_map is then left unspecified.
bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, std::u32string_view p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, FieldMap &r_map, MapError &r_error);
// The map as text in the format's canonical form: the preamble lines, "COLUMNS ROWS", then every
// declared row with each cell's symbol ('*', the plant symbols, object symbols, empty_symbol for an
// empty cell) and no trailing empty cells; LF line ends, a final LF, no byte-order mark.
// p_plant_symbols as read (species 1, 2, …). Parsing the result gives the same map.
std::string write_field_map(const FieldMap &p_map, std::u32string_view p_plant_symbols);

// What a cell holds, as painting sets it.
struct CellContent {
	enum Kind : uint8_t {
		EMPTY,
		PLANT,
		OBJECT,
	};
	Kind kind = EMPTY;
	int species = 0; // PLANT
	char32_t symbol = 0; // OBJECT

	bool operator==(const CellContent &p_other) const {
		return kind == p_other.kind && species == p_other.species && symbol == p_other.symbol;
	}
};

// What a cell holds now.
CellContent get_cell(const FieldMap &p_map, int p_column, int p_row);
// Sets a cell; returns whether it changed. Keeps plant_count and the object list in step.
bool set_cell(FieldMap &r_map, int p_column, int p_row, const CellContent &p_content);

// Weights over a rectangle of the map's cells (a brush following a placement layer's filters: see
// placement_layer_weights); a cell outside the rectangle weighs 0.
struct CellWeights {
	int column = 0;
	int row = 0;
	int columns = 0;
	int rows = 0;
	std::vector<float> values; // columns × rows, row-major, each 0–1
	float at(int p_column, int p_row) const;
};

// A brush stroke: every cell whose centre lies within p_radius cells of p_center (in cells, x along
// columns, y along rows) gets p_content, if its seeded draw (p_seed, column, row) falls below
// p_density (1: every cell); an erasing stroke (p_content EMPTY) empties every cell in reach. With
// p_weights, a painted cell's chance is p_density × its weight, and an erased cell is emptied when
// its draw falls below its weight. The changed cells are appended to r_changed as column, row pairs.
void paint_cells(FieldMap &r_map, float p_center_x, float p_center_y, float p_radius, const CellContent &p_content,
		float p_density, uint64_t p_seed, std::vector<int> &r_changed, const CellWeights *p_weights = nullptr);

// Gives the map p_columns × p_rows cells (each at least 1): cells and objects inside both sizes
// stay where they are, the rest is cut off or added empty. Returns false (and leaves the map) for a
// size out of p_limits.
bool resize_field_map(FieldMap &r_map, int p_columns, int p_rows, const MapLimits &p_limits);

// The same with '*' as the only plant.
bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, const std::string &p_source,
		const MapLimits &p_limits, FieldMap &r_map, MapError &r_error);

} // namespace sunflower
