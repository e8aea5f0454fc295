#pragma once
// The one place where engine types and core (GLM / std) types meet.
#include "godot_api.h"

#include "core/field_simulation.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
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

// A height map from an image's pixels as RGBA floats (Image.FORMAT_RGBAF): red 0–1 spans p_height_min
// to p_height_max (as HeightMapShape3D.update_map_data_from_image reads it), alpha below one half is a
// hole. Returns what is wrong with the arguments, or an empty string.
inline std::string to_core_height_grid(const PackedFloat32Array &p_rgba, int64_t p_width, int64_t p_depth, Vector2 p_origin,
		Vector2 p_size, double p_height_min, double p_height_max, sunflower::HeightGrid &r_grid) {
	if (p_width < 2 || p_depth < 2 || p_width > 16384 || p_depth > 16384) {
		return "height map: " + std::to_string(p_width) + " × " + std::to_string(p_depth) +
				" pixels; it needs 2 to 16384 on each side";
	}
	if (p_rgba.size() != p_width * p_depth * 4) {
		return "height map: " + std::to_string(p_rgba.size()) + " floats for " + std::to_string(p_width) + " × " +
				std::to_string(p_depth) + " RGBA pixels";
	}
	if (!(p_size.x > 0.0f && p_size.y > 0.0f) || !std::isfinite(p_size.x) || !std::isfinite(p_size.y) ||
			!std::isfinite(p_origin.x) || !std::isfinite(p_origin.y)) {
		return "height map: the rectangle it covers needs a finite position and a positive size";
	}
	if (!std::isfinite(p_height_min) || !std::isfinite(p_height_max)) {
		return "height map: the height range needs finite ends";
	}
	r_grid.width = int(p_width);
	r_grid.depth = int(p_depth);
	r_grid.origin = to_core(p_origin);
	r_grid.size = to_core(p_size);
	const float *pixel = p_rgba.data();
	const float low = float(p_height_min);
	const float span = float(p_height_max - p_height_min);
	r_grid.heights.resize(size_t(p_width) * size_t(p_depth));
	for (size_t i = 0; i < r_grid.heights.size(); ++i, pixel += 4) {
		r_grid.heights[i] = pixel[3] >= 0.5f ? low + pixel[0] * span : NAN;
	}
	return std::string();
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
