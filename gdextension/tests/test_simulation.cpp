#include "field_simulation.h"

#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <map>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <numeric>

using namespace sunflower;

namespace {

std::string rect_map(int p_columns, int p_rows) {
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	for (int r = 0; r < p_rows; ++r) {
		text += std::string(static_cast<size_t>(p_columns), '*') + "\n";
	}
	return text;
}

void load(FieldSimulation &r_sim, const std::string &p_text, float p_chunk = 8.0f) {
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
Placed placed(const InstanceBuffer &p_bucket, uint32_t p_index) {
	const float *instance = p_bucket.get_data() + size_t(p_index) * p_bucket.get_stride();
	if (p_bucket.get_stride() == FAR_FLOATS_PER_INSTANCE) {
		return { read_far_instance(instance).root, instance[FAR_CELL_OR_SHARE] };
	}
	return { glm::vec3(instance[3], instance[7], instance[11]), instance[15] };
}

int64_t total(const std::array<int64_t, LOD_COUNT> &p_counts) {
	return std::accumulate(p_counts.begin(), p_counts.end(), int64_t(0));
}

// Whether the engine draws far tile p_tile seen from p_camera: its node is shown (it has a plant
// to draw), the camera's distance to its box centre is within its range, and no tile above it is
// (each tile's node has its parent's as visibility parent: a node is drawn only where its parent's
// range has not begun).
bool tile_drawn_from(const FieldSimulation &p_sim, uint32_t p_tile, const glm::vec3 &p_camera) {
	const auto shown_from = [&](uint32_t p_t) {
		return glm::distance(p_camera, p_sim.get_tile_bounds(p_t).center()) >= p_sim.get_tile_shown_from(p_t);
	};
	if (!p_sim.is_tile_drawn(p_tile) || !shown_from(p_tile)) {
		return false;
	}
	for (uint32_t above = p_sim.get_tile(p_tile).parent; above != FieldSimulation::NO_TILE; above = p_sim.get_tile(above).parent) {
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
int64_t drawn(const FieldSimulation &p_sim, int64_t *r_thinned = nullptr, int64_t *r_fading = nullptr) {
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
		const bool whole = p_sim.get_shape().whole;
		const uint32_t bottom = p_sim.get_bucket(mesh_bucket(level, 0)).get_count();
		CHECK(p_sim.get_bucket(mesh_bucket(level, 0)).get_stride() == (whole ? WHOLE_FLOATS_PER_INSTANCE : FLOATS_PER_INSTANCE));
		CHECK(p_sim.get_bucket(mesh_bucket(level, 1)).get_count() == (whole ? 0 : bottom));
		CHECK(p_sim.get_bucket(mesh_bucket(level, 2)).get_count() == (whole ? 0 : bottom));
		add(p_sim.get_bucket(mesh_bucket(level, 0)), int(level));
	}
	add(p_sim.get_bucket(BUCKET_IMPOSTOR), LOD_SPRITE);
	const FieldLayout &layout = p_sim.get_layout();
	std::vector<uint8_t> mask(size_t(layout.grid_x) * size_t(layout.grid_z));
	p_sim.write_active_mask(0, mask.data());
	int64_t thinned = 0;
	int64_t fading = 0;
	const glm::vec3 observer = p_sim.get_observer();
	for (uint32_t t = 0; t < p_sim.get_tile_count(); ++t) {
		const FieldSimulation::Tile &tile = p_sim.get_tile(t);
		if (!tile_drawn_from(p_sim, t, observer)) {
			continue;
		}
		// The engine draws the first get_tile_visible_count records; the others must be ones the
		// shader would leave out.
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		p_sim.write_tile_instances(t, records.data());
		REQUIRE(p_sim.get_tile_visible_count(t) <= tile.plants);
		for (size_t k = 0; k < p_sim.get_tile_visible_count(t); ++k) {
			const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
			REQUIRE(record.cell < mask.size());
			const FieldSimulation::TileChoice choice = p_sim.choose_tile_level(glm::distance(observer, record.root));
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
		for (uint32_t i = 0; i < chunk.count && !p_sim.is_chunk_active(c); ++i) {
			const Plant &left_out = layout.plants[layout.chunk_plants[chunk.first + i]];
			if (p_sim.plant_tile_level(left_out) < p_sim.choose_tile_level(glm::distance(observer, left_out.root())).level) {
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
	const bool whole = p_sim.get_shape().whole;
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

} // namespace

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
		sim.set_observer({ x, 1.7f, 30.0f });
		sim.request_lod_update();
		sim.update(0.016f);
		CAPTURE(x);
		CHECK(drawn(sim) == 24000);
		const auto counts = sim.get_lod_counts();
		CHECK(total(counts) == 24000);
		// With no frustum, part by part, the mesh buckets hold exactly the plants counted at mesh levels
		// (mesh 3 but those wholly faded into their impostors). Drawn whole, plants fading into the
		// next level are in its bucket too.
		for (uint32_t level = 0; level < LOD_MESH_3 && !sim.get_shape().whole; ++level) {
			CHECK(sim.get_bucket(mesh_bucket(level, 0)).get_count() == counts[level]);
		}
		CHECK(sim.get_bucket(mesh_bucket(LOD_MESH_3, 0)).get_count() <= counts[LOD_MESH_3] + counts[LOD_MESH_2]);
	}
	sim.set_observer({ 50.0f, 1.7f, 30.0f });
	sim.request_lod_update();
	sim.update(0.016f);
	auto counts = sim.get_lod_counts();
	// Plants within 6 m of the observer on a 4-per-m² field: about π·6²·4 ≈ 450.
	CHECK(counts[LOD_MESH_1] > 350);
	CHECK(counts[LOD_MESH_1] < 550);
	CHECK(counts[LOD_BILLBOARD] > 15000);
	sim.set_observer({ 1000.0f, 1.7f, 1000.0f });
	sim.request_lod_update();
	sim.update(0.016f);
	counts = sim.get_lod_counts();
	CHECK(counts[LOD_BILLBOARD] == 24000);
	CHECK(sim.get_bucket(mesh_bucket(0, 0)).get_count() == 0);
}

TEST_CASE("far tiles: every chunk in one tile of its species, at most TILE_CHUNKS × TILE_CHUNKS cells; records carry their chunk's cell") {
	FieldSimulation sim;
	MapError error;
	std::string text = "90 70\n";
	for (int r = 0; r < 70; ++r) {
		std::string row;
		for (int c = 0; c < 90; ++c) {
			row += (c / 7 + r / 5) % 3 == 0 ? 'm' : '*';
		}
		text += row + "\n";
	}
	REQUIRE(sim.load_map(text, U"m", U"m", "tiles", MapLimits{}, error));
	LayoutParams params;
	params.chunk_size = 4.0f; // 45 × 35 m: 12 × 9 chunk cells
	sim.set_layout_params(params);
	const FieldLayout &layout = sim.get_layout();
	REQUIRE(layout.grid_x == 12);
	std::vector<int> tile_of(sim.get_chunk_count(), -1);
	uint32_t plants = 0;
	for (uint32_t t = 0; t < sim.get_tile_count(); ++t) {
		const FieldSimulation::Tile &tile = sim.get_tile(t);
		if (tile.level > 0) {
			continue; // merged tiles: see the next test
		}
		plants += tile.plants;
		uint32_t in_chunks = 0;
		int x0 = 1 << 30, x1 = -1, z0 = 1 << 30, z1 = -1;
		for (uint32_t k = 0; k < tile.count; ++k) {
			const uint32_t chunk = sim.get_tile_chunk(t, k);
			CHECK(tile_of[chunk] == -1);
			tile_of[chunk] = int(t);
			CHECK(layout.chunks[chunk].species == tile.species);
			in_chunks += layout.chunks[chunk].count;
			const int x = int(sim.get_chunk_cell(chunk)) % layout.grid_x;
			const int z = int(sim.get_chunk_cell(chunk)) / layout.grid_x;
			x0 = std::min(x0, x), x1 = std::max(x1, x), z0 = std::min(z0, z), z1 = std::max(z1, z);
		}
		CHECK(in_chunks == tile.plants);
		CHECK(x0 / FieldSimulation::TILE_CHUNKS == x1 / FieldSimulation::TILE_CHUNKS); // one square of cells
		CHECK(z0 / FieldSimulation::TILE_CHUNKS == z1 / FieldSimulation::TILE_CHUNKS);
		// The records are the tile's chunks' plants (highest tile level first), each with its chunk's
		// cell and within its bounds.
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		sim.write_tile_instances(t, records.data());
		const ChunkBounds bounds = sim.get_tile_bounds(t);
		std::map<std::pair<float, float>, uint32_t> cells; // by root (x, z)
		for (uint32_t c = 0; c < tile.count; ++c) {
			const uint32_t chunk = sim.get_tile_chunk(t, c);
			for (uint32_t p = 0; p < layout.chunks[chunk].count; ++p) {
				const Plant &plant = layout.plants[layout.chunk_plants[layout.chunks[chunk].first + p]];
				cells[{ plant.root().x, plant.root().z }] = sim.get_chunk_cell(chunk);
			}
		}
		uint32_t previous_level = FieldSimulation::MAX_TILE_LEVELS;
		for (size_t k = 0; k < tile.plants; ++k) {
			const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
			const auto cell = cells.find({ record.root.x, record.root.z });
			REQUIRE(cell != cells.end());
			CHECK(record.cell == cell->second);
			cells.erase(cell);
			CHECK(record.levels_above <= previous_level);
			previous_level = record.levels_above;
			CHECK(glm::all(glm::lessThanEqual(bounds.min, record.root)));
			CHECK(glm::all(glm::lessThanEqual(record.root, bounds.max)));
		}
		CHECK(cells.empty());
	}
	CHECK(plants == sim.get_plant_count());
	CHECK(std::count(tile_of.begin(), tile_of.end(), -1) == 0);
	CHECK(sim.get_tile_count() < sim.get_chunk_count() / 4); // merged: 12 × 9 cells make 2 × 2 tiles per species
	// The mask marks exactly the active chunks' cells, per species, and its version moves with them.
	const uint32_t version = sim.get_mask_version();
	sim.set_observer({ 20.0f, 1.7f, 15.0f });
	for (int frame = 0; frame < 30; ++frame) { // the activation budget spreads a jump over updates
		sim.update(0.016f);
	}
	CHECK(sim.get_mask_version() != version);
	for (uint32_t species = 0; species < 2; ++species) {
		std::vector<uint8_t> mask(size_t(layout.grid_x) * size_t(layout.grid_z));
		sim.write_active_mask(species, mask.data());
		for (uint32_t c = 0; c < sim.get_chunk_count(); ++c) {
			if (layout.chunks[c].species == species) {
				CHECK((mask[sim.get_chunk_cell(c)] != 0) == sim.is_chunk_active(c));
			}
		}
	}
	uint32_t hidden = 0;
	for (uint32_t t = 0; t < sim.get_tile_count(); ++t) {
		bool some_static = false;
		for (uint32_t k = 0; k < sim.get_tile(t).count; ++k) {
			some_static = some_static || !sim.is_chunk_active(sim.get_tile_chunk(t, k));
		}
		CHECK(sim.is_tile_drawn(t) == some_static);
		hidden += sim.is_tile_drawn(t) ? 0 : 1;
	}
	CHECK(hidden > 0); // the tiles around the observer are all near: nothing left for them to draw
	const uint32_t settled = sim.get_mask_version();
	sim.update(0.016f);
	CHECK(sim.get_mask_version() == settled); // nothing turned
}

TEST_CASE("far tiles merge with distance: nested quarters, parents covering their children, one level drawn at each place") {
	FieldSimulation sim;
	load(sim, rect_map(240, 240), 2.0f); // 120 m square, 57 600 plants; 60 × 60 chunk cells, 8 × 8 tiles
	const uint32_t plant_count = sim.get_plant_count();
	LayoutParams params = sim.get_layout_params();
	params.tile_merge_distance = 10.0f;
	sim.set_layout_params(params);
	LodParams near;
	near.distances = { 1.0f, 2.0f, 3.0f, 4.0f }; // few active chunks: the tiles draw nearly every plant
	sim.set_lod(near);
	const FieldLayout &layout = sim.get_layout();
	REQUIRE(layout.grid_x == 60);
	std::array<uint32_t, FieldSimulation::MAX_TILE_LEVELS> tiles_at{};
	std::array<uint32_t, FieldSimulation::MAX_TILE_LEVELS> plants_at{};
	uint32_t top = 0;
	std::map<std::pair<float, float>, uint32_t> levels; // each plant's level, by where it stands
	for (const Plant &plant : layout.plants) {
		levels[{ plant.position.x, plant.position.y }] = sim.plant_tile_level(plant);
	}
	for (uint32_t t = 0; t < sim.get_tile_count(); ++t) {
		const FieldSimulation::Tile &tile = sim.get_tile(t);
		CAPTURE(t);
		++tiles_at[tile.level];
		plants_at[tile.level] += tile.plants;
		top = std::max(top, tile.level);
		CHECK((tile.key >> 56) == uint64_t(tile.level));
		CHECK((t == 0 || sim.get_tile(t - 1).level <= tile.level)); // level by level
		CHECK(sim.get_tile_begin(t) == (tile.level == 0 ? 0.0f : 10.0f * float(1u << (tile.level - 1))));
		// Shown from where its farthest corner from the camera is at its level's distance at least.
		const ChunkBounds bounds = sim.get_tile_bounds(t);
		CHECK(sim.get_tile_shown_from(t) ==
				doctest::Approx(tile.level == 0 ? 0.0f : sim.get_tile_begin(t) + 0.5f * glm::length(bounds.max - bounds.min)));
		// Its records tell the levels above its own that keep each plant too.
		{
			std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
			sim.write_tile_instances(t, records.data());
			uint32_t above = 0;
			for (size_t k = 0; k < tile.plants; ++k) {
				const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
				const uint32_t level = levels[{ record.root.x, record.root.z }];
				CHECK(record.levels_above == level - tile.level);
				above += record.levels_above > 0 ? 1 : 0;
			}
			CHECK(above < tile.plants);
		}
		if (!tile.is_top()) {
			CHECK(sim.get_tile(tile.parent).level == tile.level + 1);
			CHECK(sim.get_tile(tile.parent).species == tile.species);
		}
		if (tile.level == 0) {
			continue;
		}
		// Its chunks are its children's, and its records exactly their plants kept at its level.
		std::vector<uint32_t> chunks;
		for (uint32_t child = 0; child < sim.get_tile_count(); ++child) {
			for (uint32_t k = 0; k < sim.get_tile(child).count && sim.get_tile(child).parent == t; ++k) {
				chunks.push_back(sim.get_tile_chunk(child, k));
			}
		}
		std::vector<uint32_t> own;
		for (uint32_t k = 0; k < tile.count; ++k) {
			own.push_back(sim.get_tile_chunk(t, k));
		}
		std::sort(chunks.begin(), chunks.end());
		std::sort(own.begin(), own.end());
		CHECK(own == chunks);
		std::vector<std::pair<float, float>> kept;
		for (uint32_t chunk : own) {
			for (uint32_t k = 0; k < layout.chunks[chunk].count; ++k) {
				const Plant &plant = layout.plants[layout.chunk_plants[layout.chunks[chunk].first + k]];
				if (sim.plant_tile_level(plant) >= tile.level) {
					kept.emplace_back(plant.position.x, plant.position.y);
				}
			}
		}
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		sim.write_tile_instances(t, records.data());
		std::vector<std::pair<float, float>> held;
		for (size_t k = 0; k < tile.plants; ++k) {
			const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
			held.emplace_back(record.root.x, record.root.z);
			CHECK(std::find(own.begin(), own.end(), layout.grid_chunks[record.cell]) != own.end());
		}
		std::sort(kept.begin(), kept.end());
		std::sort(held.begin(), held.end());
		CHECK(held == kept);
	}
	// 8 × 8 tiles, then 4 × 4, 2 × 2 and one; each level a quarter of the one below.
	static_assert(FieldSimulation::TILE_CHUNKS == 8);
	CHECK(top == 3);
	CHECK(tiles_at[0] == 64);
	CHECK(tiles_at[1] == 16);
	CHECK(tiles_at[3] == 1);
	CHECK(plants_at[0] == plant_count);
	for (uint32_t level = 1; level <= top; ++level) {
		const double p = FieldSimulation::tile_density(level);
		const double sd = std::sqrt(plant_count * p * (1.0 - p));
		CAPTURE(level);
		CHECK(std::abs(double(plants_at[level]) - plant_count * p) < 5.0 * sd);
	}
	// Every place drawn by one level: from inside, from the edge, from far and from high above, every
	// plant is drawn once or stood in for by the merged tile drawn there; the farther, the fewer drawn.
	int64_t previous_thinned = -1;
	int64_t faded = 0;
	int64_t records_left = 0; // records of drawn tiles past their visible count
	for (const glm::vec3 &camera : { glm::vec3(60.0f, 1.7f, 60.0f), glm::vec3(-10.0f, 1.7f, 60.0f),
				 glm::vec3(-80.0f, 1.7f, 60.0f), glm::vec3(-250.0f, 1.7f, 60.0f) }) {
		CAPTURE(camera.x);
		sim.set_observer(camera);
		for (int frame = 0; frame < 40; ++frame) { // the activation budget spreads a jump over updates
			sim.update(0.016f);
		}
		int64_t thinned = 0;
		int64_t fading = 0;
		CHECK(drawn(sim, &thinned, &fading) == plant_count);
		faded += fading;
		CHECK(thinned >= previous_thinned);
		CHECK((camera.x < -200.0f || thinned > previous_thinned)); // from 80 m on, all at the top level
		previous_thinned = thinned;
		// A cut through the tree of tiles: the level-0 squares of the tiles drawn add up to at most
		// the 64 of the field (each place drawn by one tile), and from afar a few large tiles draw it.
		uint32_t tiles_drawn = 0;
		uint32_t squares = 0;
		for (uint32_t t = 0; t < sim.get_tile_count(); ++t) {
			if (tile_drawn_from(sim, t, camera)) {
				++tiles_drawn;
				squares += 1u << (2u * sim.get_tile(t).level);
				records_left += sim.get_tile(t).plants - sim.get_tile_visible_count(t);
			}
		}
		CHECK(squares <= 64);
		CHECK(tiles_drawn <= (camera.x < -200.0f ? 1u : 64u));
	}
	// Along a line across the field and out: each tile holding a plant its distance gives to the
	// tile's level is drawn by the engine (checked in drawn()).
	for (float x = -47.0f; x < 170.0f; x += 13.0f) {
		CAPTURE(x);
		sim.set_observer(glm::vec3(x, 1.7f, 41.0f));
		for (int frame = 0; frame < 40; ++frame) {
			sim.update(0.016f);
		}
		CHECK(drawn(sim) == plant_count);
	}
	CHECK(double(previous_thinned) > 0.9 * plant_count); // from 250 m away, level 3 stands in
	CHECK(faded > 0); // plants the next level leaves out, fading out one by one
	CHECK(records_left > 0); // tiles whose plants are all beyond a merge distance draw fewer records
	// Without merging: the level-0 tiles alone.
	params.tile_merge_distance = 0.0f;
	sim.set_layout_params(params);
	CHECK(sim.get_tile_count() == 64);
	CHECK(drawn(sim) == plant_count);
}

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
	const FieldLayout &layout = sim.get_layout();
	CHECK(int64_t(layout.grid_x) * layout.grid_z <= FieldLayout::MAX_CHUNK_CELLS);
	CHECK(layout.chunk_size == 2.0f); // 1 000 × 20 cells
	CHECK(sim.get_plant_count() == 40);
}

TEST_CASE("a plant's own LOD matches its distance outside the hysteresis bands") {
	FieldSimulation sim;
	load(sim, rect_map(80, 80));
	const glm::vec3 observer(20.0f, 1.0f, 20.0f);
	sim.set_observer(observer);
	sim.request_lod_update();
	for (int i = 0; i < 10; ++i) { // chunks turn active over a few updates (ACTIVATION_BUDGET)
		sim.update(0.016f);
	}
	LodSelector plain;
	plain.configure(sim.get_lod().get_params());
	const float margin = sim.get_lod().get_params().hysteresis;
	for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
		const Plant &plant = sim.get_layout().plants[i];
		const glm::vec3 middle(plant.position.x, 0.5f * sim.get_shape().height * sim.get_shape().part_scale, plant.position.y);
		const float distance = glm::length(observer - middle);
		bool near_threshold = false;
		for (float d : sim.get_lod().get_params().distances) {
			near_threshold |= std::abs(distance - d) < margin;
		}
		if (!near_threshold && distance < 20.0f) {
			CHECK(sim.get_plant_lod(i) == plain.select(distance * distance));
		}
	}
}

TEST_CASE("LOD is re-selected every interval, not every frame") {
	FieldSimulation sim;
	load(sim, rect_map(40, 30));
	sim.set_observer({ 10.0f, 1.7f, 7.5f });
	sim.update(0.016f);
	const auto near_counts = sim.get_lod_counts();
	CHECK(near_counts[LOD_MESH_1] > 0);
	sim.set_observer({ 10.0f, 1.7f, 11.0f }); // a step (not a jump: under JUMP_DISTANCE)
	sim.update(0.1f);
	CHECK(sim.get_lod_counts()[LOD_MESH_1] == near_counts[LOD_MESH_1]);
	sim.update(0.2f); // 0.3 s since the last selection
	CHECK(sim.get_lod_counts()[LOD_MESH_1] != near_counts[LOD_MESH_1]);
}

TEST_CASE("the frustum culls what is written, not what is counted") {
	FieldSimulation sim;
	load(sim, rect_map(40, 40));
	sim.set_observer({ 10.0f, 1.7f, 10.0f });
	sim.update(0.016f);
	const uint32_t all = sim.get_bucket(mesh_bucket(0, 0)).get_count();
	const auto counts = sim.get_lod_counts();
	// Keep only x > 10 (an outward plane with normal −x at x = 10).
	const glm::vec4 plane(-1.0f, 0.0f, 0.0f, -10.0f);
	sim.get_frustum().set_planes(&plane, 1);
	sim.update(0.016f);
	const uint32_t half = sim.get_bucket(mesh_bucket(0, 0)).get_count();
	CHECK(half < all);
	CHECK(half > all / 3);
	CHECK(sim.get_lod_counts() == counts);
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
		field->set_wind(wind);
		field->set_lod(lod);
		field->set_observer(eye);
	}
	sim.get_frustum().set_planes(&plane, 1);
	for (int frame = 0; frame < 600; ++frame) { // 20 s: the plants' b redraws come round
		sim.update(1.0f / 30.0f);
		unculled.update(1.0f / 30.0f);
	}
	// The plants that spent the 20 s out of view sway as they would have in view.
	uint32_t compared = 0;
	for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
		if (sim.get_layout().plants[i].position.x < 8.0f && sim.get_plant_lod(i) < LOD_SPRITE) {
			PartTransforms culled, seen;
			sim.get_plant_parts(i, culled);
			unculled.get_plant_parts(i, seen);
			CHECK(culled.origin[2] == seen.origin[2]);
			++compared;
		}
	}
	CHECK(compared > 100);
	// What each plant's own test keeps, bucket by bucket, for planes that cut the chunks' boxes: across
	// the field (at a chunk's edge, within its plants' reach), and level, through the middle of the
	// culling spheres' bottoms and of their tops (plants differ in size).
	const PlantShape &shape = sim.get_shape();
	std::vector<float> bottoms, tops;
	for (const Plant &plant : sim.get_layout().plants) {
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
		sim.get_frustum().set_planes(&cut, 1);
		sim.update(0.001f);
		std::array<uint32_t, BUCKET_COUNT> expected{};
		uint32_t out_of_view = 0;
		for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
			const Plant &plant = sim.get_layout().plants[i];
			if (!sim.is_chunk_active(plant.chunk)) {
				continue;
			}
			const float scale = shape.part_scale * plant.scale;
			const glm::vec3 middle = plant.root() + glm::vec3(0.0f, 0.5f * shape.height * scale, 0.0f);
			if (!sim.get_frustum().intersects_sphere(middle, shape.cull_radius * scale)) {
				++out_of_view;
				continue;
			}
			const uint8_t level = sim.get_plant_lod(i);
			++expected[level >= LOD_SPRITE ? BUCKET_IMPOSTOR : mesh_bucket(level, 0)];
		}
		CHECK(out_of_view > sim.get_plant_count() / 8);
		CHECK(std::accumulate(expected.begin(), expected.end(), 0u) > sim.get_plant_count() / 8);
		for (uint32_t b : { mesh_bucket(LOD_MESH_1, 0), mesh_bucket(LOD_MESH_2, 0), mesh_bucket(LOD_MESH_3, 0), BUCKET_IMPOSTOR }) {
			CHECK(sim.get_bucket(b).get_count() == expected[b]);
		}
	}
}

