#pragma once
// Everything that happens to a field after its map is read: layout, per-plant wind, LOD buckets and
// the MultiMesh instance buffers, per frame. Plain C++17 + GLM: no engine types.
//
// Representation rule (every plant is drawn in exactly one representation, or in the mesh 3 →
// impostor cross-fade in two, with complementary shares):
// - the field is cut into square chunks. A chunk near the observer is *active*: each of its plants
//   has its own LOD (with hysteresis) and is written, swaying, into the dynamic buckets
//   (mesh level × part, sprite, billboard), frustum-culled;
// - every other chunk is *static*: its plants are drawn from the impostor buffer of its *tile*, a
//   square of TILE_CHUNKS × TILE_CHUNKS grid cells of one species, written once (sprites and
//   billboards are one multi-view impostor; one MultiMesh draws a whole tile). Every plant of a
//   tile is in its buffer; the impostor shader skips those whose chunk is active, as the active
//   mask (one byte per grid cell and species) says. Far away, merged tiles (2 × 2 tiles, then
//   4 × 4, …) stand in for their children, drawing a nested quarter of their plants per level
//   (see TILE_CHUNKS). Counts report a static plant as sprite or
//   billboard by the distance from the camera to its chunk's bounding-box centre.
#include "field_layout.h"
#include "field_map.h"
#include "frustum.h"
#include "instance_buffer.h"
#include "lod_selector.h"
#include "plant_shape.h"
#include "wind_model.h"
#include "worker_pool.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
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

// A body that plants part around: a point in the field's space and the radius it reaches.
struct Pusher {
	glm::vec3 position{ 0.0f };
	float radius = float(param::PUSHER_RADIUS.default_value);
};

struct ChunkBounds {
	glm::vec3 min{ 0.0f };
	glm::vec3 max{ 0.0f };
	glm::vec3 center() const { return (min + max) * 0.5f; }
};

class FieldSimulation {
public:
	FieldSimulation();

