#pragma once
// Far tiles: the static representation of every plant not in an active chunk (near_field.h). A tile
// is the chunks of one species in a square of TILE_CHUNKS × TILE_CHUNKS grid cells, drawn from one
// buffer (level 0): one multi-view impostor record per plant, one MultiMesh a tile, written at a build
// and again, nearest the observer first, as the observer moves (write_tile_steps, next_tile_to_order).
// Every plant of a tile is in its buffer; the impostor shader skips those whose chunk is active, as
// the active mask (NearField::write_active_mask) says.
//
// While the field's tile merge distance is above 0, tiles merge with distance: a level-L tile covers
// the square of 2 × 2 level-(L − 1) tiles (its children, whose parent it is) and holds the plants of
// its chunks whose tile level (plant_tile_level) is at least L: a quarter of the plants per level,
// each level's a subset of the one below. Each far plant takes the look of the level its distance
// from the observer gives it (choose_tile_level: level L from merge_distance(L) on, fading in over
// the half octave before), so no tile's worth of plants switches at once, and the impostor shader
// widens the plants by 1 / √density to keep the field's cover. Which tile draws it is a cut through
// the tree of tiles: a tile is drawn from get_tile_shown_from on, where all its plants are given to
// its level or above, unless its parent is drawn (the engine's visibility parent); a tile draws each
// of its plants at the level given to it, so whether a tile or its children draw a place changes
// nothing on screen. Levels stop once one tile per species covers the field. Level-0 tiles come
// first, ordered by where they lie, then species; then level 1's, and so on.
#include "field_plants.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sunflower {

class FarTiles {
public:
	static constexpr int TILE_CHUNKS = 8;
	static constexpr uint32_t MAX_TILE_LEVELS = 8;
	static constexpr uint32_t NO_TILE = UINT32_MAX;
	struct Tile {
		uint32_t first = 0; // range in the tile chunk list (get_tile_chunk)
		uint32_t count = 0;
		uint32_t plants = 0; // in its buffer: those of its chunks at its level or above
		uint32_t species = 0;
		uint32_t level = 0;
		uint32_t parent = NO_TILE; // the tile of the next level covering it
		// Where it lies: (level << 56) | tile cell × MAX_SPECIES + species (the same in any layout of the
		// map's size).
		uint64_t key = 0;
		glm::vec2 area_min{ 0.0f }; // x, z bounds of its plants' roots
		glm::vec2 area_max{ 0.0f };
		// kept_from[M]: how many of its plants a level M keeps (all of them below its own level).
		// Its records come highest level first, so these are its first kept_from[M] records.
		std::array<uint32_t, MAX_TILE_LEVELS> kept_from{};
		// No level lies above it: it keeps every plant beyond its merge distance.
		bool is_top() const { return parent == NO_TILE; }
	};
	// Plants fade from one tile level to the next over the last TILE_MERGE_FADE octave before each
	// merge distance (from merge_distance(L) / 2^TILE_MERGE_FADE to merge_distance(L)), one after
	// another: a plant the next level leaves out dithers away, in the order of its own random and
	// over a quarter of the band (the impostor shader's MERGE_PLANT_FADE), the others widen to keep
	// the cover, and at the merge distance the next level's tile draws those same plants at the
	// same width. So no tile's worth of plants switches at once.
	static constexpr float TILE_MERGE_FADE = 0.5f;
	// The visible counts are counted again whenever the observer has moved this far across the ground.
	static constexpr float TILE_COUNT_SLACK = 1.0f;
	// The tile level that draws a far plant p_distance from the observer, and how far its fade to the
	// next level has come (0 … 1: the share of the plants that level leaves out already gone).
	// Mirrored by the impostor shader (tile_choice): keep the two in step.
	struct TileChoice {
		uint32_t level = 0;
		float fade = 0.0f;
	};

	explicit FarTiles(const FieldPlants &p_plants) :
			_plants(p_plants) {}

	// The tiles of the plants' layout as it is now.
	void build();
	// Counts each tile's visible records again when the observer has moved TILE_COUNT_SLACK across the
	// ground since the last count (or the tiles were built since).
	void follow_observer(const glm::vec3 &p_observer);

