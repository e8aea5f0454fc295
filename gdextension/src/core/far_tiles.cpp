#include "far_tiles.h"

#include "random_hash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <utility>

namespace sunflower {

void FarTiles::build() {
	const FieldLayout &layout = _plants.get_layout();
	const size_t chunk_count = _plants.get_map_chunk_count(); // (not the chunks of plants play added)
	// Each chunk's tile key, then the chunks grouped by key (in chunk order within a tile).
	const uint64_t tiles_x = uint64_t((layout.grid_x + TILE_CHUNKS - 1) / TILE_CHUNKS);
	std::vector<std::pair<uint64_t, uint32_t>> keyed(chunk_count);
	for (uint32_t c = 0; c < chunk_count; ++c) {
		const uint64_t x = _plants.get_chunk_cell(c) % uint32_t(layout.grid_x) / TILE_CHUNKS;
		const uint64_t z = _plants.get_chunk_cell(c) / uint32_t(layout.grid_x) / TILE_CHUNKS;
		keyed[c] = { (z * tiles_x + x) * FieldMap::MAX_SPECIES + layout.chunks[c].species, c };
	}
	std::sort(keyed.begin(), keyed.end());
	_tiles.clear();
	_tile_chunks.resize(chunk_count);
	for (size_t i = 0; i < chunk_count; ++i) {
		const auto &[key, chunk] = keyed[i];
		if (_tiles.empty() || _tiles.back().key != key) {
			Tile tile;
			tile.first = static_cast<uint32_t>(i);
			tile.species = layout.chunks[chunk].species;
			tile.key = key;
			_tiles.push_back(tile);
		}
		_tile_chunks[i] = chunk;
		++_tiles.back().count;
		_tiles.back().plants += layout.chunks[chunk].count;
	}
	_chunk_kept.clear();
	_merged_first.clear();
	_merged_plants.clear();
	if (_plants.get_layout_params().tile_merge_distance > 0.0f) {
		_merge_tiles();
	}
	_finish_tiles();
}

void FarTiles::_finish_tiles() {
	const FieldLayout &layout = _plants.get_layout();
	for (Tile &tile : _tiles) {
		const Chunk &first = layout.chunks[_tile_chunks[tile.first]];
		tile.area_min = first.min;
		tile.area_max = first.max;
		tile.kept_from.fill(0);
		for (uint32_t k = 0; k < tile.count; ++k) {
			const uint32_t chunk = _tile_chunks[tile.first + k];
			tile.area_min = glm::min(tile.area_min, layout.chunks[chunk].min);
			tile.area_max = glm::max(tile.area_max, layout.chunks[chunk].max);
			for (uint32_t level = 0; level < MAX_TILE_LEVELS; ++level) {
				tile.kept_from[level] += _chunk_kept.empty() ? layout.chunks[chunk].count : _chunk_kept[chunk][std::max(level, tile.level)];
			}
		}
	}
	_tile_visible.resize(_tiles.size());
	for (size_t t = 0; t < _tiles.size(); ++t) {
		_tile_visible[t] = _tiles[t].plants;
	}
	_tile_counts_due = true;
}

void FarTiles::_count_tile_records(const glm::vec3 &p_observer) {
	_tile_count_observer = p_observer;
	_tile_counts_due = false;
	const glm::vec2 eye(p_observer.x, p_observer.z);
	for (size_t t = 0; t < _tiles.size(); ++t) {
		const Tile &tile = _tiles[t];
		// The ground distance is at most the distance the shader measures to a root; the observer
		// may move TILE_COUNT_SLACK before the next count.
		const float nearest = glm::length(eye - glm::clamp(eye, tile.area_min, tile.area_max)) - TILE_COUNT_SLACK;
		const uint32_t level = std::max(choose_tile_level(std::max(nearest, 0.0f)).level, tile.level);
		_tile_visible[t] = tile.kept_from[level];
	}
}

void FarTiles::_merge_tiles() {
	const FieldLayout &layout = _plants.get_layout();
	// Per chunk, how many of its plants each level keeps (level 0: all), and its plants kept at
	// level 1 or above ordered by tile level, highest first (map order within a level), so that a
	// merged tile of level L writes the first kept[c][L] of each chunk's.
	std::vector<std::array<uint32_t, MAX_TILE_LEVELS>> &kept = _chunk_kept;
	kept.assign(_plants.get_map_chunk_count(), {});
	_merged_first.assign(_plants.get_map_chunk_count(), 0);
	_merged_plants.clear();
	std::vector<std::pair<uint32_t, uint32_t>> ordered; // (MAX_TILE_LEVELS − level, plant)
	for (size_t c = 0; c < _plants.get_map_chunk_count(); ++c) {
		const Chunk &chunk = layout.chunks[c];
		ordered.clear();
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t plant = layout.chunk_plants[chunk.first + k];
			const uint32_t level = plant_tile_level(layout.plants[plant]);
			for (uint32_t l = 0; l <= level; ++l) {
				++kept[c][l];
			}
			if (level > 0) {
				ordered.emplace_back(MAX_TILE_LEVELS - level, plant);
			}
		}
		std::stable_sort(ordered.begin(), ordered.end(),
				[](const auto &p_a, const auto &p_b) { return p_a.first < p_b.first; });
		_merged_first[c] = static_cast<uint32_t>(_merged_plants.size());
		for (const auto &[order, plant] : ordered) {
			_merged_plants.push_back(plant);
		}
	}
	_merged_plants.shrink_to_fit();
	size_t below_first = 0; // the level below's tiles: [below_first, below_end)
	for (uint32_t level = 1; level < MAX_TILE_LEVELS; ++level) {
		const size_t below_end = _tiles.size();
		std::array<bool, FieldMap::MAX_SPECIES> species{};
		size_t species_count = 0;
		for (size_t t = below_first; t < below_end; ++t) {
			species_count += species[_tiles[t].species] ? 0 : 1;
			species[_tiles[t].species] = true;
		}
		if (below_end - below_first <= species_count) {
			return; // one tile per species covers the field
		}
		// Each tile below, keyed by the tile of this level covering it (its first chunk's cell tells).
		const uint32_t span = uint32_t(TILE_CHUNKS) << level; // grid cells along this level's side
		const uint64_t tiles_x = (uint64_t(layout.grid_x) + span - 1) / span;
		std::vector<std::pair<uint64_t, uint32_t>> keyed;
		keyed.reserve(below_end - below_first);
		for (size_t t = below_first; t < below_end; ++t) {
			const uint32_t cell = _plants.get_chunk_cell(get_tile_chunk(uint32_t(t), 0));
			const uint64_t x = cell % uint32_t(layout.grid_x) / span;
			const uint64_t z = cell / uint32_t(layout.grid_x) / span;
			keyed.emplace_back((uint64_t(level) << 56) | ((z * tiles_x + x) * FieldMap::MAX_SPECIES + _tiles[t].species),
					uint32_t(t));
		}
		std::sort(keyed.begin(), keyed.end());
		for (const auto &[key, child] : keyed) {
			if (_tiles.size() == below_end || _tiles.back().key != key) {
				Tile tile;
				tile.first = static_cast<uint32_t>(_tile_chunks.size());
				tile.species = _tiles[child].species;
				tile.level = level;
				tile.key = key;
				_tiles.push_back(tile);
			}
			Tile &parent = _tiles.back();
			_tiles[child].parent = uint32_t(_tiles.size() - 1);
			for (uint32_t k = 0; k < _tiles[child].count; ++k) {
				const uint32_t chunk = get_tile_chunk(child, k);
				_tile_chunks.push_back(chunk);
				++parent.count;
				parent.plants += kept[chunk][level];
			}
		}
		below_first = below_end;
	}
}

