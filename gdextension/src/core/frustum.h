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

	enum Overlap {
		OUTSIDE, // beyond a plane: every sphere inside the box fails intersects_sphere()
		CROSSING, // neither: test each sphere
		INSIDE, // within every plane: every sphere inside the box passes
	};
	// A box within this many metres of a plane counts as crossing it, so that rounding never decides
	// a box against what its spheres' own tests say (a float's step is 0.5 mm at 4 km).
	static constexpr float BOX_MARGIN = 0.01f;
	// Where the box [p_low, p_high] lies, for spheres that fit inside it. When it is CROSSING,
	// r_crossing (if given) gets the planes it crosses: the only ones a sphere inside the box can be
	// beyond, so its intersects_sphere() says what this frustum's does, testing fewer planes.
	Overlap classify_box(const glm::vec3 &p_low, const glm::vec3 &p_high, Frustum *r_crossing = nullptr) const {
		Overlap overlap = INSIDE;
		if (r_crossing != nullptr) {
			r_crossing->_count = 0;
		}
		for (size_t i = 0; i < _count; ++i) {
			const glm::vec4 &plane = _planes[i];
			// The box's corners least and most far along the plane's normal.
			const float nearest = plane.x * (plane.x > 0.0f ? p_low.x : p_high.x) +
					plane.y * (plane.y > 0.0f ? p_low.y : p_high.y) + plane.z * (plane.z > 0.0f ? p_low.z : p_high.z);
			const float farthest = plane.x * (plane.x > 0.0f ? p_high.x : p_low.x) +
					plane.y * (plane.y > 0.0f ? p_high.y : p_low.y) + plane.z * (plane.z > 0.0f ? p_high.z : p_low.z);
			if (nearest - plane.w > BOX_MARGIN) {
				return OUTSIDE;
			}
			if (farthest - plane.w > -BOX_MARGIN) {
				overlap = CROSSING;
				if (r_crossing != nullptr) {
					r_crossing->_planes[r_crossing->_count++] = plane;
				}
			}
		}
		return overlap;
	}

private:
	std::array<glm::vec4, 6> _planes{};
	size_t _count = 0;
};

} // namespace sunflower
