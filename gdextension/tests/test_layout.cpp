#include "field_layout.h"

#include <doctest/doctest.h>

#include <set>

using namespace sunflower;

namespace {

FieldMap full_map(int p_columns, int p_rows) {
	FieldMap map;
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	for (int r = 0; r < p_rows; ++r) {
		text += std::string(static_cast<size_t>(p_columns), '*') + "\n";
	}
	MapError error;
	REQUIRE(parse_field_map(text, U"", "full", MapLimits{}, map, error));
	return map;
}

} // namespace

TEST_CASE("positions follow x = (column + α)·cell, z = (row + α)·cell with α ∈ [0, 0.5)") {
	const FieldMap map = full_map(40, 30);
	LayoutParams params;
	FieldLayout layout;
	build_layout(map, params, Ground{}, layout);
	REQUIRE(layout.plants.size() == 1200);
	CHECK(layout.size.x == doctest::Approx(20.0f)); // a 40 × 30 map is a 20 × 15 m field
	CHECK(layout.size.y == doctest::Approx(15.0f));
	for (size_t i = 0; i < layout.plants.size(); ++i) {
		const Plant &plant = layout.plants[i];
		const int column = static_cast<int>(i % 40);
		const int row = static_cast<int>(i / 40);
		CHECK(plant.alpha() >= 0.0f);
		CHECK(plant.alpha() < 0.5f);
		CHECK(plant.position.x == doctest::Approx((float(column) + plant.alpha()) * 0.5f));
		CHECK(plant.position.y == doctest::Approx((float(row) + plant.alpha()) * 0.5f)); // the same α on z
	}
}

TEST_CASE("a seed reproduces a field exactly; another seed does not") {
	const FieldMap map = full_map(10, 10);
	LayoutParams params;
	params.seed = 42;
	FieldLayout a, b, c;
	build_layout(map, params, Ground{}, a);
	build_layout(map, params, Ground{}, b);
	params.seed = 43;
	build_layout(map, params, Ground{}, c);
	int same = 0;
	for (size_t i = 0; i < a.plants.size(); ++i) {
		CHECK(a.plants[i].position == b.plants[i].position);
		CHECK(a.plants[i].yaw == b.plants[i].yaw);
		same += a.plants[i].alpha() == c.plants[i].alpha() ? 1 : 0;
	}
	CHECK(same < 5);
}

TEST_CASE("independent jitter moves x and z by different amounts") {
	const FieldMap map = full_map(10, 10);
	LayoutParams params;
	params.independent_jitter = true;
	FieldLayout layout;
	build_layout(map, params, Ground{}, layout);
	int differ = 0;
	for (size_t i = 0; i < layout.plants.size(); ++i) {
		const float jx = layout.plants[i].position.x / 0.5f - float(i % 10);
		const float jz = layout.plants[i].position.y / 0.5f - float(i / 10);
		CHECK(jz >= 0.0f);
		CHECK(jz < 0.5f);
		differ += std::abs(jx - jz) > 1e-4f ? 1 : 0;
	}
	CHECK(differ > 90);
}

TEST_CASE("chunks hold every plant exactly once and bound their plants") {
	const FieldMap map = full_map(100, 70);
	LayoutParams params;
	params.chunk_size = 8.0f;
	FieldLayout layout;
	build_layout(map, params, Ground{}, layout);
	CHECK(layout.chunks.size() == 7 * 5);
	std::set<uint32_t> seen;
	for (uint32_t c = 0; c < layout.chunks.size(); ++c) {
		const Chunk &chunk = layout.chunks[c];
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t index = layout.chunk_plants[chunk.first + k];
			CHECK(seen.insert(index).second);
			const Plant &plant = layout.plants[index];
			CHECK(plant.chunk == c);
			CHECK(plant.position.x >= chunk.min.x);
			CHECK(plant.position.x <= chunk.max.x);
			CHECK(plant.position.y >= chunk.min.y);
			CHECK(plant.position.y <= chunk.max.y);
		}
	}
	CHECK(seen.size() == layout.plants.size());
}
