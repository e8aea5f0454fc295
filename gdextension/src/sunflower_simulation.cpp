#include "sunflower_simulation.h"

#include "binding/class_binder.h"
#include "binding/convert.h"
#include "binding/rendering_server.h"

#include <algorithm>
#include <chrono>
#include <cmath>

using namespace sunflower;


void SunflowerSimulation::bind_methods() {
	const char *CLASS = "SunflowerSimulation";
	gdx::bind_method(CLASS, "load_map", &SunflowerSimulation::load_map, { "text", "source", "legend", "max_plants" });
	gdx::bind_method(CLASS, "clear", &SunflowerSimulation::clear);
	gdx::bind_method(CLASS, "get_map_columns", &SunflowerSimulation::get_map_columns);
	gdx::bind_method(CLASS, "get_map_rows", &SunflowerSimulation::get_map_rows);
	gdx::bind_method(CLASS, "get_map_objects", &SunflowerSimulation::get_map_objects);
	gdx::bind_method(CLASS, "set_layout", &SunflowerSimulation::set_layout, { "cell_size", "seed", "independent_jitter", "chunk_size" });
	gdx::bind_method(CLASS, "set_plant_shape", &SunflowerSimulation::set_plant_shape, { "part_scale", "cull_radius", "height" });
	gdx::bind_method(CLASS, "set_wind", &SunflowerSimulation::set_wind, { "power", "direction" });
	gdx::bind_method(CLASS, "set_wind_dynamics", &SunflowerSimulation::set_wind_dynamics, { "values" });
	gdx::bind_method(CLASS, "set_lod", &SunflowerSimulation::set_lod, { "distances", "hysteresis", "interval", "force_level" });
	gdx::bind_method(CLASS, "set_observer", &SunflowerSimulation::set_observer, { "position", "frustum" });
	gdx::bind_method(CLASS, "set_worker_threads", &SunflowerSimulation::set_worker_threads, { "threads", "parallel_min_plants" });
	gdx::bind_method(CLASS, "get_worker_threads", &SunflowerSimulation::get_worker_threads);
	gdx::bind_method(CLASS, "get_last_task_count", &SunflowerSimulation::get_last_task_count);
	gdx::bind_method(CLASS, "set_bucket_multimesh", &SunflowerSimulation::set_bucket_multimesh, { "bucket", "multimesh" });
	gdx::bind_method(CLASS, "set_chunk_multimeshes", &SunflowerSimulation::set_chunk_multimeshes, { "chunk", "sprite", "billboard" });
	gdx::bind_method(CLASS, "release_multimeshes", &SunflowerSimulation::release_multimeshes);
	gdx::bind_method(CLASS, "get_chunk_count", &SunflowerSimulation::get_chunk_count);
	gdx::bind_method(CLASS, "get_chunk_aabb", &SunflowerSimulation::get_chunk_aabb, { "chunk" });
	gdx::bind_method(CLASS, "update", &SunflowerSimulation::update, { "delta" });
	gdx::bind_method(CLASS, "get_plant_count", &SunflowerSimulation::get_plant_count);
	gdx::bind_method(CLASS, "get_lod_counts", &SunflowerSimulation::get_lod_counts);
	gdx::bind_method(CLASS, "get_plant_position", &SunflowerSimulation::get_plant_position, { "plant" });
	gdx::bind_method(CLASS, "get_plant_lod", &SunflowerSimulation::get_plant_lod, { "plant" });
	gdx::bind_method(CLASS, "get_plant_parts", &SunflowerSimulation::get_plant_parts, { "plant" });
	gdx::bind_method(CLASS, "get_bucket_instance_count", &SunflowerSimulation::get_bucket_instance_count, { "bucket" });
	gdx::bind_method(CLASS, "get_last_update_usec", &SunflowerSimulation::get_last_update_usec);
	gdx::bind_method(CLASS, "get_memory_bytes", &SunflowerSimulation::get_memory_bytes);
	gdx::bind_method(CLASS, "get_time", &SunflowerSimulation::get_time);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_SPRITE", BUCKET_SPRITE);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_BILLBOARD", BUCKET_BILLBOARD);
	gdx::bind_integer_constant(CLASS, "", "BUCKET_COUNT", BUCKET_COUNT);
}

