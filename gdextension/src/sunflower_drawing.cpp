// SunflowerDrawing: a simulation's MultiMeshes (near buckets each frame, far tiles once), the far-tile
// table and the active masks.
#include "sunflower_drawing.h"

#include "binding/error_macros.h"
#include "binding/rendering_server.h"
#include "convert.h"

#include <algorithm>
#include <chrono>
#include <iterator>

using namespace sunflower;

void SunflowerDrawing::bind_methods() {
	gdx::bind_method(CLASS, "attach", &SunflowerDrawing::attach, { "simulation" });
	gdx::bind_method(CLASS, "draw", &SunflowerDrawing::draw);
	gdx::bind_method(CLASS, "get_last_draw_usec", &SunflowerDrawing::get_last_draw_usec);
	gdx::bind_method(CLASS, "set_bucket_multimesh", &SunflowerDrawing::set_bucket_multimesh, { "bucket", "multimesh" });
	gdx::bind_method(CLASS, "set_bucket_shadow_multimesh", &SunflowerDrawing::set_bucket_shadow_multimesh, { "bucket", "multimesh" });
	gdx::bind_method(CLASS, "set_tile_multimesh", &SunflowerDrawing::set_tile_multimesh, { "tile", "multimesh" });
	gdx::bind_method(CLASS, "adopt_tile_multimesh", &SunflowerDrawing::adopt_tile_multimesh, { "tile", "multimesh" });
	gdx::bind_method(CLASS, "release_multimeshes", &SunflowerDrawing::release_multimeshes);
	gdx::bind_method(CLASS, "get_bucket_instance_count", &SunflowerDrawing::get_bucket_instance_count, { "bucket" });
	gdx::bind_method(CLASS, "get_filled_buckets", &SunflowerDrawing::get_filled_buckets);
	gdx::bind_method(CLASS, "mesh_bucket", &SunflowerDrawing::mesh_bucket, { "level", "part" });
	gdx::bind_method(CLASS, "get_tile_count", &SunflowerDrawing::get_tile_count);
	gdx::bind_method(CLASS, "get_tile_ids", &SunflowerDrawing::get_tile_ids);
	gdx::bind_method(CLASS, "get_tile_places", &SunflowerDrawing::get_tile_places);
	gdx::bind_method(CLASS, "get_tile_merge_rule", &SunflowerDrawing::get_tile_merge_rule);
	gdx::bind_method(CLASS, "choose_tile_level", &SunflowerDrawing::choose_tile_level, { "distance" });
	gdx::bind_method(CLASS, "get_active_mask", &SunflowerDrawing::get_active_mask, { "species" });
	gdx::bind_method(CLASS, "get_tiles_drawn", &SunflowerDrawing::get_tiles_drawn);
	gdx::bind_method(CLASS, "get_mask_version", &SunflowerDrawing::get_mask_version);
	gdx::bind_method(CLASS, "get_chunk_grid", &SunflowerDrawing::get_chunk_grid);
	gdx::bind_method(CLASS, "compute_chunk_signatures", &SunflowerDrawing::compute_chunk_signatures);
	gdx::bind_method(CLASS, "get_chunk_count", &SunflowerDrawing::get_chunk_count);
	gdx::bind_method(CLASS, "get_chunk_aabb", &SunflowerDrawing::get_chunk_aabb, { "chunk" });

	gdx::bind_integer_constant(CLASS, "", "PART_COUNT", PART_COUNT);
	gdx::bind_integer_constant(CLASS, "", "MESH_LEVEL_COUNT", LOD_MESH_COUNT);
	gdx::bind_integer_constant(CLASS, "", "LOD_COUNT", LOD_COUNT);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_IMPOSTOR", BUCKET_IMPOSTOR);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_COUNT", BUCKET_COUNT);
	gdx::bind_integer_constant(CLASS, "", "TILE_IDS", TILE_IDS);
	gdx::bind_integer_constant(CLASS, "", "TILE_PLACES", TILE_PLACES);
	gdx::bind_integer_constant(CLASS, "", "FLOATS_PER_INSTANCE", FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "WHOLE_FLOATS_PER_INSTANCE", WHOLE_FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "FAR_FLOATS_PER_INSTANCE", FAR_FLOATS_PER_INSTANCE);
	gdx::bind_integer_constant(CLASS, "", "FAR_SIGNED_STEPS", far_steps::SIGNED);
	gdx::bind_integer_constant(CLASS, "", "FAR_BRIGHTNESS_STEPS", far_steps::BRIGHTNESS);
	gdx::bind_integer_constant(CLASS, "", "FAR_STEP_BITS", far_steps::STEP_BITS);
	gdx::bind_integer_constant(CLASS, "", "FAR_CELL_BITS", far_steps::CELL_BITS);
}

