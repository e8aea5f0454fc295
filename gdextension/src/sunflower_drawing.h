#pragma once
// SunflowerDrawing: the drawing handoff of a SunflowerSimulation (attach): the MultiMeshes it fills
// (the near buckets each frame, the far tiles once and again nearest the observer), the far-tile
// table and the active masks the driver builds its nodes from. After the simulation's update, draw()
// gives the renderer that frame's instances, so no per-frame array travels through GDScript.
#include "binding/class_binder.h"
#include "core/tile_reorder.h"
#include "sunflower_simulation.h"

#include <vector>

class SunflowerDrawing {
public:
	static constexpr const char *CLASS = "SunflowerDrawing";
	static void bind_methods();

	// Draws p_simulation's plants from now on (the MultiMeshes given before are let go).
	void attach(gdx::Instance<SunflowerSimulation> p_simulation);
	// Gives the renderer the frame's instances (after SunflowerSimulation::update).
	void draw();
	int64_t get_last_draw_usec() const { return _last_draw_usec; }

	void set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh);
	// A second MultiMesh for a bucket that gets the same instances every frame: the node that casts
	// the bucket's shadows with another mesh (an invalid RID: none).
	void set_bucket_shadow_multimesh(int64_t p_bucket, gdx::Rid p_multimesh);
	void set_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh);
	void adopt_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh);
	void release_multimeshes();
	int64_t get_bucket_instance_count(int64_t p_bucket) const;
	gdx::PackedByteArray get_filled_buckets() const;
	static int64_t mesh_bucket(int64_t p_level, int64_t p_part);

	int64_t get_tile_count() const;
	// The far-tile table, read once per build. Per tile, TILE_IDS integers: its key (where it lies),
	// signature (what it draws), species, level and parent (−1: none); TILE_PLACES floats: its box
	// (position x, y, z, size x, y, z), the distance its level begins and the camera distance it is
	// shown from (FarTiles).
	static constexpr int64_t TILE_IDS = 5;
	static constexpr int64_t TILE_PLACES = 8;
	gdx::PackedInt64Array get_tile_ids() const;
	gdx::PackedFloat32Array get_tile_places() const;
	// The rest of the impostor shader's tile_merge (the tile's level first): the top level, the
	// distance level 1 begins, the fade's share of an octave.
	gdx::PackedFloat32Array get_tile_merge_rule() const;
	gdx::Vector2 choose_tile_level(double p_distance) const;
	gdx::PackedByteArray get_active_mask(int64_t p_species) const;
	gdx::PackedByteArray get_tiles_drawn() const;
	int64_t get_mask_version() const;
	gdx::PackedInt32Array get_chunk_grid() const;
	void compute_chunk_signatures();
	int64_t get_chunk_count() const;
	gdx::AABB get_chunk_aabb(int64_t p_chunk) const;

private:
	// The attached simulation's core, its MultiMeshes let go when its chunks changed since they were
	// given; null, after an error naming p_method, when none is attached or it is gone.
	sunflower::FieldSimulation *_core(const char *p_method);
	const sunflower::FieldSimulation *_core(const char *p_method) const;
	void _release(const sunflower::FieldSimulation &p_sim);
	void _push_bucket(const sunflower::FieldSimulation &p_sim, uint32_t p_bucket);
	// Writes the tile's records (nearest the observer first) into its MultiMesh.
	void _upload_tile(const sunflower::FieldSimulation &p_sim, uint32_t p_tile);
	void _order_tiles(const sunflower::FieldSimulation &p_sim);
	bool _is_tile(const sunflower::FieldSimulation &p_sim, int64_t p_tile) const;

	struct BucketTarget {
		gdx::Rid multimesh;
		// A MultiMesh that draws the same instances with a cheaper mesh into the shadow passes only
		// (set_bucket_shadow_multimesh), or none.
		gdx::Rid shadow;
		gdx::PackedFloat32Array staging;
		uint32_t allocated = 0;
		uint32_t stride = 0; // floats per instance allocated (the bucket's)
		uint32_t last_count = 0;
		glm::vec3 bounds_low{ 0.0f }; // the box last given to the renderer
		glm::vec3 bounds_high{ 0.0f };
	};

	gdx::Held<SunflowerSimulation> _simulation;
	// The simulation's chunks the MultiMeshes are held for (SunflowerSimulation::get_chunks_version):
	// when its chunks change, the MultiMeshes given before are let go.
	uint64_t _chunks_version = NO_CHUNKS;
	static constexpr uint64_t NO_CHUNKS = ~uint64_t(0);
	std::vector<BucketTarget> _buckets; // BUCKET_COUNT per species of the map
	std::vector<gdx::Rid> _tiles; // each tile's impostors (sprite and billboard are one multi-view impostor)
	std::vector<int64_t> _tile_visible; // each tile's MultiMesh's visible instances as last set (−1: not yet)
	std::vector<uint32_t> _tile_counts; // each tile's MultiMesh's instances as allocated (or adopted)
	// The tiles' records written again nearest the observer first, TILE_ORDER_PLANTS_PER_FRAME plants a
	// frame into _reorder_buffer, and given to the tile's MultiMesh when complete; given up if the
	// field's records change meanwhile (_reorder_version: theirs when it began).
	sunflower::TileReorder _reorder;
	gdx::PackedFloat32Array _reorder_buffer;
	uint32_t _reorder_version = 0;
	static constexpr uint32_t TILE_ORDER_PLANTS_PER_FRAME = 1024;
	int64_t _last_draw_usec = 0;
};