	uint32_t get_tile_count() const { return static_cast<uint32_t>(_tiles.size()); }
	const Tile &get_tile(uint32_t p_tile) const { return _tiles[p_tile]; }
	// The k-th chunk of a tile (k < Tile::count), in chunk order within each child.
	uint32_t get_tile_chunk(uint32_t p_tile, uint32_t p_k) const { return _tile_chunks[_tiles[p_tile].first + p_k]; }
	ChunkBounds get_tile_bounds(uint32_t p_tile) const;
	// The tile's plants' records: Tile::plants × FAR_FLOATS_PER_INSTANCE floats; while tiles merge,
	// level by level, highest first (chunk after chunk within a level), else chunk after chunk.
	// Given an observer (the field's frame), each level's chunks come nearest it first (by their
	// middles), and each chunk's plants in map order or backwards, whichever begins nearer it: drawn
	// nearest first, the hidden far quads' pixels fail the engine's early depth test instead of being
	// shaded and covered (8–10 % of a software frame over the large field, docs/performance.md,
	// table 12). Without one, in map order.
	void write_tile_instances(uint32_t p_tile, float *r_out, const glm::vec3 *p_observer = nullptr) const;
	// write_tile_instances a few chunks at a time: a step is one chunk's plants of one level's group
	// (get_tile_steps in all). Writes steps from p_from on at r_out (the records of the steps before
	// it written already) until p_budget plants are written or the tile ends; adds them to
	// r_written and returns the next step (get_tile_steps when done).
	uint32_t write_tile_steps(uint32_t p_tile, float *r_out, const glm::vec3 *p_observer, uint32_t p_from, uint32_t p_budget,
			uint32_t &r_written) const;
	uint32_t get_tile_steps(uint32_t p_tile) const;
	// A tile's records ordered for an observer at p_ordered_for (x, z; NaN: not ordered for any)
	// are written again for one at p_observer once it has moved TILE_ORDER_SLACK or a share
	// TILE_ORDER_TURN of its distance from the tile's middle, whichever is more: the nearest such
	// tile (p_ordered_for: one place per tile), or NO_TILE. Far tiles turn a little each time.
	uint32_t next_tile_to_order(const std::vector<glm::vec2> &p_ordered_for, const glm::vec3 &p_observer) const;
	static constexpr float TILE_ORDER_SLACK = 16.0f;
	static constexpr float TILE_ORDER_TURN = 0.5f;
	// How many of the tile's first records the engine must draw: those kept at the lowest level the
	// observer's distance may give any of its plants (Tile::kept_from), counted from a distance
	// TILE_COUNT_SLACK nearer than the observer's place at the last count. A level-0 tile seen from
	// beyond the first merge distance draws a quarter of its records.
	uint32_t get_tile_visible_count(uint32_t p_tile) const { return _tile_visible[p_tile]; }
	// Two tiles with equal keys and signatures draw the same (see FieldPlants::get_chunk_signature).
	uint64_t get_tile_signature(uint32_t p_tile) const;
	// The distance from the observer at which a far plant's place turns to the tile's level.
	float get_tile_begin(uint32_t p_tile) const { return merge_distance(_tiles[p_tile].level); }
	// 0 for level 0; for level L the merge distance × 2^(L − 1).
	float merge_distance(uint32_t p_level) const;
	TileChoice choose_tile_level(float p_distance) const;
	// The camera distance (to the tile's box centre) from which the engine may draw a tile: its
	// merge distance plus the box's reach, so that choose_tile_level gives every plant in it its
	// level or a higher one (0 for level 0). Nearer, its children draw its place; from there on it
	// does, unless its parent is shown from there too.
	float get_tile_shown_from(uint32_t p_tile) const;
	// The highest tile level (0: tiles never merge).
	uint32_t get_top_tile_level() const { return _tiles.empty() ? 0 : _tiles.back().level; }
	// The share of its chunks' plants a tile of p_level holds on average: 4^−level.
	static float tile_density(uint32_t p_level) { return 1.0f / float(1u << (2u * std::min(p_level, 15u))); }
	// The highest tile level a plant is kept at (0 … MAX_TILE_LEVELS − 1), from its seeded place:
	// level ≥ L for a share 4^−L of the plants.
	uint32_t plant_tile_level(const Plant &p_plant) const;

	size_t get_memory_bytes() const;

private:
	// The merged levels above the level-0 tiles.
	void _merge_tiles();
	// Each tile's area and kept_from, once its plants are known.
	void _finish_tiles();
	void _count_tile_records(const glm::vec3 &p_observer);

	const FieldPlants &_plants;
	std::vector<Tile> _tiles;
	std::vector<uint32_t> _tile_chunks;
	// Per chunk (empty when tiles do not merge): how many of its plants each tile level keeps, and
	// where its plants kept at level 1 or above start in _merged_plants, ordered by tile level,
	// highest first, so that level L's are the first _chunk_kept[c][L] (1 B a plant on average).
	std::vector<std::array<uint32_t, MAX_TILE_LEVELS>> _chunk_kept;
	std::vector<uint32_t> _merged_first;
	std::vector<uint32_t> _merged_plants;
	std::vector<uint32_t> _tile_visible; // per tile: get_tile_visible_count
	glm::vec3 _tile_count_observer{ 0.0f }; // where the observer was when they were counted
	bool _tile_counts_due = true;
};

} // namespace sunflower
