// Core tests of the near field: per-plant LOD, activation, culling, fades, buffers.
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

TEST_CASE("a plant's own LOD matches its distance outside the hysteresis bands") {
	FieldSimulation sim;
	load(sim, rect_map(80, 80));
	const glm::vec3 observer(20.0f, 1.0f, 20.0f);
	sim.near().set_observer(observer);
	sim.near().request_lod_update();
	for (int i = 0; i < 10; ++i) { // chunks turn active over a few updates (ACTIVATION_BUDGET)
		sim.update(0.016f);
	}
	LodSelector plain;
	plain.configure(sim.near().get_lod().get_params());
	const float margin = sim.near().get_lod().get_params().hysteresis;
	for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
		const Plant &plant = sim.plants().get_layout().plants[i];
		const glm::vec3 middle(plant.position.x, 0.5f * sim.plants().get_shape().height * sim.plants().get_shape().part_scale, plant.position.y);
		const float distance = glm::length(observer - middle);
		bool near_threshold = false;
		for (float d : sim.near().get_lod().get_params().distances) {
			near_threshold |= std::abs(distance - d) < margin;
		}
		if (!near_threshold && distance < 20.0f) {
			CHECK(sim.near().get_plant_lod(i) == plain.select(distance * distance));
		}
	}
}

TEST_CASE("a plant type's LOD scale moves its switches: twice the scale, twice the distances") {
	for (const float scale : { 0.5f, 2.0f }) {
		FieldSimulation sim;
		load(sim, rect_map(120, 120));
		PlantShape shape = sim.plants().get_shape();
		shape.lod_scale = scale;
		sim.set_shape(shape);
		const glm::vec3 observer(30.0f, 1.0f, 30.0f);
		sim.near().set_observer(observer);
		sim.near().request_lod_update();
		for (int i = 0; i < 20; ++i) { // chunks turn active over a few updates (ACTIVATION_BUDGET)
			sim.update(0.016f);
		}
		LodSelector plain;
		plain.configure(sim.near().get_lod().get_params());
		const float margin = sim.near().get_lod().get_params().hysteresis * scale;
		int checked = 0;
		int moved = 0; // plants whose level differs from what the unscaled distances would give
		for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
			const Plant &plant = sim.plants().get_layout().plants[i];
			const glm::vec3 middle(plant.position.x, 0.5f * shape.height * sim.plants().get_shape().part_scale, plant.position.y);
			const float distance = glm::length(observer - middle);
			bool near_threshold = false;
			for (float d : sim.near().get_lod().get_params().distances) {
				near_threshold |= std::abs(distance - d * scale) < margin;
			}
			if (!near_threshold && distance < 20.0f * scale) {
				const float seen = distance / scale;
				CHECK(sim.near().get_plant_lod(i) == plain.select(seen * seen));
				moved += sim.near().get_plant_lod(i) != plain.select(distance * distance) ? 1 : 0;
				++checked;
			}
		}
		CHECK(checked > 100);
		CHECK(moved > 50);
		// A scale that is not positive keeps the current one.
		shape.lod_scale = -1.0f;
		sim.set_shape(shape);
		CHECK(sim.plants().get_shape().lod_scale == scale);
	}
}

TEST_CASE("LOD is re-selected every interval, not every frame") {
	FieldSimulation sim;
	load(sim, rect_map(40, 30));
	sim.near().set_observer({ 10.0f, 1.7f, 7.5f });
	sim.update(0.016f);
	const auto near_counts = sim.near().get_lod_counts();
	CHECK(near_counts[LOD_MESH_1] > 0);
	sim.near().set_observer({ 10.0f, 1.7f, 11.0f }); // a step (not a jump: under JUMP_DISTANCE)
	sim.update(0.1f);
	CHECK(sim.near().get_lod_counts()[LOD_MESH_1] == near_counts[LOD_MESH_1]);
	sim.update(0.2f); // 0.3 s since the last selection
	CHECK(sim.near().get_lod_counts()[LOD_MESH_1] != near_counts[LOD_MESH_1]);
}

