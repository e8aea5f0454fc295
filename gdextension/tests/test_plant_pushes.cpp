// Core tests of pushers: bodies the plants part around.
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

namespace {

// The horizontal lean of a plant's head now: where its top is, relative to its root (x, z).
glm::vec2 head_offset(const FieldSimulation &p_sim, uint32_t p_plant) {
	PartTransforms parts;
	p_sim.near().get_plant_parts(p_plant, parts);
	const glm::vec3 top = parts.origin[2] + parts.basis[2][1];
	return glm::vec2(top.x - parts.origin[0].x, top.z - parts.origin[0].z);
}

} // namespace

TEST_CASE("pushers: plants within the radius bend away from the body and spring back once it leaves") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20)); // 10 × 10 m, a plant every 0.5 m
	WindParams calm;
	calm.power = 0.0f;
	sim.near().set_wind(calm);
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	sim.near().get_pushes().set_params(1.0f, 1.0f);
	sim.update(0.016f);
	CHECK(sim.near().get_pushes().get_pushed_count() == 0);

	const Pusher body{ { 5.0f, 1.0f, 5.0f }, 1.0f };
	sim.near().get_pushes().set_pushers(&body, 1);
	for (int i = 0; i < 60; ++i) {
		sim.update(1.0f / 60.0f);
	}
	std::vector<uint32_t> near, far;
	sim.plants().find_plants_near({ 5.0f, 5.0f }, 0.9f, near);
	REQUIRE(near.size() > 5);
	CHECK(sim.near().get_pushes().get_pushed_count() >= near.size());
	for (uint32_t plant : near) {
		const glm::vec2 away = sim.plants().get_layout().plants[plant].position - glm::vec2(5.0f, 5.0f);
		const glm::vec2 lean = head_offset(sim, plant);
		if (glm::length(away) > 0.05f) {
			CHECK(glm::dot(lean, away) > 0.0f); // away from the body
			CHECK(glm::length(lean) > 0.05f);
		}
	}
	sim.plants().find_plants_near({ 5.0f, 5.0f }, 3.0f, far);
	for (uint32_t plant : far) {
		if (glm::distance(sim.plants().get_layout().plants[plant].position, glm::vec2(5.0f, 5.0f)) > 1.0f) {
			CHECK(glm::length(head_offset(sim, plant)) < 1e-5f); // outside the radius, calm air: upright
		}
	}

	sim.near().get_pushes().set_pushers(nullptr, 0); // the body leaves
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.near().get_pushes().get_pushed_count() > 0); // still springing back after half the recovery time
	for (int i = 0; i < 45; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.near().get_pushes().get_pushed_count() == 0); // settled within the recovery time (and a margin): no state left
	for (uint32_t plant : near) {
		CHECK(glm::length(head_offset(sim, plant)) < 1e-3f);
	}
}

TEST_CASE("pushers: wind and push state live with active chunks only; a chunk turning inactive drops its pushes") {
	FieldSimulation sim;
	load(sim, rect_map(160, 20)); // 80 × 10 m in 8 m chunks
	WindParams calm;
	calm.power = 0.0f;
	sim.near().set_wind(calm);
	sim.near().get_pushes().set_params(1.0f, 1.0f);
	sim.near().set_observer({ 16.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	const Pusher body{ { 16.0f, 1.0f, 5.0f }, 1.5f }; // across the border of two chunks
	sim.near().get_pushes().set_pushers(&body, 1);
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	std::vector<uint32_t> near;
	sim.plants().find_plants_near({ 16.0f, 5.0f }, 1.4f, near);
	const auto chunk_of = [&](uint32_t p_plant) { return sim.plants().get_layout().plants[p_plant].chunk; };
	const uint32_t west = chunk_of(10 * 160 + 30); // a full map: plant = row · columns + column, x = 15 m
	const uint32_t east = chunk_of(10 * 160 + 34); // x = 17 m
	uint32_t pushed_east = 0;
	for (uint32_t plant : near) {
		pushed_east += chunk_of(plant) == east ? 1 : 0;
	}
	REQUIRE(pushed_east > 3);
	REQUIRE(near.size() > pushed_east + 3);
	CHECK(sim.near().get_pushes().get_pushed_count() >= near.size());

	// Walk east until the western chunk is no longer active while the eastern one still is (the
	// western plants' pushes were found first, so dropping them moves the eastern ones' slots).
	float x = 16.0f;
	while (sim.near().is_chunk_active(west) && x < 80.0f) {
		x += 1.0f;
		sim.near().set_observer({ x, 1.7f, 5.0f });
		sim.update(1.0f / 60.0f);
	}
	REQUIRE(sim.near().is_chunk_active(east));
	CHECK(sim.near().get_pushes().get_pushed_count() < near.size()); // the western plants' pushes went with their chunk
	CHECK(sim.near().get_pushes().get_pushed_count() >= pushed_east); // the eastern ones' stay (their slots renumbered)
	// Straight back: the eastern plants are meshes again and still pushed away, through their
	// renumbered slots; the western ones start afresh and are pushed again.
	sim.near().set_observer({ 16.0f, 1.7f, 5.0f });
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	for (uint32_t plant : near) {
		const glm::vec2 away = sim.plants().get_layout().plants[plant].position - glm::vec2(16.0f, 5.0f);
		if (glm::length(away) > 0.05f && glm::length(away) < 1.3f) {
			CHECK(glm::dot(head_offset(sim, plant), away) > 0.0f);
		}
	}
	// Far from everything: no chunk active, so no push state is held at all.
	sim.near().set_observer({ -500.0f, 1.7f, 5.0f });
	sim.update(1.0f / 60.0f);
	CHECK(sim.near().get_pushes().get_pushed_count() == 0);
	// Back: the plants come upright with fresh state, the body pushes them again.
	sim.near().set_observer({ 16.0f, 1.7f, 5.0f });
	sim.near().get_pushes().set_pushers(nullptr, 0);
	sim.update(1.0f / 60.0f);
	for (uint32_t plant : near) {
		CHECK(glm::length(head_offset(sim, plant)) < 1e-5f);
	}
	sim.near().get_pushes().set_pushers(&body, 1);
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.near().get_pushes().get_pushed_count() >= near.size());
}

TEST_CASE("pushers: a body above the plants pushes nothing; a push never bends a plant past max_bend") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20));
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	const Pusher high{ { 5.0f, 8.0f, 5.0f }, 1.0f };
	sim.near().get_pushes().set_pushers(&high, 1);
	sim.update(0.016f);
	CHECK(sim.near().get_pushes().get_pushed_count() == 0);
	WindParams storm;
	storm.power = 100.0f;
	sim.near().set_wind(storm);
	sim.near().get_pushes().set_params(10.0f, 1.0f);
	const Pusher low{ { 5.0f, 0.5f, 5.0f }, 2.0f };
	sim.near().get_pushes().set_pushers(&low, 1);
	for (int i = 0; i < 120; ++i) {
		sim.update(1.0f / 60.0f);
	}
	for (uint32_t plant = 0; plant < sim.plants().get_plant_count(); ++plant) {
		PartTransforms parts;
		sim.near().get_plant_parts(plant, parts);
		const float tilt = std::acos(glm::normalize(parts.basis[1][1]).y) + 0.0f;
		CHECK(tilt <= sim.near().get_wind().get_params().max_bend * 1.001f);
	}
}
