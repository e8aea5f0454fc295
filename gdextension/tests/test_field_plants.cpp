// Core tests of the plants a field holds: map, layout, forms, variety, painting.
#include "field_test_support.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

using namespace sunflower;
using namespace sunflower_test;

TEST_CASE("a field too large for the chunk grid gets larger chunks") {
	FieldSimulation sim;
	MapError error;
	std::string text = "2000 40\n";
	for (int r = 0; r < 40; ++r) {
		text += "*" + std::string(1999, '.') + "\n";
	}
	REQUIRE(sim.load_map(text, U"", "wide", MapLimits{}, error));
	LayoutParams params;
	params.cell_size = 1.0f; // 2 000 × 40 m
	params.chunk_size = 1.0f; // 80 000 cells: too many
	sim.set_layout_params(params);
	const FieldLayout &layout = sim.plants().get_layout();
	CHECK(int64_t(layout.grid_x) * layout.grid_z <= FieldLayout::MAX_CHUNK_CELLS);
	CHECK(layout.chunk_size == 2.0f); // 1 000 × 20 cells
	CHECK(sim.plants().get_plant_count() == 40);
}

TEST_CASE("a failed load keeps the previous field") {
	FieldSimulation sim;
	load(sim, rect_map(10, 10));
	MapError error;
	CHECK_FALSE(sim.load_map("10 10\n**x\n", U"", "bad.field", MapLimits{}, error));
	CHECK(error.to_string() == "bad.field:2:3: unexpected 'x'; expected '*' (a sunflower), ' ' or '.' (nothing), or a symbol the field's legend maps");
	CHECK(sim.plants().get_plant_count() == 100);
}

TEST_CASE("setting the same layout again keeps the field as it is; a different one rebuilds it") {
	FieldSimulation sim;
	load(sim, rect_map(80, 80));
	sim.near().set_observer({ 20.0f, 1.7f, 20.0f });
	sim.update(0.016f);
	const uint32_t chunks = sim.plants().get_chunk_count();
	uint32_t active = 0;
	for (uint32_t c = 0; c < chunks; ++c) {
		active += sim.near().is_chunk_active(c) ? 1 : 0;
	}
	REQUIRE(active > 0);
	CHECK_FALSE(sim.set_layout_params(sim.plants().get_layout_params()));
	uint32_t still_active = 0;
	for (uint32_t c = 0; c < chunks; ++c) {
		still_active += sim.near().is_chunk_active(c) ? 1 : 0;
	}
	CHECK(still_active == active); // no rebuild: chunk state survives
	LayoutParams params = sim.plants().get_layout_params();
	params.seed += 1;
	CHECK(sim.set_layout_params(params));
	for (uint32_t c = 0; c < sim.plants().get_chunk_count(); ++c) {
		CHECK_FALSE(sim.near().is_chunk_active(c)); // rebuilt: nothing active until the next update
	}
}

