#include "frustum.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace sunflower {

void Frustum::set_planes(const glm::vec4 *p_planes, size_t p_count) {
	_count = 0;
	for (size_t i = 0; i < std::min<size_t>(p_count, _planes.size()); ++i) {
		const glm::vec3 normal(p_planes[i]);
		const float length = glm::length(normal);
		if (!(length > 1e-6f)) {
			continue; // a degenerate plane culls nothing
		}
		_planes[_count++] = p_planes[i] / length;
	}
}

} // namespace sunflower
