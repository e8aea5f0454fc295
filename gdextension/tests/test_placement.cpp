#include "placement.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace sunflower;

namespace {

PlacementRules field(int p_columns, int p_rows, float p_cell = 1.0f) {
	PlacementRules rules;
	rules.columns = p_columns;
	rules.rows = p_rows;
	rules.cell_size = p_cell;
	rules.seed = 7;
	return rules;
}

std::vector<uint8_t> whole(const PlacementRules &p_rules, WorkerPool *p_pool = nullptr) {
	std::vector<uint8_t> cells;
	REQUIRE(check_placement(p_rules) == "");
	REQUIRE(generate_placement(p_rules, CellRect{ 0, 0, p_rules.columns, p_rules.rows }, p_pool, cells));
	return cells;
}

uint8_t at(const PlacementRules &p_rules, const std::vector<uint8_t> &p_cells, int p_column, int p_row) {
	return p_cells[static_cast<size_t>(p_row) * static_cast<size_t>(p_rules.columns) + static_cast<size_t>(p_column)];
}

// Heights rising along x at p_degrees everywhere.
std::vector<float> incline(const PlacementRules &p_rules, float p_degrees) {
	std::vector<float> heights;
	const float rise = static_cast<float>(std::tan(double(p_degrees) * 3.14159265358979 / 180.0));
	for (int r = 0; r < p_rules.rows; r++) {
		for (int c = 0; c < p_rules.columns; c++) {
			heights.push_back(static_cast<float>(c) * p_rules.cell_size * rise);
		}
	}
	return heights;
}

double share(const std::vector<uint8_t> &p_cells, uint8_t p_value) {
	size_t n = 0;
	for (uint8_t cell : p_cells) {
		n += cell == p_value ? 1 : 0;
	}
	return double(n) / double(p_cells.size());
}

// A hillside with every kind of filter, the layers depending on one another through spacing.
PlacementRules hillside(int p_columns, int p_rows) {
	PlacementRules rules = field(p_columns, p_rows, 0.5f);
	rules.seed = 20081;
	for (int r = 0; r < p_rows; r++) {
		for (int c = 0; c < p_columns; c++) {
			const float x = static_cast<float>(c) * 0.5f;
			const float z = static_cast<float>(r) * 0.5f;
			rules.heights.push_back(0.0005f * x * x + 3.0f * std::sin(z * 0.05f) + 0.1f * x);
		}
	}
	PlacementLayer trees;
	trees.species = 1;
	trees.density = 0.08f;
	trees.noise = NoiseFilter{ true, 30.0f, 3, 0.55f, 0.1f, 1, false };
	trees.paths.enabled = true;
	trees.paths.lines = { { 0.0f, 10.0f, 40.0f, 30.0f, 200.0f, 25.0f } };
	trees.paths.half_width = 2.0f;
	trees.paths.falloff = 3.0f;
	trees.exclusion.enabled = true;
	trees.exclusion.footprints = { { 50.0f, 50.0f, 60.0f, 50.0f, 60.0f, 58.0f, 50.0f, 58.0f } };
	trees.exclusion.falloff = 1.0f;
	PlacementLayer grass;
	grass.species = 0;
	grass.density = 0.9f;
	grass.slope = RangeFilter{ true, 0.0f, 20.0f, 5.0f, false };
	grass.paths = trees.paths;
	grass.paths.falloff = 0.5f;
	grass.spacing = SpacingFilter{ true, 0, 1.5f };
	PlacementLayer flowers;
	flowers.species = 2;
	flowers.mode = PlacementLayer::PLACE;
	flowers.density = 0.3f;
	flowers.height = RangeFilter{ true, 0.0f, 8.0f, 2.0f, false };
	flowers.mask.enabled = true;
	flowers.mask.width = 4;
	flowers.mask.height = 4;
	flowers.mask.values = { 0, 255, 255, 0, 255, 255, 0, 0, 128, 128, 64, 0, 0, 0, 255, 255 };
	flowers.mask.size_x = static_cast<float>(p_columns) * 0.5f;
	flowers.mask.size_z = static_cast<float>(p_rows) * 0.5f;
	flowers.spacing = SpacingFilter{ true, 0, 1.0f };
	PlacementLayer clearing;
	clearing.mode = PlacementLayer::ERASE;
	clearing.density = 1.0f;
	clearing.noise = NoiseFilter{ true, 12.0f, 2, 0.8f, 0.0f, 2, false };
	rules.layers = { trees, grass, flowers, clearing };
	return rules;
}

uint64_t fnv(const std::vector<uint8_t> &p_cells) {
	uint64_t h = 1469598103934665603ull;
	for (uint8_t cell : p_cells) {
		h = (h ^ cell) * 1099511628211ull;
	}
	return h;
}

} // namespace

