// Core tests of far tiles: grouping, records, merging with distance.
#include "field_test_support.h"
#include "tile_reorder.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

using namespace sunflower;
using namespace sunflower_test;

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
	const FieldLayout &layout = sim.plants().get_layout();
	REQUIRE(layout.grid_x == 12);
	std::vector<int> tile_of(sim.plants().get_chunk_count(), -1);
	uint32_t plants = 0;
	for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
		const FarTiles::Tile &tile = sim.tiles().get_tile(t);
		if (tile.level > 0) {
			continue; // merged tiles: see the next test
		}
		plants += tile.plants;
		uint32_t in_chunks = 0;
		int x0 = 1 << 30, x1 = -1, z0 = 1 << 30, z1 = -1;
		for (uint32_t k = 0; k < tile.count; ++k) {
			const uint32_t chunk = sim.tiles().get_tile_chunk(t, k);
			CHECK(tile_of[chunk] == -1);
			tile_of[chunk] = int(t);
			CHECK(layout.chunks[chunk].species == tile.species);
			in_chunks += layout.chunks[chunk].count;
			const int x = int(sim.plants().get_chunk_cell(chunk)) % layout.grid_x;
			const int z = int(sim.plants().get_chunk_cell(chunk)) / layout.grid_x;
			x0 = std::min(x0, x), x1 = std::max(x1, x), z0 = std::min(z0, z), z1 = std::max(z1, z);
		}
		CHECK(in_chunks == tile.plants);
		CHECK(x0 / FarTiles::TILE_CHUNKS == x1 / FarTiles::TILE_CHUNKS); // one square of cells
		CHECK(z0 / FarTiles::TILE_CHUNKS == z1 / FarTiles::TILE_CHUNKS);
		// The records are the tile's chunks' plants (highest tile level first), each with its chunk's
		// cell and within its bounds.
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		sim.tiles().write_tile_instances(t, records.data());
		const ChunkBounds bounds = sim.tiles().get_tile_bounds(t);
		std::map<std::pair<float, float>, uint32_t> cells; // by root (x, z)
		for (uint32_t c = 0; c < tile.count; ++c) {
			const uint32_t chunk = sim.tiles().get_tile_chunk(t, c);
			for (uint32_t p = 0; p < layout.chunks[chunk].count; ++p) {
				const Plant &plant = layout.plants[layout.chunk_plants[layout.chunks[chunk].first + p]];
				cells[{ plant.root().x, plant.root().z }] = sim.plants().get_chunk_cell(chunk);
			}
		}
		uint32_t previous_level = FarTiles::MAX_TILE_LEVELS;
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
	CHECK(plants == sim.plants().get_plant_count());
	CHECK(std::count(tile_of.begin(), tile_of.end(), -1) == 0);
	CHECK(sim.tiles().get_tile_count() < sim.plants().get_chunk_count() / 4); // merged: 12 × 9 cells make 2 × 2 tiles per species
	// The mask marks exactly the active chunks' cells, per species, and its version moves with them.
	const uint32_t version = sim.get_mask_version();
	sim.near().set_observer({ 20.0f, 1.7f, 15.0f });
	for (int frame = 0; frame < 30; ++frame) { // the activation budget spreads a jump over updates
		sim.update(0.016f);
	}
	CHECK(sim.get_mask_version() != version);
	for (uint32_t species = 0; species < 2; ++species) {
		std::vector<uint8_t> mask(size_t(layout.grid_x) * size_t(layout.grid_z));
		sim.near().write_active_mask(species, mask.data());
		for (uint32_t c = 0; c < sim.plants().get_chunk_count(); ++c) {
			if (layout.chunks[c].species == species) {
				CHECK((mask[sim.plants().get_chunk_cell(c)] != 0) == sim.near().is_chunk_active(c));
			}
		}
	}
	uint32_t hidden = 0;
	for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
		bool some_static = false;
		for (uint32_t k = 0; k < sim.tiles().get_tile(t).count; ++k) {
			some_static = some_static || !sim.near().is_chunk_active(sim.tiles().get_tile_chunk(t, k));
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
	const uint32_t plant_count = sim.plants().get_plant_count();
	LayoutParams params = sim.plants().get_layout_params();
	params.tile_merge_distance = 10.0f;
	sim.set_layout_params(params);
	LodParams near;
	near.distances = { 1.0f, 2.0f, 3.0f, 4.0f }; // few active chunks: the tiles draw nearly every plant
	sim.near().set_lod(near);
	const FieldLayout &layout = sim.plants().get_layout();
	REQUIRE(layout.grid_x == 60);
	std::array<uint32_t, FarTiles::MAX_TILE_LEVELS> tiles_at{};
	std::array<uint32_t, FarTiles::MAX_TILE_LEVELS> plants_at{};
	uint32_t top = 0;
	std::map<std::pair<float, float>, uint32_t> levels; // each plant's level, by where it stands
	for (const Plant &plant : layout.plants) {
		levels[{ plant.position.x, plant.position.y }] = sim.tiles().plant_tile_level(plant);
	}
	for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
		const FarTiles::Tile &tile = sim.tiles().get_tile(t);
		CAPTURE(t);
		++tiles_at[tile.level];
		plants_at[tile.level] += tile.plants;
		top = std::max(top, tile.level);
		CHECK((tile.key >> 56) == uint64_t(tile.level));
		CHECK((t == 0 || sim.tiles().get_tile(t - 1).level <= tile.level)); // level by level
		CHECK(sim.tiles().get_tile_begin(t) == (tile.level == 0 ? 0.0f : 10.0f * float(1u << (tile.level - 1))));
		// Shown from where its farthest corner from the camera is at its level's distance at least.
		const ChunkBounds bounds = sim.tiles().get_tile_bounds(t);
		CHECK(sim.tiles().get_tile_shown_from(t) ==
				doctest::Approx(tile.level == 0 ? 0.0f : sim.tiles().get_tile_begin(t) + 0.5f * glm::length(bounds.max - bounds.min)));
		// Its records tell the levels above its own that keep each plant too.
		{
			std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
			sim.tiles().write_tile_instances(t, records.data());
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
			CHECK(sim.tiles().get_tile(tile.parent).level == tile.level + 1);
			CHECK(sim.tiles().get_tile(tile.parent).species == tile.species);
		}
		if (tile.level == 0) {
			continue;
		}
		// Its chunks are its children's, and its records exactly their plants kept at its level.
		std::vector<uint32_t> chunks;
		for (uint32_t child = 0; child < sim.tiles().get_tile_count(); ++child) {
			for (uint32_t k = 0; k < sim.tiles().get_tile(child).count && sim.tiles().get_tile(child).parent == t; ++k) {
				chunks.push_back(sim.tiles().get_tile_chunk(child, k));
			}
		}
		std::vector<uint32_t> own;
		for (uint32_t k = 0; k < tile.count; ++k) {
			own.push_back(sim.tiles().get_tile_chunk(t, k));
		}
		std::sort(chunks.begin(), chunks.end());
		std::sort(own.begin(), own.end());
		CHECK(own == chunks);
		std::vector<std::pair<float, float>> kept;
		for (uint32_t chunk : own) {
			for (uint32_t k = 0; k < layout.chunks[chunk].count; ++k) {
				const Plant &plant = layout.plants[layout.chunk_plants[layout.chunks[chunk].first + k]];
				if (sim.tiles().plant_tile_level(plant) >= tile.level) {
					kept.emplace_back(plant.position.x, plant.position.y);
				}
			}
		}
		std::vector<float> records(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
		sim.tiles().write_tile_instances(t, records.data());
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
	static_assert(FarTiles::TILE_CHUNKS == 8);
	CHECK(top == 3);
	CHECK(tiles_at[0] == 64);
	CHECK(tiles_at[1] == 16);
	CHECK(tiles_at[3] == 1);
	CHECK(plants_at[0] == plant_count);
	for (uint32_t level = 1; level <= top; ++level) {
		const double p = FarTiles::tile_density(level);
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
		sim.near().set_observer(camera);
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
		for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
			if (tile_drawn_from(sim, t, camera)) {
				++tiles_drawn;
				squares += 1u << (2u * sim.tiles().get_tile(t).level);
				records_left += sim.tiles().get_tile(t).plants - sim.tiles().get_tile_visible_count(t);
			}
		}
		CHECK(squares <= 64);
		CHECK(tiles_drawn <= (camera.x < -200.0f ? 1u : 64u));
	}
	// Along a line across the field and out: each tile holding a plant its distance gives to the
	// tile's level is drawn by the engine (checked in drawn()).
	for (float x = -47.0f; x < 170.0f; x += 13.0f) {
		CAPTURE(x);
		sim.near().set_observer(glm::vec3(x, 1.7f, 41.0f));
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
	CHECK(sim.tiles().get_tile_count() == 64);
	CHECK(drawn(sim) == plant_count);
}

namespace {

// A 90 × 70 field of sunflowers in 4 m chunks, its tiles merged from 10 m (the ordering tests').
void load_ordering_field(FieldSimulation &r_sim) {
	MapError error;
	std::string text = "90 70\n";
	for (int r = 0; r < 70; ++r) {
		text += std::string(90, '*') + "\n";
	}
	REQUIRE(r_sim.load_map(text, U"", U"", "order", MapLimits{}, error));
	LayoutParams params;
	params.chunk_size = 4.0f;
	params.tile_merge_distance = 10.0f; // merged tiles too
	r_sim.set_layout_params(params);
}

} // namespace

TEST_CASE("far tiles' records ordered for an observer: the same records in the same level groups, chunks nearest first, each chunk's plants from its nearer end; written a few chunks at a time, the same; a tile is ordered again once the observer moves on") {
	FieldSimulation sim;
	load_ordering_field(sim);
	const FieldLayout &layout = sim.plants().get_layout();
	const FarTiles &tiles = sim.tiles();
	REQUIRE(tiles.get_top_tile_level() > 0);
	for (const glm::vec3 observer : { glm::vec3(-30.0f, 1.7f, 50.0f), glm::vec3(20.0f, 1.7f, 15.0f) }) {
		const glm::vec2 at(observer.x, observer.z);
		for (uint32_t t = 0; t < tiles.get_tile_count(); ++t) {
			const FarTiles::Tile &tile = tiles.get_tile(t);
			std::vector<float> plain(size_t(tile.plants) * FAR_FLOATS_PER_INSTANCE);
			std::vector<float> ordered(plain.size());
			tiles.write_tile_instances(t, plain.data());
			tiles.write_tile_instances(t, ordered.data(), &observer);
			// A few chunks at a time (at least 50 plants a call), the same records.
			std::vector<float> sliced(plain.size());
			uint32_t step = 0;
			uint32_t written = 0;
			uint32_t calls = 0;
			while (step < tiles.get_tile_steps(t) && calls++ < 100000) {
				step = tiles.write_tile_steps(t, sliced.data() + size_t(written) * FAR_FLOATS_PER_INSTANCE, &observer, step, 50, written);
			}
			CHECK(written == tile.plants);
			CHECK(sliced == ordered);
			std::map<uint32_t, glm::vec2> middles; // each chunk's middle, by its cell
			for (uint32_t k = 0; k < tile.count; ++k) {
				const Chunk &chunk = layout.chunks[tiles.get_tile_chunk(t, k)];
				middles[sim.plants().get_chunk_cell(tiles.get_tile_chunk(t, k))] = (chunk.min + chunk.max) * 0.5f;
			}
			// Level groups: the same levels in the same places (kept_from's prefixes hold), the same records
			// in each; within a group chunks nearest first, and each chunk's plants.
			size_t group = 0;
			std::vector<std::pair<float, float>> plain_roots;
			std::vector<std::pair<float, float>> ordered_roots;
			float chunk_distance = -1.0f;
			uint32_t cell = UINT32_MAX;
			// Each chunk's roots in each level's group (levels above, cell), in plain (map) order and as ordered.
			std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<float, float>>> plain_runs;
			std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<float, float>>> ordered_runs;
			uint32_t unsorted = 0;
			for (size_t k = 0; k <= tile.plants; ++k) {
				const bool end = k == tile.plants;
				const FarInstance a = end ? FarInstance{} : read_far_instance(plain.data() + k * FAR_FLOATS_PER_INSTANCE);
				const FarInstance b = end ? FarInstance{} : read_far_instance(ordered.data() + k * FAR_FLOATS_PER_INSTANCE);
				const FarInstance first = read_far_instance(plain.data() + group * FAR_FLOATS_PER_INSTANCE);
				if (end || a.levels_above != first.levels_above) { // a group ends
					std::sort(plain_roots.begin(), plain_roots.end());
					std::sort(ordered_roots.begin(), ordered_roots.end());
					CHECK(plain_roots == ordered_roots);
					plain_roots.clear();
					ordered_roots.clear();
					chunk_distance = -1.0f;
					cell = UINT32_MAX;
					group = k;
					if (end) {
						break;
					}
				}
				CHECK(a.levels_above == b.levels_above);
				plain_roots.emplace_back(a.root.x, a.root.z);
				ordered_roots.emplace_back(b.root.x, b.root.z);
				plain_runs[{ a.levels_above, a.cell }].emplace_back(a.root.x, a.root.z);
				ordered_runs[{ b.levels_above, b.cell }].emplace_back(b.root.x, b.root.z);
				const float to_chunk = glm::distance(middles.at(b.cell), at);
				if (b.cell != cell) { // the next chunk: not nearer the observer than the one before it
					unsorted += to_chunk < chunk_distance - 1e-4f ? 1 : 0;
					chunk_distance = to_chunk;
					cell = b.cell;
				}
			}
			CHECK(unsorted == 0);
			// A chunk's plants in map order, backwards when the observer is ahead of its middle on the
			// axis it is farther off on.
			uint32_t misordered = 0;
			for (auto &[run, roots] : plain_runs) {
				const glm::vec2 off = at - middles.at(run.second);
				if (std::abs(off.y) >= std::abs(off.x) ? off.y > 0.0f : off.x > 0.0f) {
					std::reverse(roots.begin(), roots.end());
				}
				misordered += roots == ordered_runs[run] ? 0 : 1;
			}
			CHECK(misordered == 0);
		}
	}
	// Ordering again: none ordered yet, the nearest tile first; ordered where the observer stands,
	// none; moved less than TILE_ORDER_SLACK, none; moved 20 m, the nearest tile.
	const glm::vec3 observer(20.0f, 1.7f, 15.0f);
	std::vector<glm::vec2> ordered_for(tiles.get_tile_count(), glm::vec2(std::nanf("")));
	uint32_t nearest = 0;
	for (uint32_t t = 0; t < tiles.get_tile_count(); ++t) {
		const auto middle = [&](uint32_t p_tile) {
			return (tiles.get_tile(p_tile).area_min + tiles.get_tile(p_tile).area_max) * 0.5f;
		};
		if (glm::distance(middle(t), glm::vec2(20.0f, 15.0f)) < glm::distance(middle(nearest), glm::vec2(20.0f, 15.0f))) {
			nearest = t;
		}
	}
	CHECK(tiles.next_tile_to_order(ordered_for, observer) == nearest);
	ordered_for.assign(tiles.get_tile_count(), glm::vec2(20.0f, 15.0f));
	CHECK(tiles.next_tile_to_order(ordered_for, observer) == FarTiles::NO_TILE);
	CHECK(tiles.next_tile_to_order(ordered_for, observer + glm::vec3(0.7f * FarTiles::TILE_ORDER_SLACK, 0.0f, 0.0f)) ==
			FarTiles::NO_TILE);
	CHECK(tiles.next_tile_to_order(ordered_for, observer + glm::vec3(0.0f, 0.0f, 20.0f)) != FarTiles::NO_TILE);
	ordered_for.clear(); // no tiles given to the engine yet
	CHECK(tiles.next_tile_to_order(ordered_for, observer) == FarTiles::NO_TILE);
}

TEST_CASE("tile reorder: one tile at a time, the nearest due first, written whole over several calls as for the observer it began for; then not again until the observer moves on") {
	FieldSimulation sim;
	load_ordering_field(sim);
	const FarTiles &tiles = sim.tiles();
	REQUIRE(tiles.get_tile_count() > 2);
	TileReorder reorder;
	const glm::vec3 observer(20.0f, 1.7f, 15.0f);
	CHECK(reorder.begin(tiles, observer) == FarTiles::NO_TILE); // no tiles followed yet
	reorder.resize(tiles.get_tile_count());
	std::vector<glm::vec2> never(tiles.get_tile_count(), glm::vec2(std::nanf("")));
	// Every tile once, nearest first (as next_tile_to_order picks), each in slices of 40 plants while
	// the observer moves on meanwhile: the records ordered for where it was when the tile began.
	std::vector<uint32_t> order;
	uint32_t calls = 0;
	glm::vec3 eye = observer;
	while (calls++ < 100000) {
		const uint32_t expected = tiles.next_tile_to_order(never, eye);
		const uint32_t tile = reorder.begin(tiles, eye);
		if (tile == FarTiles::NO_TILE) {
			break;
		}
		CHECK(tile == expected);
		CHECK(reorder.begin(tiles, eye) == FarTiles::NO_TILE); // one at a time
		const glm::vec3 began = eye;
		std::vector<float> buffer(size_t(tiles.get_tile(tile).plants) * FAR_FLOATS_PER_INSTANCE);
		uint32_t slices = 1;
		while (!reorder.advance(tiles, buffer.data(), 40)) {
			CHECK(reorder.get_tile() == tile);
			eye.x += 0.01f; // less than TILE_ORDER_SLACK in all
			++slices;
		}
		CHECK(reorder.get_tile() == FarTiles::NO_TILE);
		CHECK(reorder.get_written() == tiles.get_tile(tile).plants);
		CHECK(slices >= tiles.get_tile(tile).plants / 40 / 2); // a budget a call, not the whole tile
		std::vector<float> whole(buffer.size());
		tiles.write_tile_instances(tile, whole.data(), &began);
		CHECK(buffer == whole);
		never[tile] = glm::vec2(began.x, began.z);
		order.push_back(tile);
	}
	CHECK(order.size() == tiles.get_tile_count());
	CHECK(reorder.begin(tiles, eye) == FarTiles::NO_TILE); // all ordered for about here
	// Moved 20 m: the nearest due tile again; given up by cancel and by set_ordered of that tile.
	const glm::vec3 moved = observer + glm::vec3(0.0f, 0.0f, 20.0f);
	const uint32_t due = reorder.begin(tiles, moved);
	CHECK(due == tiles.next_tile_to_order(never, moved));
	REQUIRE(due != FarTiles::NO_TILE);
	reorder.cancel();
	CHECK(reorder.get_tile() == FarTiles::NO_TILE);
	CHECK(reorder.begin(tiles, moved) == due);
	reorder.set_ordered(due, moved);
	CHECK(reorder.get_tile() == FarTiles::NO_TILE);
	CHECK(reorder.begin(tiles, moved) != due);
	// Following fewer tiles: one in progress beyond them is given up, and none beyond is begun.
	reorder.resize(0);
	CHECK(reorder.get_tile() == FarTiles::NO_TILE);
	CHECK(reorder.begin(tiles, moved) == FarTiles::NO_TILE);
}