TEST_CASE("the frustum culls what is written, not what is counted") {
	FieldSimulation sim;
	load(sim, rect_map(40, 40));
	sim.near().set_observer({ 10.0f, 1.7f, 10.0f });
	sim.update(0.016f);
	const uint32_t all = sim.near().get_bucket(mesh_bucket(0, 0)).get_count();
	const auto counts = sim.near().get_lod_counts();
	// Keep only x > 10 (an outward plane with normal −x at x = 10).
	const glm::vec4 plane(-1.0f, 0.0f, 0.0f, -10.0f);
	sim.near().get_frustum().set_planes(&plane, 1);
	sim.update(0.016f);
	const uint32_t half = sim.near().get_bucket(mesh_bucket(0, 0)).get_count();
	CHECK(half < all);
	CHECK(half > all / 3);
	CHECK(sim.near().get_lod_counts() == counts);
}

TEST_CASE("chunks out of view or wholly in it are culled as their plants would be, and keep their wind") {
	// Keep only x > 12: chunks left of it lie out of view, right of it wholly in view, on it across.
	const glm::vec4 plane(-1.0f, 0.0f, 0.0f, -12.0f);
	const glm::vec3 eye{ 15.0f, 1.7f, 15.0f };
	WindParams wind;
	wind.model = WIND_THESIS; // the model whose plants carry state from frame to frame
	wind.power = 3.0f;
	LodParams lod;
	lod.fade = 0.0f; // each plant in one bucket
	// 30 × 30 m of 8 m chunks, all near the eye; plants of sizes 0.7–1.3, so that level planes cut
	// through their culling spheres.
	MapError error;
	LayoutParams layout;
	layout.chunk_size = 8.0f;
	layout.varieties[0].scale_min = 0.7f;
	layout.varieties[0].scale_max = 1.3f;
	FieldSimulation sim;
	FieldSimulation unculled; // the same field seen whole
	for (FieldSimulation *field : { &sim, &unculled }) {
		REQUIRE(field->load_map(rect_map(60, 60), U"", "sim", MapLimits{}, error));
		field->set_layout_params(layout);
		field->near().set_wind(wind);
		field->near().set_lod(lod);
		field->near().set_observer(eye);
	}
	sim.near().get_frustum().set_planes(&plane, 1);
	for (int frame = 0; frame < 600; ++frame) { // 20 s: the plants' b redraws come round
		sim.update(1.0f / 30.0f);
		unculled.update(1.0f / 30.0f);
	}
	// The plants that spent the 20 s out of view sway as they would have in view.
	uint32_t compared = 0;
	for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
		if (sim.plants().get_layout().plants[i].position.x < 8.0f && sim.near().get_plant_lod(i) < LOD_SPRITE) {
			PartTransforms culled, seen;
			sim.near().get_plant_parts(i, culled);
			unculled.near().get_plant_parts(i, seen);
			CHECK(culled.origin[2] == seen.origin[2]);
			++compared;
		}
	}
	CHECK(compared > 100);
	// What each plant's own test keeps, bucket by bucket, for planes that cut the chunks' boxes: across
	// the field (at a chunk's edge, within its plants' reach), and level, through the middle of the
	// culling spheres' bottoms and of their tops (plants differ in size).
	const PlantShape &shape = sim.plants().get_shape();
	std::vector<float> bottoms, tops;
	for (const Plant &plant : sim.plants().get_layout().plants) {
		const float scale = shape.part_scale * plant.scale;
		bottoms.push_back(plant.ground + (0.5f * shape.height - shape.cull_radius) * scale);
		tops.push_back(plant.ground + (0.5f * shape.height + shape.cull_radius) * scale);
	}
	std::sort(bottoms.begin(), bottoms.end());
	std::sort(tops.begin(), tops.end());
	const glm::vec4 cuts[] = { plane, { -1.0f, 0.0f, 0.0f, -8.5f }, { 0.0f, 1.0f, 0.0f, bottoms[bottoms.size() / 2] },
		{ 0.0f, -1.0f, 0.0f, -tops[tops.size() / 2] } };
	for (size_t c = 0; c < std::size(cuts); ++c) {
		CAPTURE(c);
		const glm::vec4 &cut = cuts[c];
		sim.near().get_frustum().set_planes(&cut, 1);
		sim.update(0.001f);
		std::array<uint32_t, BUCKET_COUNT> expected{};
		uint32_t out_of_view = 0;
		for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
			const Plant &plant = sim.plants().get_layout().plants[i];
			if (!sim.near().is_chunk_active(plant.chunk)) {
				continue;
			}
			const float scale = shape.part_scale * plant.scale;
			const glm::vec3 middle = plant.root() + glm::vec3(0.0f, 0.5f * shape.height * scale, 0.0f);
			if (!sim.near().get_frustum().intersects_sphere(middle, shape.cull_radius * scale)) {
				++out_of_view;
				continue;
			}
			const uint8_t level = sim.near().get_plant_lod(i);
			++expected[level >= LOD_SPRITE ? BUCKET_IMPOSTOR : mesh_bucket(level, 0)];
		}
		CHECK(out_of_view > sim.plants().get_plant_count() / 8);
		CHECK(std::accumulate(expected.begin(), expected.end(), 0u) > sim.plants().get_plant_count() / 8);
		for (uint32_t b : { mesh_bucket(LOD_MESH_1, 0), mesh_bucket(LOD_MESH_2, 0), mesh_bucket(LOD_MESH_3, 0), BUCKET_IMPOSTOR }) {
			CHECK(sim.near().get_bucket(b).get_count() == expected[b]);
		}
	}
}

