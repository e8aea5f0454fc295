#pragma once
// A view frustum as six planes with outward normals (Godot's Camera3D.get_frustum() convention):
// a point p is outside a plane when dot(normal, p) > d.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace sunflower {

class Frustum {
public:
	// An unset frustum contains everything.
	void clear() { _count = 0; }
	// p_planes: (normal.x, normal.y, normal.z, d) each; at most six are used.
	void set_planes(const glm::vec4 *p_planes, size_t p_count);

	bool intersects_sphere(const glm::vec3 &p_center, float p_radius) const {
		for (size_t i = 0; i < _count; ++i) {
			const glm::vec4 &plane = _planes[i];
			if (plane.x * p_center.x + plane.y * p_center.y + plane.z * p_center.z - plane.w > p_radius) {
				return false;
			}
		}
		return true;
	}

private:
	std::array<glm::vec4, 6> _planes{};
	size_t _count = 0;
};

} // namespace sunflower
