#include "field_simulation.h"

#include "random_hash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>
#include <cmath>
#include <cstring>

namespace sunflower {

FieldSimulation::FieldSimulation() {
	_make_buckets();
	_wind.configure(WindParams{});
	_lod.configure(LodParams{});
}

bool FieldSimulation::load_map(const std::string &p_text, const std::u32string &p_legend, const std::string &p_source,
		const MapLimits &p_limits, MapError &r_error) {
	return load_map(p_text, p_legend, std::u32string(), p_source, p_limits, r_error);
}

bool FieldSimulation::load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, MapError &r_error) {
	FieldMap parsed;
	if (!parse_field_map(p_text, p_legend, p_plant_symbols, p_source, p_limits, parsed, r_error)) {
		return false;
	}
	_map = std::move(parsed);
	_plant_symbols = p_plant_symbols;
	_rebuild();
	return true;
}

void FieldSimulation::paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density,
		uint64_t p_seed, bool p_relayout, std::vector<int> &r_changed) {
	const size_t before = r_changed.size();
	paint_cells(_map, p_center.x, p_center.y, p_radius, p_content, p_density, p_seed, r_changed);
	if (p_relayout && r_changed.size() != before) {
		_rebuild();
	}
}

void FieldSimulation::replace_map(FieldMap p_map) {
	_map = std::move(p_map);
	_rebuild();
}

void FieldSimulation::clear() {
	_map = FieldMap{};
	_rebuild();
}

bool FieldSimulation::set_layout_params(const LayoutParams &p_params) {
	LayoutParams params = p_params;
	params.cell_size = sanitize(param::CELL_SIZE, p_params.cell_size, _layout_params.cell_size);
	params.chunk_size = sanitize(param::CHUNK_SIZE, p_params.chunk_size, _layout_params.chunk_size);
	params.tile_merge_distance =
			sanitize(param::TILE_MERGE_DISTANCE, p_params.tile_merge_distance, _layout_params.tile_merge_distance);
	for (size_t s = 0; s < params.varieties.size(); ++s) {
		PlantVariety &variety = params.varieties[s];
		const PlantVariety &current = _layout_params.varieties[s];
		variety.yaw_range = sanitize(param::PLANT_YAW_RANGE, variety.yaw_range, current.yaw_range);
		variety.scale_min = sanitize(param::PLANT_SCALE_MIN, variety.scale_min, current.scale_min);
		variety.scale_max = std::max(variety.scale_min, sanitize(param::PLANT_SCALE_MAX, variety.scale_max, current.scale_max));
		variety.brightness = sanitize(param::PLANT_BRIGHTNESS_VARIATION, variety.brightness, current.brightness);
		variety.tint = sanitize(param::PLANT_TINT_VARIATION, variety.tint, current.tint);
	}
	if (params == _layout_params) {
		return false;
	}
	_layout_params = params;
	_rebuild();
	return true;
}

void FieldSimulation::set_ground(Ground p_ground) {
	p_ground.tilt = sanitize(param::GROUND_TILT, p_ground.tilt, _ground.tilt);
	_ground = std::move(p_ground);
	_rebuild();
}

void FieldSimulation::set_lod(const LodParams &p_params) {
	_lod.configure(p_params);
	_lod_due = true;
}

void FieldSimulation::set_shape(const PlantShape &p_shape, uint32_t p_species) {
	if (p_species >= _shapes.size()) {
		return;
	}
	PlantShape &current = _shapes[p_species];
	const PlantShape defaults;
	PlantShape shape = p_shape;
	// A form that is not finite and positive keeps the built-in sunflower's value.
	for (int i = 0; i < 3; ++i) {
		if (!(shape.part_lengths[i] > 0.0f) || !std::isfinite(shape.part_lengths[i])) {
			shape.part_lengths[i] = defaults.part_lengths[i];
		}
	}
	shape.middle_variation = sanitize(param::PLANT_MIDDLE_VARIATION, shape.middle_variation, current.middle_variation);
	shape.stiffness = sanitize(param::PLANT_STIFFNESS, shape.stiffness, current.stiffness);
	shape.height = shape.height > 0.0f && std::isfinite(shape.height) ? shape.height : defaults.height;
	shape.cull_radius = shape.cull_radius > 0.0f && std::isfinite(shape.cull_radius) ? shape.cull_radius : defaults.cull_radius;
	shape.part_scale = shape.part_scale > 0.0f && std::isfinite(shape.part_scale) ? shape.part_scale : current.part_scale;
	const bool drawn_otherwise = shape.whole != current.whole;
	current = shape;
	_chunk_signatures.clear(); // the impostors' scale may have changed
	_lod_due = true;
	if (drawn_otherwise) {
		_make_buckets();
	}
}

void FieldSimulation::set_plant_height(float p_metres, uint32_t p_species) {
	if (p_species >= _shapes.size()) {
		return;
	}
	PlantShape shape = _shapes[p_species];
	const float parts = shape.parts_height();
	shape.part_scale = sanitize(param::PLANT_HEIGHT, p_metres, shape.part_scale * parts) / parts;
	set_shape(shape, p_species);
}

void FieldSimulation::_rebuild() {
	build_layout(_map, _layout_params, _ground, _layout);
	const size_t plants = _layout.plants.size();
	_plant_lod.assign(plants, LOD_BILLBOARD);
	_chunk_wind.clear(); // the old field's states go with their memory
	_chunk_wind.resize(_layout.chunks.size());
	_pushed.clear(); // the slots pointed at the old field's plants
	_chunk_active.assign(_layout.chunks.size(), 0);
	_chunk_signatures.clear(); // the shape or variety may have changed too: computed anew
	_visit_mark.assign(_layout.chunks.size(), 0);
	_lod_pass = 0;
	_active_chunks.clear();
	_previous_active.clear();
	_changed_chunks.clear();
	_active_plants = 0;
	_make_buckets();
	_build_tiles();
	++_mask_version;
	_lod_due = true;
}