gdx::String SunflowerSimulation::load_map(const gdx::PackedByteArray &p_text, const gdx::String &p_source,
		const gdx::String &p_legend, int64_t p_max_plants) {
	MapLimits limits;
	if (p_max_plants > 0) {
		limits.max_plants = p_max_plants;
	}
	MapError error;
	if (!_sim.load_map(gdx::to_core(p_text), gdx::to_core_u32(p_legend), p_source.utf8(), limits, error)) {
		return gdx::String(error.to_string());
	}
	release_multimeshes(); // the old field's chunks no longer exist
	return gdx::String();
}

void SunflowerSimulation::clear() {
	_sim.clear();
	release_multimeshes();
}

int64_t SunflowerSimulation::get_map_columns() const {
	return _sim.get_map().columns;
}

int64_t SunflowerSimulation::get_map_rows() const {
	return _sim.get_map().rows;
}

gdx::PackedInt32Array SunflowerSimulation::get_map_objects() const {
	std::vector<int32_t> flat;
	for (const MapObject &object : _sim.get_map().objects) {
		flat.insert(flat.end(), { object.column, object.row, static_cast<int32_t>(object.symbol) });
	}
	gdx::PackedInt32Array out;
	out.assign(flat.data(), flat.size());
	return out;
}

void SunflowerSimulation::set_layout(double p_cell_size, int64_t p_seed, bool p_independent_jitter, double p_chunk_size) {
	LayoutParams params = _sim.get_layout_params();
	params.cell_size = static_cast<float>(p_cell_size);
	params.seed = static_cast<uint64_t>(p_seed);
	params.independent_jitter = p_independent_jitter;
	params.chunk_size = static_cast<float>(p_chunk_size);
	if (_sim.set_layout_params(params)) {
		release_multimeshes(); // the chunks changed
	}
}

void SunflowerSimulation::set_plant_shape(double p_part_scale, double p_cull_radius, double p_height) {
	PlantShape shape;
	shape.part_scale = std::isfinite(p_part_scale) && p_part_scale > 0.0 ? float(p_part_scale) : shape.part_scale;
	shape.cull_radius = std::isfinite(p_cull_radius) && p_cull_radius > 0.0 ? float(p_cull_radius) : shape.cull_radius;
	shape.height = std::isfinite(p_height) && p_height > 0.0 ? float(p_height) : shape.height;
	_sim.set_shape(shape);
}

void SunflowerSimulation::set_wind(double p_power, gdx::Vector2 p_direction) {
	WindParams params = _sim.get_wind().get_params();
	params.power = static_cast<float>(p_power);
	params.direction = gdx::to_core(p_direction);
	_sim.set_wind(params);
}

void SunflowerSimulation::set_wind_dynamics(const gdx::PackedFloat32Array &p_values) {
	const float *v = p_values.data();
	if (p_values.size() != 8) {
		gdx::print_error("set_wind_dynamics expects 8 values (d1, d2, h, max_bend, flip_interval, flip_chance, gust_speed, gust_share)",
				__func__, __FILE__, __LINE__);
		return;
	}
	WindParams params = _sim.get_wind().get_params();
	params.d1 = v[0];
	params.d2 = v[1];
	params.h = v[2];
	params.max_bend = v[3];
	params.flip_interval = v[4];
	params.flip_chance = v[5];
	params.gust_speed = v[6];
	params.gust_share = v[7];
	_sim.set_wind(params);
}

void SunflowerSimulation::set_lod(const gdx::PackedFloat32Array &p_distances, double p_hysteresis, double p_interval,
		int64_t p_force_level) {
	LodParams params = _sim.get_lod().get_params();
	if (p_distances.size() == 4) {
		std::copy_n(p_distances.data(), 4, params.distances.begin());
	} else {
		gdx::print_error("set_lod expects 4 distances", __func__, __FILE__, __LINE__);
	}
	params.hysteresis = std::isfinite(p_hysteresis) ? std::max(0.0f, float(p_hysteresis)) : params.hysteresis;
	params.interval = std::isfinite(p_interval) ? std::max(0.0f, float(p_interval)) : params.interval;
	params.force_level = p_force_level >= 0 && p_force_level < LOD_COUNT ? int(p_force_level) : -1;
	_sim.set_lod(params);
}