TEST_CASE("a bucket's box holds its plants, as near as they are, and empties with them") {
	FieldSimulation sim;
	load(sim, rect_map(200, 200)); // 100 × 100 m
	const glm::vec3 eye{ 50.0f, 1.7f, 50.0f };
	sim.set_observer(eye);
	sim.update(0.016f);
	const float radius = PlantShape::CULL_RADIUS * PlantShape{}.part_scale * 1.5f; // the largest plant's
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		const InstanceBuffer &bucket = sim.get_bucket(b);
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
	const InstanceBuffer &nearest = sim.get_bucket(mesh_bucket(LOD_MESH_1, 0));
	const float reach = lod.distances[0] + lod.hysteresis + radius;
	CHECK(glm::all(glm::greaterThanEqual(nearest.get_bounds_low(), eye - glm::vec3(reach, 2.0f, reach))));
	CHECK(glm::all(glm::lessThanEqual(nearest.get_bounds_high(), eye + glm::vec3(reach, 2.0f * radius + 4.0f, reach))));
	// Nothing in view: every box is empty.
	const glm::vec4 plane(0.0f, -1.0f, 0.0f, -1000.0f); // keeps only y > 1 000 m
	sim.get_frustum().set_planes(&plane, 1);
	sim.update(0.016f);
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		CHECK(sim.get_bucket(b).get_count() == 0);
		CHECK(sim.get_bucket(b).get_bounds_low().x > sim.get_bucket(b).get_bounds_high().x);
	}
}

