// SunflowerSimulation's drawing: the MultiMeshes it fills (near buckets each frame, far tiles once),
// the far-tile table, the active masks, and the frame's update.
#include "sunflower_simulation.h"

#include "binding/class_binder.h"
#include "binding/convert.h"
#include "binding/error_macros.h"
#include "binding/rendering_server.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

using namespace sunflower;

void SunflowerSimulation::set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
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

void SunflowerSimulation::set_bucket_shadow_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
	SF_FAIL_COND_MSG(p_bucket < 0 || p_bucket >= int64_t(_buckets.size()),
			"bucket " + std::to_string(p_bucket) + " is out of range (0 to " + std::to_string(_buckets.size() - 1) + ")");
	BucketTarget &target = _buckets[static_cast<size_t>(p_bucket)];
	target.shadow = p_multimesh;
	target.allocated = 0; // both are allocated anew at the next push
	target.last_count = 0;
	target.bounds_low = target.bounds_high = glm::vec3(0.0f);
}

void SunflowerSimulation::set_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	if (!_is_tile(p_tile) || !gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	_tiles.resize(_sim.tiles().get_tile_count());
	_reorder.resize(uint32_t(_tiles.size()));
	_tile_counts.resize(_tiles.size(), 0);
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh;
	_upload_tile(static_cast<uint32_t>(p_tile));
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // allocating the data drew every instance
}

void SunflowerSimulation::adopt_tile_multimesh(int64_t p_tile, gdx::Rid p_multimesh) {
	if (!_is_tile(p_tile)) {
		return;
	}
	_tiles.resize(_sim.tiles().get_tile_count());
	_reorder.resize(uint32_t(_tiles.size()));
	_tile_counts.resize(_tiles.size(), 0);
	// Ordered for the previous field's observer, taken to be about where this one's is (a field edited
	// in place): written again once the observer moves on, not all at once after every edit.
	_reorder.set_ordered(uint32_t(p_tile), _sim.near().get_observer());
	_tiles[static_cast<size_t>(p_tile)] = p_multimesh; // its data is this tile's already
	_tile_counts[static_cast<size_t>(p_tile)] = _sim.tiles().get_tile(uint32_t(p_tile)).plants;
	_tile_visible.resize(_tiles.size(), -1);
	_tile_visible[static_cast<size_t>(p_tile)] = -1; // its count is the previous field's
}

int64_t SunflowerSimulation::get_tile_count() const {
	return _sim.tiles().get_tile_count();
}

