// NearField's level-of-detail pass: which chunks are active, and each active plant's level.
#include "near_field.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sunflower {

float NearField::_chunk_distance_sq(uint32_t p_chunk) const {
	const ChunkBounds bounds = _plants.get_chunk_bounds(p_chunk);
	const glm::vec3 nearest = glm::clamp(_observer, bounds.min, bounds.max);
	const glm::vec3 d = _observer - nearest;
	return glm::dot(d, d);
}

uint8_t NearField::_static_chunk_lod(uint32_t p_chunk) const {
	// The engine's visibility-range rule: the sprite is shown while distance ≤ end (= the billboard
	// distance, scaled for the plant type), measured from the camera to the centre of the instance's
	// bounding box.
	const float distance = glm::length(_observer - _plants.get_chunk_bounds(p_chunk).center());
	const float scale = _plants.get_shape(_plants.get_layout().chunks[p_chunk].species).lod_scale;
	return distance <= get_billboard_distance() * scale ? LOD_SPRITE : LOD_BILLBOARD;
}

void NearField::_activation_bounds(bool &r_forced, float &r_enter, float &r_leave) const {
	const LodParams &params = _lod.get_params();
	// A chunk becomes active once any of it could need a mesh; it goes static again a margin later.
	// A forced representation makes every chunk active, so every plant is drawn in it.
	r_forced = params.force_level >= 0 && params.force_level < LOD_COUNT;
	r_enter = params.distances[2] + 2.0f * params.hysteresis;
	r_leave = r_enter + 2.0f * params.hysteresis + 1.0f;
}

void NearField::_select_added_lods() {
	bool forced = false;
	float enter = 0.0f;
	float leave = 0.0f;
	_activation_bounds(forced, enter, leave);
	for (uint32_t c = _plants.get_map_chunk_count(); c < _plants.get_chunk_count(); ++c) {
		_select_chunk_lods(c, forced, enter, leave);
	}
}