TEST_CASE("a bucket's box holds its plants, as near as they are, and empties with them") {
	FieldSimulation sim;
	load(sim, rect_map(200, 200)); // 100 × 100 m
	const glm::vec3 eye{ 50.0f, 1.7f, 50.0f };
	sim.near().set_observer(eye);
	sim.update(0.016f);
	const float radius = PlantShape::CULL_RADIUS * PlantShape{}.part_scale * 1.5f; // the largest plant's
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		const InstanceBuffer &bucket = sim.near().get_bucket(b);
		REQUIRE(bucket.get_count() > 0);
		for (uint32_t i = 0; i < bucket.get_count(); ++i) {
			const glm::vec3 origin = placed(bucket, i).root;
			CHECK(glm::all(glm::greaterThanEqual(origin, bucket.get_bounds_low())));
			CHECK(glm::all(glm::lessThanEqual(origin, bucket.get_bounds_high())));
		}
	}
	// Mesh 1 reaches its switch distance (with hysteresis) and a plant's sphere round the observer:
	// a box of a few metres in a field of a hundred, which is what lets a shadow cascade skip it.
	const LodParams lod;
	const InstanceBuffer &nearest = sim.near().get_bucket(mesh_bucket(LOD_MESH_1, 0));
	const float reach = lod.distances[0] + lod.hysteresis + radius;
	CHECK(glm::all(glm::greaterThanEqual(nearest.get_bounds_low(), eye - glm::vec3(reach, 2.0f, reach))));
	CHECK(glm::all(glm::lessThanEqual(nearest.get_bounds_high(), eye + glm::vec3(reach, 2.0f * radius + 4.0f, reach))));
	// Nothing in view: every box is empty.
	const glm::vec4 plane(0.0f, -1.0f, 0.0f, -1000.0f); // keeps only y > 1 000 m
	sim.near().get_frustum().set_planes(&plane, 1);
	sim.update(0.016f);
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		CHECK(sim.near().get_bucket(b).get_count() == 0);
		CHECK(sim.near().get_bucket(b).get_bounds_low().x > sim.near().get_bucket(b).get_bounds_high().x);
	}
}

