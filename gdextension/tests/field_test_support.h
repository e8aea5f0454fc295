#pragma once
// What the simulation's core tests share: small maps, loading, reading buckets back, and the count of
// what the engine draws (every plant exactly once).
#include "field_simulation.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

namespace sunflower_test {

using namespace sunflower;


inline std::string rect_map(int p_columns, int p_rows) {
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	for (int r = 0; r < p_rows; ++r) {
		text += std::string(static_cast<size_t>(p_columns), '*') + "\n";
	}
	return text;
}

inline void load(FieldSimulation &r_sim, const std::string &p_text, float p_chunk = 8.0f) {
	MapError error;
	REQUIRE(r_sim.load_map(p_text, U"", "sim", MapLimits{}, error));
	LayoutParams params;
	params.chunk_size = p_chunk;
	r_sim.set_layout_params(params);
}

// Where instance p_index of a bucket stands, and its share of the pixels (the colour's alpha; the
// impostors' compact records hold it in place of a cell).
struct Placed {
	glm::vec3 root{ 0.0f };
	float share = 1.0f;
};
inline Placed placed(const InstanceBuffer &p_bucket, uint32_t p_index) {
	const float *instance = p_bucket.get_data() + size_t(p_index) * p_bucket.get_stride();
	if (p_bucket.get_stride() == FAR_FLOATS_PER_INSTANCE) {
		return { read_far_instance(instance).root, instance[FAR_CELL_OR_SHARE] };
	}
	return { glm::vec3(instance[3], instance[7], instance[11]), instance[15] };
}

inline int64_t total(const std::array<int64_t, LOD_COUNT> &p_counts) {
	return std::accumulate(p_counts.begin(), p_counts.end(), int64_t(0));
}

// Whether the engine draws far tile p_tile seen from p_camera: its node is shown (it has a plant
// to draw), the camera's distance to its box centre is within its range, and no tile above it is
// (each tile's node has its parent's as visibility parent: a node is drawn only where its parent's
// range has not begun).
inline bool tile_drawn_from(const FieldSimulation &p_sim, uint32_t p_tile, const glm::vec3 &p_camera) {
	const auto shown_from = [&](uint32_t p_t) {
		return glm::distance(p_camera, p_sim.tiles().get_tile_bounds(p_t).center()) >= p_sim.tiles().get_tile_shown_from(p_t);
	};
	if (!p_sim.is_tile_drawn(p_tile) || !shown_from(p_tile)) {
		return false;
	}
	for (uint32_t above = p_sim.tiles().get_tile(p_tile).parent; above != FarTiles::NO_TILE; above = p_sim.tiles().get_tile(above).parent) {
		if (shown_from(above)) {
			return false;
		}
	}
	return true;
}

// Plants drawn by the dynamic buckets plus the records of the tiles drawn from the observer that
// the impostor shader keeps (those whose chunk cell the active mask leaves 0): with no frustum,
// every plant must be drawn exactly once, or, in a cross-fade, twice with complementary shares that
// add up to one: mesh 3 and its impostor (the instance colours' alpha, the patterns each level's
// shader keeps), or, drawn whole, two adjacent mesh levels (the finer with a positive alpha, the
// coarser with a negative one: the other pixels); or, where its distance gives it to a merged
// level that leaves it out, not at all (counted as drawn once: the merged tile stands in for it). A
// far tile the engine draws draws each plant it holds at the level the observer's distance gives
// the plant (choose_tile_level, the impostor shader's rule), never below its own, if that level
// keeps it (one it leaves out while fading to the next level counts as drawn). Returns the plants
// drawn or stood in for; r_thinned (if given) gets those stood in for, r_fading those fading out.
inline int64_t drawn(const FieldSimulation &p_sim, int64_t *r_thinned = nullptr, int64_t *r_fading = nullptr) {
	struct Drawn {
		float share = 0.0f;
		int representations = 0;
		int finest = -1; // the finest level drawn (3: impostor)
		int levels = 0; // bits: the levels drawn
		bool complement = false; // a level drew the other pixels (negative alpha)
	};
	std::map<std::pair<float, float>, Drawn> plants; // by root (x, z)
	auto add = [&](const InstanceBuffer &p_bucket, int p_level) {
		for (uint32_t i = 0; i < p_bucket.get_count(); ++i) {
			const Placed instance = placed(p_bucket, i);
			Drawn &plant = plants[{ instance.root.x, instance.root.z }];
			plant.share += std::abs(instance.share);
			plant.representations += 1;
			plant.levels |= 1 << p_level;
			plant.complement = plant.complement || instance.share < 0.0f;
			if (p_level == 0) { // nothing fades into mesh 1
				CHECK(instance.share > 0.0f);
			}
		}
	};
	for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
		// Part by part, the three parts of a plant in their buckets; drawn whole, one instance.
		const bool whole = p_sim.plants().get_shape().whole;
		const uint32_t bottom = p_sim.near().get_bucket(mesh_bucket(level, 0)).get_count();
		CHECK(p_sim.near().get_bucket(mesh_bucket(level, 0)).get_stride() == (whole ? WHOLE_FLOATS_PER_INSTANCE : FLOATS_PER_INSTANCE));
		CHECK(p_sim.near().get_bucket(mesh_bucket(level, 1)).get_count() == (whole ? 0 : bottom));
		CHECK(p_sim.near().get_bucket(mesh_bucket(level, 2)).get_count() == (whole ? 0 : bottom));
		add(p_sim.near().get_bucket(mesh_bucket(level, 0)), int(level));
	}
	add(p_sim.near().get_bucket(BUCKET_IMPOSTOR), LOD_SPRITE);
	const FieldLayout &layout = p_sim.plants().get_layout();
	std::vector<uint8_t> mask(size_t(layout.grid_x) * size_t(layout.grid_z));
	p_sim.near().write_active_mask(0, mask.data());
	int64_t thinned = 0;
	int64_t fading = 0;
	const glm::vec3 observer = p_sim.near().get_observer();
	for (uint32_t t = 0; t < p_sim.tiles().get_tile_count(); ++t) {
		const FarTiles::Tile &tile = p_sim.tiles().get_tile(t);
		if (!tile_drawn_from(p_sim, t, observer)) {
			continue;
		}
		// The engine draws the first get_tile_visible_count records; the others must be ones the
		// shader would leave out.
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		p_sim.tiles().write_tile_instances(t, records.data());
		REQUIRE(p_sim.tiles().get_tile_visible_count(t) <= tile.plants);
		for (size_t k = 0; k < p_sim.tiles().get_tile_visible_count(t); ++k) {
			const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
			REQUIRE(record.cell < mask.size());
			const FarTiles::TileChoice choice = p_sim.tiles().choose_tile_level(glm::distance(observer, record.root));
			const uint32_t plant_level = tile.level + record.levels_above;
			if (mask[record.cell] != 0) {
				continue;
			}
			CAPTURE(t);
			CHECK(choice.level >= tile.level); // else the shader leaves it out: its level's tile is not drawn
			if (choice.level < tile.level || plant_level < choice.level) {
				continue;
			}
			fading += choice.fade > 0.0f && plant_level == choice.level ? 1 : 0;
			Drawn &plant = plants[{ record.root.x, record.root.z }];
			plant.share += 1.0f;
			plant.representations += 1;
			plant.levels |= 1 << LOD_SPRITE;
		}
	}
	// The plants of static chunks their distance gives to a level that leaves them out: no other
	// representation may draw them.
	for (uint32_t c = 0; c < layout.chunks.size(); ++c) {
		const Chunk &chunk = layout.chunks[c];
		for (uint32_t i = 0; i < chunk.count && !p_sim.near().is_chunk_active(c); ++i) {
			const Plant &left_out = layout.plants[layout.chunk_plants[chunk.first + i]];
			if (p_sim.tiles().plant_tile_level(left_out) < p_sim.tiles().choose_tile_level(glm::distance(observer, left_out.root())).level) {
				Drawn &plant = plants[{ left_out.position.x, left_out.position.y }];
				plant.share += 1.0f;
				plant.representations += 1;
				++thinned;
			}
		}
	}
	if (r_fading) {
		*r_fading = fading;
	}
	if (r_thinned) {
		*r_thinned = thinned;
	}
	const bool whole = p_sim.plants().get_shape().whole;
	for (const auto &[root, plant] : plants) {
		CHECK(plant.share == doctest::Approx(1.0f).epsilon(1e-5));
		CHECK(plant.representations <= 2);
		if (plant.representations == 2) {
			// The pairs: mesh 3 and its impostor; drawn whole, also mesh 1 and 2, or 2 and 3, the coarser
			// drawing the other pixels.
			const bool impostor_pair = plant.levels == ((1 << LOD_MESH_3) | (1 << LOD_SPRITE)) && !plant.complement;
			const bool mesh_pair = whole && plant.complement &&
					(plant.levels == ((1 << LOD_MESH_1) | (1 << LOD_MESH_2)) || plant.levels == ((1 << LOD_MESH_2) | (1 << LOD_MESH_3)));
			CHECK((impostor_pair || mesh_pair));
		} else {
			CHECK(!plant.complement);
		}
	}
	return int64_t(plants.size());
}

} // namespace sunflower_test