uint32_t FarTiles::plant_tile_level(const Plant &p_plant) const {
	// Two bits of a hash of the plant's place per level: all zero with probability 1/4, so the
	// plants kept at level L are a quarter of those kept at L − 1, and among them.
	uint32_t x_bits = 0;
	uint32_t z_bits = 0;
	std::memcpy(&x_bits, &p_plant.position.x, sizeof(x_bits));
	std::memcpy(&z_bits, &p_plant.position.y, sizeof(z_bits));
	uint64_t hash = hash_plant(_plants.get_layout_params().seed, (uint64_t(x_bits) << 32) | z_bits, STREAM_TILE_LEVEL);
	uint32_t level = 0;
	while (level + 1 < MAX_TILE_LEVELS && (hash >> 62) == 0) {
		++level;
		hash <<= 2;
	}
	return level;
}

float FarTiles::merge_distance(uint32_t p_level) const {
	if (p_level == 0) {
		return 0.0f;
	}
	return _plants.get_layout_params().tile_merge_distance * float(1u << (p_level - 1));
}

FarTiles::TileChoice FarTiles::choose_tile_level(float p_distance) const {
	// merge_distance doubles per level, so level L begins where 1 + log2(distance / merge_distance(1))
	// reaches L.
	const uint32_t top = get_top_tile_level();
	if (top == 0) {
		return {};
	}
	const float octaves = std::max(1.0f + std::log2(std::max(p_distance, 1e-3f) / merge_distance(1)), 0.0f);
	const float level = std::floor(octaves);
	if (level >= float(top)) {
		return { top, 0.0f };
	}
	const float into = octaves - level; // 0 … 1 between this level's merge distance and the next's
	return { uint32_t(level), std::clamp((into - (1.0f - TILE_MERGE_FADE)) / TILE_MERGE_FADE, 0.0f, 1.0f) };
}