	// Reads a map. On success replaces the field and rebuilds the layout; on failure keeps the current
	// field and fills r_error.
	bool load_map(const std::string &p_text, const std::u32string &p_legend, const std::string &p_source,
			const MapLimits &p_limits, MapError &r_error);
	// The same with p_plant_symbols: the legend's plant types, species 1, 2, … ('*' is species 0).
	bool load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
			const std::string &p_source, const MapLimits &p_limits, MapError &r_error);
	void clear();
	// Replaces the map (one already read, e.g. edited) and rebuilds the layout.
	void replace_map(FieldMap p_map);
	const FieldMap &get_map() const { return _map; }
	// The legend's plant symbols the map was read with (species 1, 2, …).
	const std::u32string &get_plant_symbols() const { return _plant_symbols; }
	// A brush stroke on the map (see paint_cells; p_center and p_radius in cells), then, when
	// p_relayout, the layout rebuilt if anything changed; the changed cells are appended to r_changed.
	// (A simulation that only edits a map, for a painter, skips the layout.)
	void paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density, uint64_t p_seed,
			bool p_relayout, std::vector<int> &r_changed);

	// Rebuilds the layout when the (sanitised) parameters differ from the current ones; returns
	// whether it did.
	bool set_layout_params(const LayoutParams &p_params);
	const LayoutParams &get_layout_params() const { return _layout_params; }
	// Stands the plants on p_ground (rebuilding the layout). Plants whose cells have no ground go.
	void set_ground(Ground p_ground);
	const Ground &get_ground() const { return _ground; }
	void set_wind(const WindParams &p_params) { _wind.configure(p_params); }
	const WindModel &get_wind() const { return _wind; }
	void set_lod(const LodParams &p_params);
	const LodSelector &get_lod() const { return _lod; }
	// A species' form (species 0: '*').
	void set_shape(const PlantShape &p_shape, uint32_t p_species = 0);
	// Sets the part scale for a plant p_metres tall from its root to the top of its parts
	// (param::PLANT_HEIGHT rules).
	void set_plant_height(float p_metres, uint32_t p_species = 0);
	const PlantShape &get_shape(uint32_t p_species = 0) const { return _shapes[p_species % _shapes.size()]; }
	uint32_t get_species_count() const { return uint32_t(_map.species_count); }
	// Buckets in all: BUCKET_COUNT per species of the map.
	uint32_t get_bucket_count() const { return uint32_t(_buckets.size()); }

	void set_observer(const glm::vec3 &p_position) { _observer = p_position; }
	const glm::vec3 &get_observer() const { return _observer; }
	Frustum &get_frustum() { return _frustum; }

	// One frame: advances time by p_delta, re-selects LOD when the interval has passed (or when forced),
	// moves the plants and fills the dynamic buckets.
	void update(float p_delta);
	// Makes the next update re-select LODs regardless of the interval.
	void request_lod_update() { _lod_due = true; }
	// An observer that moved farther than this since the last LOD pass gets one at the next update,
	// whatever the interval (a teleport; at 0.25 s intervals normal walking and flying stay below).
	static constexpr float JUMP_DISTANCE = 4.0f;
	// The most plants whose chunks turn active in one update (nearest chunks first).
	static constexpr uint32_t ACTIVATION_BUDGET = 4096;

	// Bodies the plants part around, from the next update on. A plant within a pusher's radius bends
	// away from its centre (whole plant from the ground, the bottom part most, like a stalk) by up to
	// p_strength (a bend, as the wind's), added to the wind's; once free it springs back, critically
	// damped, settling within p_recovery_seconds. Only plants being pushed or springing back hold any
	// state, so a field without pushers costs what it did.
	void set_pushers(const Pusher *p_pushers, size_t p_count);
	void set_push_params(float p_strength, float p_recovery_seconds);
	// Plants pushed now or springing back.
	uint32_t get_pushed_count() const { return static_cast<uint32_t>(_pushed.size()); }
	// The plants whose roots lie within p_radius of p_center (x, z), appended to r_plants.
	void find_plants_near(const glm::vec2 &p_center, float p_radius, std::vector<uint32_t> &r_plants) const;

	// Threads that move the near plants, the caller included: 0 picks the hardware's count (at most
	// param::MAX_AUTO_THREADS), 1 moves them all on the caller, at most param::MAX_THREADS. The
	// threads live as long as the simulation.
	// Runs of active chunks per thread: more runs than threads balance uneven runs and late wake-ups.
	static constexpr uint32_t TASKS_PER_THREAD = 4;
	void set_worker_threads(uint32_t p_threads);
	uint32_t get_worker_threads() const { return _pool ? _pool->get_thread_count() : 1; }
	// Below this many plants in active chunks the near work stays on one thread: waking the others
	// costs more than it saves below ~25 000 on two cores (the core benchmark's thread table).
	static constexpr uint32_t PARALLEL_MIN_PLANTS = 32768;
	// Benchmarks move the threshold to measure where a second thread pays.
	void set_parallel_min_plants(uint32_t p_plants) { _parallel_min_plants = p_plants; }
	uint32_t get_parallel_min_plants() const { return _parallel_min_plants; }
	// Plants in active chunks, and how many parallel tasks (runs of active chunks) the last update
	// split them into: 1 when it ran on the caller alone.
	uint32_t get_active_plant_count() const { return _active_plants; }
	uint32_t get_last_task_count() const { return _last_tasks; }

	const FieldLayout &get_layout() const { return _layout; }
	uint32_t get_plant_count() const { return static_cast<uint32_t>(_layout.plants.size()); }
	const InstanceBuffer &get_bucket(uint32_t p_bucket) const { return _buckets[p_bucket]; }
	double get_time() const { return _time; }

	uint32_t get_chunk_count() const { return static_cast<uint32_t>(_layout.chunks.size()); }
	ChunkBounds get_chunk_bounds(uint32_t p_chunk) const;
	bool is_chunk_active(uint32_t p_chunk) const { return _chunk_active[p_chunk] != 0; }
	// The static impostor instances of a chunk's plants, compact (FarInstance): count ×
	// FAR_FLOATS_PER_INSTANCE floats into r_out.
	void write_chunk_instances(uint32_t p_chunk, float *r_out) const;
	// The grid cell a chunk lies in (FieldLayout: z·grid_x + x).
	uint32_t get_chunk_cell(uint32_t p_chunk) const { return _chunk_cells[p_chunk]; }

	// Far tiles: the chunks of one species in a square of TILE_CHUNKS × TILE_CHUNKS grid cells, drawn
	// from one buffer (level 0). While the field's tile merge distance is above 0, tiles merge with
	// distance: a level-L tile covers the square of 2 × 2 level-(L − 1) tiles (its children, whose
	// parent it is) and holds the plants of its chunks whose tile level (plant_tile_level) is at least
	// L: a quarter of the plants per level, each level's a subset of the one below. Each far plant
	// takes the look of the level its distance from the observer gives it (choose_tile_level: level L
	// from merge_distance(L) on, fading in over the half octave before), so no tile's worth of plants
	// switches at once, and the impostor shader widens the plants by 1 / √density to keep the field's
	// cover. Which tile draws it is a cut through the tree of tiles: a tile is drawn from
	// get_tile_shown_from on, where all its plants are given to its level or above, unless its parent
	// is drawn (the engine's visibility parent); a tile draws each of its plants at the level given to
	// it, so whether a tile or its children draw a place changes nothing on screen. Levels stop once
	// one tile per species covers the field. Level-0 tiles come first, ordered by where they lie, then
	// species; then level 1's, and so on.
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
	uint32_t get_tile_count() const { return static_cast<uint32_t>(_tiles.size()); }
	const Tile &get_tile(uint32_t p_tile) const { return _tiles[p_tile]; }
	// The k-th chunk of a tile (k < Tile::count), in chunk order within each child.
	uint32_t get_tile_chunk(uint32_t p_tile, uint32_t p_k) const { return _tile_chunks[_tiles[p_tile].first + p_k]; }
	ChunkBounds get_tile_bounds(uint32_t p_tile) const;
	// The tile's plants' records: Tile::plants × FAR_FLOATS_PER_INSTANCE floats; while tiles merge,
	// level by level, highest first (chunk after chunk within a level), else chunk after chunk.
	void write_tile_instances(uint32_t p_tile, float *r_out) const;
	// How many of the tile's first records the engine must draw: those kept at the lowest level the
	// observer's distance may give any of its plants (Tile::kept_from), counted again whenever the
	// observer has moved TILE_COUNT_SLACK metres across the ground, from a distance that much
	// nearer. A level-0 tile seen from beyond the first merge distance draws a quarter of its records.
	uint32_t get_tile_visible_count(uint32_t p_tile) const { return _tile_visible[p_tile]; }
	static constexpr float TILE_COUNT_SLACK = 1.0f;
	// Two tiles with equal keys and signatures draw the same (see get_chunk_signature).
	uint64_t get_tile_signature(uint32_t p_tile) const;
	// The distance from the observer at which a far plant's place turns to level L
	// (merge_distance(L)): 0 for level 0; for level L the merge distance × 2^(L − 1).
	float get_tile_begin(uint32_t p_tile) const;
	float merge_distance(uint32_t p_level) const;
	// Plants fade from one tile level to the next over the last TILE_MERGE_FADE octave before each
	// merge distance (from merge_distance(L) / 2^TILE_MERGE_FADE to merge_distance(L)), one after
	// another: a plant the next level leaves out dithers away, in the order of its own random and
	// over a quarter of the band (the impostor shader's MERGE_PLANT_FADE), the others widen to keep
	// the cover, and at the merge distance the next level's tile draws those same plants at the
	// same width. So no tile's worth of plants switches at once.
	static constexpr float TILE_MERGE_FADE = 0.5f;
	// The tile level that draws a far plant p_distance from the observer, and how far its fade to the
	// next level has come (0 … 1: the share of the plants that level leaves out already gone).
	// Mirrored by the impostor shader (tile_choice): keep the two in step.
	struct TileChoice {
		uint32_t level = 0;
		float fade = 0.0f;
	};
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
	// Which chunks of p_species are active: grid_x × grid_z bytes into r_out, 255 for an active
	// chunk's cell, else 0 (the impostor shader's mask).
	void write_active_mask(uint32_t p_species, uint8_t *r_out) const;
	// Changes whenever a chunk turns active or static, or the field is rebuilt.
	uint32_t get_mask_version() const { return _mask_version; }
	// Whether a tile has a plant to draw now: false when all its chunks are active (its node is then
	// hidden, so that it costs no draw call).
	bool is_tile_drawn(uint32_t p_tile) const;
	// Where a chunk lies: grid cell × MAX_SPECIES + species (the same in any layout of the map's size).
	uint64_t get_chunk_key(uint32_t p_chunk) const;
	// A hash of a chunk's static instance data (what its impostor buffers hold): two chunks with equal
	// keys and signatures draw the same, so a rebuilt field can keep the old one's GPU buffers.
	// Computed for every chunk by compute_chunk_signatures() (a worker may call it), else on demand.
	uint64_t get_chunk_signature(uint32_t p_chunk) const;
	void compute_chunk_signatures();
	// The distance at which a static chunk switches from sprite to billboard (engine visibility range).
	float get_billboard_distance() const { return _lod.get_params().distances[3]; }

	// The representation a plant is drawn in now: its own LOD in an active chunk, else the chunk's.
	uint8_t get_plant_lod(uint32_t p_plant) const;
	std::array<int64_t, LOD_COUNT> get_lod_counts() const;
	// Plants per representation of one species.
	std::array<int64_t, LOD_COUNT> get_lod_counts(uint32_t p_species) const;
	// CPU memory held for the field, in bytes (map cells, layout, per-plant state, dynamic buffers).
	size_t get_memory_bytes() const;
	// The three part transforms of a plant as they are drawn now (upright for impostors).
	void get_plant_parts(uint32_t p_plant, PartTransforms &r_parts) const;