void FieldSimulation::_build_tiles() {
	const size_t chunk_count = _layout.chunks.size();
	_chunk_cells.assign(chunk_count, 0);
	for (size_t cell = 0; cell + 1 < _layout.grid_chunks.size(); ++cell) {
		for (uint32_t c = _layout.grid_chunks[cell]; c < _layout.grid_chunks[cell + 1]; ++c) {
			_chunk_cells[c] = static_cast<uint32_t>(cell);
		}
	}
	// Each chunk's tile key, then the chunks grouped by key (in chunk order within a tile).
	const uint64_t tiles_x = uint64_t((_layout.grid_x + TILE_CHUNKS - 1) / TILE_CHUNKS);
	std::vector<std::pair<uint64_t, uint32_t>> keyed(chunk_count);
	for (uint32_t c = 0; c < chunk_count; ++c) {
		const uint64_t x = _chunk_cells[c] % uint32_t(_layout.grid_x) / TILE_CHUNKS;
		const uint64_t z = _chunk_cells[c] / uint32_t(_layout.grid_x) / TILE_CHUNKS;
		keyed[c] = { (z * tiles_x + x) * FieldMap::MAX_SPECIES + _layout.chunks[c].species, c };
	}
	std::sort(keyed.begin(), keyed.end());
	_tiles.clear();
	_tile_chunks.resize(chunk_count);
	for (size_t i = 0; i < chunk_count; ++i) {
		const auto &[key, chunk] = keyed[i];
		if (_tiles.empty() || _tiles.back().key != key) {
			Tile tile;
			tile.first = static_cast<uint32_t>(i);
			tile.species = _layout.chunks[chunk].species;
			tile.key = key;
			_tiles.push_back(tile);
		}
		_tile_chunks[i] = chunk;
		++_tiles.back().count;
		_tiles.back().plants += _layout.chunks[chunk].count;
	}
	_chunk_kept.clear();
	_merged_first.clear();
	_merged_plants.clear();
	if (_layout_params.tile_merge_distance > 0.0f) {
		_merge_tiles();
	}
	_finish_tiles();
}

void FieldSimulation::_finish_tiles() {
	for (Tile &tile : _tiles) {
		const Chunk &first = _layout.chunks[_tile_chunks[tile.first]];
		tile.area_min = first.min;
		tile.area_max = first.max;
		tile.kept_from.fill(0);
		for (uint32_t k = 0; k < tile.count; ++k) {
			const uint32_t chunk = _tile_chunks[tile.first + k];
			tile.area_min = glm::min(tile.area_min, _layout.chunks[chunk].min);
			tile.area_max = glm::max(tile.area_max, _layout.chunks[chunk].max);
			for (uint32_t level = 0; level < MAX_TILE_LEVELS; ++level) {
				tile.kept_from[level] += _chunk_kept.empty() ? _layout.chunks[chunk].count : _chunk_kept[chunk][std::max(level, tile.level)];
			}
		}
	}
	_tile_visible.resize(_tiles.size());
	for (size_t t = 0; t < _tiles.size(); ++t) {
		_tile_visible[t] = _tiles[t].plants;
	}
	_tile_counts_due = true;
}

void FieldSimulation::_count_tile_records() {
	_tile_count_observer = _observer;
	_tile_counts_due = false;
	const glm::vec2 eye(_observer.x, _observer.z);
	for (size_t t = 0; t < _tiles.size(); ++t) {
		const Tile &tile = _tiles[t];
		// The ground distance is at most the distance the shader measures to a root; the observer
		// may move TILE_COUNT_SLACK before the next count.
		const float nearest = glm::length(eye - glm::clamp(eye, tile.area_min, tile.area_max)) - TILE_COUNT_SLACK;
		const uint32_t level = std::max(choose_tile_level(std::max(nearest, 0.0f)).level, tile.level);
		_tile_visible[t] = tile.kept_from[level];
	}
}

