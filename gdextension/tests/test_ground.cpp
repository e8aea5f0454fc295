#include "field_simulation.h"
#include "ground.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace sunflower;

namespace {

FieldMap parse(const std::string &p_text, const std::u32string &p_legend = U"") {
	FieldMap map;
	MapError error;
	REQUIRE(parse_field_map(p_text, p_legend, "ground", MapLimits{}, map, error));
	return map;
}

std::string full_text(int p_columns, int p_rows) {
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	for (int r = 0; r < p_rows; ++r) {
		text += std::string(static_cast<size_t>(p_columns), '*') + "\n";
	}
	return text;
}

// A width × depth lattice over [origin, origin + size] with heights from p_height(x, z) (metres).
template <typename Height>
HeightGrid lattice(int p_width, int p_depth, glm::vec2 p_origin, glm::vec2 p_size, Height p_height) {
	HeightGrid grid;
	grid.width = p_width;
	grid.depth = p_depth;
	grid.origin = p_origin;
	grid.size = p_size;
	for (int z = 0; z < p_depth; ++z) {
		for (int x = 0; x < p_width; ++x) {
			const glm::vec2 at = p_origin + p_size * glm::vec2(float(x) / float(p_width - 1), float(z) / float(p_depth - 1));
			grid.heights.push_back(p_height(x, z, at));
		}
	}
	return grid;
}

// Rolling hills, by sample index.
HeightGrid hills(int p_width, int p_depth, glm::vec2 p_origin, glm::vec2 p_size) {
	return lattice(p_width, p_depth, p_origin, p_size, [](int x, int z, glm::vec2) {
		return 2.0f * std::sin(0.3f * float(x)) * std::cos(0.2f * float(z)) + 0.1f * float(x);
	});
}

// A tilted plane h = 0.5·x − 0.25·z + 3 (bilinear reproduces it exactly).
HeightGrid plane(int p_width, int p_depth, glm::vec2 p_origin, glm::vec2 p_size) {
	return lattice(p_width, p_depth, p_origin, p_size, [](int, int, glm::vec2 p) { return 0.5f * p.x - 0.25f * p.y + 3.0f; });
}

} // namespace

TEST_CASE("a height grid is bilinear between its samples, and NaN outside it or beside a hole") {
	HeightGrid grid = hills(9, 7, glm::vec2(-2.0f, 1.0f), glm::vec2(16.0f, 12.0f)); // 2 m between samples
	for (int z = 0; z < grid.depth; ++z) {
		for (int x = 0; x < grid.width; ++x) {
			const glm::vec2 at = grid.origin + glm::vec2(2.0f * float(x), 2.0f * float(z));
			CHECK(grid.sample(at) == doctest::Approx(grid.heights[size_t(z * grid.width + x)]).epsilon(1e-5));
		}
	}
	// Between four samples: the bilinear mix, here a quarter of the way along x and half along z.
	const float h00 = grid.heights[size_t(2 * 9 + 3)], h10 = grid.heights[size_t(2 * 9 + 4)];
	const float h01 = grid.heights[size_t(3 * 9 + 3)], h11 = grid.heights[size_t(3 * 9 + 4)];
	const float expected = 0.5f * (h00 + 0.25f * (h10 - h00)) + 0.5f * (h01 + 0.25f * (h11 - h01));
	CHECK(grid.sample(grid.origin + glm::vec2(6.5f, 5.0f)) == doctest::Approx(expected).epsilon(1e-5));
	// The far edges are inside; past them is no ground.
	CHECK(std::isfinite(grid.sample(grid.origin + grid.size)));
	CHECK(std::isnan(grid.sample(grid.origin + grid.size + glm::vec2(0.01f, 0.0f))));
	CHECK(std::isnan(grid.sample(grid.origin - glm::vec2(0.0f, 0.01f))));
	CHECK(std::isnan(grid.sample(glm::vec2(NAN, 3.0f))));
	// A hole takes the four cells around its sample, not their other neighbours.
	grid.heights[size_t(3 * 9 + 4)] = NAN;
	CHECK(std::isnan(grid.sample(grid.origin + glm::vec2(7.0f, 5.0f))));
	CHECK(std::isnan(grid.sample(grid.origin + glm::vec2(9.0f, 7.0f))));
	CHECK(std::isfinite(grid.sample(grid.origin + glm::vec2(11.0f, 5.0f))));
	// A lattice of the wrong size, or of one sample a side, spans nothing.
	HeightGrid broken = grid;
	broken.heights.pop_back();
	CHECK(std::isnan(broken.sample(grid.origin + glm::vec2(1.0f))));
}

