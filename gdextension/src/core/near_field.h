#pragma once
// The near field: the plants close to the observer, each with its own level of detail and wind, written
// every frame into the dynamic buckets. Every plant is drawn in exactly one representation, or in the
// mesh 3 → impostor cross-fade in two, with complementary shares:
// - the field is cut into square chunks (field_layout.h). A chunk near the observer is *active*: each
//   of its plants has its own LOD (with hysteresis) and is written, swaying, into the buckets
//   (mesh level × part, and the impostor), frustum-culled;
// - every other chunk is *static*, drawn by the far tiles (far_tiles.h), which skip the active chunks'
//   plants as write_active_mask says. Counts report a static plant as sprite or billboard by the
//   distance from the camera to its chunk's bounding-box centre (the engine's visibility-range rule).
#include "field_plants.h"
#include "frustum.h"
#include "instance_buffer.h"
#include "lod_selector.h"
#include "plant_pushes.h"
#include "wind_model.h"
#include "worker_pool.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace sunflower {

// The dynamic buckets of one species: mesh levels 1–3 × parts (bottom, middle, head), then the
// impostors (sprites and billboards draw the same multi-view impostor, so they share one bucket).
// Species s has buckets [s × BUCKET_COUNT, (s + 1) × BUCKET_COUNT).
constexpr uint32_t PART_COUNT = 3;
constexpr uint32_t BUCKET_IMPOSTOR = LOD_MESH_COUNT * PART_COUNT;
constexpr uint32_t BUCKET_COUNT = BUCKET_IMPOSTOR + 1;

constexpr uint32_t mesh_bucket(uint32_t p_level, uint32_t p_part) {
	return p_level * PART_COUNT + p_part;
}

// Every species' buckets, species by species.
using BucketSet = std::vector<InstanceBuffer>;

class NearField {
public:
	explicit NearField(const FieldPlants &p_plants);
	NearField(const NearField &) = delete;
	NearField &operator=(const NearField &) = delete;

	// Every plant's state anew for the plants' layout as it is now (all static, LODs due).
	void rebuild();
	// The buckets anew, empty, with each species' strides (a species drawn otherwise, whole or in parts).
	void make_buckets();

	void set_wind(const WindParams &p_params) { _wind.configure(p_params); }
	const WindModel &get_wind() const { return _wind; }
	// The levels' settings (the param:: rules apply); they are drawn at the quality.
	void set_lod(const LodParams &p_params);
	const LodParams &get_lod_params() const { return _lod_params; }
	// The share of the switch distances and the fade plants are drawn at: a frame budget's quality,
	// in (0, 1] (out of it or not finite: the current one stays).
	void set_quality(float p_quality);
	float get_quality() const { return _quality; }
	// Where a plant of p_species turns from the finer level of switch p_switch (0: mesh 1 → 2, …,
	// 3: sprite → billboard) to the coarser one, coming nearer: the switch distance at the quality
	// less the hysteresis, times the type's PlantShape::lod_scale.
	float get_finer_distance(uint32_t p_species, uint32_t p_switch) const;
	// The stump a cut plant of p_species leaves, metres (param::PLANT_STUMP_HEIGHT; 0: none): its
	// bottom part, upright, shortened to that height, drawn at its mesh level (drawn whole: the
	// plant's record with a negative middle stretch, which the shader draws so). A plant of one part
	// (no middle or head) has no bottom part of its own: its cut plants leave nothing.
	void set_stump_height(uint32_t p_species, float p_metres);
	float get_stump_height(uint32_t p_species) const { return _stump_heights[p_species % _stump_heights.size()]; }
	const LodSelector &get_lod() const { return _lod; }
	// The distance at which a static chunk switches from sprite to billboard (engine visibility range).
	float get_billboard_distance() const { return _lod.get_params().distances[3]; }
	void set_observer(const glm::vec3 &p_position) { _observer = p_position; }
	const glm::vec3 &get_observer() const { return _observer; }
	Frustum &get_frustum() { return _frustum; }
	PlantPushes &get_pushes() { return _pushes; }
	const PlantPushes &get_pushes() const { return _pushes; }

	// One frame: advances time by p_delta, moves the pushed plants, re-selects LOD when the interval
	// has passed (or when due), moves the plants and fills the buckets. Returns whether a chunk turned
	// active or static.
	bool update(float p_delta);
	// Makes the next update re-select LODs regardless of the interval.
	void request_lod_update() { _lod_due = true; }
	// The chunks of plants play added (FieldPlants::add_plant) change: drop_added() forgets them
	// before FieldPlants::group_added() makes them anew (their plants' wind and pushes start again),
	// take_added() takes the new ones after; they are active at every distance.
	void drop_added();
	void take_added();
	// A plant type's shape changed (its impostors' size): the active chunks' impostor records anew.
	void reshape();
	// An observer that moved farther than this since the last LOD pass gets one at the next update,
	// whatever the interval (a teleport; at 0.25 s intervals normal walking and flying stay below).
	static constexpr float JUMP_DISTANCE = 4.0f;
	// The most plants whose chunks turn active in one update (nearest chunks first).
	static constexpr uint32_t ACTIVATION_BUDGET = 4096;

