#pragma once
// Where plants stand. A field lies on one of three grounds:
// - FLAT: the plane y = 0 of the field's space (the thesis' field);
// - GRID: a height map, sampled bilinearly where each plant's root falls;
// - HEIGHTS: one height per ground point (see ground_points()), measured elsewhere — the addon casts
//   rays at physics colliders and hands the hits in.
// A point with no ground under it (outside the grid, next to a hole, a ray that hit nothing) is NaN:
// no plant grows there.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sunflower {

// A height map over a rectangle of the field's space (x, z). Samples lie on a regular lattice whose
// first and last rows and columns are the rectangle's edges, as the vertices of a HeightMapShape3D.
struct HeightGrid {
	// The most samples along either side.
	static constexpr int MAX_SIDE = 16384;
	int width = 0; // samples along x (≥ 2 to span anything)
	int depth = 0; // samples along z
	std::vector<float> heights; // width × depth, row by row (z major), metres; NaN marks a hole
	glm::vec2 origin{ 0.0f }; // x, z of sample (0, 0)
	glm::vec2 size{ 0.0f }; // x, z extent from the first sample to the last

	bool is_valid() const;
	// The height at p (x, z), bilinear between the four samples around it; NaN outside the rectangle
	// or when any of the four is a hole.
	float sample(const glm::vec2 &p) const;
	// The ground's upward unit normal at p, from the bilinear surface's slope ((0, 1, 0) where sample()
	// is NaN).
	glm::vec3 normal(const glm::vec2 &p) const;
};

// A height grid from an image's pixels as RGBA floats (p_floats of them, row by row): red 0–1 spans
// p_height_min to p_height_max (as the engine's HeightMapShape3D reads an image), alpha below one half
// is a hole. Returns what is wrong with the arguments (r_grid untouched), or an empty string.
std::string height_grid_from_rgba(const float *p_rgba, size_t p_floats, int64_t p_width, int64_t p_depth, const glm::vec2 &p_origin,
		const glm::vec2 &p_size, double p_height_min, double p_height_max, HeightGrid &r_grid);

struct Ground {
	enum Kind : uint8_t {
		FLAT,
		GRID,
		HEIGHTS,
	};
	Kind kind = FLAT;
	HeightGrid grid; // GRID
	// HEIGHTS: one height per ground point, in ground_points() order; a list of another length gives
	// no ground anywhere.
	std::vector<float> heights;
	// HEIGHTS: the ground's normals at those points (x, y, z each), or empty (upright plants).
	std::vector<float> normals;
	// How far plants lean from upright towards the ground's normal: 0 upright (sunflowers), 1 along
	// the normal.
	float tilt = 0.0f;

	// The height under ground point p_index at p (x, z); NaN when there is no ground there.
	float height_at(uint32_t p_index, const glm::vec2 &p) const;
	// The lean a plant takes there: the horizontal part (x, z) of its up axis, length sin(tilt angle).
	glm::vec2 lean_at(uint32_t p_index, const glm::vec2 &p) const;
};

} // namespace sunflower