TEST_CASE("with wind the transforms change over time; without it the plants stay upright") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20));
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	WindParams calm;
	calm.power = 0.0f;
	sim.near().set_wind(calm);
	sim.update(0.016f);
	PartTransforms before, after;
	sim.near().get_plant_parts(0, before);
	for (int i = 0; i < 30; ++i) {
		sim.update(0.016f);
	}
	sim.near().get_plant_parts(0, after);
	for (int part = 0; part < 3; ++part) {
		CHECK(after.origin[part] == before.origin[part]);
		const glm::vec3 up = glm::normalize(after.basis[part][1]);
		CHECK(up.y == doctest::Approx(1.0f));
	}
	const float *data = sim.near().get_bucket(mesh_bucket(0, 2)).get_data();
	const std::vector<float> calm_heads(data, data + 12);

	WindParams windy;
	windy.power = 3.0f;
	sim.near().set_wind(windy);
	sim.update(0.016f);
	sim.near().get_plant_parts(0, before);
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	sim.near().get_plant_parts(0, after);
	CHECK(glm::length(after.origin[2] - before.origin[2]) > 1e-4f);
	const glm::vec3 up = glm::normalize(after.basis[1][1]);
	CHECK(up.y < 0.99999f);
	data = sim.near().get_bucket(mesh_bucket(0, 2)).get_data();
	CHECK(std::vector<float>(data, data + 12) != calm_heads);
}

TEST_CASE("steady state allocates nothing: buffers keep their storage along a repeated path") {
	FieldSimulation sim;
	load(sim, rect_map(100, 100));
	const auto walk = [&]() {
		for (float x = 0.0f; x < 50.0f; x += 0.5f) {
			sim.near().set_observer({ x, 1.7f, 25.0f });
			sim.update(0.05f);
		}
	};
	walk();
	std::array<const float *, BUCKET_COUNT> data{};
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		data[b] = sim.near().get_bucket(b).get_data();
	}
	walk();
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		CHECK(sim.near().get_bucket(b).get_data() == data[b]);
	}
}