TEST_CASE("placement: a layer with no filter takes its density's share of cells, the same every run") {
	PlacementRules rules = field(300, 300);
	PlacementLayer layer;
	layer.species = 2;
	layer.density = 0.25f;
	rules.layers = { layer };
	const std::vector<uint8_t> cells = whole(rules);
	CHECK(share(cells, 3) == doctest::Approx(0.25).epsilon(0.03));
	CHECK(share(cells, 3) + share(cells, 0) == doctest::Approx(1.0));
	CHECK(whole(rules) == cells);
	rules.seed = 8;
	CHECK(whole(rules) != cells);
}

TEST_CASE("placement: a height range takes cells at its ends, part of its falloff and none beyond") {
	PlacementRules rules = field(100, 10);
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			rules.heights.push_back(static_cast<float>(c)); // height = column
		}
	}
	PlacementLayer layer;
	layer.height = RangeFilter{ true, 20.0f, 40.0f, 0.0f, false };
	rules.layers = { layer };
	std::vector<uint8_t> cells = whole(rules);
	for (int r = 0; r < rules.rows; r++) {
		CHECK(at(rules, cells, 19, r) == 0);
		CHECK(at(rules, cells, 20, r) == 1); // at the low limit
		CHECK(at(rules, cells, 40, r) == 1); // at the high limit
		CHECK(at(rules, cells, 41, r) == 0);
	}
	// A falloff of 40 m: 30 m above the top end keeps a quarter of the cells, 41 m above none.
	rules.layers[0].height.falloff = 40.0f;
	rules.rows = 2000;
	rules.heights.clear();
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			rules.heights.push_back(static_cast<float>(c));
		}
	}
	cells = whole(rules);
	int kept = 0;
	for (int r = 0; r < rules.rows; r++) {
		kept += at(rules, cells, 70, r);
		CHECK(at(rules, cells, 30, r) == 1);
		CHECK(at(rules, cells, 81, r) == 0);
	}
	CHECK(double(kept) / rules.rows == doctest::Approx(0.25).epsilon(0.15));
	rules.layers[0].height.invert = true;
	cells = whole(rules);
	CHECK(at(rules, cells, 30, 0) == 0);
	CHECK(at(rules, cells, 85, 0) == 1);
}

TEST_CASE("placement: a slope range follows the ground's incline") {
	PlacementRules rules = field(40, 40, 0.5f);
	PlacementLayer layer;
	layer.slope = RangeFilter{ true, 0.0f, 30.0f, 0.0f, false };
	rules.layers = { layer };
	rules.heights = incline(rules, 29.5f);
	CHECK(share(whole(rules), 1) == 1.0);
	rules.heights = incline(rules, 30.5f);
	CHECK(share(whole(rules), 1) == 0.0);
	// In the falloff: 35° with 10° of falloff keeps half.
	rules.layers[0].slope.falloff = 10.0f;
	rules.columns = rules.rows = 400;
	rules.heights = incline(rules, 35.0f);
	CHECK(share(whole(rules), 1) == doctest::Approx(0.5).epsilon(0.05));
	rules.heights = incline(rules, 40.5f);
	CHECK(share(whole(rules), 1) == 0.0);
	rules.heights.clear(); // level ground
	CHECK(share(whole(rules), 1) == 1.0);
}