TEST_CASE("a height grid's normal is the slope's; a plane's is exact everywhere") {
	const HeightGrid grid = plane(5, 5, glm::vec2(0.0f), glm::vec2(8.0f, 8.0f));
	const glm::vec3 expected = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.25f));
	for (const glm::vec2 at : { glm::vec2(0.3f, 0.9f), glm::vec2(4.0f, 4.0f), glm::vec2(7.9f, 2.2f) }) {
		CHECK(grid.sample(at) == doctest::Approx(0.5f * at.x - 0.25f * at.y + 3.0f).epsilon(1e-5));
		const glm::vec3 n = grid.normal(at);
		CHECK(glm::distance(n, expected) < 1e-5f);
	}
	CHECK(grid.normal(glm::vec2(-1.0f)) == glm::vec3(0.0f, 1.0f, 0.0f)); // no ground: upright
}

TEST_CASE("plants stand on a height grid: roots on the ground, holes empty and counted, the rest unchanged") {
	const FieldMap map = parse(full_text(40, 30));
	LayoutParams params;
	FieldLayout flat;
	build_layout(map, params, Ground{}, flat);
	CHECK(flat.cells_without_ground == 0);
	for (const Plant &plant : flat.plants) {
		CHECK(plant.ground == 0.0f);
	}

	Ground ground;
	ground.kind = Ground::GRID;
	ground.grid = hills(21, 16, glm::vec2(0.0f), glm::vec2(20.0f, 15.0f)); // 1 m between samples
	ground.grid.heights[size_t(5 * 21 + 10)] = NAN; // a hole at (10, 5): 2 × 2 m around it
	FieldLayout hilly;
	build_layout(map, params, ground, hilly);
	// The hole's four cells hold 16 plant cells of 0.5 m; a plant falls in them when its root does.
	size_t expected_holes = 0;
	size_t kept = 0;
	for (const Plant &plant : flat.plants) {
		const bool in_hole = plant.position.x >= 9.0f && plant.position.x <= 11.0f && plant.position.y >= 4.0f &&
				plant.position.y <= 6.0f;
		if (in_hole) {
			++expected_holes;
			continue;
		}
		// Every other plant is the flat field's plant, lifted onto the ground.
		REQUIRE(kept < hilly.plants.size());
		const Plant &lifted = hilly.plants[kept++];
		CHECK(lifted.position == plant.position);
		CHECK(lifted.yaw == plant.yaw);
		CHECK(lifted.alpha() == plant.alpha());
		CHECK(lifted.ground == doctest::Approx(ground.grid.sample(plant.position)));
		CHECK(lifted.lean() == glm::vec2(0.0f)); // upright unless tilted
	}
	CHECK(expected_holes > 0);
	CHECK(hilly.cells_without_ground == expected_holes);
	CHECK(hilly.plants.size() + expected_holes == flat.plants.size());
	// A chunk's vertical bounds hold its plants' roots.
	for (const Chunk &chunk : hilly.chunks) {
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const float y = hilly.plants[hilly.chunk_plants[chunk.first + k]].ground;
			CHECK(y >= chunk.ground_min);
			CHECK(y <= chunk.ground_max);
		}
		CHECK(chunk.ground_min < chunk.ground_max); // hills, not a plane
	}
}

TEST_CASE("listed heights stand plants and objects on the ground points, in order; a short list is no ground") {
	const FieldMap map = parse("4 3\n*o**\n**.*\no***\n", U"o");
	LayoutParams params;
	std::vector<glm::vec2> points;
	ground_points(map, params, points);
	REQUIRE(points.size() == 9 + 2); // 9 plant cells, then 2 objects
	CHECK(points[9] == glm::vec2(0.75f, 0.25f)); // the objects' cell centres
	CHECK(points[10] == glm::vec2(0.25f, 1.25f));

	FieldLayout flat;
	build_layout(map, params, Ground{}, flat);
	Ground ground;
	ground.kind = Ground::HEIGHTS;
	for (size_t i = 0; i < points.size(); ++i) {
		ground.heights.push_back(float(i) + 0.5f);
		if (i < 9) {
			CHECK(points[i] == flat.plants[i].position); // the roots the layout uses
		}
	}
	ground.heights[4] = NAN; // a ray that hit nothing
	ground.heights[10] = NAN;
	FieldLayout listed;
	build_layout(map, params, ground, listed);
	REQUIRE(listed.plants.size() == 8);
	CHECK(listed.cells_without_ground == 1);
	CHECK(listed.plants[3].ground == 3.5f);
	CHECK(listed.plants[4].ground == 5.5f); // the fifth plant cell had no ground
	CHECK(listed.plants[4].position == flat.plants[5].position);
	REQUIRE(listed.object_ground.size() == 2);
	CHECK(listed.object_ground[0] == 9.5f);
	CHECK(std::isnan(listed.object_ground[1]));

	ground.heights.pop_back();
	build_layout(map, params, ground, listed);
	CHECK(listed.plants.size() == 0);
	CHECK(listed.cells_without_ground == 9);
}

