#pragma once
// MultiMesh instance data. The dynamic buckets: 16 floats per instance, the 3×4 matrix
// [basis | origin] row by row, then the instance colour (r, g, b, a): Godot's RenderingServer
// MULTIMESH_TRANSFORM_3D layout with colours. The static chunks' impostors: a compact 8-float
// record (FarInstance, below).
#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

// A near plant drawn whole: one instance whose mesh holds all three parts (a part's index in each
// vertex's UV2.x), placed by the shader (shaders/plant_bend.gdshaderinc: keep the two in step). The
// transform is the plant's own frame (standing on its ground, turned by its yaw, at its size) and
// the custom data what bends the parts in that frame:
//   16, 17: the bottom part's tilt, a vector (x, z) whose length is the angle in radians, about
//           the horizontal axis along it;
//   18: the upper parts' tilt angle about the same axis, radians;
//   19: the middle part's stretch along its length (the thesis' s' = s + α/10, as a factor).
constexpr uint32_t WHOLE_FLOATS_PER_INSTANCE = FLOATS_PER_INSTANCE + 4;

struct WholePlant {
	glm::mat3 basis{ 1.0f }; // lean · yaw · size
	glm::vec3 origin{ 0.0f }; // the root
	glm::vec2 tilt{ 0.0f }; // the bottom part's, in the plant's frame
	float upper = 0.0f;
	float middle = 1.0f;
};

inline void write_whole_instance(float *r_out, const WholePlant &p_plant, const glm::vec4 &p_color) {
	write_instance(r_out, p_plant.basis, p_plant.origin, p_color);
	r_out[16] = p_plant.tilt.x;
	r_out[17] = p_plant.tilt.y;
	r_out[18] = p_plant.upper;
	r_out[19] = p_plant.middle;
}

inline WholePlant read_whole_instance(const float *p_in) {
	WholePlant plant;
	for (int row = 0; row < 3; ++row) {
		for (int column = 0; column < 3; ++column) {
			plant.basis[column][row] = p_in[row * 4 + column];
		}
		plant.origin[row] = p_in[row * 4 + 3];
	}
	plant.tilt = glm::vec2(p_in[16], p_in[17]);
	plant.upper = p_in[18];
	plant.middle = p_in[19];
	return plant;
}

// A plant's impostor, compact: 8 floats (32 B on the GPU), uploaded as the rows of Godot's
// MULTIMESH_TRANSFORM_2D instances without colours. The engine hands the impostor shader the field
// node's transform times the matrix they make; the shader undoes the node's transform and reads
// the record back (shaders/impostor.gdshader: keep the two in step):
//   0: scale·cos(yaw)   1: scale·sin(yaw)   2: root z       3: root x
//   4: lean x, lean z   5: tone             6: cell / share 7: root y
// In a far tile's record float 6 is cell + 65 536 × levels above: the grid cell of the plant's
// chunk (FieldLayout: z·grid_x + x), which tells the shader whether the dynamic buckets draw the
// plant now, and how many tile levels above the tile's own keep the plant too
// (FarInstance::levels_above); in the near impostor bucket's it is the plant's share of the pixels
// (1, or less in its cross-fade with mesh 3: the material's `records_hold_shares`). Floats 4 and 5
// hold two 8-bit steps each, as low + 256·high: the lean in 1/127 steps of [−1, 1] (0 exact); the
// tone's brightness in 1/128 steps of [0, 2) (1 exact) and its warmth in 1/127 steps of [−1, 1]
// (0 exact). These whole numbers survive the node's transform and its inverse: float rounding there
// stays under 0.02 below 65 536, and grows with the value, to about 0.16 at float 6's largest
// (524 287), within the 0.5 the reader's rounding allows.
constexpr uint32_t FAR_FLOATS_PER_INSTANCE = 8;

struct FarInstance {
	glm::vec3 root{ 0.0f };
	float yaw = 0.0f;
	float scale = 1.0f;
	glm::vec2 lean{ 0.0f }; // the up axis' horizontal part (x, z), as Plant::lean
	glm::vec2 tone{ 1.0f, 0.0f }; // brightness, warmth, as Plant::tone
	uint32_t cell = 0; // < 65 536 (FieldLayout::MAX_CHUNK_CELLS)
	// In a far tile: how many tile levels above the tile's own keep the plant too (its
	// FieldSimulation::plant_tile_level less the tile's level, at most MAX_LEVELS_ABOVE). The tile
	// draws it where the observer's distance gives it to any of those levels, and fades it out
	// towards the level above the last (FieldSimulation::choose_tile_level).
	uint32_t levels_above = 0;
	static constexpr uint32_t MAX_LEVELS_ABOVE = 7;
};

// The record's encoding. The impostor shader reads it with the same numbers
// (shaders/records.gdshaderinc), which an engine test compares with these (bound as FAR_*).
namespace far_steps {
// Values in [−1, 1] travel in steps of 1/SIGNED_STEPS (a byte: 0 … 2·SIGNED_STEPS).
constexpr uint32_t SIGNED = 127;
constexpr float SIGNED_STEPS = float(SIGNED);
// Brightness in [0, 2) travels in steps of 1/BRIGHTNESS (1 exact).
constexpr uint32_t BRIGHTNESS = 128;
// Two steps share a float as low + 2^STEP_BITS · high.
constexpr uint32_t STEP_BITS = 8;
// Float FAR_CELL_OR_SHARE of a far tile's record: the cell in its low CELL_BITS bits, the levels
// above in the bits over them.
constexpr uint32_t CELL_BITS = 16;
inline float signed_unit(float p_value) {
	return std::round(std::clamp(p_value, -1.0f, 1.0f) * SIGNED_STEPS) + SIGNED_STEPS;
}
inline float brightness(float p_value) {
	return std::round(std::clamp(p_value, 0.0f, 255.0f / float(BRIGHTNESS)) * float(BRIGHTNESS));
}
} // namespace far_steps