void SunflowerDrawing::attach(gdx::Instance<SunflowerSimulation> p_simulation) {
	SF_FAIL_COND_MSG(!p_simulation.instance, "attach: takes a SunflowerSimulation");
	_simulation = gdx::Held<SunflowerSimulation>(p_simulation);
	_chunks_version = NO_CHUNKS; // the MultiMeshes of a simulation drawn before are let go
	_buckets.clear();
	_tiles.clear();
	_tile_visible.clear();
	_reorder.resize(0);
	_tile_counts.clear();
}

const FieldSimulation *SunflowerDrawing::_core(const char *p_method) const {
	const SunflowerSimulation *simulation = _simulation.get();
	SF_FAIL_COND_V_MSG(!simulation, nullptr,
			std::string(p_method) + ": no simulation to draw (attach one; the one attached may be gone)");
	return &simulation->core();
}

FieldSimulation *SunflowerDrawing::_core(const char *p_method) {
	SunflowerSimulation *simulation = _simulation.get();
	SF_FAIL_COND_V_MSG(!simulation, nullptr,
			std::string(p_method) + ": no simulation to draw (attach one; the one attached may be gone)");
	if (simulation->get_chunks_version() != _chunks_version) {
		_release(simulation->core()); // its chunks changed: the MultiMeshes given were for the old ones
		_chunks_version = simulation->get_chunks_version();
	}
	return &simulation->core();
}

void SunflowerDrawing::set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
	if (!_core("set_bucket_multimesh")) {
		return; // (its chunks looked at: the buckets are the map's)
	}
	SF_FAIL_COND_MSG(p_bucket < 0 || p_bucket >= int64_t(_buckets.size()),
			"bucket " + std::to_string(p_bucket) + " is out of range (0 to " + std::to_string(_buckets.size() - 1) + ": " +
					std::to_string(BUCKET_COUNT) + " per species)");
	if (!gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	BucketTarget &target = _buckets[static_cast<size_t>(p_bucket)];
	target.multimesh = p_multimesh;
	target.allocated = 0;
	target.last_count = 0;
}

void SunflowerDrawing::set_bucket_shadow_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
	if (!_core("set_bucket_shadow_multimesh")) {
		return; // (its chunks looked at: the buckets are the map's)
	}
	SF_FAIL_COND_MSG(p_bucket < 0 || p_bucket >= int64_t(_buckets.size()),
			"bucket " + std::to_string(p_bucket) + " is out of range (0 to " + std::to_string(_buckets.size() - 1) + ")");
	BucketTarget &target = _buckets[static_cast<size_t>(p_bucket)];
	target.shadow = p_multimesh;
	target.allocated = 0; // both are allocated anew at the next push
	target.last_count = 0;
	target.bounds_low = target.bounds_high = glm::vec3(0.0f);
}

void SunflowerDrawing::set_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	FieldSimulation *core = _core("set_tile_multimesh");
	if (!core) {
		return;
	}
	FieldSimulation &sim = *core;
	if (!_is_tile(sim, p_tile) || !gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	_tiles.resize(sim.tiles().get_tile_count());
	_reorder.resize(uint32_t(_tiles.size()));
	_tile_counts.resize(_tiles.size(), 0);
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh;
	_upload_tile(sim, static_cast<uint32_t>(p_tile));
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // allocating the data drew every instance
}

void SunflowerDrawing::adopt_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	FieldSimulation *core = _core("adopt_tile_multimesh");
	if (!core) {
		return;
	}
	FieldSimulation &sim = *core;
	if (!_is_tile(sim, p_tile)) {
		return;
	}
	_tiles.resize(sim.tiles().get_tile_count());
	_reorder.resize(uint32_t(_tiles.size()));
	_tile_counts.resize(_tiles.size(), 0);
	// Ordered for the previous field's observer, taken to be about where this one's is (a field edited
	// in place): written again once the observer moves on, not all at once after every edit.
	_reorder.set_ordered(uint32_t(p_tile), sim.near().get_observer());
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh; // its data is this tile's already
	_tile_counts[static_cast<size_t>(p_tile)] = sim.tiles().get_tile(uint32_t(p_tile)).plants;
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // its count is the previous field's
}