TEST_CASE("on ground: parts, impostors and bounds stand on the roots; tilt leans them along the normal") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(full_text(20, 20), U"", "ground", MapLimits{}, error));
	Ground ground;
	ground.kind = Ground::GRID;
	ground.grid = plane(11, 11, glm::vec2(0.0f), glm::vec2(10.0f, 10.0f));
	sim.set_ground(ground);
	REQUIRE(sim.plants().get_plant_count() == 400);
	const float plant_top = sim.plants().get_shape().height * sim.plants().get_shape().part_scale;
	for (uint32_t c = 0; c < sim.plants().get_chunk_count(); ++c) {
		const ChunkBounds bounds = sim.plants().get_chunk_bounds(c);
		const Chunk &chunk = sim.plants().get_layout().chunks[c];
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const Plant &plant = sim.plants().get_layout().plants[sim.plants().get_layout().chunk_plants[chunk.first + k]];
			CHECK(bounds.min.y <= plant.ground);
			CHECK(bounds.max.y >= plant.ground + plant_top);
		}
	}
	PartTransforms parts;
	std::vector<float> impostors(size_t(sim.plants().get_layout().chunks[0].count) * FAR_FLOATS_PER_INSTANCE);
	sim.plants().write_chunk_instances(0, impostors.data());
	const Plant &first = sim.plants().get_layout().plants[sim.plants().get_layout().chunk_plants[0]];
	CHECK(read_far_instance(impostors.data()).root.y == first.ground);
	CHECK(read_far_instance(impostors.data()).lean == glm::vec2(0.0f)); // upright
	sim.near().get_plant_parts(sim.plants().get_layout().chunk_plants[0], parts);
	CHECK(parts.origin[0].y == doctest::Approx(first.ground));
	CHECK(glm::distance(parts.origin[0], first.root()) < 1e-5f);

	// Fully tilted, every plant's up axis is the plane's normal, parts and impostors alike: the lean is
	// kept in 1/127 steps, so the up axis is within half a step of the normal's on each axis.
	ground.tilt = 1.0f;
	sim.set_ground(ground);
	const glm::vec3 normal = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.25f));
	const float half_step = 0.5f / 127.0f * std::sqrt(2.0f) + 1e-4f;
	sim.near().get_plant_parts(7, parts);
	CHECK(glm::distance(glm::normalize(parts.basis[0][1]), normal) < half_step);
	CHECK(glm::distance(glm::normalize(parts.basis[2][1]), normal) < half_step);
	const glm::vec3 mesh_up = glm::normalize(parts.basis[0][1]);
	CHECK(glm::distance(parts.origin[0], sim.plants().get_layout().plants[7].root()) < 1e-5f);
	sim.plants().write_chunk_instances(0, impostors.data());
	const uint32_t tilted = sim.plants().get_layout().plants[7].chunk == 0 ? 7 : 0;
	const auto &order = sim.plants().get_layout().chunk_plants;
	const size_t slot = size_t(std::find(order.begin(), order.end(), tilted) - order.begin());
	REQUIRE(slot < sim.plants().get_layout().chunks[0].count);
	// The record keeps the same steps: the impostor stands exactly as the mesh does (on a plane every
	// plant leans alike).
	const glm::vec3 impostor_up = lean_rotation(read_far_instance(impostors.data() + slot * FAR_FLOATS_PER_INSTANCE).lean)[1];
	CHECK(glm::distance(impostor_up, normal) < half_step);
	CHECK(glm::distance(impostor_up, mesh_up) < 1e-5f);
	// Half tilted: between upright and the normal.
	ground.tilt = 0.5f;
	sim.set_ground(ground);
	sim.near().get_plant_parts(7, parts);
	const glm::vec3 half = glm::normalize(parts.basis[0][1]);
	CHECK(half.y > normal.y);
	CHECK(half.y < 1.0f);
}