// Which float of a compact record holds the chunk's cell (far tiles) or the share (near bucket).
constexpr uint32_t FAR_CELL_OR_SHARE = 6;

inline void write_far_instance(float *r_out, const FarInstance &p_instance) {
	r_out[0] = p_instance.scale * std::cos(p_instance.yaw);
	r_out[1] = p_instance.scale * std::sin(p_instance.yaw);
	r_out[2] = p_instance.root.z;
	r_out[3] = p_instance.root.x;
	constexpr float high = float(1u << far_steps::STEP_BITS);
	r_out[4] = far_steps::signed_unit(p_instance.lean.x) + high * far_steps::signed_unit(p_instance.lean.y);
	r_out[5] = far_steps::brightness(p_instance.tone.x) + high * far_steps::signed_unit(p_instance.tone.y);
	const uint32_t above = std::min(p_instance.levels_above, FarInstance::MAX_LEVELS_ABOVE);
	constexpr uint32_t cell_mask = (1u << far_steps::CELL_BITS) - 1u;
	r_out[FAR_CELL_OR_SHARE] = float(std::min(p_instance.cell, cell_mask) + (above << far_steps::CELL_BITS));
	r_out[7] = p_instance.root.y;
}

// What the shader reads back (the lean and tone in their steps).
inline FarInstance read_far_instance(const float *p_in) {
	constexpr uint32_t step_mask = (1u << far_steps::STEP_BITS) - 1u;
	const auto low = [](float p_value) { return float(uint32_t(std::lround(p_value)) & step_mask); };
	const auto high = [](float p_value) { return float(uint32_t(std::lround(p_value)) >> far_steps::STEP_BITS); };
	FarInstance instance;
	instance.root = glm::vec3(p_in[3], p_in[7], p_in[2]);
	instance.scale = std::sqrt(p_in[0] * p_in[0] + p_in[1] * p_in[1]);
	instance.yaw = std::atan2(p_in[1], p_in[0]);
	using far_steps::SIGNED_STEPS;
	instance.lean = (glm::vec2(low(p_in[4]), high(p_in[4])) - SIGNED_STEPS) / SIGNED_STEPS;
	instance.tone = glm::vec2(low(p_in[5]) / float(far_steps::BRIGHTNESS), (high(p_in[5]) - SIGNED_STEPS) / SIGNED_STEPS);
	const uint32_t stored = uint32_t(std::max(std::lround(p_in[FAR_CELL_OR_SHARE]), 0l));
	instance.cell = stored & ((1u << far_steps::CELL_BITS) - 1u);
	instance.levels_above = stored >> far_steps::CELL_BITS;
	return instance;
}

// A growable buffer of instances; grows geometrically and never shrinks, so steady state
// allocates nothing.
class InstanceBuffer {
public:
	// p_stride: floats per instance (FLOATS_PER_INSTANCE, or WHOLE_FLOATS_PER_INSTANCE for plants
	// drawn whole).
	explicit InstanceBuffer(uint32_t p_stride = FLOATS_PER_INSTANCE) :
			_stride(p_stride) {}
	uint32_t get_stride() const { return _stride; }
	void clear() {
		_count = 0;
		_low = glm::vec3(std::numeric_limits<float>::infinity());
		_high = -_low;
	}
	float *push() {
		if (_count >= get_capacity()) {
			_data.resize(std::max<size_t>(64, size_t(get_capacity()) * 2) * _stride);
		}
		return _data.data() + static_cast<size_t>(_count++) * _stride;
	}
	// Appends another buffer's instances, of the same stride (growing like push, so steady state
	// allocates nothing).
	void append(const InstanceBuffer &p_other) {
		const uint32_t count = _count + p_other._count;
		if (count > get_capacity()) {
			_data.resize(std::max<size_t>(count, size_t(get_capacity()) * 2) * _stride);
		}
		std::copy_n(p_other._data.data(), size_t(p_other._count) * _stride, _data.data() + size_t(_count) * _stride);
		_count = count;
		_low = glm::min(_low, p_other._low);
		_high = glm::max(_high, p_other._high);
	}
	// Widens the box that holds what the instances draw by a sphere (a plant's culling sphere, the
	// writer's to give for each plant it pushes): the renderer culls the whole bucket by this box in
	// every pass, the shadow cascades' included. Empty (low above high) after clear().
	void include(const glm::vec3 &p_centre, float p_radius) {
		_low = glm::min(_low, p_centre - p_radius);
		_high = glm::max(_high, p_centre + p_radius);
	}
	const glm::vec3 &get_bounds_low() const { return _low; }
	const glm::vec3 &get_bounds_high() const { return _high; }
	uint32_t get_count() const { return _count; }
	uint32_t get_capacity() const { return static_cast<uint32_t>(_data.size() / _stride); }
	const float *get_data() const { return _data.data(); }

private:
	std::vector<float> _data;
	uint32_t _stride = FLOATS_PER_INSTANCE;
	uint32_t _count = 0;
	glm::vec3 _low{ std::numeric_limits<float>::infinity() };
	glm::vec3 _high{ -std::numeric_limits<float>::infinity() };
};

} // namespace sunflower