TEST_CASE("with wind the transforms change over time; without it the plants stay upright") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20));
	sim.set_observer({ 5.0f, 1.7f, 5.0f });
	WindParams calm;
	calm.power = 0.0f;
	sim.set_wind(calm);
	sim.update(0.016f);
	PartTransforms before, after;
	sim.get_plant_parts(0, before);
	for (int i = 0; i < 30; ++i) {
		sim.update(0.016f);
	}
	sim.get_plant_parts(0, after);
	for (int part = 0; part < 3; ++part) {
		CHECK(after.origin[part] == before.origin[part]);
		const glm::vec3 up = glm::normalize(after.basis[part][1]);
		CHECK(up.y == doctest::Approx(1.0f));
	}
	const float *data = sim.get_bucket(mesh_bucket(0, 2)).get_data();
	const std::vector<float> calm_heads(data, data + 12);

	WindParams windy;
	windy.power = 3.0f;
	sim.set_wind(windy);
	sim.update(0.016f);
	sim.get_plant_parts(0, before);
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	sim.get_plant_parts(0, after);
	CHECK(glm::length(after.origin[2] - before.origin[2]) > 1e-4f);
	const glm::vec3 up = glm::normalize(after.basis[1][1]);
	CHECK(up.y < 0.99999f);
	data = sim.get_bucket(mesh_bucket(0, 2)).get_data();
	CHECK(std::vector<float>(data, data + 12) != calm_heads);
}