	// Threads that move the near plants, the caller included: 0 picks the hardware's count (at most
	// param::MAX_AUTO_THREADS), 1 moves them all on the caller, at most param::MAX_THREADS. The
	// threads live as long as the field.
	void set_worker_threads(uint32_t p_threads);
	uint32_t get_worker_threads() const { return _pool ? _pool->get_thread_count() : 1; }
	// Runs of active chunks per thread: more runs than threads balance uneven runs and late wake-ups.
	static constexpr uint32_t TASKS_PER_THREAD = 4;
	// Below this many plants in active chunks the near work stays on one thread: waking the others
	// costs more than it saves below ~25 000 on two cores (the core benchmark's thread table).
	static constexpr uint32_t PARALLEL_MIN_PLANTS = 32768;
	// Benchmarks move the threshold to measure where a second thread pays.
	void set_parallel_min_plants(uint32_t p_plants) { _parallel_min_plants = p_plants; }
	// Plants in active chunks, and how many parallel tasks (runs of active chunks) the last update
	// split them into: 1 when it ran on the caller alone.
	uint32_t get_active_plant_count() const { return _active_plants; }
	uint32_t get_last_task_count() const { return _last_tasks; }

	// Buckets in all: BUCKET_COUNT per species of the map.
	uint32_t get_bucket_count() const { return uint32_t(_buckets.size()); }
	const InstanceBuffer &get_bucket(uint32_t p_bucket) const { return _buckets[p_bucket]; }
	bool is_chunk_active(uint32_t p_chunk) const { return _chunk_active[p_chunk] != 0; }
	// Which chunks of p_species are active: grid_x × grid_z bytes into r_out, 255 for an active
	// chunk's cell, else 0 (the impostor shader's mask).
	void write_active_mask(uint32_t p_species, uint8_t *r_out) const;
	// The representation a plant is drawn in now: its own LOD in an active chunk, else the chunk's.
	uint8_t get_plant_lod(uint32_t p_plant) const;
	// Plants per representation of one species, and of all.
	std::array<int64_t, LOD_COUNT> get_lod_counts(uint32_t p_species) const;
	std::array<int64_t, LOD_COUNT> get_lod_counts() const;
	// The three part transforms of a plant as they are drawn now (upright for impostors).
	void get_plant_parts(uint32_t p_plant, PartTransforms &r_parts) const;
	// CPU memory held for the per-plant state and the buckets, in bytes.
	size_t get_memory_bytes() const;

private:
	// LOD selection and chunk activation (near_field_lod.cpp).
	void _select_lods();
	void _select_chunk_lods(uint32_t p_chunk, bool p_forced, float p_enter, float p_leave);
	// Whether a representation is forced, and the distances at which chunks turn active and static.
	void _activation_bounds(bool &r_forced, float &r_enter, float &r_leave) const;
	// The added plants' chunks (FieldPlants::add_plant) active, their plants' levels selected.
	void _select_added_lods();
	uint8_t _static_chunk_lod(uint32_t p_chunk) const;
	float _chunk_distance_sq(uint32_t p_chunk) const;
	// Moves the plants of active chunks [p_first, p_last) and writes the visible ones into r_buckets.
	void _move_chunks(size_t p_first, size_t p_last, float p_delta, BucketSet &r_buckets);
	glm::vec2 _plant_bend(const PlantWind &p_wind, const Plant &p_plant, bool p_moving) const;
	// A flattened plant's bend: by max_bend away from where it faces, whatever the wind.
	glm::vec2 _flat_bend(const Plant &p_plant) const;
	// A cut plant's stump (set_stump_height) into r_bucket, when its type leaves one.
	void _write_stump(const Plant &p_plant, const PlantShape &p_shape, float p_stump, const glm::vec4 &p_color,
			InstanceBuffer &r_bucket) const;
	// Fills an active chunk's impostor records.
	void _write_records(uint32_t p_chunk);
	// The wind state of a plant of an active chunk (nullptr for any other plant).
	const PlantWind *_wind_of(uint32_t p_plant) const;
	PlantWind *_wind_of(uint32_t p_plant) { return const_cast<PlantWind *>(static_cast<const NearField *>(this)->_wind_of(p_plant)); }

	const FieldPlants &_plants;
	const PlantPushes::WindOf _wind_lookup;
	WindModel _wind;
	LodSelector _lod; // _lod_params at _quality
	LodParams _lod_params;
	float _quality = 1.0f;
	Frustum _frustum;
	PlantPushes _pushes;
	glm::vec3 _observer{ 0.0f };
	std::array<float, FieldMap::MAX_SPECIES> _stump_heights{};

	std::vector<uint8_t> _plant_lod;
	// The wind state of the plants of active chunks (only they are drawn as meshes), per chunk in
	// chunk_plants order; empty for a chunk that is not active, so it costs only what is near.
	std::vector<std::vector<PlantWind>> _chunk_wind;
	// Their plants' impostor records as the static chunks have them (FieldPlants::write_chunk_instances),
	// alike per chunk: a near impostor is a copy with its share in place of the cell, not a yaw's sine
	// and cosine, a tone's hash and their steps each frame.
	std::vector<std::vector<float>> _chunk_records;
	std::vector<uint8_t> _chunk_active;
	std::vector<uint32_t> _active_chunks;
	std::vector<uint32_t> _previous_active;
	uint32_t _changed_chunks = 0; // chunks turned active or static by the last LOD pass
	std::vector<uint32_t> _visit_mark; // per chunk: the LOD pass that last visited it
	uint32_t _lod_pass = 0;
	std::vector<std::pair<float, uint32_t>> _activation; // (distance², chunk) turning active, scratch
	glm::vec3 _lod_observer{ 0.0f }; // where the observer was at the last LOD pass
	BucketSet _buckets;
	std::unique_ptr<WorkerPool> _pool;
	std::vector<BucketSet> _task_buckets; // the buckets of parallel tasks after the first
	uint32_t _parallel_min_plants = PARALLEL_MIN_PLANTS;
	uint32_t _active_plants = 0;
	uint32_t _last_tasks = 1;

	double _time = 0.0;
	float _since_lod = 0.0f;
	bool _lod_due = true;
};

} // namespace sunflower
