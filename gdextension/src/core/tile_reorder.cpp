#include "tile_reorder.h"

#include "instance_buffer.h"

#include <cmath>

namespace sunflower {

void TileReorder::resize(uint32_t p_tiles) {
	_ordered_for.resize(p_tiles, glm::vec2(std::nanf("")));
	if (_tile != FarTiles::NO_TILE && _tile >= p_tiles) {
		cancel();
	}
}

void TileReorder::set_ordered(uint32_t p_tile, const glm::vec3 &p_observer) {
	if (p_tile >= _ordered_for.size()) {
		return;
	}
	_ordered_for[p_tile] = glm::vec2(p_observer.x, p_observer.z);
	if (_tile == p_tile) {
		cancel();
	}
}

void TileReorder::cancel() {
	_tile = FarTiles::NO_TILE;
	_step = 0;
	_written = 0;
}

uint32_t TileReorder::begin(const FarTiles &p_tiles, const glm::vec3 &p_observer) {
	if (_tile != FarTiles::NO_TILE) {
		return FarTiles::NO_TILE;
	}
	_tile = p_tiles.next_tile_to_order(_ordered_for, p_observer);
	_observer = p_observer;
	_step = 0;
	_written = 0;
	return _tile;
}

bool TileReorder::advance(const FarTiles &p_tiles, float *r_buffer, uint32_t p_budget) {
	if (_tile == FarTiles::NO_TILE) {
		return false;
	}
	_step = p_tiles.write_tile_steps(_tile, r_buffer + size_t(_written) * FAR_FLOATS_PER_INSTANCE, &_observer, _step, p_budget, _written);
	if (_step < p_tiles.get_tile_steps(_tile)) {
		return false;
	}
	_ordered_for[_tile] = glm::vec2(_observer.x, _observer.z);
	_tile = FarTiles::NO_TILE;
	_step = 0;
	return true;
}

} // namespace sunflower