int64_t SunflowerDrawing::get_tile_count() const {
	const FieldSimulation *core = _core("get_tile_count");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	return sim.tiles().get_tile_count();
}

gdx::PackedInt64Array SunflowerDrawing::get_tile_ids() const {
	const FieldSimulation *core = _core("get_tile_ids");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	const FarTiles &tiles = sim.tiles();
	gdx::PackedInt64Array out;
	out.resize(int64_t(tiles.get_tile_count()) * TILE_IDS);
	int64_t *row = out.data();
	for (uint32_t t = 0; t < tiles.get_tile_count(); ++t, row += TILE_IDS) {
		const FarTiles::Tile &tile = tiles.get_tile(t);
		row[0] = int64_t(tile.key);
		row[1] = int64_t(tiles.get_tile_signature(t));
		row[2] = tile.species;
		row[3] = tile.level;
		row[4] = tile.is_top() ? -1 : int64_t(tile.parent);
	}
	return out;
}

gdx::PackedFloat32Array SunflowerDrawing::get_tile_places() const {
	const FieldSimulation *core = _core("get_tile_places");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	const FarTiles &tiles = sim.tiles();
	gdx::PackedFloat32Array out;
	out.resize(int64_t(tiles.get_tile_count()) * TILE_PLACES);
	float *row = out.data();
	for (uint32_t t = 0; t < tiles.get_tile_count(); ++t, row += TILE_PLACES) {
		const ChunkBounds bounds = tiles.get_tile_bounds(t);
		const float values[TILE_PLACES] = { bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x - bounds.min.x,
			bounds.max.y - bounds.min.y, bounds.max.z - bounds.min.z, tiles.get_tile_begin(t), tiles.get_tile_shown_from(t) };
		std::copy(values, values + TILE_PLACES, row);
	}
	return out;
}

gdx::PackedFloat32Array SunflowerDrawing::get_tile_merge_rule() const {
	const FieldSimulation *core = _core("get_tile_merge_rule");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	// The impostor shader's tile_merge after the tile's own level: the field's top level, where
	// level 1 begins, the fade's share of an octave.
	const float values[] = { float(sim.tiles().get_top_tile_level()), sim.tiles().merge_distance(1), FarTiles::TILE_MERGE_FADE };
	gdx::PackedFloat32Array out;
	out.assign(values, std::size(values));
	return out;
}

gdx::Vector2 SunflowerDrawing::choose_tile_level(double p_distance) const {
	const FieldSimulation *core = _core("choose_tile_level");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	const FarTiles::TileChoice choice = sim.tiles().choose_tile_level(float(p_distance));
	return gdx::Vector2{ float(choice.level), choice.fade };
}

gdx::PackedByteArray SunflowerDrawing::get_active_mask(int64_t p_species) const {
	const FieldSimulation *core = _core("get_active_mask");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedByteArray out;
	if (!SunflowerSimulation::is_species(p_species)) {
		return out;
	}
	const FieldLayout &layout = sim.plants().get_layout();
	out.resize(int64_t(layout.grid_x) * layout.grid_z);
	sim.near().write_active_mask(uint32_t(p_species), out.data());
	return out;
}

gdx::PackedByteArray SunflowerDrawing::get_tiles_drawn() const {
	const FieldSimulation *core = _core("get_tiles_drawn");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedByteArray out;
	out.resize(sim.tiles().get_tile_count());
	for (uint32_t tile = 0; tile < sim.tiles().get_tile_count(); ++tile) {
		out.data()[tile] = sim.is_tile_drawn(tile) ? 1 : 0;
	}
	return out;
}

int64_t SunflowerDrawing::get_mask_version() const {
	const FieldSimulation *core = _core("get_mask_version");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	return sim.get_mask_version();
}

gdx::PackedInt32Array SunflowerDrawing::get_chunk_grid() const {
	const FieldSimulation *core = _core("get_chunk_grid");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedInt32Array out;
	out.resize(2);
	out.data()[0] = sim.plants().get_layout().grid_x;
	out.data()[1] = sim.plants().get_layout().grid_z;
	return out;
}

void SunflowerDrawing::compute_chunk_signatures() {
	FieldSimulation *core = _core("compute_chunk_signatures");
	if (!core) {
		return;
	}
	FieldSimulation &sim = *core;
	sim.compute_chunk_signatures();
}

void SunflowerDrawing::release_multimeshes() {
	if (const FieldSimulation *core = _core("release_multimeshes")) {
		_release(*core);
	}
}