TEST_CASE("a plant type's form and variety: parts stack by their lengths, sizes and yaws stay within their ranges") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map("10 10\n**********\n**********\n**********\n", U"", "form", MapLimits{}, error));
	PlantShape shape;
	shape.part_lengths = glm::vec3(2.0f, 0.5f, 1.0f);
	shape.middle_variation = 0.0f;
	sim.set_shape(shape);
	sim.set_plant_height(7.0f); // 3.5 model units tall: 2 m per unit
	LayoutParams params = sim.plants().get_layout_params();
	params.varieties[0].yaw_range = 1.0f;
	params.varieties[0].scale_min = 0.5f;
	params.varieties[0].scale_max = 1.5f;
	REQUIRE(sim.set_layout_params(params));
	float smallest = 10.0f, largest = 0.0f, widest_yaw = 0.0f;
	for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
		const Plant &plant = sim.plants().get_layout().plants[i];
		smallest = std::min(smallest, plant.scale);
		largest = std::max(largest, plant.scale);
		widest_yaw = std::max(widest_yaw, std::abs(plant.yaw));
		PartTransforms parts;
		sim.near().get_plant_parts(i, parts);
		// Upright (no wind): the middle starts 2 units up and the head 0.5 above it, at 2 m a unit.
		CHECK(parts.origin[1].y - parts.origin[0].y == doctest::Approx(2.0f * 2.0f * plant.scale));
		CHECK(parts.origin[2].y - parts.origin[1].y == doctest::Approx(0.5f * 2.0f * plant.scale));
		CHECK(glm::length(parts.basis[0][1]) == doctest::Approx(2.0f * plant.scale));
		// Chunk bounds hold the tallest plant.
		const ChunkBounds bounds = sim.plants().get_chunk_bounds(plant.chunk);
		CHECK(bounds.max.y >= plant.ground + shape.height * 2.0f * plant.scale);
	}
	CHECK(smallest >= 0.5f);
	CHECK(largest <= 1.5f);
	CHECK(largest - smallest > 0.8f); // 30 plants spread over the range
	CHECK(widest_yaw <= 1.0f);
	CHECK(widest_yaw > 0.7f);
	// A reversed range is read as one size; a nonsense length keeps the current one (the table's rule).
	params.varieties[0].scale_min = 2.0f;
	params.varieties[0].scale_max = 1.0f;
	sim.set_layout_params(params);
	CHECK(sim.plants().get_layout_params().varieties[0].scale_max == 2.0f);
	const glm::vec3 before = sim.plants().get_shape().part_lengths;
	shape.part_lengths = glm::vec3(NAN, -1.0f, 1.5f);
	sim.set_shape(shape);
	CHECK(sim.plants().get_shape().part_lengths == glm::vec3(before.x, before.y, 1.5f));
	// A plant of one part: the empty slots above it have no length, and its height spans the one part.
	shape.part_lengths = glm::vec3(4.0f, 0.0f, 0.0f);
	sim.set_shape(shape);
	CHECK(sim.plants().get_shape().part_lengths == glm::vec3(4.0f, 0.0f, 0.0f));
	CHECK(sim.plants().shape_of_height(2.0f, 0).part_scale == doctest::Approx(0.5f));
	// No length at all could not be scaled to a height: the lengths stay.
	shape.part_lengths = glm::vec3(0.0f);
	sim.set_shape(shape);
	CHECK(sim.plants().get_shape().part_lengths == glm::vec3(4.0f, 0.0f, 0.0f));
}

TEST_CASE("colour variety: plants are white without it; with it, seeded brightness and tint within the ranges") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(rect_map(20, 20), U"", "colour", MapLimits{}, error));
	LodParams lod;
	lod.force_level = LOD_MESH_1;
	sim.near().set_lod(lod);
	sim.update(0.0f);
	const InstanceBuffer &heads = sim.near().get_bucket(mesh_bucket(LOD_MESH_1, 2));
	REQUIRE(heads.get_count() > 0);
	for (uint32_t i = 0; i < heads.get_count(); ++i) {
		const float *colour = heads.get_data() + size_t(i) * FLOATS_PER_INSTANCE + TRANSFORM_FLOATS;
		CHECK(glm::vec4(colour[0], colour[1], colour[2], colour[3]) == glm::vec4(1.0f));
	}
	LayoutParams params = sim.plants().get_layout_params();
	params.varieties[0].brightness = 0.2f;
	params.varieties[0].tint = 0.1f;
	sim.set_layout_params(params);
	sim.update(0.0f);
	float darkest = 2.0f, brightest = 0.0f, warmest = -1.0f, coolest = 1.0f;
	for (uint32_t i = 0; i < heads.get_count(); ++i) {
		const float *colour = heads.get_data() + size_t(i) * FLOATS_PER_INSTANCE + TRANSFORM_FLOATS;
		const float brightness = colour[1];
		const float warmth = colour[0] / brightness - 1.0f;
		CHECK(colour[2] / brightness == doctest::Approx(1.0f - warmth));
		darkest = std::min(darkest, brightness);
		brightest = std::max(brightest, brightness);
		warmest = std::max(warmest, warmth);
		coolest = std::min(coolest, warmth);
	}
	CHECK(darkest >= 0.8f - 1e-5f);
	CHECK(brightest <= 1.2f + 1e-5f);
	CHECK(brightest - darkest > 0.3f);
	CHECK(warmest <= 0.1f + 1e-5f);
	CHECK(coolest >= -0.1f - 1e-5f);
	CHECK(warmest - coolest > 0.15f);
	// The static impostors carry the same colour as the meshes of the same plant (in 1/64 steps).
	std::vector<float> impostors(size_t(sim.plants().get_layout().chunks[0].count) * FAR_FLOATS_PER_INSTANCE);
	sim.plants().write_chunk_instances(0, impostors.data());
	for (uint32_t k = 0; k < sim.plants().get_layout().chunks[0].count; ++k) {
		const Plant &plant = sim.plants().get_layout().plants[sim.plants().get_layout().chunk_plants[k]];
		const glm::vec3 colour = tone_colour(read_far_instance(impostors.data() + size_t(k) * FAR_FLOATS_PER_INSTANCE).tone);
		CHECK(glm::distance(colour, glm::vec3(plant.color(params.varieties[0]))) < 0.02f);
	}
}

