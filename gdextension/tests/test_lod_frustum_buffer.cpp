#include "frustum.h"
#include "instance_buffer.h"
#include "lod_selector.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

using namespace sunflower;

TEST_CASE("thesis thresholds 6 / 10 / 20 / 25 m, compared squared") {
	LodSelector lod;
	lod.configure(LodParams{});
	CHECK(lod.select(0.0f) == LOD_MESH_1);
	CHECK(lod.select(35.9f) == LOD_MESH_1);
	CHECK(lod.select(36.0f) == LOD_MESH_2);
	CHECK(lod.select(99.9f) == LOD_MESH_2);
	CHECK(lod.select(100.0f) == LOD_MESH_3);
	CHECK(lod.select(399.0f) == LOD_MESH_3);
	CHECK(lod.select(400.0f) == LOD_SPRITE);
	CHECK(lod.select(624.0f) == LOD_SPRITE);
	CHECK(lod.select(625.0f) == LOD_BILLBOARD);
	CHECK(lod.select(1e9f) == LOD_BILLBOARD);
}

TEST_CASE("hysteresis: switch to less detail a margin later, to more detail a margin earlier") {
	LodParams params;
	params.hysteresis = 1.0f;
	LodSelector lod;
	lod.configure(params);
	const auto sq = [](float p_d) { return p_d * p_d; };
	CHECK(lod.update(LOD_MESH_1, sq(6.5f)) == LOD_MESH_1); // inside the band: keep
	CHECK(lod.update(LOD_MESH_1, sq(7.1f)) == LOD_MESH_2);
	CHECK(lod.update(LOD_MESH_2, sq(5.5f)) == LOD_MESH_2); // inside the band: keep
	CHECK(lod.update(LOD_MESH_2, sq(4.9f)) == LOD_MESH_1);
	CHECK(lod.update(LOD_MESH_1, sq(30.0f)) == LOD_BILLBOARD); // far jumps cross several levels
	CHECK(lod.update(LOD_BILLBOARD, sq(1.0f)) == LOD_MESH_1);
	// Walking back and forth across a threshold inside the band never flips the level.
	uint8_t level = LOD_SPRITE;
	int flips = 0;
	for (int i = 0; i < 100; ++i) {
		const uint8_t next = lod.update(level, sq(25.0f + ((i % 2) ? 0.8f : -0.8f)));
		flips += next != level ? 1 : 0;
		level = next;
	}
	CHECK(flips == 0);
}

TEST_CASE("frustum: spheres outside any plane are culled, an unset frustum keeps everything") {
	Frustum frustum;
	CHECK(frustum.intersects_sphere({ 1e6f, 0, 0 }, 0.1f));
	// A box |x| ≤ 10, |y| ≤ 10, |z| ≤ 10 as six outward planes (normal, d), unnormalised on purpose.
	const glm::vec4 planes[6] = { { 2, 0, 0, 20 }, { -1, 0, 0, 10 }, { 0, 1, 0, 10 }, { 0, -1, 0, 10 }, { 0, 0, 1, 10 }, { 0, 0, -1, 10 } };
	frustum.set_planes(planes, 6);
	CHECK(frustum.intersects_sphere({ 0, 0, 0 }, 1.0f));
	CHECK(frustum.intersects_sphere({ 10.5f, 0, 0 }, 1.0f)); // overlaps the boundary
	CHECK_FALSE(frustum.intersects_sphere({ 11.5f, 0, 0 }, 1.0f));
	CHECK_FALSE(frustum.intersects_sphere({ 0, 0, -12.0f }, 1.0f));
}