void SunflowerDrawing::_release(const FieldSimulation &p_sim) {
	_buckets.assign(p_sim.near().get_bucket_count(), BucketTarget{});
	_tiles.clear();
	_tile_visible.clear();
	_reorder.resize(0);
	_tile_counts.clear();
}

int64_t SunflowerDrawing::get_chunk_count() const {
	const FieldSimulation *core = _core("get_chunk_count");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	return sim.plants().get_chunk_count();
}

gdx::AABB SunflowerDrawing::get_chunk_aabb(int64_t p_chunk) const {
	const FieldSimulation *core = _core("get_chunk_aabb");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	SF_FAIL_COND_V_MSG(p_chunk < 0 || p_chunk >= int64_t(sim.plants().get_chunk_count()), gdx::AABB{},
			"chunk " + std::to_string(p_chunk) + " is out of range (the field has " + std::to_string(sim.plants().get_chunk_count()) +
					" chunks)");
	const ChunkBounds bounds = sim.plants().get_chunk_bounds(static_cast<uint32_t>(p_chunk));
	return gdx::to_godot_aabb(bounds.min, bounds.max);
}

void SunflowerDrawing::_upload_tile(const FieldSimulation &p_sim, uint32_t p_tile) {
	const uint32_t count = p_sim.tiles().get_tile(p_tile).plants;
	gdx::PackedFloat32Array buffer;
	buffer.resize(int64_t(count) * FAR_FLOATS_PER_INSTANCE);
	const glm::vec3 &observer = p_sim.near().get_observer();
	p_sim.tiles().write_tile_instances(p_tile, buffer.data(), &observer);
	_reorder.set_ordered(p_tile, observer); // (a write of it in progress given up: written whole now)
	_tile_counts[p_tile] = count;
	if (_tiles[p_tile].is_valid()) {
		gdx::RenderingServer::multimesh_allocate_data(_tiles[p_tile], count, gdx::RenderingServer::COMPACT);
		// A merged tile keeps a quarter of its plants a level: one of a few large plants may keep
		// none, and Vulkan refuses an empty buffer with an engine error.
		if (count > 0) {
			gdx::RenderingServer::multimesh_set_buffer(_tiles[p_tile], buffer);
		}
	}
}

void SunflowerDrawing::_order_tiles(const FieldSimulation &p_sim) {
	// One tile at a time has its records written again, nearest the observer first, once the observer
	// has moved on from where they were ordered (TileReorder), a few chunks a frame.
	const FarTiles &tiles = p_sim.tiles();
	if (_reorder.get_tile() != FarTiles::NO_TILE && _reorder_version != p_sim.get_records_version()) {
		_reorder.cancel(); // the records changed meanwhile: the driver gives the tiles anew
	}
	if (_reorder.get_tile() == FarTiles::NO_TILE) {
		const uint32_t tile = _reorder.begin(tiles, p_sim.near().get_observer());
		if (tile == FarTiles::NO_TILE) {
			return;
		}
		_reorder_version = p_sim.get_records_version();
		_reorder_buffer.resize(int64_t(tiles.get_tile(tile).plants) * FAR_FLOATS_PER_INSTANCE);
	}
	const uint32_t tile = _reorder.get_tile();
	if (!_reorder.advance(tiles, _reorder_buffer.data(), TILE_ORDER_PLANTS_PER_FRAME)) {
		return;
	}
	// (Its MultiMesh holds as many instances unless the field was laid out again in place since: the
	// driver gives that one its tiles anew.)
	const uint32_t written = _reorder.get_written();
	if (_tiles[tile].is_valid() && written > 0 && _tile_counts[tile] == written) {
		gdx::RenderingServer::multimesh_set_buffer(_tiles[tile], _reorder_buffer);
	}
}

