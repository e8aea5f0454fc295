#include "frustum.h"
#include "instance_buffer.h"
#include "lod_selector.h"

#include <doctest/doctest.h>

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
