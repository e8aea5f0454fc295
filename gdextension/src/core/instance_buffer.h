#pragma once
// MultiMesh instance data: 16 floats per instance, the 3×4 matrix [basis | origin] row by row, then
// the instance colour (r, g, b, a): Godot's RenderingServer MULTIMESH_TRANSFORM_3D layout with
// colours.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sunflower {

// The transform's floats: the first 12 of an instance (and all of a part's in get_plant_parts).
constexpr uint32_t TRANSFORM_FLOATS = 12;
constexpr uint32_t FLOATS_PER_INSTANCE = TRANSFORM_FLOATS + 4;

inline void write_transform(float *r_out, const glm::mat3 &p_basis, const glm::vec3 &p_origin) {
	for (int row = 0; row < 3; ++row) {
		r_out[row * 4 + 0] = p_basis[0][row];
		r_out[row * 4 + 1] = p_basis[1][row];
		r_out[row * 4 + 2] = p_basis[2][row];
		r_out[row * 4 + 3] = p_origin[row];
	}
}

inline void write_instance(float *r_out, const glm::mat3 &p_basis, const glm::vec3 &p_origin, const glm::vec4 &p_color) {
	write_transform(r_out, p_basis, p_origin);
	r_out[12] = p_color.x;
	r_out[13] = p_color.y;
	r_out[14] = p_color.z;
	r_out[15] = p_color.w;
}

// A growable buffer of instances; grows geometrically and never shrinks, so steady state
// allocates nothing.
class InstanceBuffer {
public:
	void clear() { _count = 0; }
	float *push() {
		if (_count >= get_capacity()) {
			_data.resize(std::max<size_t>(64, size_t(get_capacity()) * 2) * FLOATS_PER_INSTANCE);
		}
		return _data.data() + static_cast<size_t>(_count++) * FLOATS_PER_INSTANCE;
	}
	// Appends another buffer's instances (growing like push, so steady state allocates nothing).
	void append(const InstanceBuffer &p_other) {
		const uint32_t count = _count + p_other._count;
		if (count > get_capacity()) {
			_data.resize(std::max<size_t>(count, size_t(get_capacity()) * 2) * FLOATS_PER_INSTANCE);
		}
		std::copy_n(p_other._data.data(), size_t(p_other._count) * FLOATS_PER_INSTANCE,
				_data.data() + size_t(_count) * FLOATS_PER_INSTANCE);
		_count = count;
	}
	uint32_t get_count() const { return _count; }
	uint32_t get_capacity() const { return static_cast<uint32_t>(_data.size() / FLOATS_PER_INSTANCE); }
	const float *get_data() const { return _data.data(); }

private:
	std::vector<float> _data;
	uint32_t _count = 0;
};

} // namespace sunflower