TEST_CASE("static chunks choose sprite or billboard by the distance to their box centre") {
	FieldSimulation sim;
	load(sim, rect_map(400, 20), 8.0f); // a 200 m strip
	sim.near().set_observer({ 0.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	for (uint32_t c = 0; c < sim.plants().get_chunk_count(); ++c) {
		if (sim.near().is_chunk_active(c)) {
			continue;
		}
		const float distance = glm::length(sim.near().get_observer() - sim.plants().get_chunk_bounds(c).center());
		const uint32_t plant = sim.plants().get_layout().chunk_plants[sim.plants().get_layout().chunks[c].first];
		CHECK(sim.near().get_plant_lod(plant) == (distance <= 25.0f ? LOD_SPRITE : LOD_BILLBOARD));
	}
}

TEST_CASE("a forced representation draws every plant in it, and memory per plant stays small") {
	FieldSimulation sim;
	load(sim, rect_map(100, 60)); // 6 000 plants
	LodParams params;
	params.force_level = LOD_MESH_2;
	sim.near().set_lod(params);
	sim.near().set_observer({ 1000.0f, 1.7f, 1000.0f }); // far away: normally all billboards
	sim.update(0.016f);
	CHECK(sim.near().get_lod_counts()[LOD_MESH_2] == 6000);
	CHECK(sim.near().get_bucket(mesh_bucket(1, 0)).get_count() == 6000);
	CHECK(drawn(sim) == 6000);
	params.force_level = LOD_BILLBOARD;
	sim.near().set_lod(params);
	sim.update(0.016f);
	CHECK(sim.near().get_bucket(BUCKET_IMPOSTOR).get_count() == 6000);
	CHECK(sim.near().get_bucket(mesh_bucket(1, 0)).get_count() == 0);
	CHECK(drawn(sim) == 6000);
	params.force_level = -1;
	sim.near().set_lod(params);
	sim.update(0.016f);
	CHECK(sim.near().get_lod_counts()[LOD_BILLBOARD] == 6000);
	CHECK(drawn(sim) == 6000);

	FieldSimulation big;
	load(big, rect_map(1000, 200)); // 200 000 plants, far observer: only static chunks
	big.near().set_observer({ -500.0f, 1.7f, -500.0f });
	big.update(0.016f);
	const double per_plant = double(big.get_memory_bytes()) / 200000.0;
	CAPTURE(per_plant);
	CHECK(per_plant <= 40.0); // #15: ≤ 40 B a plant (a 28 B layout, no wind state for far plants)
}

TEST_CASE("a near impostor is its plant's static record, and takes a new plant size at once") {
	FieldSimulation sim;
	load(sim, rect_map(60, 60)); // 30 × 30 m around an observer in the middle: impostors beyond 20 m
	sim.near().set_observer({ 15.0f, 1.7f, 15.0f });
	std::map<std::pair<float, float>, uint32_t> by_root;
	for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
		const Plant &plant = sim.plants().get_layout().plants[i];
		by_root[{ plant.position.x, plant.position.y }] = i;
	}
	// Every near impostor against the record its plant has as a static one, at the plant size now.
	auto check_records = [&](float p_part_scale) {
		const InstanceBuffer &sprites = sim.near().get_bucket(BUCKET_IMPOSTOR);
		REQUIRE(sprites.get_count() > 100);
		for (uint32_t k = 0; k < sprites.get_count(); ++k) {
			const FarInstance drawn = read_far_instance(sprites.get_data() + size_t(k) * FAR_FLOATS_PER_INSTANCE);
			const auto found = by_root.find({ drawn.root.x, drawn.root.z });
			REQUIRE(found != by_root.end());
			const Plant &plant = sim.plants().get_layout().plants[found->second];
			const FarInstance expected = sim.plants().far_instance(plant, 0);
			CHECK(drawn.scale == doctest::Approx(p_part_scale * plant.scale).epsilon(1e-5));
			CHECK(drawn.scale == doctest::Approx(expected.scale).epsilon(1e-5));
			CHECK(std::abs(std::remainder(drawn.yaw - expected.yaw, TAU)) < 1e-4f);
			CHECK(glm::length(drawn.tone - expected.tone) < 0.01f);
			CHECK(glm::length(drawn.lean - expected.lean) < 0.01f);
			CHECK(drawn.root.y == expected.root.y);
		}
	};
	for (int i = 0; i < 4; ++i) { // chunks turn active a budget's worth per update
		sim.update(0.016f);
	}
	check_records(sim.plants().get_shape().part_scale);
	PlantShape larger = sim.plants().get_shape();
	larger.part_scale *= 2.0f; // the plant type made taller in the inspector, say
	sim.set_shape(larger);
	sim.update(0.016f);
	check_records(larger.part_scale);
}

TEST_CASE("mesh 3 dithers into its impostor over the fade metres before the sprite switch, the same whichever level a plant is at") {
	FieldSimulation sim;
	load(sim, rect_map(120, 120)); // 60 × 60 m
	LodParams lod; // switches at 6, 10, 20, 25 m, hysteresis 0.5 m, fade 3 m: from 16.5 to 19.5 m
	lod.interval = 0.0f;
	sim.near().set_lod(lod);
	const glm::vec3 eye{ 30.0f, 1.7f, 30.0f };
	sim.near().set_observer(eye);
	const float middle = 0.5f * PlantShape::HEIGHT * float(param::PLANT_HEIGHT.default_value) / 3.0f;
	auto impostor_shares = [&]() {
		std::map<std::pair<float, float>, float> shares;
		const InstanceBuffer &sprites = sim.near().get_bucket(BUCKET_IMPOSTOR);
		for (uint32_t i = 0; i < sprites.get_count(); ++i) {
			const Placed instance = placed(sprites, i);
			shares[{ instance.root.x, instance.root.z }] = instance.share;
		}
		const InstanceBuffer &meshes = sim.near().get_bucket(mesh_bucket(LOD_MESH_3, 0));
		for (uint32_t i = 0; i < meshes.get_count(); ++i) {
			const float *instance = meshes.get_data() + size_t(i) * meshes.get_stride();
			shares.emplace(std::make_pair(instance[3], instance[11]), 0.0f); // mesh 3 alone: no impostor
		}
		return shares;
	};
	int in_band = 0;
	int switching = 0;
	SUBCASE("part by part") {}
	SUBCASE("drawn whole") { // the same shares, on one instance per plant
		PlantShape shape;
		shape.whole = true;
		sim.set_shape(shape);
	}
	// Walk out and back in: plants near 20 m are at mesh 3 on one way and sprites on the other.
	for (float step : { 0.0f, 0.6f, 1.2f, 0.6f, 0.0f }) {
		sim.near().set_observer(eye + glm::vec3(step, 0.0f, 0.0f));
		for (int i = 0; i < 10; ++i) { // chunks turn active a budget's worth per update
			sim.near().request_lod_update();
			sim.update(0.016f);
		}
		const auto shares = impostor_shares();
		for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
			const Plant &plant = sim.plants().get_layout().plants[i];
			const float distance = glm::length(eye + glm::vec3(step, 0.0f, 0.0f) - (plant.root() + glm::vec3(0.0f, middle, 0.0f)));
			if (distance < 12.0f || distance > 22.0f) {
				continue;
			}
			const auto found = shares.find({ plant.root().x, plant.root().z });
			const float expected = std::clamp((distance - 16.5f) / 3.0f, 0.0f, 1.0f);
			CAPTURE(distance);
			// Not in a near bucket: in a static chunk, drawn as a whole impostor.
			const bool as_expected = found == shares.end() ? !sim.near().is_chunk_active(plant.chunk) && expected == 1.0f
														   : found->second == doctest::Approx(expected).epsilon(1e-3);
			CHECK(as_expected);
			in_band += expected > 0.0f && expected < 1.0f ? 1 : 0;
			switching += distance > 19.5f && distance < 20.5f ? 1 : 0;
		}
		CHECK(drawn(sim) == sim.plants().get_plant_count());
	}
	CHECK(in_band > 500);
	CHECK(switching > 100);
	lod.fade = 0.0f; // no fade: mesh 3 wholly up to its switch
	sim.near().set_lod(lod);
	sim.near().request_lod_update();
	sim.update(0.016f);
	for (const auto &[root, share] : impostor_shares()) {
		CHECK((share == 0.0f || share == 1.0f));
	}
	CHECK(drawn(sim) == sim.plants().get_plant_count());
}

