#include "near_field.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

namespace sunflower {

NearField::NearField(const FieldPlants &p_plants) :
		_plants(p_plants), _wind_lookup([this](uint32_t p_plant) { return _wind_of(p_plant); }) {
	_wind.configure(WindParams{});
	_lod.configure(LodParams{});
	make_buckets();
}

void NearField::rebuild() {
	const size_t chunks = _plants.get_chunk_count();
	_plant_lod.assign(_plants.get_plant_count(), LOD_BILLBOARD);
	_chunk_wind.clear(); // the old field's states go with their memory
	_chunk_wind.resize(chunks);
	_chunk_records.clear();
	_chunk_records.resize(chunks);
	_pushes.clear(); // the slots pointed at the old field's plants
	_chunk_active.assign(chunks, 0);
	_visit_mark.assign(chunks, 0);
	_lod_pass = 0;
	_active_chunks.clear();
	_previous_active.clear();
	_changed_chunks = 0;
	_active_plants = 0;
	make_buckets();
	_lod_due = true;
}

void NearField::drop_added() {
	const FieldLayout &layout = _plants.get_layout();
	const uint32_t map_chunks = _plants.get_map_chunk_count();
	// (By index: an added plant's slot may already hold a plant added since, not yet in a chunk.)
	_pushes.drop_plants_from(_plants.get_map_plant_count(), _wind_lookup);
	const auto added = [map_chunks](uint32_t p_chunk) { return p_chunk >= map_chunks; };
	for (uint32_t c : _active_chunks) { // (the added chunks are all active: each turns static here)
		if (added(c)) {
			_active_plants -= layout.chunks[c].count;
			++_changed_chunks;
		}
	}
	_active_chunks.erase(std::remove_if(_active_chunks.begin(), _active_chunks.end(), added), _active_chunks.end());
	_previous_active.erase(std::remove_if(_previous_active.begin(), _previous_active.end(), added), _previous_active.end());
	_chunk_wind.resize(std::min<size_t>(_chunk_wind.size(), map_chunks));
	_chunk_records.resize(std::min<size_t>(_chunk_records.size(), map_chunks));
	_chunk_active.resize(std::min<size_t>(_chunk_active.size(), map_chunks));
	_visit_mark.resize(std::min<size_t>(_visit_mark.size(), map_chunks));
}

void NearField::take_added() {
	const size_t chunks = _plants.get_chunk_count();
	_chunk_wind.resize(chunks);
	_chunk_records.resize(chunks);
	_chunk_active.resize(chunks, 0);
	_visit_mark.resize(chunks, 0);
	_plant_lod.resize(_plants.get_plant_count(), LOD_BILLBOARD);
	_select_added_lods(); // active now, each plant at its level (no whole LOD pass)
}

void NearField::reshape() {
	for (uint32_t c : _active_chunks) {
		_write_records(c);
	}
}

void NearField::_write_records(uint32_t p_chunk) {
	std::vector<float> &records = _chunk_records[p_chunk];
	records.resize(size_t(_plants.get_layout().chunks[p_chunk].count) * FAR_FLOATS_PER_INSTANCE);
	_plants.write_chunk_instances(p_chunk, records.data());
}

void NearField::set_stump_height(uint32_t p_species, float p_metres) {
	if (p_species < _stump_heights.size()) {
		_stump_heights[p_species] = sanitize(param::PLANT_STUMP_HEIGHT, p_metres, _stump_heights[p_species]);
	}
}

void NearField::_write_stump(const Plant &p_plant, const PlantShape &p_shape, float p_stump, const glm::vec4 &p_color,
		InstanceBuffer &r_bucket) const {
	const float size = p_shape.part_scale * p_plant.scale; // metres a model unit
	if (p_shape.whole) {
		// The whole-plant shader draws only the bottom part of a record whose middle stretch is
		// negative, upright and that many model units tall (plant_bend.gdshaderinc).
		WholePlant whole;
		_wind.whole_plant(p_plant, glm::vec2(0.0f), p_shape, whole);
		whole.middle = -std::min(p_stump / size, p_shape.part_lengths[0]);
		write_whole_instance(r_bucket.push(), whole, p_color);
		return;
	}
	PartTransforms parts;
	_wind.part_transforms(p_plant, glm::vec2(0.0f), p_shape, parts);
	const float bottom = p_shape.part_lengths[0] * size; // metres
	glm::mat3 basis = parts.basis[0];
	if (bottom > p_stump) {
		basis[1] *= p_stump / bottom; // shortened along the part's own up axis
	}
	write_instance(r_bucket.push(), basis, parts.origin[0], p_color);
}

void NearField::set_lod(const LodParams &p_params) {
	_lod_params = LodSelector::sanitized(p_params, _lod_params);
	LodParams drawn = _lod_params;
	for (float &distance : drawn.distances) {
		distance *= _quality;
	}
	drawn.fade *= _quality;
	_lod.configure(drawn);
	_lod_due = true;
}

void NearField::set_quality(float p_quality) {
	if (p_quality > 0.0f && p_quality <= 1.0f && p_quality != _quality) {
		_quality = p_quality;
		set_lod(_lod_params);
	}
}

float NearField::get_finer_distance(uint32_t p_species, uint32_t p_switch) const {
	const LodParams &params = _lod.get_params();
	const float distance = std::max(0.0f, params.distances[std::min<size_t>(p_switch, 3)] - params.hysteresis);
	return distance * _plants.get_shape(p_species).lod_scale;
}

void NearField::write_active_mask(uint32_t p_species, uint8_t *r_out) const {
	const FieldLayout &layout = _plants.get_layout();
	std::fill_n(r_out, size_t(layout.grid_x) * size_t(layout.grid_z), uint8_t(0));
	for (uint32_t c : _active_chunks) {
		if (layout.chunks[c].species == p_species && c < _plants.get_map_chunk_count()) {
			r_out[_plants.get_chunk_cell(c)] = 255;
		}
	}
}

void NearField::set_worker_threads(uint32_t p_threads) {
	uint32_t threads = std::min(p_threads, param::MAX_THREADS);
	if (threads == 0) {
		threads = std::clamp(std::thread::hardware_concurrency(), 1u, param::MAX_AUTO_THREADS);
	}
	if (threads == get_worker_threads()) {
		return;
	}
	_pool.reset(threads > 1 ? new WorkerPool(threads) : nullptr);
	_task_buckets.assign(threads > 1 ? threads * TASKS_PER_THREAD - 1 : 0, BucketSet{});
	make_buckets();
}

void NearField::make_buckets() {
	BucketSet buckets;
	const uint32_t species_count = std::max(_plants.get_species_count(), 1u);
	for (uint32_t species = 0; species < species_count; ++species) {
		const bool whole = _plants.get_shape(species).whole;
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

namespace {

// A near impostor: the plant's static record, p_share (how much of the plant the impostor draws, below
// 1 in a cross-fade) in place of the cell.
void write_impostor(InstanceBuffer &r_bucket, const float *p_record, float p_share) {
	float *out = r_bucket.push();
	std::copy_n(p_record, FAR_FLOATS_PER_INSTANCE, out);
	out[FAR_CELL_OR_SHARE] = p_share;
}

} // namespace

bool NearField::update(float p_delta) {
	const float delta = std::isfinite(p_delta) ? std::clamp(p_delta, 0.0f, 1.0f) : 0.0f;
	_time += double(delta);
	_wind.advance(delta);
	_pushes.update(delta, _plants, _wind_lookup);
	_since_lod += delta;
	const glm::vec3 moved = _observer - _lod_observer;
	if (glm::dot(moved, moved) > JUMP_DISTANCE * JUMP_DISTANCE) {
		_lod_due = true; // the observer jumped: do not wait for the interval
	}
	if (_lod_due || _since_lod >= _lod.get_params().interval) {
		_lod_due = false; // _select_lods() sets it again when chunks are left for the next update
		_since_lod = 0.0f;
		_select_lods();
	} else {
		_changed_chunks = 0;
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
		return _changed_chunks > 0;
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
	return _changed_chunks > 0;
}

void NearField::_move_chunks(size_t p_first, size_t p_last, float p_delta, BucketSet &r_buckets) {
	const FieldLayout &layout = _plants.get_layout();
	for (InstanceBuffer &bucket : r_buckets) {
		bucket.clear();
	}
	const bool moving = _wind.get_effective_power() > 0.0f;
	const bool advancing = moving && _wind.advances_plants(); // plants with wind state of their own
	const bool fading = _lod.get_params().force_level < 0 && _lod.get_params().fade > 0.0f;
	PartTransforms parts;
	WholePlant whole;
	for (size_t a = p_first; a < p_last; ++a) {
		const Chunk &chunk = layout.chunks[_active_chunks[a]];
		PlantWind *winds = _chunk_wind[_active_chunks[a]].data();
		const float *records = _chunk_records[_active_chunks[a]].data();
		const PlantShape &shape = _plants.get_shape(chunk.species);
		const PlantVariety &variety = _plants.get_layout_params().varieties[chunk.species];
		InstanceBuffer *buckets = r_buckets.data() + size_t(chunk.species) * BUCKET_COUNT;
		const float radius = shape.cull_radius * shape.part_scale;
		const float mid_height = 0.5f * shape.height * shape.part_scale;
		// (A plant of one part has no bottom part of its own to leave.)
		const float stump = shape.part_lengths[1] + shape.part_lengths[2] > 0.0f ? _stump_heights[chunk.species] : 0.0f;
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
				const uint32_t index = layout.chunk_plants[chunk.first + k];
				if (_plant_lod[index] < LOD_SPRITE) {
					_wind.advance_plant(winds[k], _plants.get_layout_params().seed, index, _time, p_delta);
				}
			}
			continue;
		}
		for (uint32_t k = 0; k < chunk.count; ++k) {
			const uint32_t index = layout.chunk_plants[chunk.first + k];
			const PlantState state = _plants.get_plant_state(index);
			if (state == PlantState::GONE || (state == PlantState::CUT && stump <= 0.0f)) {
				continue;
			}
			const Plant &plant = layout.plants[index];
			const uint8_t lod = _plant_lod[index];
			const glm::vec3 middle = plant.root() + glm::vec3(0.0f, mid_height * plant.scale, 0.0f);
			const float reach = radius * plant.scale; // the culling sphere's radius
			const bool visible = overlap == Frustum::INSIDE || crossing.intersects_sphere(middle, reach);
			if (state == PlantState::CUT) {
				if (visible && lod < LOD_SPRITE) {
					InstanceBuffer &bucket = buckets[mesh_bucket(lod, 0)];
					_write_stump(plant, shape, stump, plant.color(variety), bucket);
					bucket.include(middle, reach);
				}
				continue;
			}
			const float *record = records + size_t(k) * FAR_FLOATS_PER_INSTANCE;
			if (lod >= LOD_SPRITE) {
				if (visible && state == PlantState::STANDING) { // (a flattened plant lies: no impostor stands it up)
					write_impostor(buckets[BUCKET_IMPOSTOR], record, 1.0f);
					buckets[BUCKET_IMPOSTOR].include(middle, reach);
				}
				continue;
			}
			PlantWind &wind = winds[k];
			if (advancing) {
				_wind.advance_plant(wind, _plants.get_layout_params().seed, index, _time, p_delta);
			}
			if (!visible) {
				continue;
			}
			const glm::vec2 bend = state == PlantState::FLATTENED ? _flat_bend(plant) : _plant_bend(wind, plant, moving);
			// Mesh 3 near the sprite switch dithers into the impostor: both drawn, the impostor's
			// share in its colour's alpha, the mesh's in the rest (complementary screen-door patterns).
			// The plant's distance as FieldPlants::plant_distance_sq measures it: to its middle.
			const glm::vec3 to_eye = _observer - middle;
			const float distance_sq = fading ? shape.lod_distance_sq(glm::dot(to_eye, to_eye)) : 0.0f;
			const float share = lod == LOD_MESH_3 && fading && state == PlantState::STANDING ? _lod.impostor_share(distance_sq) : 0.0f;
			if (share > 0.0f) {
				write_impostor(buckets[BUCKET_IMPOSTOR], record, share);
				buckets[BUCKET_IMPOSTOR].include(middle, reach);
				if (share >= 1.0f) {
					continue;
				}
			}
			glm::vec4 color = plant.color(variety);
			color.w = 1.0f - share;
			if (shape.whole) {
				_wind.whole_plant(plant, bend, shape, whole);
				// Drawn whole (by the addon's plant shader), mesh 1 and 2 near their switches dither into
				// the next level the same way: the coarser mesh keeps the other pixels, which a negative
				// alpha asks for (plant_surface.gdshaderinc).
				const float coarser = lod < LOD_MESH_3 && fading ? _lod.fade_share(lod, distance_sq) : 0.0f;
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
			_wind.part_transforms(plant, bend, shape, parts);
			for (uint32_t part = 0; part < PART_COUNT; ++part) {
				InstanceBuffer &bucket = buckets[mesh_bucket(lod, part)];
				write_instance(bucket.push(), parts.basis[part], parts.origin[part], color);
				bucket.include(middle, reach);
			}
		}
	}
}

glm::vec2 NearField::_flat_bend(const Plant &p_plant) const {
	return glm::vec2(std::sin(p_plant.yaw), std::cos(p_plant.yaw)) * _wind.get_bend_limit();
}

glm::vec2 NearField::_plant_bend(const PlantWind &p_wind, const Plant &p_plant, bool p_moving) const {
	glm::vec2 bend = p_moving ? _wind.bend_vector(p_wind, p_plant.position) : glm::vec2(0.0f);
	if (p_wind.push_slot == 0) {
		return bend;
	}
	bend += _pushes.get_offset(p_wind);
	const float size = glm::length(bend);
	const float limit = _wind.get_bend_limit();
	return size > limit ? bend * (limit / size) : bend; // a pushed plant still bends at most max_bend
}

const PlantWind *NearField::_wind_of(uint32_t p_plant) const {
	const FieldLayout &layout = _plants.get_layout();
	const uint32_t chunk = layout.plants[p_plant].chunk;
	if (chunk >= _chunk_active.size() || !_chunk_active[chunk]) {
		return nullptr;
	}
	// A chunk lists its plants in map order, so the plant's place among them is found by bisection.
	const Chunk &range = layout.chunks[chunk];
	const auto first = layout.chunk_plants.begin() + range.first;
	const auto found = std::lower_bound(first, first + range.count, p_plant);
	return _chunk_wind[chunk].data() + (found - first);
}

void NearField::get_plant_parts(uint32_t p_plant, PartTransforms &r_parts) const {
	const FieldLayout &layout = _plants.get_layout();
	const Plant &plant = layout.plants[p_plant];
	glm::vec2 bend(0.0f);
	const PlantWind *wind = _wind_of(p_plant);
	if (_plants.get_plant_state(p_plant) == PlantState::FLATTENED) {
		bend = _flat_bend(plant);
	} else if (wind != nullptr && _plant_lod[p_plant] < LOD_SPRITE) {
		bend = _plant_bend(*wind, plant, _wind.get_effective_power() > 0.0f);
	}
	_wind.part_transforms(plant, bend, _plants.get_shape(_plants.species_of(plant)), r_parts);
}


size_t NearField::get_memory_bytes() const {
	size_t bytes = _plant_lod.capacity() + _chunk_wind.capacity() * sizeof(_chunk_wind[0]);
	for (const std::vector<PlantWind> &winds : _chunk_wind) {
		bytes += winds.capacity() * sizeof(PlantWind);
	}
	bytes += _chunk_records.capacity() * sizeof(_chunk_records[0]);
	for (const std::vector<float> &records : _chunk_records) {
		bytes += records.capacity() * sizeof(float);
	}
	bytes += _chunk_active.capacity() + _visit_mark.capacity() * sizeof(uint32_t);
	bytes += (_active_chunks.capacity() + _previous_active.capacity()) * sizeof(uint32_t);
	bytes += _activation.capacity() * sizeof(_activation[0]) + _pushes.get_memory_bytes();
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

} // namespace sunflower