TEST_CASE("placement: noise takes the cells its value passes the threshold at") {
	PlacementRules rules = field(200, 200, 0.5f);
	PlacementLayer layer;
	layer.noise = NoiseFilter{ true, 8.0f, 3, 0.5f, 0.0f, 4, false };
	rules.layers = { layer };
	const std::vector<uint8_t> cells = whole(rules);
	int agree = 0;
	double low = 1.0;
	double high = 0.0;
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			// The noise is a field of its own (another seed, the same for every layer of this noise seed).
			const float value = placement_noise(0, static_cast<float>(c), static_cast<float>(r), 1);
			low = std::min(low, double(value));
			high = std::max(high, double(value));
		}
	}
	CHECK(low >= 0.0);
	CHECK(high <= 1.0);
	CHECK(high - low > 0.8); // it spans most of 0–1
	// Placed cells come in patches: most of a placed cell's neighbours are placed too.
	int placed = 0;
	for (int r = 1; r < rules.rows - 1; r++) {
		for (int c = 1; c < rules.columns - 1; c++) {
			if (at(rules, cells, c, r)) {
				placed++;
				agree += at(rules, cells, c + 1, r) + at(rules, cells, c, r + 1);
			}
		}
	}
	CHECK(share(cells, 1) > 0.2);
	CHECK(share(cells, 1) < 0.8);
	CHECK(double(agree) / (2.0 * placed) > 0.9);
	// A higher threshold takes a subset.
	rules.layers[0].noise.threshold = 0.6f;
	const std::vector<uint8_t> fewer = whole(rules);
	for (size_t i = 0; i < cells.size(); i++) {
		CHECK((fewer[i] == 0 || cells[i] == 1));
	}
	CHECK(share(fewer, 1) < share(cells, 1));
	rules.layers[0].noise.invert = true;
	const std::vector<uint8_t> inverted = whole(rules);
	for (size_t i = 0; i < cells.size(); i++) {
		CHECK((inverted[i] == 0 || fewer[i] == 0));
	}
}

TEST_CASE("placement: no plant within a path's half width, all from its falloff's end on") {
	PlacementRules rules = field(100, 100);
	PlacementLayer layer;
	layer.paths.enabled = true;
	layer.paths.lines = { { 0.0f, 0.0f, 100.0f, 100.0f } }; // the diagonal
	layer.paths.half_width = 5.0f;
	layer.paths.falloff = 4.0f;
	rules.layers = { layer };
	const std::vector<uint8_t> cells = whole(rules);
	int in_falloff = 0;
	int kept = 0;
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			const float distance = std::fabs(static_cast<float>(c - r)) / std::sqrt(2.0f);
			if (distance <= 5.0f) {
				CHECK(at(rules, cells, c, r) == 0);
			} else if (distance >= 9.0f) {
				CHECK(at(rules, cells, c, r) == 1);
			} else {
				in_falloff++;
				kept += at(rules, cells, c, r);
			}
		}
	}
	CHECK(kept > 0);
	CHECK(kept < in_falloff);
	rules.layers[0].paths.invert = true; // reeds along a river
	const std::vector<uint8_t> near = whole(rules);
	CHECK(at(rules, near, 50, 50) == 1);
	CHECK(at(rules, near, 90, 10) == 0);
}

TEST_CASE("placement: an exclusion footprint keeps every plant out of it") {
	PlacementRules rules = field(60, 60);
	PlacementLayer layer;
	layer.exclusion.enabled = true;
	// A square turned 45° about (30, 30), 10 m from its middle to each corner, written clockwise.
	layer.exclusion.footprints = { { 30.0f, 20.0f, 20.0f, 30.0f, 30.0f, 40.0f, 40.0f, 30.0f } };
	rules.layers = { layer };
	std::vector<uint8_t> cells = whole(rules);
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			const float manhattan = std::fabs(static_cast<float>(c) + 0.5f - 30.0f) + std::fabs(static_cast<float>(r) + 0.5f - 30.0f);
			CHECK(at(rules, cells, c, r) == (manhattan <= 10.0f ? 0 : 1)); // its edge is in it
		}
	}
	std::reverse(rules.layers[0].exclusion.footprints[0].begin(), rules.layers[0].exclusion.footprints[0].end());
	for (size_t i = 0; i < 8; i += 2) { // reversed pairs are (z, x): swap back, now counter-clockwise
		std::swap(rules.layers[0].exclusion.footprints[0][i], rules.layers[0].exclusion.footprints[0][i + 1]);
	}
	CHECK(whole(rules) == cells);
}