void FieldSimulation::_merge_tiles() {
	// Per chunk, how many of its plants each level keeps (level 0: all), and its plants kept at
	// level 1 or above ordered by tile level, highest first (map order within a level), so that a
	// merged tile of level L writes the first kept[c][L] of each chunk's.
	std::vector<std::array<uint32_t, MAX_TILE_LEVELS>> &kept = _chunk_kept;
	kept.assign(_layout.chunks.size(), {});
	_merged_first.assign(_layout.chunks.size(), 0);
	_merged_plants.clear();
	std::vector<std::pair<uint32_t, uint32_t>> ordered; // (MAX_TILE_LEVELS − level, plant)
	for (size_t c = 0; c < _layout.chunks.size(); ++c) {
		const Chunk &chunk = _layout.chunks[c];
		ordered.clear();
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t plant = _layout.chunk_plants[chunk.first + k];
			const uint32_t level = plant_tile_level(_layout.plants[plant]);
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
		const uint64_t tiles_x = (uint64_t(_layout.grid_x) + span - 1) / span;
		std::vector<std::pair<uint64_t, uint32_t>> keyed;
		keyed.reserve(below_end - below_first);
		for (size_t t = below_first; t < below_end; ++t) {
			const uint32_t cell = _chunk_cells[get_tile_chunk(uint32_t(t), 0)];
			const uint64_t x = cell % uint32_t(_layout.grid_x) / span;
			const uint64_t z = cell / uint32_t(_layout.grid_x) / span;
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

uint32_t FieldSimulation::plant_tile_level(const Plant &p_plant) const {
	// Two bits of a hash of the plant's place per level: all zero with probability 1/4, so the
	// plants kept at level L are a quarter of those kept at L − 1, and among them.
	uint32_t x_bits = 0;
	uint32_t z_bits = 0;
	std::memcpy(&x_bits, &p_plant.position.x, sizeof(x_bits));
	std::memcpy(&z_bits, &p_plant.position.y, sizeof(z_bits));
	uint64_t hash = hash_plant(_layout_params.seed, (uint64_t(x_bits) << 32) | z_bits, STREAM_TILE_LEVEL);
	uint32_t level = 0;
	while (level + 1 < MAX_TILE_LEVELS && (hash >> 62) == 0) {
		++level;
		hash <<= 2;
	}
	return level;
}

float FieldSimulation::get_tile_begin(uint32_t p_tile) const {
	return merge_distance(_tiles[p_tile].level);
}

float FieldSimulation::merge_distance(uint32_t p_level) const {
	if (p_level == 0) {
		return 0.0f;
	}
	return _layout_params.tile_merge_distance * float(1u << (p_level - 1));
}

FieldSimulation::TileChoice FieldSimulation::choose_tile_level(float p_distance) const {
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

float FieldSimulation::get_tile_shown_from(uint32_t p_tile) const {
	const Tile &tile = _tiles[p_tile];
	if (tile.level == 0) {
		return 0.0f;
	}
	const ChunkBounds bounds = get_tile_bounds(p_tile);
	const float reach = 0.5f * glm::length(bounds.max - bounds.min); // box centre to its farthest plant
	return merge_distance(tile.level) + reach;
}

ChunkBounds FieldSimulation::get_tile_bounds(uint32_t p_tile) const {
	ChunkBounds bounds = get_chunk_bounds(get_tile_chunk(p_tile, 0));
	for (uint32_t k = 1; k < _tiles[p_tile].count; ++k) {
		const ChunkBounds chunk = get_chunk_bounds(get_tile_chunk(p_tile, k));
		bounds.min = glm::min(bounds.min, chunk.min);
		bounds.max = glm::max(bounds.max, chunk.max);
	}
	return bounds;
}

void FieldSimulation::write_tile_instances(uint32_t p_tile, float *r_out) const {
	const Tile &tile = _tiles[p_tile];
	if (_chunk_kept.empty()) { // tiles do not merge
		for (uint32_t k = 0; k < tile.count; ++k) {
			const Chunk &chunk = _layout.chunks[get_tile_chunk(p_tile, k)];
			_write_records(get_tile_chunk(p_tile, k), _layout.chunk_plants.data() + chunk.first, chunk.count, r_out);
			r_out += size_t(chunk.count) * FAR_FLOATS_PER_INSTANCE;
		}
		return;
	}
	std::vector<uint32_t> level_zero; // a chunk's plants no merged level keeps
	for (uint32_t level = MAX_TILE_LEVELS; level-- > tile.level;) {
		for (uint32_t k = 0; k < tile.count; ++k) {
			const uint32_t chunk = get_tile_chunk(p_tile, k);
			const uint32_t *plants = nullptr;
			uint32_t count = 0;
			if (level > 0) {
				// A chunk's merged plants come highest level first: level L's follow those above it.
				const std::array<uint32_t, MAX_TILE_LEVELS> &kept = _chunk_kept[chunk];
				const uint32_t above = level + 1 < MAX_TILE_LEVELS ? kept[level + 1] : 0;
				plants = _merged_plants.data() + _merged_first[chunk] + above;
				count = kept[level] - above;
			} else {
				level_zero.clear();
				const Chunk &own = _layout.chunks[chunk];
				for (uint32_t p = own.first; p < own.first + own.count; ++p) {
					if (plant_tile_level(_layout.plants[_layout.chunk_plants[p]]) == 0) {
						level_zero.push_back(_layout.chunk_plants[p]);
					}
				}
				plants = level_zero.data();
				count = uint32_t(level_zero.size());
			}
			_write_records(chunk, plants, count, r_out, level - tile.level);
			r_out += size_t(count) * FAR_FLOATS_PER_INSTANCE;
		}
	}
}

uint64_t FieldSimulation::get_tile_signature(uint32_t p_tile) const {
	// FNV-1a over the chunks' keys and signatures, never 0 (the level picks which plants it holds).
	uint64_t hash = 1469598103934665603ull ^ _tiles[p_tile].count ^ (uint64_t(_tiles[p_tile].level) << 40);
	for (uint32_t k = 0; k < _tiles[p_tile].count; ++k) {
		const uint32_t chunk = get_tile_chunk(p_tile, k);
		for (uint64_t value : { get_chunk_key(chunk), get_chunk_signature(chunk) }) {
			for (int byte = 0; byte < 8; ++byte) {
				hash = (hash ^ ((value >> (8 * byte)) & 0xFFu)) * 1099511628211ull;
			}
		}
	}
	return hash == 0 ? 1 : hash;
}

bool FieldSimulation::is_tile_drawn(uint32_t p_tile) const {
	for (uint32_t k = 0; k < _tiles[p_tile].count; ++k) {
		if (!_chunk_active[get_tile_chunk(p_tile, k)]) {
			return true;
		}
	}
	return false;
}

void FieldSimulation::write_active_mask(uint32_t p_species, uint8_t *r_out) const {
	std::fill_n(r_out, size_t(_layout.grid_x) * size_t(_layout.grid_z), uint8_t(0));
	for (uint32_t c : _active_chunks) {
		if (_layout.chunks[c].species == p_species) {
			r_out[_chunk_cells[c]] = 255;
		}
	}
}

void FieldSimulation::set_worker_threads(uint32_t p_threads) {
	uint32_t threads = std::min(p_threads, param::MAX_THREADS);
	if (threads == 0) {
		threads = std::clamp(std::thread::hardware_concurrency(), 1u, param::MAX_AUTO_THREADS);
	}
	if (threads == get_worker_threads()) {
		return;
	}
	_pool.reset(threads > 1 ? new WorkerPool(threads) : nullptr);
	_task_buckets.assign(threads > 1 ? threads * TASKS_PER_THREAD - 1 : 0, BucketSet{});
	_make_buckets();
}

void FieldSimulation::_make_buckets() {
	BucketSet buckets;
	const uint32_t species_count = uint32_t(std::max(_map.species_count, 1));
	for (uint32_t species = 0; species < species_count; ++species) {
		const bool whole = _shapes[species].whole;
		for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
			// Drawn whole, a plant is one instance in its level's first bucket (the others stay empty).
			// The impostors are compact records, as the far tiles' (with the share in place of the cell).
			const bool whole_plants = whole && b < BUCKET_IMPOSTOR && b % PART_COUNT == 0;
			const uint32_t stride = whole_plants ? WHOLE_FLOATS_PER_INSTANCE : FLOATS_PER_INSTANCE;
			buckets.emplace_back(b == BUCKET_IMPOSTOR ? FAR_FLOATS_PER_INSTANCE : stride);
		}
	}
	_buckets = buckets;
	for (BucketSet &set : _task_buckets) {
		set = buckets;
	}
}

ChunkBounds FieldSimulation::get_chunk_bounds(uint32_t p_chunk) const {
	const Chunk &chunk = _layout.chunks[p_chunk];
	const PlantShape &shape = _shapes[chunk.species];
	const float scale = shape.part_scale * chunk.scale_max;
	const float reach = shape.cull_radius * scale;
	ChunkBounds bounds;
	bounds.min = glm::vec3(chunk.min.x - reach, chunk.ground_min, chunk.min.y - reach);
	bounds.max = glm::vec3(chunk.max.x + reach, chunk.ground_max + shape.height * scale * 1.05f, chunk.max.y + reach);
	return bounds;
}

float FieldSimulation::_chunk_distance_sq(uint32_t p_chunk) const {
	const ChunkBounds bounds = get_chunk_bounds(p_chunk);
	const glm::vec3 nearest = glm::clamp(_observer, bounds.min, bounds.max);
	const glm::vec3 d = _observer - nearest;
	return glm::dot(d, d);
}

float FieldSimulation::_plant_distance_sq(const Plant &p_plant) const {
	// From the observer's eye to the plant's middle: on the ground this is the thesis' distance.
	const PlantShape &shape = _shapes[_species_of(p_plant)];
	const glm::vec3 d = _observer - (p_plant.root() + glm::vec3(0.0f, 0.5f * shape.height * shape.part_scale * p_plant.scale, 0.0f));
	return glm::dot(d, d);
}

uint8_t FieldSimulation::_static_chunk_lod(uint32_t p_chunk) const {
	// The engine's visibility-range rule: the sprite is shown while distance ≤ end (= the billboard
	// distance), measured from the camera to the centre of the instance's bounding box.
	const float distance = glm::length(_observer - get_chunk_bounds(p_chunk).center());
	return distance <= get_billboard_distance() ? LOD_SPRITE : LOD_BILLBOARD;
}

FieldSimulation::GridRange FieldSimulation::_grid_range(const glm::vec2 &p_center, float p_reach) const {
	const float size = _layout.chunk_size;
	GridRange range;
	range.x0 = std::max(0, static_cast<int>(std::floor((p_center.x - p_reach) / size)));
	range.x1 = std::min(_layout.grid_x - 1, static_cast<int>(std::floor((p_center.x + p_reach) / size)));
	range.z0 = std::max(0, static_cast<int>(std::floor((p_center.y - p_reach) / size)));
	range.z1 = std::min(_layout.grid_z - 1, static_cast<int>(std::floor((p_center.y + p_reach) / size)));
	return range;
}

void FieldSimulation::_select_lods() {
	const LodParams &params = _lod.get_params();
	// A chunk becomes active once any of it could need a mesh; it goes static again a margin later.
	// A forced representation makes every chunk active, so every plant is drawn in it.
	const bool forced = params.force_level >= 0 && params.force_level < LOD_COUNT;
	const float enter = params.distances[2] + 2.0f * params.hysteresis;
	const float leave = enter + 2.0f * params.hysteresis + 1.0f;
	_changed_chunks.clear();
	_previous_active.swap(_active_chunks);
	_active_chunks.clear();
	_active_plants = 0;
	++_lod_pass;
	if (forced) {
		for (uint32_t c = 0; c < _layout.chunks.size(); ++c) {
			_select_chunk_lods(c, true, enter, leave);
		}
		return;
	}
	// Only chunks that are active now, or whose grid cell lies within reach, can be active next:
	// the work depends on what is near the observer, not on the size of the field.
	for (uint32_t c : _previous_active) {
		_select_chunk_lods(c, false, enter, leave);
	}
	float plant_reach = 0.0f; // the farthest a plant of any species reaches from its root
	for (uint32_t species = 0; species < get_species_count(); ++species) {
		const PlantShape &shape = _shapes[species];
		plant_reach = std::max(plant_reach, shape.cull_radius * shape.part_scale * _layout_params.varieties[species].scale_max);
	}
	const float reach = leave + plant_reach;
	const GridRange cells = _grid_range(glm::vec2(_observer.x, _observer.z), reach);
	// Chunks turning active are taken nearest first, at most ACTIVATION_BUDGET plants per update: after
	// a jump of the observer the plants next to it are meshes at once, and the rest of the
	// neighbourhood follows over the next updates (drawn as static impostors meanwhile) instead of
	// all in one long frame.
	_activation.clear();
	for (int z = cells.z0; z <= cells.z1; ++z) {
		for (int x = cells.x0; x <= cells.x1; ++x) {
			const size_t cell = static_cast<size_t>(z) * size_t(_layout.grid_x) + size_t(x);
			for (uint32_t c = _layout.grid_chunks[cell]; c < _layout.grid_chunks[cell + 1]; ++c) {
				if (_visit_mark[c] == _lod_pass) {
					continue;
				}
				const float distance_sq = _chunk_distance_sq(c);
				if (distance_sq < enter * enter) {
					_activation.push_back({ distance_sq, c });
				}
				_visit_mark[c] = _lod_pass;
			}
		}
	}
	std::sort(_activation.begin(), _activation.end());
	uint32_t activated = 0;
	for (const auto &[distance_sq, c] : _activation) {
		if (activated >= ACTIVATION_BUDGET) {
			_lod_due = true; // the rest next update
			break;
		}
		activated += _layout.chunks[c].count;
		_select_chunk_lods(c, false, enter, leave);
	}
	_lod_observer = _observer;
}

void FieldSimulation::_select_chunk_lods(uint32_t p_chunk, bool p_forced, float p_enter, float p_leave) {
	const LodParams &params = _lod.get_params();
	_visit_mark[p_chunk] = _lod_pass;
	const float distance_sq = p_forced ? 0.0f : _chunk_distance_sq(p_chunk);
	const bool was_active = _chunk_active[p_chunk] != 0;
	const bool active = p_forced || (was_active ? distance_sq < p_leave * p_leave : distance_sq < p_enter * p_enter);
	if (active != was_active) {
		_chunk_active[p_chunk] = active ? 1 : 0;
		_changed_chunks.push_back(p_chunk);
	}
	const Chunk &chunk = _layout.chunks[p_chunk];
	std::vector<PlantWind> &winds = _chunk_wind[p_chunk];
	if (!active) {
		if (was_active) {
			_drop_pushes(p_chunk);
			std::vector<PlantWind>().swap(winds); // its memory back: only active chunks hold wind state
		}
		return;
	}
	_active_chunks.push_back(p_chunk);
	_active_plants += chunk.count;
	if (!was_active) {
		winds.assign(chunk.count, PlantWind{});
	}
	for (uint32_t k = 0; k < chunk.count; ++k) {
		const uint32_t index = _layout.chunk_plants[chunk.first + k];
		const float plant_sq = _plant_distance_sq(_layout.plants[index]);
		if (p_forced) {
			if (!was_active || _plant_lod[index] != params.force_level) {
				_wind.init_plant(winds[k], _layout_params.seed, index, _time);
			}
			_plant_lod[index] = static_cast<uint8_t>(params.force_level);
		} else if (!was_active) {
			_plant_lod[index] = _lod.select(plant_sq);
			_wind.init_plant(winds[k], _layout_params.seed, index, _time);
		} else {
			_plant_lod[index] = _lod.update(_plant_lod[index], plant_sq);
		}
	}
}

void FieldSimulation::update(float p_delta) {
	const float delta = std::isfinite(p_delta) ? std::clamp(p_delta, 0.0f, 1.0f) : 0.0f;
	_time += double(delta);
	_wind.advance(delta);
	_update_pushes(delta);
	_since_lod += delta;
	const glm::vec3 moved = _observer - _lod_observer;
	if (glm::dot(moved, moved) > JUMP_DISTANCE * JUMP_DISTANCE) {
		_lod_due = true; // the observer jumped: do not wait for the interval
	}
	const glm::vec2 walked(_observer.x - _tile_count_observer.x, _observer.z - _tile_count_observer.z);
	if (_tile_counts_due || glm::dot(walked, walked) > TILE_COUNT_SLACK * TILE_COUNT_SLACK) {
		_count_tile_records();
	}
	if (_lod_due || _since_lod >= _lod.get_params().interval) {
		_lod_due = false; // _select_lods() sets it again when chunks are left for the next update
		_since_lod = 0.0f;
		_select_lods();
		_mask_version += _changed_chunks.empty() ? 0 : 1;
	} else {
		_changed_chunks.clear();
	}

	// The near work: split into contiguous runs of active chunks, one per thread, when there is
	// enough of it. Each run writes its own buckets, appended in order, so the result is the same
	// as on one thread.
	uint32_t tasks = 1;
	if (_pool && _active_plants >= _parallel_min_plants) {
		tasks = static_cast<uint32_t>(std::min<size_t>(_pool->get_thread_count() * TASKS_PER_THREAD, _active_chunks.size()));
	}
	_last_tasks = std::max(tasks, 1u);
	if (_last_tasks == 1) {
		_move_chunks(0, _active_chunks.size(), delta, _buckets);
		return;
	}
	const size_t chunks = _active_chunks.size();
	auto move = [&](uint32_t p_task) {
		_move_chunks(chunks * p_task / tasks, chunks * (p_task + 1) / tasks, delta,
				p_task == 0 ? _buckets : _task_buckets[p_task - 1]);
	};
	_pool->run(tasks, move);
	for (uint32_t task = 1; task < tasks; ++task) {
		for (size_t b = 0; b < _buckets.size(); ++b) {
			_buckets[b].append(_task_buckets[task - 1][b]);
		}
	}
}

void FieldSimulation::_move_chunks(size_t p_first, size_t p_last, float p_delta, BucketSet &r_buckets) {
	for (InstanceBuffer &bucket : r_buckets) {
		bucket.clear();
	}
	const bool moving = _wind.get_effective_power() > 0.0f;
	const bool advancing = moving && _wind.advances_plants(); // plants with wind state of their own
	const bool fading = _lod.get_params().force_level < 0 && _lod.get_params().fade > 0.0f;
	PartTransforms parts;
	WholePlant whole;
	for (size_t a = p_first; a < p_last; ++a) {
		const Chunk &chunk = _layout.chunks[_active_chunks[a]];
		PlantWind *winds = _chunk_wind[_active_chunks[a]].data();
		const PlantShape &shape = _shapes[chunk.species];
		const PlantVariety &variety = _layout_params.varieties[chunk.species];
		InstanceBuffer *buckets = r_buckets.data() + size_t(chunk.species) * BUCKET_COUNT;
		const float radius = shape.cull_radius * shape.part_scale;
		const float mid_height = 0.5f * shape.height * shape.part_scale;
		// The chunk against the frustum first, by a box that holds its plants' culling spheres: a
		// chunk out of view only keeps its mesh plants' wind going, one fully in view skips the
		// plants' own tests. Either way each plant ends as its own test would have it.
		const float reach_max = radius * chunk.scale_max;
		const glm::vec3 low(chunk.min.x - reach_max, chunk.ground_min + std::min(0.0f, (mid_height - radius) * chunk.scale_max),
				chunk.min.y - reach_max);
		const glm::vec3 high(chunk.max.x + reach_max, chunk.ground_max + (mid_height + radius) * chunk.scale_max,
				chunk.max.y + reach_max);
		Frustum crossing; // the planes the chunk's box crosses: its plants need test only those
		const Frustum::Overlap overlap = _frustum.classify_box(low, high, &crossing);
		if (overlap == Frustum::OUTSIDE) {
			for (uint32_t k = 0; advancing && k < chunk.count; ++k) {
				const uint32_t index = _layout.chunk_plants[chunk.first + k];
				if (_plant_lod[index] < LOD_SPRITE) {
					_wind.advance_plant(winds[k], _layout_params.seed, index, _time, p_delta);
				}
			}
			continue;
		}
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t index = _layout.chunk_plants[chunk.first + k];
			const Plant &plant = _layout.plants[index];
			const uint8_t lod = _plant_lod[index];
			const glm::vec3 middle = plant.root() + glm::vec3(0.0f, mid_height * plant.scale, 0.0f);
			const float reach = radius * plant.scale; // the culling sphere's radius
			const bool visible = overlap == Frustum::INSIDE || crossing.intersects_sphere(middle, reach);
			if (lod >= LOD_SPRITE) {
				if (visible) {
					_write_impostor(buckets[BUCKET_IMPOSTOR].push(), plant);
					buckets[BUCKET_IMPOSTOR].include(middle, reach);
				}
				continue;
			}
			PlantWind &wind = winds[k];
			if (advancing) {
				_wind.advance_plant(wind, _layout_params.seed, index, _time, p_delta);
			}
			if (!visible) {
				continue;
			}
			// Mesh 3 near the sprite switch dithers into the impostor: both drawn, the impostor's
			// share in its colour's alpha, the mesh's in the rest (complementary screen-door patterns).
			const float share = lod == LOD_MESH_3 && fading ? _lod.impostor_share(_plant_distance_sq(plant)) : 0.0f;
			if (share > 0.0f) {
				_write_impostor(buckets[BUCKET_IMPOSTOR].push(), plant, share);
				buckets[BUCKET_IMPOSTOR].include(middle, reach);
				if (share >= 1.0f) {
					continue;
				}
			}
			glm::vec4 color = plant.color(variety);
			color.w = 1.0f - share;
			if (shape.whole) {
				_wind.whole_plant(plant, _plant_bend(wind, plant, moving), shape, whole);
				// Drawn whole (by the addon's plant shader), mesh 1 and 2 near their switches dither into
				// the next level the same way: the coarser mesh keeps the other pixels, which a negative
				// alpha asks for (plant_surface.gdshaderinc).
				const float coarser = lod < LOD_MESH_3 && fading ? _lod.fade_share(lod, _plant_distance_sq(plant)) : 0.0f;
				if (coarser > 0.0f) {
					InstanceBuffer &next = buckets[mesh_bucket(lod + 1u, 0)];
					write_whole_instance(next.push(), whole, glm::vec4(glm::vec3(color), coarser < 1.0f ? -coarser : 1.0f));
					next.include(middle, reach);
					if (coarser >= 1.0f) {
						continue;
					}
					color.w = 1.0f - coarser;
				}
				InstanceBuffer &bucket = buckets[mesh_bucket(lod, 0)];
				write_whole_instance(bucket.push(), whole, color);
				bucket.include(middle, reach);
				continue;
			}
			_wind.part_transforms(plant, _plant_bend(wind, plant, moving), shape, parts);
			for (uint32_t part = 0; part < PART_COUNT; ++part) {
				InstanceBuffer &bucket = buckets[mesh_bucket(lod, part)];
				write_instance(bucket.push(), parts.basis[part], parts.origin[part], color);
				bucket.include(middle, reach);
			}
		}
	}
}

glm::vec2 FieldSimulation::_plant_bend(const PlantWind &p_wind, const Plant &p_plant, bool p_moving) const {
	glm::vec2 bend = p_moving ? _wind.bend_vector(p_wind, p_plant.position) : glm::vec2(0.0f);
	if (p_wind.push_slot == 0) {
		return bend;
	}
	bend += _pushed[p_wind.push_slot - 1u].offset;
	const float size = glm::length(bend);
	const float limit = _wind.get_bend_limit();
	return size > limit ? bend * (limit / size) : bend; // a pushed plant still bends at most max_bend
}

void FieldSimulation::set_pushers(const Pusher *p_pushers, size_t p_count) {
	_pushers.assign(p_pushers, p_pushers + p_count);
}

void FieldSimulation::set_push_params(float p_strength, float p_recovery_seconds) {
	_push_strength = sanitize(param::PUSH_STRENGTH, p_strength, _push_strength);
	_push_recovery = sanitize(param::PUSH_RECOVERY, p_recovery_seconds, _push_recovery);
}

void FieldSimulation::find_plants_near(const glm::vec2 &p_center, float p_radius, std::vector<uint32_t> &r_plants) const {
	if (_layout.grid_chunks.empty() || !(p_radius >= 0.0f) || !std::isfinite(p_radius) || !std::isfinite(p_center.x) ||
			!std::isfinite(p_center.y)) {
		return;
	}
	const GridRange cells = _grid_range(p_center, p_radius);
	const float radius_sq = p_radius * p_radius;
	for (int z = cells.z0; z <= cells.z1; ++z) {
		for (int x = cells.x0; x <= cells.x1; ++x) {
			const size_t cell = static_cast<size_t>(z) * size_t(_layout.grid_x) + size_t(x);
			for (uint32_t c = _layout.grid_chunks[cell]; c < _layout.grid_chunks[cell + 1]; ++c) {
				const Chunk &chunk = _layout.chunks[c];
				for (uint32_t k = 0; k < chunk.count; ++k) {
					const uint32_t index = _layout.chunk_plants[chunk.first + k];
					const glm::vec2 d = _layout.plants[index].position - p_center;
					if (glm::dot(d, d) < radius_sq) {
						r_plants.push_back(index);
					}
				}
			}
		}
	}
}

const PlantWind *FieldSimulation::_wind_of(uint32_t p_plant) const {
	const uint32_t chunk = _layout.plants[p_plant].chunk;
	if (!_chunk_active[chunk]) {
		return nullptr;
	}
	// A chunk lists its plants in map order, so the plant's place among them is found by bisection.
	const Chunk &range = _layout.chunks[chunk];
	const auto first = _layout.chunk_plants.begin() + range.first;
	const auto found = std::lower_bound(first, first + range.count, p_plant);
	return _chunk_wind[chunk].data() + (found - first);
}

PlantWind *FieldSimulation::_wind_of(uint32_t p_plant) {
	return const_cast<PlantWind *>(static_cast<const FieldSimulation *>(this)->_wind_of(p_plant));
}

void FieldSimulation::_drop_pushes(uint32_t p_chunk) {
	for (size_t i = 0; i < _pushed.size();) {
		if (_layout.plants[_pushed[i].plant].chunk != p_chunk) {
			++i;
			continue;
		}
		if (i + 1 < _pushed.size()) {
			_pushed[i] = _pushed.back(); // looked at next: dropped too if it is the chunk's
			if (_layout.plants[_pushed[i].plant].chunk != p_chunk) {
				_wind_of(_pushed[i].plant)->push_slot = static_cast<uint16_t>(i + 1);
			}
		}
		_pushed.pop_back();
	}
}

void FieldSimulation::_update_pushes(float p_delta) {
	if (_pushers.empty() && _pushed.empty()) {
		return;
	}
	for (PushState &state : _pushed) {
		state.target = glm::vec2(0.0f);
	}
	for (const Pusher &pusher : _pushers) {
		if (!(pusher.radius > 0.0f)) {
			continue;
		}
		const glm::vec2 center(pusher.position.x, pusher.position.z);
		_near.clear();
		find_plants_near(center, pusher.radius, _near);
		for (uint32_t index : _near) {
			const Plant &plant = _layout.plants[index];
			const float above_root = pusher.position.y - plant.ground;
			const PlantShape &shape = _shapes[_species_of(plant)];
			if (above_root - pusher.radius > shape.height * shape.part_scale * plant.scale || above_root + pusher.radius < 0.0f) {
				continue; // flying over the plant, or under its ground
			}
			PlantWind *const state = _wind_of(index);
			if (state == nullptr) {
				continue; // not near: drawn as an impostor, which shows no push
			}
			PlantWind &wind = *state;
			if (wind.push_slot == 0) {
				if (_pushed.size() >= 0xFFFFu) {
					continue; // more than 65 535 plants pushed at once: the rest stay as they are
				}
				_pushed.push_back(PushState{ index, glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f) });
				wind.push_slot = static_cast<uint16_t>(_pushed.size());
			}
			const glm::vec2 away = _layout.plants[index].position - center;
			const float distance = glm::length(away);
			const glm::vec2 direction = distance > 1e-4f ? away / distance : glm::vec2(1.0f, 0.0f);
			_pushed[wind.push_slot - 1u].target += direction * (_push_strength * (1.0f - distance / pusher.radius));
		}
	}
	// Critically damped springs towards the targets, solved exactly (stable for any frame time):
	// with e = offset − target, e(t) = (e₀ + (v₀ + ω·e₀)·t)·e^(−ω·t). ω makes a released plant settle
	// to 0.1 % of its push ((1 + 9.2)·e^(−9.2)) in the recovery time, when its state is dropped.
	const float omega = 9.2f / _push_recovery;
	const float decay = std::exp(-omega * p_delta);
	for (size_t i = 0; i < _pushed.size();) {
		PushState &state = _pushed[i];
		const glm::vec2 e0 = state.offset - state.target;
		const glm::vec2 v0 = state.velocity;
		const glm::vec2 c = v0 + omega * e0;
		state.offset = state.target + (e0 + c * p_delta) * decay;
		state.velocity = (v0 - omega * c * p_delta) * decay;
		const bool settled = state.target == glm::vec2(0.0f) && glm::dot(state.offset, state.offset) < 4e-6f &&
				glm::dot(state.velocity, state.velocity) < 4e-4f;
		if (!settled) {
			++i;
			continue;
		}
		_wind_of(state.plant)->push_slot = 0;
		if (i + 1 < _pushed.size()) {
			state = _pushed.back();
			_wind_of(state.plant)->push_slot = static_cast<uint16_t>(i + 1);
		}
		_pushed.pop_back();
	}
}

FarInstance FieldSimulation::_far_instance(const Plant &p_plant, uint32_t p_species) const {
	FarInstance instance;
	instance.root = p_plant.root();
	instance.yaw = p_plant.yaw;
	instance.scale = _shapes[p_species].part_scale * p_plant.scale;
	instance.lean = p_plant.lean();
	instance.tone = p_plant.tone(_layout_params.varieties[p_species]);
	return instance;
}

void FieldSimulation::_write_impostor(float *r_out, const Plant &p_plant, float p_share) const {
	write_far_instance(r_out, _far_instance(p_plant, _species_of(p_plant)));
	r_out[FAR_CELL_OR_SHARE] = p_share;
}

void FieldSimulation::write_chunk_instances(uint32_t p_chunk, float *r_out) const {
	const Chunk &chunk = _layout.chunks[p_chunk];
	_write_records(p_chunk, _layout.chunk_plants.data() + chunk.first, chunk.count, r_out);
}

void FieldSimulation::_write_records(uint32_t p_chunk, const uint32_t *p_plants, uint32_t p_count, float *r_out, uint32_t p_levels_above) const {
	const uint32_t species = _layout.chunks[p_chunk].species;
	for (uint32_t k = 0; k < p_count; ++k) {
		const Plant &plant = _layout.plants[p_plants[k]];
		FarInstance instance = _far_instance(plant, species);
		instance.cell = _chunk_cells[p_chunk];
		instance.levels_above = p_levels_above;
		write_far_instance(r_out + size_t(k) * FAR_FLOATS_PER_INSTANCE, instance);
	}
}

uint64_t FieldSimulation::get_chunk_key(uint32_t p_chunk) const {
	return uint64_t(_chunk_cells[p_chunk]) * FieldMap::MAX_SPECIES + _layout.chunks[p_chunk].species;
}

uint64_t FieldSimulation::get_chunk_signature(uint32_t p_chunk) const {
	if (p_chunk < _chunk_signatures.size() && _chunk_signatures[p_chunk] != 0) {
		return _chunk_signatures[p_chunk];
	}
	const uint32_t count = _layout.chunks[p_chunk].count;
	std::vector<float> instances(size_t(count) * FAR_FLOATS_PER_INSTANCE);
	write_chunk_instances(p_chunk, instances.data());
	// FNV-1a over the bytes of the instance data, never 0.
	uint64_t hash = 1469598103934665603ull ^ count;
	const uint8_t *bytes = reinterpret_cast<const uint8_t *>(instances.data());
	for (size_t i = 0; i < instances.size() * sizeof(float); ++i) {
		hash = (hash ^ bytes[i]) * 1099511628211ull;
	}
	return hash == 0 ? 1 : hash;
}

void FieldSimulation::compute_chunk_signatures() {
	_chunk_signatures.assign(_layout.chunks.size(), 0);
	for (uint32_t c = 0; c < _layout.chunks.size(); ++c) {
		_chunk_signatures[c] = get_chunk_signature(c);
	}
}

uint8_t FieldSimulation::get_plant_lod(uint32_t p_plant) const {
	const uint32_t chunk = _layout.plants[p_plant].chunk;
	return _chunk_active[chunk] ? _plant_lod[p_plant] : _static_chunk_lod(chunk);
}

std::array<int64_t, LOD_COUNT> FieldSimulation::get_lod_counts() const {
	std::array<int64_t, LOD_COUNT> counts{};
	for (uint32_t species = 0; species < get_species_count(); ++species) {
		const std::array<int64_t, LOD_COUNT> own = get_lod_counts(species);
		for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
			counts[lod] += own[lod];
		}
	}
	return counts;
}