TEST_CASE("steady state allocates nothing: buffers keep their storage along a repeated path") {
	FieldSimulation sim;
	load(sim, rect_map(100, 100));
	const auto walk = [&]() {
		for (float x = 0.0f; x < 50.0f; x += 0.5f) {
			sim.set_observer({ x, 1.7f, 25.0f });
			sim.update(0.05f);
		}
	};
	walk();
	std::array<const float *, BUCKET_COUNT> data{};
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		data[b] = sim.get_bucket(b).get_data();
	}
	walk();
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		CHECK(sim.get_bucket(b).get_data() == data[b]);
	}
}

TEST_CASE("a failed load keeps the previous field") {
	FieldSimulation sim;
	load(sim, rect_map(10, 10));
	MapError error;
	CHECK_FALSE(sim.load_map("10 10\n**x\n", U"", "bad.field", MapLimits{}, error));
	CHECK(error.to_string() == "bad.field:2:3: unexpected 'x'; expected '*' (a sunflower), ' ' or '.' (nothing), or a symbol the field's legend maps");
	CHECK(sim.get_plant_count() == 100);
}

TEST_CASE("static chunks choose sprite or billboard by the distance to their box centre") {
	FieldSimulation sim;
	load(sim, rect_map(400, 20), 8.0f); // a 200 m strip
	sim.set_observer({ 0.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	for (uint32_t c = 0; c < sim.get_chunk_count(); ++c) {
		if (sim.is_chunk_active(c)) {
			continue;
		}
		const float distance = glm::length(sim.get_observer() - sim.get_chunk_bounds(c).center());
		const uint32_t plant = sim.get_layout().chunk_plants[sim.get_layout().chunks[c].first];
		CHECK(sim.get_plant_lod(plant) == (distance <= 25.0f ? LOD_SPRITE : LOD_BILLBOARD));
	}
}

TEST_CASE("a forced representation draws every plant in it, and memory per plant stays small") {
	FieldSimulation sim;
	load(sim, rect_map(100, 60)); // 6 000 plants
	LodParams params;
	params.force_level = LOD_MESH_2;
	sim.set_lod(params);
	sim.set_observer({ 1000.0f, 1.7f, 1000.0f }); // far away: normally all billboards
	sim.update(0.016f);
	CHECK(sim.get_lod_counts()[LOD_MESH_2] == 6000);
	CHECK(sim.get_bucket(mesh_bucket(1, 0)).get_count() == 6000);
	CHECK(drawn(sim) == 6000);
	params.force_level = LOD_BILLBOARD;
	sim.set_lod(params);
	sim.update(0.016f);
	CHECK(sim.get_bucket(BUCKET_IMPOSTOR).get_count() == 6000);
	CHECK(sim.get_bucket(mesh_bucket(1, 0)).get_count() == 0);
	CHECK(drawn(sim) == 6000);
	params.force_level = -1;
	sim.set_lod(params);
	sim.update(0.016f);
	CHECK(sim.get_lod_counts()[LOD_BILLBOARD] == 6000);
	CHECK(drawn(sim) == 6000);

	FieldSimulation big;
	load(big, rect_map(1000, 200)); // 200 000 plants, far observer: only static chunks
	big.set_observer({ -500.0f, 1.7f, -500.0f });
	big.update(0.016f);
	const double per_plant = double(big.get_memory_bytes()) / 200000.0;
	CAPTURE(per_plant);
	CHECK(per_plant <= 40.0); // #15: ≤ 40 B a plant (a 28 B layout, no wind state for far plants)
}

TEST_CASE("setting the same layout again keeps the field as it is; a different one rebuilds it") {
	FieldSimulation sim;
	load(sim, rect_map(80, 80));
	sim.set_observer({ 20.0f, 1.7f, 20.0f });
	sim.update(0.016f);
	const uint32_t chunks = sim.get_chunk_count();
	uint32_t active = 0;
	for (uint32_t c = 0; c < chunks; ++c) {
		active += sim.is_chunk_active(c) ? 1 : 0;
	}
	REQUIRE(active > 0);
	CHECK_FALSE(sim.set_layout_params(sim.get_layout_params()));
	uint32_t still_active = 0;
	for (uint32_t c = 0; c < chunks; ++c) {
		still_active += sim.is_chunk_active(c) ? 1 : 0;
	}
	CHECK(still_active == active); // no rebuild: chunk state survives
	LayoutParams params = sim.get_layout_params();
	params.seed += 1;
	CHECK(sim.set_layout_params(params));
	for (uint32_t c = 0; c < sim.get_chunk_count(); ++c) {
		CHECK_FALSE(sim.is_chunk_active(c)); // rebuilt: nothing active until the next update
	}
}

namespace {

// The horizontal lean of a plant's head now: where its top is, relative to its root (x, z).
glm::vec2 head_offset(const FieldSimulation &p_sim, uint32_t p_plant) {
	PartTransforms parts;
	p_sim.get_plant_parts(p_plant, parts);
	const glm::vec3 top = parts.origin[2] + parts.basis[2][1];
	return glm::vec2(top.x - parts.origin[0].x, top.z - parts.origin[0].z);
}

} // namespace

TEST_CASE("pushers: plants within the radius bend away from the body and spring back once it leaves") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20)); // 10 × 10 m, a plant every 0.5 m
	WindParams calm;
	calm.power = 0.0f;
	sim.set_wind(calm);
	sim.set_observer({ 5.0f, 1.7f, 5.0f });
	sim.set_push_params(1.0f, 1.0f);
	sim.update(0.016f);
	CHECK(sim.get_pushed_count() == 0);

	const Pusher body{ { 5.0f, 1.0f, 5.0f }, 1.0f };
	sim.set_pushers(&body, 1);
	for (int i = 0; i < 60; ++i) {
		sim.update(1.0f / 60.0f);
	}
	std::vector<uint32_t> near, far;
	sim.find_plants_near({ 5.0f, 5.0f }, 0.9f, near);
	REQUIRE(near.size() > 5);
	CHECK(sim.get_pushed_count() >= near.size());
	for (uint32_t plant : near) {
		const glm::vec2 away = sim.get_layout().plants[plant].position - glm::vec2(5.0f, 5.0f);
		const glm::vec2 lean = head_offset(sim, plant);
		if (glm::length(away) > 0.05f) {
			CHECK(glm::dot(lean, away) > 0.0f); // away from the body
			CHECK(glm::length(lean) > 0.05f);
		}
	}
	sim.find_plants_near({ 5.0f, 5.0f }, 3.0f, far);
	for (uint32_t plant : far) {
		if (glm::distance(sim.get_layout().plants[plant].position, glm::vec2(5.0f, 5.0f)) > 1.0f) {
			CHECK(glm::length(head_offset(sim, plant)) < 1e-5f); // outside the radius, calm air: upright
		}
	}

	sim.set_pushers(nullptr, 0); // the body leaves
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.get_pushed_count() > 0); // still springing back after half the recovery time
	for (int i = 0; i < 45; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.get_pushed_count() == 0); // settled within the recovery time (and a margin): no state left
	for (uint32_t plant : near) {
		CHECK(glm::length(head_offset(sim, plant)) < 1e-3f);
	}
}