TEST_CASE("placement: an image mask's channel weighs the cells under it") {
	PlacementRules rules = field(40, 20);
	PlacementLayer layer;
	layer.mask.enabled = true;
	layer.mask.width = 2;
	layer.mask.height = 1;
	layer.mask.values = { 255, 0 };
	layer.mask.x = 0.0f;
	layer.mask.z = 0.0f;
	layer.mask.size_x = 20.0f; // over the left half only
	layer.mask.size_z = 20.0f;
	layer.mask.outside = 0.0f;
	rules.layers = { layer };
	const std::vector<uint8_t> cells = whole(rules);
	for (int r = 0; r < rules.rows; r++) {
		CHECK(at(rules, cells, 2, r) == 1); // under the white pixel
		CHECK(at(rules, cells, 18, r) == 0); // under the black one
		CHECK(at(rules, cells, 30, r) == 0); // outside the rectangle
	}
	rules.layers[0].mask.outside = 1.0f;
	CHECK(at(rules, whole(rules), 30, 0) == 1);
}

TEST_CASE("placement: spacing keeps a layer's plants away from an earlier layer's") {
	PlacementRules rules = field(120, 120, 0.5f);
	PlacementLayer trees;
	trees.species = 1;
	trees.density = 0.02f;
	PlacementLayer grass;
	grass.species = 0;
	grass.mode = PlacementLayer::FILL;
	grass.spacing = SpacingFilter{ true, 0, 1.5f };
	rules.layers = { trees, grass };
	const std::vector<uint8_t> cells = whole(rules);
	int tree_count = 0;
	for (int r = 0; r < rules.rows; r++) {
		for (int c = 0; c < rules.columns; c++) {
			if (at(rules, cells, c, r) != 2) {
				continue;
			}
			tree_count++;
			for (int dr = -3; dr <= 3; dr++) {
				for (int dc = -3; dc <= 3; dc++) {
					const int cc = c + dc;
					const int rr = r + dr;
					if ((dr || dc) && cc >= 0 && rr >= 0 && cc < rules.columns && rr < rules.rows &&
							static_cast<float>(dr * dr + dc * dc) * 0.25f <= 1.5f * 1.5f) {
						CHECK(at(rules, cells, cc, rr) != 1);
					}
				}
			}
		}
	}
	CHECK(tree_count > 100);
	CHECK(share(cells, 1) > 0.5); // grass everywhere else
	CHECK(at(rules, cells, 0, 0) + at(rules, cells, 1, 0) > 0);
}

TEST_CASE("placement: a layer's weights are its filters' product at each cell, spacing read from a map") {
	PlacementRules rules = field(60, 40, 0.5f);
	PlacementLayer trees;
	trees.species = 1;
	PlacementLayer grass;
	grass.density = 0.25f; // not in the weights: a brush brings its own density
	grass.slope = RangeFilter{ true, 0.0f, 30.0f, 10.0f, false };
	grass.height = RangeFilter{ true, -100.0f, 5.0f, 0.0f, false };
	grass.spacing = SpacingFilter{ true, 0, 1.5f };
	rules.layers = { trees, grass };
	rules.heights = incline(rules, 35.0f); // half way through the slope's falloff
	const float rise = static_cast<float>(std::tan(35.0 * 3.14159265358979 / 180.0)) * 0.5f; // a column's rise
	std::vector<float> weights;
	REQUIRE(placement_layer_weights(rules, 1, CellRect{ 0, 0, 60, 40 }, {}, weights));
	REQUIRE(weights.size() == 60u * 40u);
	for (int c = 0; c < 60; c++) {
		const float height = static_cast<float>(c) * rise;
		// Half by the slope below 5 m up; nothing above (a sharp edge).
		CHECK(weights[static_cast<size_t>(20 * 60 + c)] == doctest::Approx(height <= 5.0f ? 0.5f : 0.0f).epsilon(0.01));
	}
	// A tree in the map: no grass within 1.5 m (3 cells) of it, the rest as before.
	std::vector<uint8_t> map(60 * 40, 0);
	map[static_cast<size_t>(20 * 60 + 5)] = 2;
	std::vector<float> spaced;
	REQUIRE(placement_layer_weights(rules, 1, CellRect{ 2, 17, 8, 7 }, map, spaced));
	REQUIRE(spaced.size() == 8u * 7u);
	for (int r = 0; r < 7; r++) {
		for (int c = 0; c < 8; c++) {
			const int dc = c + 2 - 5;
			const int dr = r + 17 - 20;
			const bool near = static_cast<float>(dc * dc + dr * dr) * 0.25f <= 1.5f * 1.5f;
			CHECK(spaced[static_cast<size_t>(r * 8 + c)] == (near ? 0.0f : weights[static_cast<size_t>((r + 17) * 60 + c + 2)]));
		}
	}
	// The weights agree with generation: where a cell's weight is 0 the layer never places.
	rules.layers[1].density = 1.0f;
	rules.layers[0].density = 0.0f;
	const std::vector<uint8_t> cells = whole(rules);
	for (size_t i = 0; i < cells.size(); i++) {
		if (weights[i] == 0.0f) {
			CHECK(cells[i] == 0);
		}
	}
	CHECK_FALSE(placement_layer_weights(rules, 2, CellRect{ 0, 0, 1, 1 }, {}, weights)); // no third layer
	CHECK_FALSE(placement_layer_weights(rules, 1, CellRect{ 55, 0, 10, 1 }, {}, weights)); // past the edge
}