float FarTiles::get_tile_shown_from(uint32_t p_tile) const {
	const Tile &tile = _tiles[p_tile];
	if (tile.level == 0) {
		return 0.0f;
	}
	const ChunkBounds bounds = get_tile_bounds(p_tile);
	const float reach = 0.5f * glm::length(bounds.max - bounds.min); // box centre to its farthest plant
	return merge_distance(tile.level) + reach;
}

ChunkBounds FarTiles::get_tile_bounds(uint32_t p_tile) const {
	ChunkBounds bounds = _plants.get_chunk_bounds(get_tile_chunk(p_tile, 0));
	for (uint32_t k = 1; k < _tiles[p_tile].count; ++k) {
		const ChunkBounds chunk = _plants.get_chunk_bounds(get_tile_chunk(p_tile, k));
		bounds.min = glm::min(bounds.min, chunk.min);
		bounds.max = glm::max(bounds.max, chunk.max);
	}
	return bounds;
}

void FarTiles::write_tile_instances(uint32_t p_tile, float *r_out, const glm::vec3 *p_observer) const {
	uint32_t written = 0;
	write_tile_steps(p_tile, r_out, p_observer, 0, UINT32_MAX, written);
}

uint32_t FarTiles::get_tile_steps(uint32_t p_tile) const {
	const Tile &tile = _tiles[p_tile];
	return tile.count * (_chunk_kept.empty() ? 1 : MAX_TILE_LEVELS - tile.level);
}

uint32_t FarTiles::write_tile_steps(uint32_t p_tile, float *r_out, const glm::vec3 *p_observer, uint32_t p_from, uint32_t p_budget,
		uint32_t &r_written) const {
	const FieldLayout &layout = _plants.get_layout();
	const Tile &tile = _tiles[p_tile];
	// The tile's chunks (k), nearest the observer first when there is one (ties in chunk order, so
	// that each call finds the same order).
	std::vector<std::pair<float, uint32_t>> order(tile.count);
	const glm::vec2 observer = p_observer ? glm::vec2(p_observer->x, p_observer->z) : glm::vec2(0.0f);
	for (uint32_t k = 0; k < tile.count; ++k) {
		const Chunk &chunk = layout.chunks[get_tile_chunk(p_tile, k)];
		const glm::vec2 away = (chunk.min + chunk.max) * 0.5f - observer;
		order[k] = { p_observer ? glm::dot(away, away) : 0.0f, k };
	}
	if (p_observer) {
		std::sort(order.begin(), order.end());
	}
	// A chunk's plants come in map order (rows along +x, one after another along +z); backwards
	// when the observer lies ahead of the chunk's middle along the axis it is farther off on: the
	// rows nearest it first when it looks along z, each row's plants nearest it first when it looks
	// along x (the plants one line of sight crosses are in one row then).
	std::vector<uint32_t> backwards;
	std::vector<uint32_t> level_zero; // a chunk's plants no merged level keeps
	const uint32_t steps = get_tile_steps(p_tile);
	const uint32_t budget_end = r_written + std::min(p_budget, UINT32_MAX - r_written);
	uint32_t step = p_from;
	for (; step < steps && r_written < budget_end; ++step) {
		const uint32_t chunk = get_tile_chunk(p_tile, order[step % tile.count].second);
		// While tiles merge, the levels' groups come highest first: level L's follow those above it.
		const uint32_t level = _chunk_kept.empty() ? 0 : MAX_TILE_LEVELS - 1 - step / tile.count;
		const uint32_t *plants = layout.chunk_plants.data() + layout.chunks[chunk].first;
		uint32_t count = layout.chunks[chunk].count;
		if (!_chunk_kept.empty() && level > 0) {
			const std::array<uint32_t, MAX_TILE_LEVELS> &kept = _chunk_kept[chunk];
			const uint32_t above = level + 1 < MAX_TILE_LEVELS ? kept[level + 1] : 0;
			plants = _merged_plants.data() + _merged_first[chunk] + above;
			count = kept[level] - above;
		} else if (!_chunk_kept.empty()) {
			level_zero.clear();
			for (uint32_t i = 0; i < count; ++i) {
				if (plant_tile_level(layout.plants[plants[i]]) == 0) {
					level_zero.push_back(plants[i]);
				}
			}
			plants = level_zero.data();
			count = uint32_t(level_zero.size());
		}
		if (p_observer) {
			const Chunk &own = layout.chunks[chunk];
			const glm::vec2 off = observer - (own.min + own.max) * 0.5f;
			if (std::abs(off.y) >= std::abs(off.x) ? off.y > 0.0f : off.x > 0.0f) {
				backwards.assign(std::make_reverse_iterator(plants + count), std::make_reverse_iterator(plants));
				plants = backwards.data();
			}
		}
		_plants.write_records(chunk, plants, count, r_out, level - tile.level);
		r_out += size_t(count) * FAR_FLOATS_PER_INSTANCE;
		r_written += count;
	}
	return step;
}