TEST_CASE("drawn whole, mesh 1 and 2 dither into the next level before their switches, the same whichever level a plant is at") {
	FieldSimulation sim;
	load(sim, rect_map(120, 120)); // 60 × 60 m
	LodParams lod; // switches at 6, 10, 20 m, hysteresis 0.5 m, fade 3 m at 20 m: 0.9 m at 6, 1.5 m at 10
	lod.interval = 0.0f;
	sim.near().set_lod(lod);
	PlantShape shape;
	shape.whole = true;
	sim.set_shape(shape);
	const glm::vec3 eye{ 30.0f, 1.7f, 30.0f };
	const float middle = 0.5f * PlantShape::HEIGHT * float(param::PLANT_HEIGHT.default_value) / 3.0f;
	const struct {
		float start, length;
	} bands[2] = { { 4.6f, 0.9f }, { 8.0f, 1.5f } };
	int in_band[2] = { 0, 0 };
	for (float step : { 0.0f, 0.4f, 0.8f, 0.4f, 0.0f }) { // out and back in: levels differ in the hysteresis bands
		const glm::vec3 at = eye + glm::vec3(step, 0.0f, 0.0f);
		sim.near().set_observer(at);
		for (int i = 0; i < 10; ++i) {
			sim.near().request_lod_update();
			sim.update(0.016f);
		}
		// Each plant's alpha per mesh level.
		std::map<std::pair<float, float>, std::array<float, 3>> alphas;
		for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
			const InstanceBuffer &bucket = sim.near().get_bucket(mesh_bucket(level, 0));
			for (uint32_t i = 0; i < bucket.get_count(); ++i) {
				const float *instance = bucket.get_data() + size_t(i) * bucket.get_stride();
				alphas.try_emplace({ instance[3], instance[11] }, std::array<float, 3>{ 0.0f, 0.0f, 0.0f });
				alphas[{ instance[3], instance[11] }][level] = instance[15];
			}
		}
		for (uint32_t i = 0; i < sim.plants().get_plant_count(); ++i) {
			const Plant &plant = sim.plants().get_layout().plants[i];
			const float distance = glm::length(at - (plant.root() + glm::vec3(0.0f, middle, 0.0f)));
			for (int band = 0; band < 2; ++band) {
				if (distance < bands[band].start - 1.0f || distance > bands[band].start + bands[band].length + 1.0f) {
					continue;
				}
				const auto found = alphas.find({ plant.root().x, plant.root().z });
				REQUIRE(found != alphas.end());
				const float share = std::clamp((distance - bands[band].start) / bands[band].length, 0.0f, 1.0f);
				const float finer = found->second[band];
				const float coarser = found->second[band + 1];
				CAPTURE(distance);
				CAPTURE(band);
				if (share <= 0.0f) {
					CHECK(finer == doctest::Approx(1.0f));
					CHECK(coarser == 0.0f);
				} else if (share >= 1.0f) {
					CHECK(finer == 0.0f);
					CHECK(coarser == doctest::Approx(1.0f));
				} else {
					CHECK(finer == doctest::Approx(1.0f - share).epsilon(1e-3));
					CHECK(coarser == doctest::Approx(-share).epsilon(1e-3)); // the other pixels
					++in_band[band];
				}
			}
		}
		CHECK(drawn(sim) == sim.plants().get_plant_count());
	}
	CHECK(in_band[0] > 40);
	CHECK(in_band[1] > 80);
	shape.whole = false; // part by part (any material): the mesh levels switch at once
	sim.set_shape(shape);
	sim.near().request_lod_update();
	sim.update(0.016f);
	for (uint32_t level = 0; level < LOD_MESH_3; ++level) {
		const InstanceBuffer &bucket = sim.near().get_bucket(mesh_bucket(level, 0));
		for (uint32_t i = 0; i < bucket.get_count(); ++i) {
			CHECK(bucket.get_data()[size_t(i) * bucket.get_stride() + 15] == 1.0f);
		}
	}
	CHECK(drawn(sim) == sim.plants().get_plant_count());
}