TEST_CASE("placement: later layers take cells, fill the empty ones, or empty them, as each says") {
	PlacementRules rules = field(50, 50);
	PlacementLayer all;
	all.species = 0;
	PlacementLayer half;
	half.species = 3;
	half.density = 0.5f;
	rules.layers = { all, half };
	std::vector<uint8_t> cells = whole(rules);
	CHECK(share(cells, 4) == doctest::Approx(0.5).epsilon(0.1));
	CHECK(share(cells, 1) + share(cells, 4) == 1.0);
	rules.layers[1].mode = PlacementLayer::FILL; // the field is full: it takes nothing
	CHECK(share(whole(rules), 1) == 1.0);
	rules.layers[1].mode = PlacementLayer::ERASE;
	cells = whole(rules);
	CHECK(share(cells, 0) == doctest::Approx(0.5).epsilon(0.1));
	CHECK(share(cells, 0) + share(cells, 1) == 1.0);
}

TEST_CASE("placement: any rectangle generated alone equals the same rectangle of the whole field") {
	const PlacementRules rules = hillside(300, 240);
	WorkerPool pool(3);
	const std::vector<uint8_t> all = whole(rules, &pool);
	CHECK(whole(rules) == all); // threads or none
	CHECK(share(all, 1) > 0.2); // grass,
	CHECK(share(all, 2) > 0.001); // trees,
	CHECK(share(all, 3) > 0.01); // flowers
	CHECK(share(all, 0) > 0.01); // and clearings
	const CellRect rects[] = { { 0, 0, 1, 1 }, { 17, 33, 40, 21 }, { 299, 239, 1, 1 }, { 100, 0, 150, 240 },
		{ 0, 120, 300, 3 }, { 250, 5, 50, 7 } };
	for (const CellRect &rect : rects) {
		std::vector<uint8_t> part;
		REQUIRE(generate_placement(rules, rect, &pool, part));
		REQUIRE(part.size() == size_t(rect.columns) * size_t(rect.rows));
		bool same = true;
		for (int r = 0; r < rect.rows; r++) {
			for (int c = 0; c < rect.columns; c++) {
				same = same && part[size_t(r) * size_t(rect.columns) + size_t(c)] == at(rules, all, rect.column + c, rect.row + r);
			}
		}
		CHECK_MESSAGE(same, "rectangle at ", rect.column, ", ", rect.row, " of ", rect.columns, " × ", rect.rows);
	}
}

TEST_CASE("placement: the same rules give the same map on every platform") {
	// The core's tests run on this machine and under Wine and QEMU (tools/test.sh): the map's hash
	// is the one this machine gave first, and each platform must give it too.
	const std::vector<uint8_t> cells = whole(hillside(300, 240));
	CHECK(fnv(cells) == 0x2b6985f40a2a9c4bull);
}

TEST_CASE("placement: a cancelled generation gives nothing") {
	const PlacementRules rules = hillside(60, 60);
	std::atomic<bool> cancel{ true };
	std::vector<uint8_t> cells;
	CHECK_FALSE(generate_placement(rules, CellRect{ 0, 0, 60, 60 }, nullptr, cells, &cancel));
	cancel = false;
	CHECK(generate_placement(rules, CellRect{ 0, 0, 60, 60 }, nullptr, cells, &cancel));
}

