#include "ground.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sunflower {

bool HeightGrid::is_valid() const {
	return width >= 2 && depth >= 2 && heights.size() == size_t(width) * size_t(depth) && size.x > 0.0f &&
			size.y > 0.0f && std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(size.x) &&
			std::isfinite(size.y);
}

namespace {

// Where p falls in the lattice: the cell's first sample (ix, iz) and the fractions across it.
struct LatticePoint {
	int ix = 0;
	int iz = 0;
	float fx = 0.0f;
	float fz = 0.0f;
};

bool locate(const HeightGrid &p_grid, const glm::vec2 &p, LatticePoint &r_point) {
	const float u = (p.x - p_grid.origin.x) / p_grid.size.x * float(p_grid.width - 1);
	const float v = (p.y - p_grid.origin.y) / p_grid.size.y * float(p_grid.depth - 1);
	// Within the rectangle, edges included (the comparison is false for NaN).
	if (!(u >= 0.0f && v >= 0.0f && u <= float(p_grid.width - 1) && v <= float(p_grid.depth - 1))) {
		return false;
	}
	r_point.ix = std::min(static_cast<int>(u), p_grid.width - 2);
	r_point.iz = std::min(static_cast<int>(v), p_grid.depth - 2);
	r_point.fx = u - float(r_point.ix);
	r_point.fz = v - float(r_point.iz);
	return true;
}

} // namespace

float HeightGrid::sample(const glm::vec2 &p) const {
	LatticePoint at;
	if (!is_valid() || !locate(*this, p, at)) {
		return NAN;
	}
	const float *row0 = heights.data() + size_t(at.iz) * size_t(width) + size_t(at.ix);
	const float *row1 = row0 + width;
	const float near_edge = row0[0] + (row0[1] - row0[0]) * at.fx;
	const float far_edge = row1[0] + (row1[1] - row1[0]) * at.fx;
	return near_edge + (far_edge - near_edge) * at.fz; // NaN when any sample is
}

glm::vec3 HeightGrid::normal(const glm::vec2 &p) const {
	LatticePoint at;
	if (!is_valid() || !locate(*this, p, at)) {
		return glm::vec3(0.0f, 1.0f, 0.0f);
	}
	const float *row0 = heights.data() + size_t(at.iz) * size_t(width) + size_t(at.ix);
	const float *row1 = row0 + width;
	const float step_x = size.x / float(width - 1);
	const float step_z = size.y / float(depth - 1);
	// The bilinear surface's slopes at p: ∂h/∂x varies along z and ∂h/∂z along x.
	const float dx = ((row0[1] - row0[0]) * (1.0f - at.fz) + (row1[1] - row1[0]) * at.fz) / step_x;
	const float dz = ((row1[0] - row0[0]) * (1.0f - at.fx) + (row1[1] - row0[1]) * at.fx) / step_z;
	const glm::vec3 n(-dx, 1.0f, -dz);
	return std::isfinite(dx) && std::isfinite(dz) ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
}

float Ground::height_at(uint32_t p_index, const glm::vec2 &p) const {
	switch (kind) {
		case GRID:
			return grid.sample(p);
		case HEIGHTS:
			return p_index < heights.size() ? heights[p_index] : NAN;
		case FLAT:
		default:
			return 0.0f;
	}
}

glm::vec2 Ground::lean_at(uint32_t p_index, const glm::vec2 &p) const {
	if (!(tilt > 0.0f)) {
		return glm::vec2(0.0f);
	}
	glm::vec3 normal(0.0f, 1.0f, 0.0f);
	if (kind == GRID) {
		normal = grid.normal(p);
	} else if (kind == HEIGHTS && size_t(p_index) * 3 + 2 < normals.size()) {
		const glm::vec3 given(normals[p_index * 3], normals[p_index * 3 + 1], normals[p_index * 3 + 2]);
		const float length = glm::length(given);
		if (std::isfinite(length) && length > 1e-6f && given.y > 0.0f) {
			normal = given / length; // an overhang's downward normal keeps the plant upright
		}
	}
	const glm::vec3 up = glm::normalize(glm::mix(glm::vec3(0.0f, 1.0f, 0.0f), normal, std::min(tilt, 1.0f)));
	return glm::vec2(up.x, up.z);
}

std::string height_grid_from_rgba(const float *p_rgba, size_t p_floats, int64_t p_width, int64_t p_depth, const glm::vec2 &p_origin,
		const glm::vec2 &p_size, double p_height_min, double p_height_max, HeightGrid &r_grid) {
	const int64_t most = HeightGrid::MAX_SIDE;
	if (p_width < 2 || p_depth < 2 || p_width > most || p_depth > most) {
		return "height map: " + std::to_string(p_width) + " × " + std::to_string(p_depth) + " pixels; it needs 2 to " +
				std::to_string(most) + " on each side";
	}
	if (p_floats != size_t(p_width * p_depth * 4) || (p_floats > 0 && p_rgba == nullptr)) {
		return "height map: " + std::to_string(p_floats) + " floats for " + std::to_string(p_width) + " × " +
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
	r_grid.origin = p_origin;
	r_grid.size = p_size;
	const float low = float(p_height_min);
	const float span = float(p_height_max - p_height_min);
	r_grid.heights.resize(size_t(p_width) * size_t(p_depth));
	const float *pixel = p_rgba;
	for (size_t i = 0; i < r_grid.heights.size(); ++i, pixel += 4) {
		r_grid.heights[i] = pixel[3] >= 0.5f ? low + pixel[0] * span : NAN;
	}
	return std::string();
}

} // namespace sunflower