gdx::PackedInt64Array SunflowerSimulation::get_tile_ids() const {
	const FarTiles &tiles = _sim.tiles();
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

gdx::PackedFloat32Array SunflowerSimulation::get_tile_places() const {
	const FarTiles &tiles = _sim.tiles();
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

gdx::PackedFloat32Array SunflowerSimulation::get_tile_merge_rule() const {
	// The impostor shader's tile_merge after the tile's own level: the field's top level, where
	// level 1 begins, the fade's share of an octave.
	const float values[] = { float(_sim.tiles().get_top_tile_level()), _sim.tiles().merge_distance(1), FarTiles::TILE_MERGE_FADE };
	gdx::PackedFloat32Array out;
	out.assign(values, std::size(values));
	return out;
}

gdx::Vector2 SunflowerSimulation::choose_tile_level(double p_distance) const {
	const FarTiles::TileChoice choice = _sim.tiles().choose_tile_level(float(p_distance));
	return gdx::Vector2{ float(choice.level), choice.fade };
}

gdx::PackedByteArray SunflowerSimulation::get_active_mask(int64_t p_species) const {
	gdx::PackedByteArray out;
	if (!_is_species(p_species)) {
		return out;
	}
	const FieldLayout &layout = _sim.plants().get_layout();
	out.resize(int64_t(layout.grid_x) * layout.grid_z);
	_sim.near().write_active_mask(uint32_t(p_species), out.data());
	return out;
}

gdx::PackedByteArray SunflowerSimulation::get_tiles_drawn() const {
	gdx::PackedByteArray out;
	out.resize(_sim.tiles().get_tile_count());
	for (uint32_t tile = 0; tile < _sim.tiles().get_tile_count(); ++tile) {
		out.data()[tile] = _sim.is_tile_drawn(tile) ? 1 : 0;
	}
	return out;
}

int64_t SunflowerSimulation::get_mask_version() const {
	return _sim.get_mask_version();
}

gdx::PackedInt32Array SunflowerSimulation::get_chunk_grid() const {
	gdx::PackedInt32Array out;
	out.resize(2);
	out.data()[0] = _sim.plants().get_layout().grid_x;
	out.data()[1] = _sim.plants().get_layout().grid_z;
	return out;
}

void SunflowerSimulation::compute_chunk_signatures() {
	_sim.compute_chunk_signatures();
}

void SunflowerSimulation::release_multimeshes() {
	_buckets.assign(_sim.near().get_bucket_count(), BucketTarget{});
	_tiles.clear();
	_tile_visible.clear();
	_reorder.resize(0);
	_tile_counts.clear();
}

int64_t SunflowerSimulation::get_chunk_count() const {
	return _sim.plants().get_chunk_count();
}

gdx::AABB SunflowerSimulation::get_chunk_aabb(int64_t p_chunk) const {
	if (!_is_chunk(p_chunk)) {
		return gdx::AABB{};
	}
	const ChunkBounds bounds = _sim.plants().get_chunk_bounds(static_cast<uint32_t>(p_chunk));
	return gdx::to_godot_aabb(bounds.min, bounds.max);
}

void SunflowerSimulation::_upload_tile(uint32_t p_tile) {
	const uint32_t count = _sim.tiles().get_tile(p_tile).plants;
	gdx::PackedFloat32Array buffer;
	buffer.resize(int64_t(count) * FAR_FLOATS_PER_INSTANCE);
	const glm::vec3 &observer = _sim.near().get_observer();
	_sim.tiles().write_tile_instances(p_tile, buffer.data(), &observer);
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

void SunflowerSimulation::_order_tiles() {
	// One tile at a time has its records written again, nearest the observer first, once the observer
	// has moved on from where they were ordered (TileReorder), a few chunks a frame.
	const FarTiles &tiles = _sim.tiles();
	if (_reorder.get_tile() != FarTiles::NO_TILE && _reorder_version != _sim.get_records_version()) {
		_reorder.cancel(); // the records changed meanwhile: the driver gives the tiles anew
	}
	if (_reorder.get_tile() == FarTiles::NO_TILE) {
		const uint32_t tile = _reorder.begin(tiles, _sim.near().get_observer());
		if (tile == FarTiles::NO_TILE) {
			return;
		}
		_reorder_version = _sim.get_records_version();
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

void SunflowerSimulation::_push_bucket(uint32_t p_bucket) {
	BucketTarget &target = _buckets[p_bucket];
	const InstanceBuffer &bucket = _sim.near().get_bucket(p_bucket);
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

void SunflowerSimulation::update(double p_delta) {
	const auto start = std::chrono::steady_clock::now();
	_sim.update(static_cast<float>(p_delta));
	for (uint32_t b = 0; b < _buckets.size(); ++b) {
		_push_bucket(b);
	}
	_order_tiles();
	// Each tile draws only its records kept at the nearest level its plants may be given.
	for (size_t t = 0; t < _tiles.size() && t < _tile_visible.size(); ++t) {
		const int64_t visible = _sim.tiles().get_tile_visible_count(uint32_t(t));
		if (_tiles[t].is_valid() && visible != _tile_visible[t]) {
			gdx::RenderingServer::multimesh_set_visible_instances(_tiles[t], visible);
			_tile_visible[t] = visible;
		}
	}
	_last_update_usec = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
}

bool SunflowerSimulation::_is_tile(int64_t p_tile) const {
	SF_FAIL_COND_V_MSG(p_tile < 0 || p_tile >= int64_t(_sim.tiles().get_tile_count()), false,
			"tile " + std::to_string(p_tile) + " is out of range (the field has " + std::to_string(_sim.tiles().get_tile_count()) +
					" tiles)");
	return true;
}

bool SunflowerSimulation::_is_chunk(int64_t p_chunk) const {
	SF_FAIL_COND_V_MSG(p_chunk < 0 || p_chunk >= int64_t(_sim.plants().get_chunk_count()), false,
			"chunk " + std::to_string(p_chunk) + " is out of range (the field has " +
					std::to_string(_sim.plants().get_chunk_count()) + " chunks)");
	return true;
}