TEST_CASE("placement: rules that cannot run say which layer and setting") {
	PlacementRules rules = field(10, 10);
	PlacementLayer layer;
	rules.layers = { layer, layer };
	CHECK(check_placement(rules) == "");
	rules.layers[1].density = NAN;
	CHECK(check_placement(rules) == "layer 2: its density is not a number from 0 to 1");
	rules.layers[1].density = 1.0f;
	rules.layers[1].slope = RangeFilter{ true, 30.0f, 10.0f, 0.0f, false };
	CHECK(check_placement(rules) == "layer 2: slope: its low end is above its high end");
	rules.layers[1].slope.enabled = false;
	rules.layers[0].spacing = SpacingFilter{ true, 0, 1.0f };
	CHECK(check_placement(rules) == "layer 1: spacing: it must name an earlier layer (1–0)");
	rules.layers[0].spacing.enabled = false;
	rules.layers[0].paths.enabled = true;
	rules.layers[0].paths.lines = { { 0.0f, 0.0f, 1.0f } };
	CHECK(check_placement(rules) == "layer 1: paths: line 1 needs two or more points with finite coordinates");
	rules.layers[0].paths.enabled = false;
	rules.heights.assign(100, 0.0f);
	rules.heights[23] = INFINITY;
	CHECK(check_placement(rules) == "the ground's height at cell 3, 2 is not a finite number");
	std::vector<uint8_t> cells;
	CHECK_FALSE(generate_placement(rules, CellRect{ 0, 0, 10, 10 }, nullptr, cells));
	rules.heights.clear();
	CHECK_FALSE(generate_placement(rules, CellRect{ 5, 5, 6, 1 }, nullptr, cells)); // past the field's edge
}

TEST_CASE("placement: hand edits are kept through a regeneration") {
	const std::vector<uint8_t> before = { 0, 1, 1, 0, 2, 2 };
	const std::vector<uint8_t> edited = { 0, 0, 1, 3, 2, 2 }; // one removed, one planted
	const std::vector<uint8_t> now = { 1, 1, 0, 0, 0, 2 }; // the rules changed
	CHECK(keep_hand_edits(before, edited, now) == std::vector<uint8_t>{ 1, 0, 0, 3, 0, 2 });
}

TEST_CASE("placement: a layer read from its row of numbers, paths and footprints") {
	const std::vector<std::string> fields = placement_layer_fields();
	std::vector<float> row(fields.size(), 0.0f);
	auto set = [&](const char *p_name, float p_value) {
		const auto found = std::find(fields.begin(), fields.end(), p_name);
		REQUIRE(found != fields.end());
		row[static_cast<size_t>(found - fields.begin())] = p_value;
	};
	set("mode", 1.0f);
	set("species", 3.0f);
	set("density", 0.5f);
	set("slope_on", 1.0f);
	set("slope_high", 30.0f);
	set("paths_on", 1.0f);
	set("paths_half_width", 2.0f);
	set("spacing_layer", 4.0f);
	PlacementLayer layer;
	const std::vector<float> lines = { 2.0f, 0.0f, 0.0f, 10.0f, 0.0f, 3.0f, 1.0f, 1.0f, 2.0f, 2.0f, 3.0f, 1.0f };
	REQUIRE(placement_layer_from(row, lines, {}, {}, layer) == "");
	CHECK(layer.mode == PlacementLayer::FILL);
	CHECK(layer.species == 3);
	CHECK(layer.density == 0.5f);
	CHECK(layer.slope.enabled);
	CHECK(layer.slope.high == 30.0f);
	CHECK_FALSE(layer.height.enabled);
	CHECK(layer.paths.lines.size() == 2);
	CHECK(layer.paths.lines[1] == std::vector<float>{ 1.0f, 1.0f, 2.0f, 2.0f, 3.0f, 1.0f });
	CHECK(layer.spacing.layer == 4);
	CHECK(placement_layer_from(row, { 3.0f, 0.0f, 0.0f }, {}, {}, layer) ==
			"the paths' points do not divide into lines of (count, x, z, …)");
	row.pop_back();
	CHECK(placement_layer_from(row, {}, {}, {}, layer).find("numbers, not") != std::string::npos);
}
