#pragma once
// The far tiles' records written again nearest the observer first as it moves (FarTiles'
// write_tile_steps and next_tile_to_order): one tile at a time, a budget of plants a frame, so that no
// frame writes a whole tile. Holds where each tile was last ordered for and the tile in progress; the
// caller holds the tile's buffer (the binding hands it to the engine whole once complete).
#include "far_tiles.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace sunflower {

class TileReorder {
public:
	// Follows the first p_tiles tiles (those the engine has been given): new ones not ordered for any
	// observer, the rest as they were. A tile in progress beyond them is given up.
	void resize(uint32_t p_tiles);
	// Tile p_tile's records were written whole for an observer at p_observer (or are taken to be): it
	// is not written again until that observer moves on. A write of it in progress is given up.
	void set_ordered(uint32_t p_tile, const glm::vec3 &p_observer);
	// Gives up the tile in progress, if any (its records changed meanwhile).
	void cancel();
	// The tile in progress, or FarTiles::NO_TILE.
	uint32_t get_tile() const { return _tile; }
	// The records of the tile in progress written so far (all of them once complete, until the next begin).
	uint32_t get_written() const { return _written; }
	// With none in progress, starts the tile due to be written again for an observer at p_observer
	// (FarTiles::next_tile_to_order) and returns it: the caller makes a buffer for its plants
	// (FarTiles::Tile::plants records). NO_TILE: none is due, or one is in progress already.
	uint32_t begin(const FarTiles &p_tiles, const glm::vec3 &p_observer);
	// Writes up to p_budget more plants of the tile in progress into r_buffer, which holds its records
	// written so far at its start. True when the tile is complete: then it counts as ordered for the
	// observer it was begun for and none is in progress.
	bool advance(const FarTiles &p_tiles, float *r_buffer, uint32_t p_budget);

private:
	std::vector<glm::vec2> _ordered_for; // where the observer was (x, z) when each tile was ordered; NaN: never
	uint32_t _tile = FarTiles::NO_TILE;
	glm::vec3 _observer{ 0.0f }; // the one the tile in progress is ordered for
	uint32_t _step = 0;
	uint32_t _written = 0;
};

} // namespace sunflower