TEST_CASE("painting changes only the painted cells' plants: every other plant keeps its place, yaw and size") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(rect_map(30, 30), U"", "paint", MapLimits{}, error));
	LayoutParams params = sim.plants().get_layout_params();
	params.varieties[0].scale_min = 0.5f;
	params.varieties[0].scale_max = 1.5f;
	sim.set_layout_params(params);
	std::map<std::pair<float, float>, std::pair<float, float>> before; // position → yaw, size
	for (const Plant &plant : sim.plants().get_layout().plants) {
		before[{ plant.position.x, plant.position.y }] = { plant.yaw, plant.scale };
	}
	std::vector<int> changed;
	sim.paint_map(glm::vec2(10.0f, 10.0f), 3.0f, CellContent{}, 1.0f, 1, true, changed);
	REQUIRE(!changed.empty());
	CHECK(sim.plants().get_plant_count() == 900 - changed.size() / 2);
	for (const Plant &plant : sim.plants().get_layout().plants) {
		const auto found = before.find({ plant.position.x, plant.position.y });
		REQUIRE(found != before.end());
		CHECK(found->second.first == plant.yaw);
		CHECK(found->second.second == plant.scale);
	}
}

TEST_CASE("a plant's stalk reaches from its root to its head, for each species' form and each plant's size") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map("4 1\n*m*m\n", U"m", U"m", "stalks", MapLimits{}, error));
	PlantShape sunflower;
	sim.set_shape(sunflower, 0);
	sim.set_plant_height(2.0f, 0);
	PlantShape tall;
	tall.part_lengths = glm::vec3(3.0f, 1.0f, 1.0f);
	tall.middle_variation = 0.0f;
	sim.set_shape(tall, 1);
	sim.set_plant_height(5.0f, 1);
	for (uint32_t p = 0; p < sim.plants().get_plant_count(); ++p) {
		const Plant &plant = sim.plants().get_layout().plants[p];
		const glm::vec2 stalk = sim.plants().get_stalk(p);
		PartTransforms parts;
		sim.near().get_plant_parts(p, parts); // upright: no wind yet
		// The head's root is where the stalk ends.
		CHECK(stalk.y == doctest::Approx(parts.origin[2].y - plant.ground).epsilon(1e-4));
		const bool second = sim.plants().species_of(plant) == 1;
		CHECK(stalk.x == doctest::Approx(PlantShape::STALK_RADIUS_SHARE * (second ? 5.0f : 2.0f) * plant.scale));
		if (second) {
			CHECK(stalk.y == doctest::Approx(4.0f * plant.scale)); // 4 of its 5 units, 5 m tall
		}
	}
}

TEST_CASE("field plants: the plant of every cell is found, in maps dense, sparse and clustered") {
	for (const int kind : { 0, 1, 2 }) {
		std::string text = "97 61\n";
		uint64_t state = 12345;
		for (int row = 0; row < 61; ++row) {
			for (int column = 0; column < 97; ++column) {
				state = state * 6364136223846793005ull + 1442695040888963407ull;
				const bool plant = kind == 0 ? (state >> 60) != 0 // dense: 15 of 16
						: kind == 1      ? (state >> 61) == 0 // sparse: 1 of 8
										 : row > 40 && column < 30; // one corner
				text += plant ? '*' : '.';
			}
			text += '\n';
		}
		FieldPlants plants;
		MapError error;
		REQUIRE(plants.load_map(text, U"", U"", "cells", MapLimits{}, error));
		uint32_t found = 0;
		for (uint32_t cell = 0; cell < 97u * 61u; ++cell) {
			const uint32_t plant = plants.plant_at_cell(cell);
			const bool has = plants.get_map().plants[cell] != 0;
			CHECK((plant != FieldPlants::NO_PLANT) == has);
			if (plant != FieldPlants::NO_PLANT) {
				CHECK(plants.cell_of_plant(plant) == cell);
				++found;
			}
		}
		CHECK(found == plants.get_plant_count());
		CHECK(plants.plant_at_cell(97u * 61u) == FieldPlants::NO_PLANT);
	}
}