void SunflowerSimulation::set_observer(gdx::Vector3 p_position, const gdx::PackedFloat32Array &p_frustum) {
	_sim.set_observer(gdx::to_core(p_position));
	const int64_t count = p_frustum.size() / 4;
	if (count > 0) {
		_sim.get_frustum().set_planes(reinterpret_cast<const glm::vec4 *>(p_frustum.data()), static_cast<size_t>(count));
	} else {
		_sim.get_frustum().clear();
	}
}

void SunflowerSimulation::set_bucket_multimesh(int64_t p_bucket, gdx::Rid p_multimesh) {
	if (!gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	if (p_bucket < 0 || p_bucket >= BUCKET_COUNT) {
		gdx::print_error("bucket " + std::to_string(p_bucket) + " is out of range", __func__, __FILE__, __LINE__);
		return;
	}
	BucketTarget &target = _buckets[static_cast<size_t>(p_bucket)];
	target.multimesh = p_multimesh;
	target.allocated = 0;
	target.last_count = 0;
}

void SunflowerSimulation::set_chunk_multimeshes(int64_t p_chunk, gdx::Rid p_sprite, gdx::Rid p_billboard) {
	if (!gdx::RenderingServer::ensure_loaded()) {
		return;
	}
	if (p_chunk < 0 || p_chunk >= int64_t(_sim.get_chunk_count())) {
		gdx::print_error("chunk " + std::to_string(p_chunk) + " is out of range", __func__, __FILE__, __LINE__);
		return;
	}
	_chunks.resize(_sim.get_chunk_count());
	_chunks[static_cast<size_t>(p_chunk)] = ChunkTarget{ p_sprite, p_billboard };
	_upload_chunk(static_cast<uint32_t>(p_chunk));
}

void SunflowerSimulation::release_multimeshes() {
	for (BucketTarget &target : _buckets) {
		target.multimesh = gdx::Rid{};
		target.allocated = 0;
		target.last_count = 0;
	}
	_chunks.clear();
}

int64_t SunflowerSimulation::get_chunk_count() const {
	return _sim.get_chunk_count();
}

gdx::AABB SunflowerSimulation::get_chunk_aabb(int64_t p_chunk) const {
	if (p_chunk < 0 || p_chunk >= int64_t(_sim.get_chunk_count())) {
		gdx::print_error("chunk " + std::to_string(p_chunk) + " is out of range", __func__, __FILE__, __LINE__);
		return gdx::AABB{};
	}
	const ChunkBounds bounds = _sim.get_chunk_bounds(static_cast<uint32_t>(p_chunk));
	return gdx::to_godot_aabb(bounds.min, bounds.max);
}

void SunflowerSimulation::_upload_chunk(uint32_t p_chunk) {
	const ChunkTarget &target = _chunks[p_chunk];
	const uint32_t count = _sim.get_layout().chunks[p_chunk].count;
	gdx::PackedFloat32Array buffer;
	buffer.resize(int64_t(count) * FLOATS_PER_INSTANCE);
	_sim.write_chunk_instances(p_chunk, buffer.data());
	const int64_t visible = _sim.is_chunk_active(p_chunk) ? 0 : -1;
	for (gdx::Rid multimesh : { target.sprite, target.billboard }) {
		if (multimesh.is_valid()) {
			gdx::RenderingServer::multimesh_allocate_data(multimesh, count);
			gdx::RenderingServer::multimesh_set_buffer(multimesh, buffer);
			gdx::RenderingServer::multimesh_set_visible_instances(multimesh, visible);
		}
	}
}

void SunflowerSimulation::_push_bucket(uint32_t p_bucket) {
	BucketTarget &target = _buckets[p_bucket];
	const InstanceBuffer &bucket = _sim.get_bucket(p_bucket);
	const uint32_t count = bucket.get_count();
	if (!target.multimesh.is_valid() || (count == 0 && target.last_count == 0)) {
		return;
	}
	if (count > target.allocated) {
		target.allocated = std::max(bucket.get_capacity(), count);
		gdx::RenderingServer::multimesh_allocate_data(target.multimesh, target.allocated);
		target.staging.resize(int64_t(target.allocated) * FLOATS_PER_INSTANCE);
	}
	if (count > 0) {
		std::copy_n(bucket.get_data(), size_t(count) * FLOATS_PER_INSTANCE, target.staging.data());
		gdx::RenderingServer::multimesh_set_buffer(target.multimesh, target.staging);
	}
	gdx::RenderingServer::multimesh_set_visible_instances(target.multimesh, count);
	target.last_count = count;
}

void SunflowerSimulation::update(double p_delta) {
	const auto start = std::chrono::steady_clock::now();
	_sim.update(static_cast<float>(p_delta));
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		_push_bucket(b);
	}
	for (uint32_t chunk : _sim.get_changed_chunks()) {
		if (chunk < _chunks.size()) {
			const int64_t visible = _sim.is_chunk_active(chunk) ? 0 : -1;
			for (gdx::Rid multimesh : { _chunks[chunk].sprite, _chunks[chunk].billboard }) {
				if (multimesh.is_valid()) {
					gdx::RenderingServer::multimesh_set_visible_instances(multimesh, visible);
				}
			}
		}
	}
	_last_update_usec = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
}