std::array<int64_t, LOD_COUNT> FieldSimulation::get_lod_counts(uint32_t p_species) const {
	std::array<int64_t, LOD_COUNT> counts{};
	for (uint32_t c = 0; c < _layout.chunks.size(); ++c) {
		const Chunk &chunk = _layout.chunks[c];
		if (chunk.species != p_species) {
			continue;
		}
		if (!_chunk_active[c]) {
			counts[_static_chunk_lod(c)] += chunk.count;
			continue;
		}
		for (uint32_t k = 0; k < chunk.count; ++k) {
			++counts[_plant_lod[_layout.chunk_plants[chunk.first + k]]];
		}
	}
	return counts;
}

size_t FieldSimulation::get_memory_bytes() const {
	size_t bytes = _map.plants.capacity() + _map.objects.capacity() * sizeof(MapObject);
	bytes += _layout.plants.capacity() * sizeof(Plant) + _layout.chunks.capacity() * sizeof(Chunk);
	bytes += _layout.chunk_plants.capacity() * sizeof(uint32_t);
	bytes += _plant_lod.capacity() + _chunk_wind.capacity() * sizeof(_chunk_wind[0]);
	for (const std::vector<PlantWind> &winds : _chunk_wind) {
		bytes += winds.capacity() * sizeof(PlantWind);
	}
	bytes += _chunk_active.capacity() + _visit_mark.capacity() * sizeof(uint32_t);
	bytes += (_chunk_cells.capacity() + _tile_chunks.capacity()) * sizeof(uint32_t) + _tiles.capacity() * sizeof(Tile);
	bytes += (_merged_first.capacity() + _merged_plants.capacity()) * sizeof(uint32_t) + _chunk_kept.capacity() * sizeof(_chunk_kept[0]);
	bytes += (_active_chunks.capacity() + _previous_active.capacity() + _changed_chunks.capacity()) * sizeof(uint32_t);
	bytes += _layout.grid_chunks.capacity() * sizeof(uint32_t) + _layout.object_ground.capacity() * sizeof(float);
	bytes += (_ground.grid.heights.capacity() + _ground.heights.capacity() + _ground.normals.capacity()) * sizeof(float);
	bytes += _pushed.capacity() * sizeof(PushState) + _pushers.capacity() * sizeof(Pusher);
	bytes += _near.capacity() * sizeof(uint32_t) + _activation.capacity() * sizeof(_activation[0]);
	for (const InstanceBuffer &bucket : _buckets) {
		bytes += size_t(bucket.get_capacity()) * bucket.get_stride() * sizeof(float);
	}
	for (const BucketSet &set : _task_buckets) {
		for (const InstanceBuffer &bucket : set) {
			bytes += size_t(bucket.get_capacity()) * bucket.get_stride() * sizeof(float);
		}
	}
	return bytes;
}

void FieldSimulation::get_plant_parts(uint32_t p_plant, PartTransforms &r_parts) const {
	const Plant &plant = _layout.plants[p_plant];
	glm::vec2 bend(0.0f);
	const PlantWind *wind = _wind_of(p_plant);
	if (wind != nullptr && _plant_lod[p_plant] < LOD_SPRITE) {
		bend = _plant_bend(*wind, plant, _wind.get_effective_power() > 0.0f);
	}
	_wind.part_transforms(plant, bend, _shapes[_species_of(plant)], r_parts);
}

} // namespace sunflower