TEST_CASE("on ground: LOD distances are measured from the plant on its hill, and pushers meet plants at their height") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(full_text(20, 20), U"", "ground", MapLimits{}, error));
	Ground ground;
	ground.kind = Ground::HEIGHTS;
	ground.heights.assign(400, 30.0f); // a plateau 30 m up
	sim.set_ground(ground);
	sim.near().set_observer(glm::vec3(5.0f, 1.0f, 5.0f)); // standing below the plateau: 29 m from the plants
	sim.update(0.0f);
	CHECK(sim.near().get_lod_counts()[LOD_MESH_1] == 0);
	sim.near().set_observer(glm::vec3(5.0f, 31.5f, 5.0f)); // on it
	sim.update(0.0f);
	CHECK(sim.near().get_lod_counts()[LOD_MESH_1] > 0);

	const Pusher low{ glm::vec3(5.0f, 0.5f, 5.0f), 1.0f };
	sim.near().get_pushes().set_pushers(&low, 1);
	sim.update(0.1f);
	CHECK(sim.near().get_pushes().get_pushed_count() == 0); // under the plateau
	const Pusher walking{ glm::vec3(5.0f, 30.5f, 5.0f), 1.0f };
	sim.near().get_pushes().set_pushers(&walking, 1);
	sim.update(0.1f);
	CHECK(sim.near().get_pushes().get_pushed_count() > 0);
}

TEST_CASE("a height grid read from RGBA pixels: red spans the height range, low alpha is a hole, bad arguments are named") {
	// 2 × 2 pixels: red 0, 0.5, 1 and a hole.
	const float pixels[] = { 0.0f, 0, 0, 1.0f, 0.5f, 0, 0, 1.0f, 1.0f, 0, 0, 1.0f, 1.0f, 0, 0, 0.2f };
	HeightGrid grid;
	CHECK(height_grid_from_rgba(pixels, 16, 2, 2, glm::vec2(-1.0f, 2.0f), glm::vec2(4.0f, 4.0f), 10.0, 20.0, grid).empty());
	CHECK(grid.width == 2);
	CHECK(grid.depth == 2);
	CHECK(grid.origin == glm::vec2(-1.0f, 2.0f));
	CHECK(grid.heights[0] == doctest::Approx(10.0f));
	CHECK(grid.heights[1] == doctest::Approx(15.0f));
	CHECK(grid.heights[2] == doctest::Approx(20.0f));
	CHECK(std::isnan(grid.heights[3]));
	// Each bad argument gets its message, and the grid is left as it was.
	const HeightGrid before = grid;
	CHECK(height_grid_from_rgba(pixels, 16, 1, 16, glm::vec2(0.0f), glm::vec2(1.0f), 0.0, 1.0, grid).find("2 to 16384") != std::string::npos);
	CHECK(height_grid_from_rgba(pixels, 16, 16385, 2, glm::vec2(0.0f), glm::vec2(1.0f), 0.0, 1.0, grid).find("2 to 16384") != std::string::npos);
	CHECK(height_grid_from_rgba(pixels, 12, 2, 2, glm::vec2(0.0f), glm::vec2(1.0f), 0.0, 1.0, grid).find("12 floats for 2 × 2") != std::string::npos);
	CHECK(height_grid_from_rgba(nullptr, 16, 2, 2, glm::vec2(0.0f), glm::vec2(1.0f), 0.0, 1.0, grid).find("16 floats") != std::string::npos);
	CHECK(height_grid_from_rgba(pixels, 16, 2, 2, glm::vec2(NAN, 0.0f), glm::vec2(1.0f), 0.0, 1.0, grid).find("rectangle") != std::string::npos);
	CHECK(height_grid_from_rgba(pixels, 16, 2, 2, glm::vec2(0.0f), glm::vec2(0.0f, 1.0f), 0.0, 1.0, grid).find("rectangle") != std::string::npos);
	CHECK(height_grid_from_rgba(pixels, 16, 2, 2, glm::vec2(0.0f), glm::vec2(1.0f), 0.0, INFINITY, grid).find("finite ends") != std::string::npos);
	CHECK(grid.origin == before.origin);
	CHECK(grid.heights.size() == before.heights.size());
}
