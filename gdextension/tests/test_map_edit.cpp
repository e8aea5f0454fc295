#include "field_map.h"

#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <utility>

using namespace sunflower;

namespace {

FieldMap parse(const std::string &p_text, const std::u32string &p_legend = U"", const std::u32string &p_plants = U"") {
	FieldMap map;
	MapError error;
	REQUIRE(parse_field_map(p_text, p_legend, p_plants, "edit", MapLimits{}, map, error));
	return map;
}

// A canonical map: comments, header, rows with inner spaces and no trailing empty cells, an empty
// row, a legend plant and objects (one of them not ASCII).
const std::string CANONICAL = "# A test field.\n"
							  "#   indented comment\n"
							  "\n"
							  "8 5\n"
							  "***  ***\n"
							  "*m*S\n"
							  "\n"
							  "  **ö**\n"
							  "mmmm\n";

} // namespace

TEST_CASE("a canonical map is written back byte for byte") {
	const FieldMap map = parse(CANONICAL, U"Sö", U"m");
	CHECK(write_field_map(map, U"m") == CANONICAL);
	CHECK(map.preamble.size() == 3);
	CHECK(map.empty_symbol == ' ');
}

TEST_CASE("any map is written in the canonical form, which reads back as the same map") {
	// A byte-order mark, CRLF ends, trailing spaces and dots, fewer rows than declared, dots inside.
	const std::string messy = "\xEF\xBB\xBF# messy\r\n6 4\r\n*..*..\r\n.**.  \r\n";
	const FieldMap map = parse(messy);
	CHECK(map.empty_symbol == '.');
	const std::string written = write_field_map(map, U"");
	CHECK(written == "# messy\n6 4\n*..*\n.**\n\n\n");
	const FieldMap again = parse(written);
	CHECK(again.plants == map.plants);
	CHECK(write_field_map(again, U"") == written); // canonical is a fixed point
}

TEST_CASE("cells: set and get plants, legend plants and objects; counts and object order follow") {
	FieldMap map = parse(CANONICAL, U"Sö", U"m");
	const int64_t plants = map.plant_count;
	CHECK(get_cell(map, 1, 1).kind == CellContent::PLANT);
	CHECK(get_cell(map, 1, 1).species == 1);
	CHECK(get_cell(map, 3, 1).kind == CellContent::OBJECT);
	CHECK(get_cell(map, 3, 1).symbol == U'S');
	CHECK(get_cell(map, 3, 0).kind == CellContent::EMPTY);
	CHECK_FALSE(set_cell(map, 0, 0, CellContent{ CellContent::PLANT, 0, 0 })); // already a sunflower
	CHECK(set_cell(map, 3, 0, CellContent{ CellContent::OBJECT, 0, U'S' }));
	CHECK(set_cell(map, 3, 1, CellContent{ CellContent::PLANT, 0, 0 })); // the stone becomes a sunflower
	CHECK(map.plant_count == plants + 1);
	CHECK(set_cell(map, 0, 4, CellContent{})); // a maize cell emptied
	CHECK(map.plant_count == plants);
	CHECK_FALSE(set_cell(map, 8, 0, CellContent{ CellContent::PLANT, 0, 0 })); // outside
	REQUIRE(map.objects.size() == 2);
	CHECK(map.objects[0].row == 0); // map order
	CHECK(map.objects[1].symbol == U'ö');
	const std::string written = write_field_map(map, U"m");
	CHECK(written.find("\n***S ***\n") != std::string::npos);
	CHECK(written.find("\n*m**\n") != std::string::npos);
	CHECK(written.find("\n mmm\n") != std::string::npos);
	const FieldMap again = parse(written, U"Sö", U"m");
	CHECK(again.plants == map.plants);
	CHECK(again.plant_count == map.plant_count);
}