void SunflowerDrawing::_push_bucket(const FieldSimulation &p_sim, uint32_t p_bucket) {
	BucketTarget &target = _buckets[p_bucket];
	const InstanceBuffer &bucket = p_sim.near().get_bucket(p_bucket);
	const uint32_t count = bucket.get_count();
	if (!target.multimesh.is_valid() || (count == 0 && target.last_count == 0)) {
		return;
	}
	// The bucket's MultiMesh and, when it has one, its shadow caster's get the same instances.
	const gdx::Rid meshes[2] = { target.multimesh, target.shadow };
	const size_t mesh_count = target.shadow.is_valid() ? 2 : 1;
	const uint32_t stride = bucket.get_stride();
	if (count > target.allocated || stride != target.stride) {
		target.allocated = std::max(bucket.get_capacity(), count);
		target.stride = stride;
		// Whole plants' records carry custom data; the impostors' are compact (2D transforms only).
		gdx::RenderingServer::Format format = gdx::RenderingServer::TRANSFORM_AND_COLOUR;
		if (stride == WHOLE_FLOATS_PER_INSTANCE) {
			format = gdx::RenderingServer::TRANSFORM_COLOUR_AND_CUSTOM;
		} else if (stride == FAR_FLOATS_PER_INSTANCE) {
			format = gdx::RenderingServer::COMPACT;
		}
		for (size_t m = 0; m < mesh_count; ++m) {
			gdx::RenderingServer::multimesh_allocate_data(meshes[m], target.allocated, format);
		}
		target.staging.resize(int64_t(target.allocated) * stride);
	}
	if (count > 0) {
		std::copy_n(bucket.get_data(), size_t(count) * stride, target.staging.data());
		// The box of this frame's plants, so that each pass (a shadow cascade, the camera) draws the
		// bucket only when they reach into it.
		const bool moved = bucket.get_bounds_low() != target.bounds_low || bucket.get_bounds_high() != target.bounds_high;
		target.bounds_low = bucket.get_bounds_low();
		target.bounds_high = bucket.get_bounds_high();
		for (size_t m = 0; m < mesh_count; ++m) {
			gdx::RenderingServer::multimesh_set_buffer(meshes[m], target.staging);
			if (moved) {
				gdx::RenderingServer::multimesh_set_custom_aabb(meshes[m], gdx::to_godot_aabb(target.bounds_low, target.bounds_high));
			}
		}
	}
	for (size_t m = 0; m < mesh_count; ++m) {
		gdx::RenderingServer::multimesh_set_visible_instances(meshes[m], count);
	}
	target.last_count = count;
}

void SunflowerDrawing::draw() {
	FieldSimulation *core = _core("draw");
	if (!core) {
		return;
	}
	const auto start = std::chrono::steady_clock::now();
	const FieldSimulation &sim = *core;
	for (uint32_t b = 0; b < _buckets.size(); ++b) {
		_push_bucket(sim, b);
	}
	_order_tiles(sim);
	// Each tile draws only its records kept at the nearest level its plants may be given.
	for (size_t t = 0; t < _tiles.size() && t < _tile_visible.size(); ++t) {
		const int64_t visible = sim.tiles().get_tile_visible_count(uint32_t(t));
		if (_tiles[t].is_valid() && visible != _tile_visible[t]) {
			gdx::RenderingServer::multimesh_set_visible_instances(_tiles[t], visible);
			_tile_visible[t] = visible;
		}
	}
	_last_draw_usec = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
}

bool SunflowerDrawing::_is_tile(const FieldSimulation &p_sim, int64_t p_tile) const {
	SF_FAIL_COND_V_MSG(p_tile < 0 || p_tile >= int64_t(p_sim.tiles().get_tile_count()), false,
			"tile " + std::to_string(p_tile) + " is out of range (the field has " + std::to_string(p_sim.tiles().get_tile_count()) +
					" tiles)");
	return true;
}

int64_t SunflowerDrawing::get_bucket_instance_count(int64_t p_bucket) const {
	const FieldSimulation *core = _core("get_bucket_instance_count");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	return p_bucket >= 0 && p_bucket < int64_t(sim.near().get_bucket_count()) ? sim.near().get_bucket(uint32_t(p_bucket)).get_count() : 0;
}

gdx::PackedByteArray SunflowerDrawing::get_filled_buckets() const {
	const FieldSimulation *core = _core("get_filled_buckets");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedByteArray out;
	out.resize(sim.near().get_bucket_count());
	uint8_t *filled = out.data();
	for (uint32_t b = 0; b < sim.near().get_bucket_count(); ++b) {
		filled[b] = sim.near().get_bucket(b).get_count() > 0 ? 1 : 0;
	}
	return out;
}

int64_t SunflowerDrawing::mesh_bucket(int64_t p_level, int64_t p_part) {
	SF_FAIL_COND_V_MSG(p_level < 0 || p_level >= LOD_MESH_COUNT || p_part < 0 || p_part >= PART_COUNT, -1,
			"mesh level " + std::to_string(p_level) + " / part " + std::to_string(p_part) + " is out of range (0–2 each)");
	return sunflower::mesh_bucket(uint32_t(p_level), uint32_t(p_part));
}