bool SunflowerSimulation::_check_plant(int64_t p_plant, const char *p_function) const {
	if (p_plant >= 0 && p_plant < int64_t(_sim.get_plant_count())) {
		return true;
	}
	gdx::print_error("plant index " + std::to_string(p_plant) + " is out of range (the field has " +
					std::to_string(_sim.get_plant_count()) + " plants)",
			p_function, __FILE__, __LINE__);
	return false;
}

int64_t SunflowerSimulation::get_plant_count() const {
	return _sim.get_plant_count();
}

gdx::PackedInt32Array SunflowerSimulation::get_lod_counts() const {
	const auto counts = _sim.get_lod_counts();
	int32_t values[LOD_COUNT];
	for (size_t i = 0; i < LOD_COUNT; ++i) {
		values[i] = static_cast<int32_t>(counts[i]);
	}
	gdx::PackedInt32Array out;
	out.assign(values, LOD_COUNT);
	return out;
}

gdx::Vector3 SunflowerSimulation::get_plant_position(int64_t p_plant) const {
	if (!_check_plant(p_plant, __func__)) {
		return gdx::Vector3{};
	}
	const glm::vec2 position = _sim.get_layout().plants[size_t(p_plant)].position;
	return gdx::Vector3{ position.x, 0.0f, position.y };
}

int64_t SunflowerSimulation::get_plant_lod(int64_t p_plant) const {
	return _check_plant(p_plant, __func__) ? _sim.get_plant_lod(uint32_t(p_plant)) : -1;
}

gdx::PackedFloat32Array SunflowerSimulation::get_plant_parts(int64_t p_plant) const {
	gdx::PackedFloat32Array out;
	if (!_check_plant(p_plant, __func__)) {
		return out;
	}
	PartTransforms parts;
	_sim.get_plant_parts(uint32_t(p_plant), parts);
	out.resize(PART_COUNT * FLOATS_PER_INSTANCE);
	float *data = out.data();
	for (uint32_t part = 0; part < PART_COUNT; ++part) {
		write_instance(data + part * FLOATS_PER_INSTANCE, parts.basis[part], parts.origin[part]);
	}
	return out;
}

int64_t SunflowerSimulation::get_bucket_instance_count(int64_t p_bucket) const {
	return p_bucket >= 0 && p_bucket < BUCKET_COUNT ? _sim.get_bucket(uint32_t(p_bucket)).get_count() : 0;
}

int64_t SunflowerSimulation::get_last_update_usec() const {
	return _last_update_usec;
}

void SunflowerSimulation::set_worker_threads(int64_t p_threads, int64_t p_parallel_min_plants) {
	const int64_t limit = int64_t(FieldSimulation::MAX_AUTO_THREADS) * 4;
	if (p_threads < 0 || p_threads > limit) {
		gdx::print_error("worker threads " + std::to_string(p_threads) + " is out of range (0 to " + std::to_string(limit) + ")",
				__func__, __FILE__, __LINE__);
		return;
	}
	_sim.set_worker_threads(static_cast<uint32_t>(p_threads));
	_sim.set_parallel_min_plants(static_cast<uint32_t>(std::clamp<int64_t>(p_parallel_min_plants, 0, INT32_MAX)));
}

int64_t SunflowerSimulation::get_worker_threads() const {
	return _sim.get_worker_threads();
}

int64_t SunflowerSimulation::get_last_task_count() const {
	return _sim.get_last_task_count();
}

int64_t SunflowerSimulation::get_memory_bytes() const {
	return static_cast<int64_t>(_sim.get_memory_bytes());
}

double SunflowerSimulation::get_time() const {
	return _sim.get_time();
}