private:
	// The buckets (and the parallel tasks' ones) anew, empty, with each species' strides.
	void _make_buckets();

	struct PushState {
		uint32_t plant = 0;
		glm::vec2 offset{ 0.0f }; // the push's bend now
		glm::vec2 velocity{ 0.0f };
		glm::vec2 target{ 0.0f }; // where the pushers want it this frame
	};
	// The grid cells (chunk_size squares) within p_reach of a point (x, z), clamped to the grid.
	struct GridRange {
		int x0 = 0, x1 = -1, z0 = 0, z1 = -1;
	};
	GridRange _grid_range(const glm::vec2 &p_center, float p_reach) const;
	void _update_pushes(float p_delta);
	glm::vec2 _plant_bend(const PlantWind &p_wind, const Plant &p_plant, bool p_moving) const;
	// The wind state of a plant of an active chunk (nullptr for any other plant).
	PlantWind *_wind_of(uint32_t p_plant);
	const PlantWind *_wind_of(uint32_t p_plant) const;
	// Drops the push states of a chunk's plants (it turns inactive: its wind states go).
	void _drop_pushes(uint32_t p_chunk);
	void _rebuild();
	void _build_tiles();
	// The merged levels above the level-0 tiles (see TILE_CHUNKS).
	void _merge_tiles();
	// The static records of p_count plants of chunk p_chunk (p_plants: their indices), each with the
	// chunk's cell and p_levels_above (FarInstance::levels_above: the plants are all of one level).
	void _write_records(uint32_t p_chunk, const uint32_t *p_plants, uint32_t p_count, float *r_out, uint32_t p_levels_above = 0) const;
	// Each tile's area and kept_from, once its plants are known.
	void _finish_tiles();
	// Tile::visible counts from the observer's place now (get_tile_visible_count).
	void _count_tile_records();
	void _select_lods();
	void _select_chunk_lods(uint32_t p_chunk, bool p_forced, float p_enter, float p_leave);
	uint8_t _static_chunk_lod(uint32_t p_chunk) const;
	float _chunk_distance_sq(uint32_t p_chunk) const;
	float _plant_distance_sq(const Plant &p_plant) const;
	// The species of a plant: its chunk's (a chunk holds one species).
	uint32_t _species_of(const Plant &p_plant) const { return _layout.chunks[p_plant.chunk].species; }
	// A plant's compact impostor record (its cell left 0).
	FarInstance _far_instance(const Plant &p_plant, uint32_t p_species) const;
	// The near impostor bucket's record: p_share is how much of the plant the impostor draws (below 1
	// in a cross-fade), in place of the cell.
	void _write_impostor(float *r_out, const Plant &p_plant, float p_share = 1.0f) const;
	// Moves the plants of active chunks [p_first, p_last) and writes the visible ones into r_buckets.
	void _move_chunks(size_t p_first, size_t p_last, float p_delta, BucketSet &r_buckets);

	FieldMap _map;
	std::u32string _plant_symbols;
	LayoutParams _layout_params;
	Ground _ground;
	FieldLayout _layout;
	WindModel _wind;
	LodSelector _lod;
	std::array<PlantShape, FieldMap::MAX_SPECIES> _shapes{};
	Frustum _frustum;
	glm::vec3 _observer{ 0.0f };

	std::vector<uint8_t> _plant_lod;
	// The wind state of the plants of active chunks (only they are drawn as meshes), per chunk in
	// chunk_plants order; empty for a chunk that is not active, so it costs only what is near.
	std::vector<std::vector<PlantWind>> _chunk_wind;
	std::vector<uint8_t> _chunk_active;
	std::vector<uint64_t> _chunk_signatures; // 0: not computed
	std::vector<uint32_t> _chunk_cells;
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
	uint32_t _mask_version = 0;
	std::vector<uint32_t> _active_chunks;
	std::vector<uint32_t> _previous_active;
	std::vector<uint32_t> _changed_chunks;
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

	std::vector<Pusher> _pushers;
	std::vector<PushState> _pushed; // PlantWind::push_slot - 1 indexes this
	std::vector<uint32_t> _near; // scratch for pushes
	float _push_strength = float(param::PUSH_STRENGTH.default_value);
	float _push_recovery = float(param::PUSH_RECOVERY.default_value);

	double _time = 0.0;
	float _since_lod = 0.0f;
	bool _lod_due = true;
};

} // namespace sunflower