TEST_CASE("pushers: wind and push state live with active chunks only; a chunk turning inactive drops its pushes") {
	FieldSimulation sim;
	load(sim, rect_map(160, 20)); // 80 × 10 m in 8 m chunks
	WindParams calm;
	calm.power = 0.0f;
	sim.set_wind(calm);
	sim.set_push_params(1.0f, 1.0f);
	sim.set_observer({ 16.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	const Pusher body{ { 16.0f, 1.0f, 5.0f }, 1.5f }; // across the border of two chunks
	sim.set_pushers(&body, 1);
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	std::vector<uint32_t> near;
	sim.find_plants_near({ 16.0f, 5.0f }, 1.4f, near);
	const auto chunk_of = [&](uint32_t p_plant) { return sim.get_layout().plants[p_plant].chunk; };
	const uint32_t west = chunk_of(10 * 160 + 30); // a full map: plant = row · columns + column, x = 15 m
	const uint32_t east = chunk_of(10 * 160 + 34); // x = 17 m
	uint32_t pushed_east = 0;
	for (uint32_t plant : near) {
		pushed_east += chunk_of(plant) == east ? 1 : 0;
	}
	REQUIRE(pushed_east > 3);
	REQUIRE(near.size() > pushed_east + 3);
	CHECK(sim.get_pushed_count() >= near.size());

	// Walk east until the western chunk is no longer active while the eastern one still is (the
	// western plants' pushes were found first, so dropping them moves the eastern ones' slots).
	float x = 16.0f;
	while (sim.is_chunk_active(west) && x < 80.0f) {
		x += 1.0f;
		sim.set_observer({ x, 1.7f, 5.0f });
		sim.update(1.0f / 60.0f);
	}
	REQUIRE(sim.is_chunk_active(east));
	CHECK(sim.get_pushed_count() < near.size()); // the western plants' pushes went with their chunk
	CHECK(sim.get_pushed_count() >= pushed_east); // the eastern ones' stay (their slots renumbered)
	// Straight back: the eastern plants are meshes again and still pushed away, through their
	// renumbered slots; the western ones start afresh and are pushed again.
	sim.set_observer({ 16.0f, 1.7f, 5.0f });
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	for (uint32_t plant : near) {
		const glm::vec2 away = sim.get_layout().plants[plant].position - glm::vec2(16.0f, 5.0f);
		if (glm::length(away) > 0.05f && glm::length(away) < 1.3f) {
			CHECK(glm::dot(head_offset(sim, plant), away) > 0.0f);
		}
	}
	// Far from everything: no chunk active, so no push state is held at all.
	sim.set_observer({ -500.0f, 1.7f, 5.0f });
	sim.update(1.0f / 60.0f);
	CHECK(sim.get_pushed_count() == 0);
	// Back: the plants come upright with fresh state, the body pushes them again.
	sim.set_observer({ 16.0f, 1.7f, 5.0f });
	sim.set_pushers(nullptr, 0);
	sim.update(1.0f / 60.0f);
	for (uint32_t plant : near) {
		CHECK(glm::length(head_offset(sim, plant)) < 1e-5f);
	}
	sim.set_pushers(&body, 1);
	for (int i = 0; i < 30; ++i) {
		sim.update(1.0f / 60.0f);
	}
	CHECK(sim.get_pushed_count() >= near.size());
}

TEST_CASE("pushers: a body above the plants pushes nothing; a push never bends a plant past max_bend") {
	FieldSimulation sim;
	load(sim, rect_map(20, 20));
	sim.set_observer({ 5.0f, 1.7f, 5.0f });
	const Pusher high{ { 5.0f, 8.0f, 5.0f }, 1.0f };
	sim.set_pushers(&high, 1);
	sim.update(0.016f);
	CHECK(sim.get_pushed_count() == 0);
	WindParams storm;
	storm.power = 100.0f;
	sim.set_wind(storm);
	sim.set_push_params(10.0f, 1.0f);
	const Pusher low{ { 5.0f, 0.5f, 5.0f }, 2.0f };
	sim.set_pushers(&low, 1);
	for (int i = 0; i < 120; ++i) {
		sim.update(1.0f / 60.0f);
	}
	for (uint32_t plant = 0; plant < sim.get_plant_count(); ++plant) {
		PartTransforms parts;
		sim.get_plant_parts(plant, parts);
		const float tilt = std::acos(glm::normalize(parts.basis[1][1]).y) + 0.0f;
		CHECK(tilt <= sim.get_wind().get_params().max_bend * 1.001f);
	}
}

TEST_CASE("mesh 3 dithers into its impostor over the fade metres before the sprite switch, the same whichever level a plant is at") {
	FieldSimulation sim;
	load(sim, rect_map(120, 120)); // 60 × 60 m
	LodParams lod; // switches at 6, 10, 20, 25 m, hysteresis 0.5 m, fade 3 m: from 16.5 to 19.5 m
	lod.interval = 0.0f;
	sim.set_lod(lod);
	const glm::vec3 eye{ 30.0f, 1.7f, 30.0f };
	sim.set_observer(eye);
	const float middle = 0.5f * PlantShape::HEIGHT * float(param::PLANT_HEIGHT.default_value) / 3.0f;
	auto impostor_shares = [&]() {
		std::map<std::pair<float, float>, float> shares;
		const InstanceBuffer &sprites = sim.get_bucket(BUCKET_IMPOSTOR);
		for (uint32_t i = 0; i < sprites.get_count(); ++i) {
			const Placed instance = placed(sprites, i);
			shares[{ instance.root.x, instance.root.z }] = instance.share;
		}
		const InstanceBuffer &meshes = sim.get_bucket(mesh_bucket(LOD_MESH_3, 0));
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
		sim.set_observer(eye + glm::vec3(step, 0.0f, 0.0f));
		for (int i = 0; i < 10; ++i) { // chunks turn active a budget's worth per update
			sim.request_lod_update();
			sim.update(0.016f);
		}
		const auto shares = impostor_shares();
		for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
			const Plant &plant = sim.get_layout().plants[i];
			const float distance = glm::length(eye + glm::vec3(step, 0.0f, 0.0f) - (plant.root() + glm::vec3(0.0f, middle, 0.0f)));
			if (distance < 12.0f || distance > 22.0f) {
				continue;
			}
			const auto found = shares.find({ plant.root().x, plant.root().z });
			const float expected = std::clamp((distance - 16.5f) / 3.0f, 0.0f, 1.0f);
			CAPTURE(distance);
			// Not in a near bucket: in a static chunk, drawn as a whole impostor.
			const bool as_expected = found == shares.end() ? !sim.is_chunk_active(plant.chunk) && expected == 1.0f
														   : found->second == doctest::Approx(expected).epsilon(1e-3);
			CHECK(as_expected);
			in_band += expected > 0.0f && expected < 1.0f ? 1 : 0;
			switching += distance > 19.5f && distance < 20.5f ? 1 : 0;
		}
		CHECK(drawn(sim) == sim.get_plant_count());
	}
	CHECK(in_band > 500);
	CHECK(switching > 100);
	lod.fade = 0.0f; // no fade: mesh 3 wholly up to its switch
	sim.set_lod(lod);
	sim.request_lod_update();
	sim.update(0.016f);
	for (const auto &[root, share] : impostor_shares()) {
		CHECK((share == 0.0f || share == 1.0f));
	}
	CHECK(drawn(sim) == sim.get_plant_count());
}

TEST_CASE("drawn whole, mesh 1 and 2 dither into the next level before their switches, the same whichever level a plant is at") {
	FieldSimulation sim;
	load(sim, rect_map(120, 120)); // 60 × 60 m
	LodParams lod; // switches at 6, 10, 20 m, hysteresis 0.5 m, fade 3 m at 20 m: 0.9 m at 6, 1.5 m at 10
	lod.interval = 0.0f;
	sim.set_lod(lod);
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
		sim.set_observer(at);
		for (int i = 0; i < 10; ++i) {
			sim.request_lod_update();
			sim.update(0.016f);
		}
		// Each plant's alpha per mesh level.
		std::map<std::pair<float, float>, std::array<float, 3>> alphas;
		for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
			const InstanceBuffer &bucket = sim.get_bucket(mesh_bucket(level, 0));
			for (uint32_t i = 0; i < bucket.get_count(); ++i) {
				const float *instance = bucket.get_data() + size_t(i) * bucket.get_stride();
				alphas.try_emplace({ instance[3], instance[11] }, std::array<float, 3>{ 0.0f, 0.0f, 0.0f });
				alphas[{ instance[3], instance[11] }][level] = instance[15];
			}
		}
		for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
			const Plant &plant = sim.get_layout().plants[i];
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
		CHECK(drawn(sim) == sim.get_plant_count());
	}
	CHECK(in_band[0] > 40);
	CHECK(in_band[1] > 80);
	shape.whole = false; // part by part (any material): the mesh levels switch at once
	sim.set_shape(shape);
	sim.request_lod_update();
	sim.update(0.016f);
	for (uint32_t level = 0; level < LOD_MESH_3; ++level) {
		const InstanceBuffer &bucket = sim.get_bucket(mesh_bucket(level, 0));
		for (uint32_t i = 0; i < bucket.get_count(); ++i) {
			CHECK(bucket.get_data()[size_t(i) * bucket.get_stride() + 15] == 1.0f);
		}
	}
	CHECK(drawn(sim) == sim.get_plant_count());
}