TEST_CASE("frustum: a box out of view holds no sphere in view, a box in view no sphere out of it, a crossing box's planes judge its spheres") {
	// Camera-like frusta (a 90° wedge with a near and a far plane, turned and tilted) against random
	// boxes; spheres that fit each box must agree with the box's verdict.
	uint32_t state = 12345u;
	auto random = [&state](float p_low, float p_high) {
		state = state * 1664525u + 1013904223u;
		return p_low + (p_high - p_low) * float(state >> 8) / float(1u << 24);
	};
	int seen[3] = { 0, 0, 0 };
	int crossed[2] = { 0, 0 }; // spheres in crossing boxes: out of view, in view
	for (int pose = 0; pose < 40; ++pose) {
		const float yaw = random(0.0f, 6.283f);
		const float pitch = random(-1.2f, 0.3f);
		const glm::vec3 eye(random(-20.0f, 20.0f), random(1.0f, 30.0f), random(-20.0f, 20.0f));
		const glm::vec3 forward(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
		const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
		const glm::vec3 up = glm::cross(right, forward);
		const glm::vec3 normals[6] = { -forward, forward, right - forward, -right - forward, up - forward, -up - forward };
		glm::vec4 planes[6];
		for (int i = 0; i < 6; ++i) {
			const glm::vec3 n = glm::normalize(normals[i]);
			const glm::vec3 on = i == 0 ? eye + 0.05f * forward : (i == 1 ? eye + 60.0f * forward : eye);
			planes[i] = glm::vec4(n, glm::dot(n, on));
		}
		Frustum frustum;
		frustum.set_planes(planes, 6);
		for (int b = 0; b < 200; ++b) {
			const glm::vec3 low(random(-60.0f, 60.0f), random(-5.0f, 30.0f), random(-60.0f, 60.0f));
			const glm::vec3 high = low + glm::vec3(random(0.5f, 16.0f), random(0.5f, 4.0f), random(0.5f, 16.0f));
			Frustum crossing;
			const Frustum::Overlap overlap = frustum.classify_box(low, high, &crossing);
			++seen[overlap];
			// Crossing, a sphere inside the box meets the planes it crosses as it meets all six.
			for (int k = 0; k < 50 && overlap == Frustum::CROSSING; ++k) {
				const glm::vec3 extent = high - low;
				const float radius = random(0.0f, 0.5f) * std::min({ extent.x, extent.y, extent.z });
				const glm::vec3 centre(random(low.x + radius, high.x - radius), random(low.y + radius, high.y - radius),
						random(low.z + radius, high.z - radius));
				const bool seen_by_all = frustum.intersects_sphere(centre, radius);
				crossed[seen_by_all] += 1;
				CHECK(crossing.intersects_sphere(centre, radius) == seen_by_all);
			}
			for (int k = 0; k < 50 && overlap != Frustum::CROSSING; ++k) {
				const glm::vec3 extent = high - low;
				const float radius = random(0.0f, 0.5f) * std::min({ extent.x, extent.y, extent.z });
				const glm::vec3 centre(random(low.x + radius, high.x - radius), random(low.y + radius, high.y - radius),
						random(low.z + radius, high.z - radius));
				CHECK(frustum.intersects_sphere(centre, radius) == (overlap == Frustum::INSIDE));
			}
		}
	}
	CHECK(seen[Frustum::OUTSIDE] > 100);
	CHECK(seen[Frustum::INSIDE] > 20);
	CHECK(seen[Frustum::CROSSING] > 100);
	CHECK(crossed[0] > 500); // crossing boxes' spheres both out of view and in it
	CHECK(crossed[1] > 500);
	// With no planes every box is in view.
	CHECK(Frustum{}.classify_box(glm::vec3(1e6f), glm::vec3(2e6f)) == Frustum::INSIDE);
}

TEST_CASE("instance layout: 16 floats, the 3×4 matrix row by row, then the colour") {
	glm::mat3 basis(glm::vec3(1, 2, 3), glm::vec3(4, 5, 6), glm::vec3(7, 8, 9)); // columns
	float out[FLOATS_PER_INSTANCE];
	write_instance(out, basis, glm::vec3(10, 11, 12), glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
	const float expected[16] = { 1, 4, 7, 10, 2, 5, 8, 11, 3, 6, 9, 12, 0.5f, 0.25f, 1.0f, 0.75f };
	static_assert(FLOATS_PER_INSTANCE == 16, "transform and colour");
	for (int i = 0; i < 16; ++i) {
		CHECK(out[i] == expected[i]);
	}
}

TEST_CASE("far records: 8 floats that read back to the plant, its lean and tone in their steps and its chunk's cell") {
	FarInstance plant;
	plant.root = glm::vec3(123.25f, -4.5f, 987.75f);
	plant.yaw = 2.5f;
	plant.scale = 1.3f;
	plant.lean = glm::vec2(0.3f, -0.6f);
	plant.tone = glm::vec2(1.13f, -0.2f);
	plant.cell = 65535;
	float out[FAR_FLOATS_PER_INSTANCE];
	static_assert(FAR_FLOATS_PER_INSTANCE == 8, "one MultiMesh 2D transform");
	write_far_instance(out, plant);
	const FarInstance back = read_far_instance(out);
	CHECK(back.root == plant.root);
	CHECK(back.scale == doctest::Approx(plant.scale));
	CHECK(back.yaw == doctest::Approx(plant.yaw));
	CHECK(std::abs(back.lean.x - plant.lean.x) <= 0.5f / 127.0f);
	CHECK(std::abs(back.lean.y - plant.lean.y) <= 0.5f / 127.0f);
	CHECK(std::abs(back.tone.x - plant.tone.x) <= 0.5f / 128.0f);
	CHECK(std::abs(back.tone.y - plant.tone.y) <= 0.5f / 127.0f);
	CHECK(back.cell == 65535u);
	FarInstance plain;
	write_far_instance(out, plain);
	CHECK(read_far_instance(out).tone == glm::vec2(1.0f, 0.0f)); // as modelled stays exact
	CHECK(read_far_instance(out).lean == glm::vec2(0.0f));
	// The steps survive a transform and its inverse, as the shader meets them: the record as a 2D
	// instance (rows 0 and 1; row 2 is (0, 0, 1, 0)), times a turned, scaled, moved node, undone.
	write_far_instance(out, plant);
	const glm::mat4 record(glm::vec4(out[0], out[4], 0, 0), glm::vec4(out[1], out[5], 0, 0), glm::vec4(out[2], out[6], 1, 0),
			glm::vec4(out[3], out[7], 0, 1));
	glm::mat4 node(1.0f);
	node[0] = glm::vec4(0.6f * 3.0f, 0.0f, -0.8f * 3.0f, 0.0f);
	node[2] = glm::vec4(0.8f * 3.0f, 0.0f, 0.6f * 3.0f, 0.0f);
	node[1] = glm::vec4(0.0f, 3.0f, 0.0f, 0.0f);
	node[3] = glm::vec4(5000.0f, 20.0f, -3000.0f, 1.0f);
	const glm::mat4 seen = glm::inverse(node) * (node * record);
	float again[FAR_FLOATS_PER_INSTANCE] = { seen[0].x, seen[1].x, seen[2].x, seen[3].x, seen[0].y, seen[1].y, seen[2].y, seen[3].y };
	const FarInstance through = read_far_instance(again);
	CHECK(through.lean == back.lean);
	CHECK(through.tone == back.tone);
	CHECK(through.cell == back.cell);
	CHECK(glm::distance(through.root, plant.root) < 1e-3f);
}

TEST_CASE("instance buffers grow geometrically and keep their storage once warm") {
	InstanceBuffer buffer;
	for (int i = 0; i < 1000; ++i) {
		buffer.push()[0] = float(i);
	}
	CHECK(buffer.get_count() == 1000);
	const float *data = buffer.get_data();
	const uint32_t capacity = buffer.get_capacity();
	for (int frame = 0; frame < 10; ++frame) {
		buffer.clear();
		for (int i = 0; i < 1000; ++i) {
			buffer.push()[0] = float(i);
		}
	}
	CHECK(buffer.get_data() == data);
	CHECK(buffer.get_capacity() == capacity);
	CHECK(buffer.get_data()[999 * FLOATS_PER_INSTANCE] == 999.0f);
}