TEST_CASE("a jump of the observer re-selects at once, nearest chunks first, within the activation budget") {
	FieldSimulation sim;
	load(sim, rect_map(400, 400), 16.0f); // 200 × 200 m, 160 000 plants
	sim.near().set_observer({ 20.0f, 1.7f, 20.0f });
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	const uint32_t settled = sim.near().get_active_plant_count();
	CHECK(settled > NearField::ACTIVATION_BUDGET); // more than one update's worth
	const glm::vec3 there(150.0f, 1.7f, 150.0f);
	sim.near().set_observer(there); // a teleport, 184 m, in the middle of an LOD interval
	sim.update(0.016f);
	std::vector<uint32_t> nearest;
	sim.plants().find_plants_near({ there.x, there.z }, 1.7f, nearest);
	REQUIRE(!nearest.empty());
	for (uint32_t plant : nearest) {
		CHECK(sim.near().get_plant_lod(plant) == LOD_MESH_1); // a mesh on the first update after the jump
	}
	uint32_t largest_chunk = 0;
	for (const Chunk &chunk : sim.plants().get_layout().chunks) {
		largest_chunk = std::max(largest_chunk, chunk.count);
	}
	CHECK(sim.near().get_active_plant_count() <= NearField::ACTIVATION_BUDGET + largest_chunk);
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	FieldSimulation fresh; // the neighbourhood as a simulation that started there has it
	load(fresh, rect_map(400, 400), 16.0f);
	fresh.near().set_observer(there);
	for (int i = 0; i < 10; ++i) {
		fresh.update(0.016f);
	}
	CHECK(sim.near().get_active_plant_count() == fresh.near().get_active_plant_count());
	CHECK(sim.near().get_lod_counts() == fresh.near().get_lod_counts());
	CHECK(drawn(sim) == sim.plants().get_plant_count()); // exactly once all the while
}