void NearField::_select_lods() {
	const FieldLayout &layout = _plants.get_layout();
	bool forced = false;
	float enter = 0.0f;
	float leave = 0.0f;
	_activation_bounds(forced, enter, leave);
	_changed_chunks = 0;
	_previous_active.swap(_active_chunks);
	_active_chunks.clear();
	_active_plants = 0;
	++_lod_pass;
	if (forced) {
		for (uint32_t c = 0; c < layout.chunks.size(); ++c) {
			_select_chunk_lods(c, true, enter, leave);
		}
		return;
	}
	// Only chunks that are active now, or whose grid cell lies within reach, can be active next:
	// the work depends on what is near the observer, not on the size of the field.
	for (uint32_t c : _previous_active) {
		_select_chunk_lods(c, false, enter, leave);
	}
	// The chunks of plants play added are active at every distance (no far tile draws them).
	for (uint32_t c = _plants.get_map_chunk_count(); c < layout.chunks.size(); ++c) {
		if (_visit_mark[c] != _lod_pass) {
			_select_chunk_lods(c, false, enter, leave);
		}
	}
	float largest_scale = 0.0f; // of the plant types' switch distances
	for (uint32_t species = 0; species < _plants.get_species_count(); ++species) {
		largest_scale = std::max(largest_scale, _plants.get_shape(species).lod_scale);
	}
	const float reach = leave * largest_scale + _plants.get_plant_reach();
	const GridRange cells = _plants.grid_range(glm::vec2(_observer.x, _observer.z), reach);
	// Chunks turning active are taken nearest first, at most ACTIVATION_BUDGET plants per update: after
	// a jump of the observer the plants next to it are meshes at once, and the rest of the
	// neighbourhood follows over the next updates (drawn as static impostors meanwhile) instead of
	// all in one long frame.
	_activation.clear();
	for (int z = cells.z0; z <= cells.z1; ++z) {
		for (int x = cells.x0; x <= cells.x1; ++x) {
			const size_t cell = static_cast<size_t>(z) * size_t(layout.grid_x) + size_t(x);
			for (uint32_t c = layout.grid_chunks[cell]; c < layout.grid_chunks[cell + 1]; ++c) {
				if (_visit_mark[c] == _lod_pass) {
					continue;
				}
				const float distance_sq = _plants.get_shape(layout.chunks[c].species).lod_distance_sq(_chunk_distance_sq(c));
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
		activated += layout.chunks[c].count;
		_select_chunk_lods(c, false, enter, leave);
	}
	_lod_observer = _observer;
}

void NearField::_select_chunk_lods(uint32_t p_chunk, bool p_forced, float p_enter, float p_leave) {
	const FieldLayout &layout = _plants.get_layout();
	const LodParams &params = _lod.get_params();
	_visit_mark[p_chunk] = _lod_pass;
	const Chunk &chunk = layout.chunks[p_chunk];
	const PlantShape &shape = _plants.get_shape(chunk.species);
	// Distances as the field's switch distances see them for this plant type (PlantShape::lod_scale).
	const float distance_sq = p_forced ? 0.0f : shape.lod_distance_sq(_chunk_distance_sq(p_chunk));
	const bool was_active = _chunk_active[p_chunk] != 0;
	const bool added = p_chunk >= _plants.get_map_chunk_count();
	const bool active =
			p_forced || added || (was_active ? distance_sq < p_leave * p_leave : distance_sq < p_enter * p_enter);
	if (active != was_active) {
		_chunk_active[p_chunk] = active ? 1 : 0;
		++_changed_chunks;
	}
	std::vector<PlantWind> &winds = _chunk_wind[p_chunk];
	if (!active) {
		if (was_active) {
			_pushes.drop_chunk(p_chunk, _plants.get_layout(), _wind_lookup);
			std::vector<PlantWind>().swap(winds); // its memory back: only active chunks hold wind state
			std::vector<float>().swap(_chunk_records[p_chunk]);
		}
		return;
	}
	_active_chunks.push_back(p_chunk);
	_active_plants += chunk.count;
	if (!was_active) {
		winds.assign(chunk.count, PlantWind{});
		_write_records(p_chunk);
	}
	for (uint32_t k = 0; k < chunk.count; ++k) {
		const uint32_t index = layout.chunk_plants[chunk.first + k];
		const float plant_sq = shape.lod_distance_sq(_plants.plant_distance_sq(layout.plants[index], _observer));
		if (p_forced) {
			if (!was_active || _plant_lod[index] != params.force_level) {
				_wind.init_plant(winds[k], _plants.get_layout_params().seed, index, _time);
			}
			_plant_lod[index] = static_cast<uint8_t>(params.force_level);
		} else if (!was_active) {
			_plant_lod[index] = _lod.select(plant_sq);
			_wind.init_plant(winds[k], _plants.get_layout_params().seed, index, _time);
		} else {
			_plant_lod[index] = _lod.update(_plant_lod[index], plant_sq);
		}
	}
}

uint8_t NearField::get_plant_lod(uint32_t p_plant) const {
	const FieldLayout &layout = _plants.get_layout();
	const uint32_t chunk = layout.plants[p_plant].chunk;
	if (chunk >= _chunk_active.size()) {
		return LOD_BILLBOARD; // an added plant taken since, or not drawn yet
	}
	return _chunk_active[chunk] ? _plant_lod[p_plant] : _static_chunk_lod(chunk);
}

std::array<int64_t, LOD_COUNT> NearField::get_lod_counts() const {
	std::array<int64_t, LOD_COUNT> counts{};
	for (uint32_t species = 0; species < _plants.get_species_count(); ++species) {
		const std::array<int64_t, LOD_COUNT> own = get_lod_counts(species);
		for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
			counts[lod] += own[lod];
		}
	}
	return counts;
}

std::array<int64_t, LOD_COUNT> NearField::get_lod_counts(uint32_t p_species) const {
	const FieldLayout &layout = _plants.get_layout();
	std::array<int64_t, LOD_COUNT> counts{};
	for (uint32_t c = 0; c < layout.chunks.size(); ++c) {
		const Chunk &chunk = layout.chunks[c];
		if (chunk.species != p_species) {
			continue;
		}
		if (!_chunk_active[c]) {
			counts[_static_chunk_lod(c)] += chunk.count;
			continue;
		}
		for (uint32_t k = 0; k < chunk.count; ++k) {
			++counts[_plant_lod[layout.chunk_plants[chunk.first + k]]];
		}
	}
	return counts;
}

} // namespace sunflower