TEST_CASE("a jump of the observer re-selects at once, nearest chunks first, within the activation budget") {
	FieldSimulation sim;
	load(sim, rect_map(400, 400), 16.0f); // 200 × 200 m, 160 000 plants
	sim.set_observer({ 20.0f, 1.7f, 20.0f });
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	const uint32_t settled = sim.get_active_plant_count();
	CHECK(settled > FieldSimulation::ACTIVATION_BUDGET); // more than one update's worth
	const glm::vec3 there(150.0f, 1.7f, 150.0f);
	sim.set_observer(there); // a teleport, 184 m, in the middle of an LOD interval
	sim.update(0.016f);
	std::vector<uint32_t> nearest;
	sim.find_plants_near({ there.x, there.z }, 1.7f, nearest);
	REQUIRE(!nearest.empty());
	for (uint32_t plant : nearest) {
		CHECK(sim.get_plant_lod(plant) == LOD_MESH_1); // a mesh on the first update after the jump
	}
	uint32_t largest_chunk = 0;
	for (const Chunk &chunk : sim.get_layout().chunks) {
		largest_chunk = std::max(largest_chunk, chunk.count);
	}
	CHECK(sim.get_active_plant_count() <= FieldSimulation::ACTIVATION_BUDGET + largest_chunk);
	for (int i = 0; i < 10; ++i) {
		sim.update(0.016f);
	}
	FieldSimulation fresh; // the neighbourhood as a simulation that started there has it
	load(fresh, rect_map(400, 400), 16.0f);
	fresh.set_observer(there);
	for (int i = 0; i < 10; ++i) {
		fresh.update(0.016f);
	}
	CHECK(sim.get_active_plant_count() == fresh.get_active_plant_count());
	CHECK(sim.get_lod_counts() == fresh.get_lod_counts());
	CHECK(drawn(sim) == sim.get_plant_count()); // exactly once all the while
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
	LayoutParams params = sim.get_layout_params();
	params.varieties[0].yaw_range = 1.0f;
	params.varieties[0].scale_min = 0.5f;
	params.varieties[0].scale_max = 1.5f;
	REQUIRE(sim.set_layout_params(params));
	float smallest = 10.0f, largest = 0.0f, widest_yaw = 0.0f;
	for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
		const Plant &plant = sim.get_layout().plants[i];
		smallest = std::min(smallest, plant.scale);
		largest = std::max(largest, plant.scale);
		widest_yaw = std::max(widest_yaw, std::abs(plant.yaw));
		PartTransforms parts;
		sim.get_plant_parts(i, parts);
		// Upright (no wind): the middle starts 2 units up and the head 0.5 above it, at 2 m a unit.
		CHECK(parts.origin[1].y - parts.origin[0].y == doctest::Approx(2.0f * 2.0f * plant.scale));
		CHECK(parts.origin[2].y - parts.origin[1].y == doctest::Approx(0.5f * 2.0f * plant.scale));
		CHECK(glm::length(parts.basis[0][1]) == doctest::Approx(2.0f * plant.scale));
		// Chunk bounds hold the tallest plant.
		const ChunkBounds bounds = sim.get_chunk_bounds(plant.chunk);
		CHECK(bounds.max.y >= plant.ground + shape.height * 2.0f * plant.scale);
	}
	CHECK(smallest >= 0.5f);
	CHECK(largest <= 1.5f);
	CHECK(largest - smallest > 0.8f); // 30 plants spread over the range
	CHECK(widest_yaw <= 1.0f);
	CHECK(widest_yaw > 0.7f);
	// A reversed range is read as one size; a nonsense form keeps the built-in one.
	params.varieties[0].scale_min = 2.0f;
	params.varieties[0].scale_max = 1.0f;
	sim.set_layout_params(params);
	CHECK(sim.get_layout_params().varieties[0].scale_max == 2.0f);
	shape.part_lengths = glm::vec3(NAN, -1.0f, 1.0f);
	sim.set_shape(shape);
	CHECK(sim.get_shape().part_lengths == PlantShape::PART_LENGTHS);
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
	CHECK(sim.get_species_count() == 2);
	CHECK(sim.get_bucket_count() == 2 * BUCKET_COUNT);
	CHECK(sim.get_map().objects.size() > 300); // 'S' stays an object
	uint32_t maize = 0;
	for (uint32_t c = 0; c < sim.get_chunk_count(); ++c) {
		const Chunk &chunk = sim.get_layout().chunks[c];
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t plant = sim.get_layout().chunk_plants[chunk.first + k];
			const glm::vec2 cell = glm::floor(sim.get_layout().plants[plant].position / 0.5f);
			const bool is_m = (int(cell.x) + int(cell.y)) % 3 == 0;
			CHECK(is_m == (chunk.species == 1)); // a chunk holds one species
		}
		maize += chunk.species == 1 ? chunk.count : 0;
	}
	CHECK(maize > 300);
	// Species 1 twice as tall, and each keeps its own variety.
	sim.set_plant_height(4.0f, 1);
	LayoutParams params = sim.get_layout_params();
	params.varieties[1].yaw_range = 0.0f;
	sim.set_layout_params(params);
	PartTransforms parts;
	for (uint32_t i = 0; i < sim.get_plant_count(); ++i) {
		const uint32_t species = sim.get_layout().chunks[sim.get_layout().plants[i].chunk].species;
		sim.get_plant_parts(i, parts);
		CHECK(glm::length(parts.basis[0][1]) == doctest::Approx(species == 1 ? 4.0f / 3.0f : 2.0f / 3.0f));
		if (species == 1) {
			CHECK(sim.get_layout().plants[i].yaw == 0.0f);
		}
	}
	// Each species' plants go to its own buckets; the counts add up per species and in all.
	LodParams lod;
	lod.force_level = LOD_MESH_2;
	sim.set_lod(lod);
	sim.update(0.0f);
	CHECK(sim.get_bucket(mesh_bucket(LOD_MESH_2, 0)).get_count() == sim.get_plant_count() - maize);
	CHECK(sim.get_bucket(BUCKET_COUNT + mesh_bucket(LOD_MESH_2, 0)).get_count() == maize);
	CHECK(sim.get_lod_counts(1)[LOD_MESH_2] == maize);
	CHECK(sim.get_lod_counts()[LOD_MESH_2] == sim.get_plant_count());
	// A plant near a point is found whatever its species.
	std::vector<uint32_t> near;
	sim.find_plants_near(glm::vec2(8.0f), 1.0f, near);
	bool both[2] = { false, false };
	for (uint32_t plant : near) {
		both[sim.get_layout().chunks[sim.get_layout().plants[plant].chunk].species] = true;
	}
	CHECK(both[0]);
	CHECK(both[1]);
	// At most MAX_SPECIES - 1 legend plants.
	CHECK_FALSE(sim.load_map("2 1\n**\n", U"", U"abcdefgh", "too_many", MapLimits{}, error));
	CHECK(error.message.find("at most 7") != std::string::npos);
}