uint32_t FarTiles::next_tile_to_order(const std::vector<glm::vec2> &p_ordered_for, const glm::vec3 &p_observer) const {
	const glm::vec2 observer(p_observer.x, p_observer.z);
	uint32_t nearest = NO_TILE;
	float nearest_distance = 0.0f;
	for (uint32_t t = 0; t < _tiles.size() && t < p_ordered_for.size(); ++t) {
		const float distance = glm::distance((_tiles[t].area_min + _tiles[t].area_max) * 0.5f, observer);
		const glm::vec2 ordered_for = p_ordered_for[t];
		const bool stale = std::isnan(ordered_for.x) ||
				glm::distance(ordered_for, observer) > std::max(TILE_ORDER_SLACK, TILE_ORDER_TURN * distance);
		if (stale && (nearest == NO_TILE || distance < nearest_distance)) {
			nearest = t;
			nearest_distance = distance;
		}
	}
	return nearest;
}

uint64_t FarTiles::get_tile_signature(uint32_t p_tile) const {
	// FNV-1a over the chunks' keys and signatures, never 0 (the level picks which plants it holds).
	uint64_t hash = 1469598103934665603ull ^ _tiles[p_tile].count ^ (uint64_t(_tiles[p_tile].level) << 40);
	for (uint32_t k = 0; k < _tiles[p_tile].count; ++k) {
		const uint32_t chunk = get_tile_chunk(p_tile, k);
		for (uint64_t value : { _plants.get_chunk_key(chunk), _plants.get_chunk_signature(chunk) }) {
			for (int byte = 0; byte < 8; ++byte) {
				hash = (hash ^ ((value >> (8 * byte)) & 0xFFu)) * 1099511628211ull;
			}
		}
	}
	return hash == 0 ? 1 : hash;
}

void FarTiles::follow_observer(const glm::vec3 &p_observer) {
	const glm::vec2 walked(p_observer.x - _tile_count_observer.x, p_observer.z - _tile_count_observer.z);
	if (_tile_counts_due || glm::dot(walked, walked) > TILE_COUNT_SLACK * TILE_COUNT_SLACK) {
		_count_tile_records(p_observer);
	}
}

size_t FarTiles::get_memory_bytes() const {
	size_t bytes = _tile_chunks.capacity() * sizeof(uint32_t) + _tiles.capacity() * sizeof(Tile);
	bytes += (_merged_first.capacity() + _merged_plants.capacity()) * sizeof(uint32_t) + _chunk_kept.capacity() * sizeof(_chunk_kept[0]);
	return bytes + _tile_visible.capacity() * sizeof(uint32_t);
}

} // namespace sunflower