TEST_CASE("a brush stroke changes the cells within its radius only, seeded by density; erasing empties them") {
	std::string text = "40 40\n";
	for (int row = 0; row < 40; ++row) {
		text += "\n";
	}
	FieldMap map = parse(text);
	std::vector<int> changed;
	const CellContent sunflower{ CellContent::PLANT, 0, 0 };
	paint_cells(map, 10.0f, 12.0f, 4.0f, sunflower, 1.0f, 7, changed);
	std::set<std::pair<int, int>> inside;
	for (int row = 0; row < 40; ++row) {
		for (int column = 0; column < 40; ++column) {
			const float dx = float(column) + 0.5f - 10.0f;
			const float dy = float(row) + 0.5f - 12.0f;
			const bool within = dx * dx + dy * dy <= 16.0f;
			CHECK(map.has_plant(column, row) == within);
			if (within) {
				inside.insert({ column, row });
			}
		}
	}
	CHECK(changed.size() == 2 * inside.size());
	CHECK(map.plant_count == int64_t(inside.size()));
	// Half density: about half the cells, the same ones for the same seed.
	FieldMap half_a = parse(text);
	FieldMap half_b = parse(text);
	FieldMap other_seed = parse(text);
	std::vector<int> scratch;
	paint_cells(half_a, 20.0f, 20.0f, 10.0f, sunflower, 0.5f, 3, scratch);
	paint_cells(half_b, 20.0f, 20.0f, 10.0f, sunflower, 0.5f, 3, scratch);
	paint_cells(other_seed, 20.0f, 20.0f, 10.0f, sunflower, 0.5f, 4, scratch);
	CHECK(half_a.plants == half_b.plants);
	CHECK(half_a.plants != other_seed.plants);
	CHECK(half_a.plant_count > 120);
	CHECK(half_a.plant_count < 200); // about half of the ~314 cells in reach
	// Erasing empties every cell in reach, whatever the density; a stroke outside the map does nothing.
	changed.clear();
	paint_cells(map, 10.0f, 12.0f, 2.0f, CellContent{}, 0.0f, 7, changed);
	CHECK(changed.size() == 2 * 12); // the 12 cells whose centres lie within 2 cells
	CHECK(map.plant_count == int64_t(inside.size()) - 12);
	changed.clear();
	paint_cells(map, -50.0f, -50.0f, 3.0f, sunflower, 1.0f, 7, changed);
	paint_cells(map, NAN, 3.0f, 3.0f, sunflower, 1.0f, 7, changed);
	CHECK(changed.empty());
}

TEST_CASE("a brush following weights paints a cell with its weight's share of the density, erases by weight") {
	std::string text = "40 40\n";
	for (int row = 0; row < 40; ++row) {
		text += "\n";
	}
	const CellContent sunflower{ CellContent::PLANT, 0, 0 };
	CellWeights weights; // columns 10–29: weight 1 left of 20, 0 from 20 on; rows 10–29; nothing outside
	weights.column = 10;
	weights.row = 10;
	weights.columns = 20;
	weights.rows = 20;
	for (int r = 0; r < 20; r++) {
		for (int c = 0; c < 20; c++) {
			weights.values.push_back(c < 10 ? 1.0f : 0.0f);
		}
	}
	FieldMap map = parse(text);
	std::vector<int> changed;
	paint_cells(map, 20.0f, 20.0f, 15.0f, sunflower, 1.0f, 7, changed, &weights);
	for (int row = 0; row < 40; ++row) {
		for (int column = 0; column < 40; ++column) {
			CHECK(map.has_plant(column, row) == (column >= 10 && column < 20 && row >= 10 && row < 30));
		}
	}
	// A weight of a half halves the share painted; the same cells as a half density.
	std::fill(weights.values.begin(), weights.values.end(), 0.5f);
	FieldMap half_weight = parse(text);
	FieldMap half_density = parse(text);
	paint_cells(half_weight, 20.0f, 20.0f, 9.0f, sunflower, 1.0f, 3, changed, &weights);
	paint_cells(half_density, 20.0f, 20.0f, 9.0f, sunflower, 0.5f, 3, changed);
	CHECK(half_weight.plants == half_density.plants);
	CHECK(half_weight.plant_count > 80);
	// Erasing by weight: cells of weight 0 stay; a NaN weight is 0.
	std::fill(weights.values.begin(), weights.values.end(), 0.0f);
	weights.values[0] = NAN;
	changed.clear();
	paint_cells(map, 20.0f, 20.0f, 30.0f, CellContent{}, 1.0f, 7, changed, &weights);
	CHECK(changed.empty());
	std::fill(weights.values.begin(), weights.values.end(), 1.0f);
	paint_cells(map, 20.0f, 20.0f, 30.0f, CellContent{}, 1.0f, 7, changed, &weights);
	CHECK(map.plant_count == 0);
}

TEST_CASE("resizing keeps the cells both sizes share and cuts or adds the rest") {
	FieldMap map = parse(CANONICAL, U"Sö", U"m");
	const int64_t plants = map.plant_count;
	REQUIRE(resize_field_map(map, 10, 7, MapLimits{}));
	CHECK(map.columns == 10);
	CHECK(map.rows == 7);
	CHECK(map.plant_count == plants);
	CHECK(write_field_map(map, U"m") == "# A test field.\n#   indented comment\n\n10 7\n***  ***\n*m*S\n\n  **ö**\nmmmm\n\n\n");
	REQUIRE(resize_field_map(map, 3, 2, MapLimits{}));
	CHECK(write_field_map(map, U"m") == "# A test field.\n#   indented comment\n\n3 2\n***\n*m*\n");
	CHECK(map.plant_count == 6);
	CHECK(map.objects.empty()); // the stone at column 3 was cut off
	CHECK_FALSE(resize_field_map(map, 0, 5, MapLimits{}));
	MapLimits small;
	small.max_cells = 100;
	CHECK_FALSE(resize_field_map(map, 20, 20, small));
	CHECK(map.columns == 3); // unchanged
}
