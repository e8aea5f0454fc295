// Core tests of the composed field: every plant drawn once along a path, several species together.
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

TEST_CASE("every plant is drawn exactly once along a path, and LOD counts follow the observer") {
	FieldSimulation sim;
	load(sim, rect_map(200, 120)); // 100 × 60 m, 24 000 plants
	SUBCASE("part by part") {}
	SUBCASE("drawn whole") {
		PlantShape shape;
		shape.whole = true;
		sim.set_shape(shape);
	}
	for (float x = -30.0f; x <= 130.0f; x += 7.3f) {
		sim.near().set_observer({ x, 1.7f, 30.0f });
		sim.near().request_lod_update();
		sim.update(0.016f);
		CAPTURE(x);
		CHECK(drawn(sim) == 24000);
		const auto counts = sim.near().get_lod_counts();
		CHECK(total(counts) == 24000);
		// With no frustum, part by part, the mesh buckets hold exactly the plants counted at mesh levels
		// (mesh 3 but those wholly faded into their impostors). Drawn whole, plants fading into the
		// next level are in its bucket too.
		for (uint32_t level = 0; level < LOD_MESH_3 && !sim.plants().get_shape().whole; ++level) {
			CHECK(sim.near().get_bucket(mesh_bucket(level, 0)).get_count() == counts[level]);
		}
		CHECK(sim.near().get_bucket(mesh_bucket(LOD_MESH_3, 0)).get_count() <= counts[LOD_MESH_3] + counts[LOD_MESH_2]);
	}
	sim.near().set_observer({ 50.0f, 1.7f, 30.0f });
	sim.near().request_lod_update();
	sim.update(0.016f);
	auto counts = sim.near().get_lod_counts();
	// Plants within 6 m of the observer on a 4-per-m² field: about π·6²·4 ≈ 450.
	CHECK(counts[LOD_MESH_1] > 350);
	CHECK(counts[LOD_MESH_1] < 550);
	CHECK(counts[LOD_BILLBOARD] > 15000);
	sim.near().set_observer({ 1000.0f, 1.7f, 1000.0f });
	sim.near().request_lod_update();
	sim.update(0.016f);
	counts = sim.near().get_lod_counts();
	CHECK(counts[LOD_BILLBOARD] == 24000);
	CHECK(sim.near().get_bucket(mesh_bucket(0, 0)).get_count() == 0);
}

TEST_CASE("several species: each has its own chunks, form, variety and buckets; LOD counts add up") {
	FieldSimulation sim;
	MapError error;
	std::string text = "32 32\n";
	for (int row = 0; row < 32; ++row) {
		for (int column = 0; column < 32; ++column) {
			text += (column + row) % 3 == 0 ? 'm' : ((column + row) % 3 == 1 ? '*' : 'S');
		}
		text += '\n';
	}
	REQUIRE(sim.load_map(text, U"S", U"m", "species", MapLimits{}, error));
	CHECK(sim.plants().get_species_count() == 2);
	CHECK(sim.near().get_bucket_count() == 2 * BUCKET_COUNT);
	CHECK(sim.plants().get_map().objects.size() > 300); // 'S' stays an object
	uint32_t maize = 0;
	for (uint32_t c = 0; c < sim.plants().get_chunk_count(); ++c) {
		const Chunk &chunk = sim.plants().get_layout().chunks[c];
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t plant = sim.plants().get_layout().chunk_plants[chunk.first + k];
			const glm::vec2 cell = glm::floor(sim.plants().get_layout().plants[plant].position / 0.5f);
			const bool is_m = (int(cell.x) + int(cell.y)) % 3 == 0;
			CHECK(is_m == (chunk.species == 1)); // a chunk holds one species
		}
		maize += chunk.species == 1 ? chunk.count : 0;
	}
	CHECK(maize > 300);
	// Species 1 twice as tall, and each keeps its own variety.
	sim.set_plant_height(4.0f, 1);
	LayoutParams params = sim.plants().get_layout_params();
	params.varieties[1].yaw_range = 0.0f;
	sim.set_layout_params(params);
	PartTransforms parts;
	for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
		const uint32_t species = sim.plants().get_layout().chunks[sim.plants().get_layout().plants[i].chunk].species;
		sim.near().get_plant_parts(i, parts);
		CHECK(glm::length(parts.basis[0][1]) == doctest::Approx(species == 1 ? 4.0f / 3.0f : 2.0f / 3.0f));
		if (species == 1) {
			CHECK(sim.plants().get_layout().plants[i].yaw == 0.0f);
		}
	}
	// Each species' plants go to its own buckets; the counts add up per species and in all.
	LodParams lod;
	lod.force_level = LOD_MESH_2;
	sim.near().set_lod(lod);
	sim.update(0.0f);
	CHECK(sim.near().get_bucket(mesh_bucket(LOD_MESH_2, 0)).get_count() == sim.plants().get_plant_count() - maize);
	CHECK(sim.near().get_bucket(BUCKET_COUNT + mesh_bucket(LOD_MESH_2, 0)).get_count() == maize);
	CHECK(sim.near().get_lod_counts(1)[LOD_MESH_2] == maize);
	CHECK(sim.near().get_lod_counts()[LOD_MESH_2] == sim.plants().get_plant_count());
	// A plant near a point is found whatever its species.
	std::vector<uint32_t> near;
	sim.plants().find_plants_near(glm::vec2(8.0f), 1.0f, near);
	bool both[2] = { false, false };
	for (uint32_t plant : near) {
		both[sim.plants().get_layout().chunks[sim.plants().get_layout().plants[plant].chunk].species] = true;
	}
	CHECK(both[0]);
	CHECK(both[1]);
	// At most MAX_SPECIES - 1 legend plants.
	CHECK_FALSE(sim.load_map("2 1\n**\n", U"", U"abcdefgh", "too_many", MapLimits{}, error));
	CHECK(error.message.find("at most 7") != std::string::npos);
}
