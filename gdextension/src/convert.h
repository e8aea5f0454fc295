#pragma once
// The one place where engine types and core (GLM / std) types meet.
#include "binding/godot_api.h"

#include "core/ground.h"
#include "core/plant_pushes.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace gdx {

inline glm::vec2 to_core(const Vector2 &p_v) {
	return glm::vec2(p_v.x, p_v.y);
}
inline glm::vec3 to_core(const Vector3 &p_v) {
	return glm::vec3(p_v.x, p_v.y, p_v.z);
}
inline Vector2 to_godot(const glm::vec2 &p_v) {
	return Vector2{ p_v.x, p_v.y };
}
inline Vector3 to_godot(const glm::vec3 &p_v) {
	return Vector3{ p_v.x, p_v.y, p_v.z };
}
inline AABB to_godot_aabb(const glm::vec3 &p_min, const glm::vec3 &p_max) {
	return AABB{ to_godot(p_min), to_godot(p_max - p_min) };
}
inline std::string to_core(const PackedByteArray &p_bytes) {
	const uint8_t *data = p_bytes.data();
	return data ? std::string(reinterpret_cast<const char *>(data), static_cast<size_t>(p_bytes.size())) : std::string();
}
// Frustum planes: (normal.x, normal.y, normal.z, d) four floats each, as the node packs them.
inline const glm::vec4 *to_core_planes(const PackedFloat32Array &p_planes) {
	return reinterpret_cast<const glm::vec4 *>(p_planes.data());
}

// A point's place on the ground (x, z), for lookups that ignore height.
inline glm::vec2 to_core_ground(const Vector3 &p_v) {
	return glm::vec2(p_v.x, p_v.z);
}

// Pushers: (x, y, z, radius) four floats each, as the node packs them.
inline void to_core_pushers(const PackedFloat32Array &p_packed, std::vector<sunflower::Pusher> &r_pushers) {
	const float *data = p_packed.data();
	r_pushers.resize(size_t(p_packed.size() / 4));
	for (size_t i = 0; i < r_pushers.size(); ++i) {
		r_pushers[i] = sunflower::Pusher{ glm::vec3(data[4 * i], data[4 * i + 1], data[4 * i + 2]), data[4 * i + 3] };
	}
}

// A height map from an image's pixels as RGBA floats: the core checks and reads them
// (sunflower::height_grid_from_rgba). Returns what is wrong with the arguments, or an empty string.
inline std::string to_core_height_grid(const PackedFloat32Array &p_rgba, int64_t p_width, int64_t p_depth, Vector2 p_origin,
		Vector2 p_size, double p_height_min, double p_height_max, sunflower::HeightGrid &r_grid) {
	return sunflower::height_grid_from_rgba(p_rgba.data(), size_t(p_rgba.size()), p_width, p_depth, to_core(p_origin), to_core(p_size),
			p_height_min, p_height_max, r_grid);
}

inline PackedInt32Array to_godot_indices(const std::vector<uint32_t> &p_indices) {
	PackedInt32Array out;
	out.resize(int64_t(p_indices.size()));
	int32_t *data = out.data();
	for (size_t i = 0; i < p_indices.size(); ++i) {
		data[i] = static_cast<int32_t>(p_indices[i]);
	}
	return out;
}

} // namespace gdx