TEST_CASE("colour variety: plants are white without it; with it, seeded brightness and tint within the ranges") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(rect_map(20, 20), U"", "colour", MapLimits{}, error));
	LodParams lod;
	lod.force_level = LOD_MESH_1;
	sim.set_lod(lod);
	sim.update(0.0f);
	const InstanceBuffer &heads = sim.get_bucket(mesh_bucket(LOD_MESH_1, 2));
	REQUIRE(heads.get_count() > 0);
	for (uint32_t i = 0; i < heads.get_count(); ++i) {
		const float *colour = heads.get_data() + size_t(i) * FLOATS_PER_INSTANCE + TRANSFORM_FLOATS;
		CHECK(glm::vec4(colour[0], colour[1], colour[2], colour[3]) == glm::vec4(1.0f));
	}
	LayoutParams params = sim.get_layout_params();
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
	std::vector<float> impostors(size_t(sim.get_layout().chunks[0].count) * FAR_FLOATS_PER_INSTANCE);
	sim.write_chunk_instances(0, impostors.data());
	for (uint32_t k = 0; k < sim.get_layout().chunks[0].count; ++k) {
		const Plant &plant = sim.get_layout().plants[sim.get_layout().chunk_plants[k]];
		const glm::vec3 colour = tone_colour(read_far_instance(impostors.data() + size_t(k) * FAR_FLOATS_PER_INSTANCE).tone);
		CHECK(glm::distance(colour, glm::vec3(plant.color(params.varieties[0]))) < 0.02f);
	}
}

TEST_CASE("painting changes only the painted cells' plants: every other plant keeps its place, yaw and size") {
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(rect_map(30, 30), U"", "paint", MapLimits{}, error));
	LayoutParams params = sim.get_layout_params();
	params.varieties[0].scale_min = 0.5f;
	params.varieties[0].scale_max = 1.5f;
	sim.set_layout_params(params);
	std::map<std::pair<float, float>, std::pair<float, float>> before; // position → yaw, size
	for (const Plant &plant : sim.get_layout().plants) {
		before[{ plant.position.x, plant.position.y }] = { plant.yaw, plant.scale };
	}
	std::vector<int> changed;
	sim.paint_map(glm::vec2(10.0f, 10.0f), 3.0f, CellContent{}, 1.0f, 1, true, changed);
	REQUIRE(!changed.empty());
	CHECK(sim.get_plant_count() == 900 - changed.size() / 2);
	for (const Plant &plant : sim.get_layout().plants) {
		const auto found = before.find({ plant.position.x, plant.position.y });
		REQUIRE(found != before.end());
		CHECK(found->second.first == plant.yaw);
		CHECK(found->second.second == plant.scale);
	}
}
