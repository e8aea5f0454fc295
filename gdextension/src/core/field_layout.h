#pragma once
// Plant layout (thesis 5.3): every '*' cell becomes one plant at
// x = (column + α)·cell, z = (row + α)·cell with α ∈ [0, 0.5) drawn once per plant from the seed,
// standing on the field's ground (ground.h): a cell with no ground under its plant gets none.
#include "field_map.h"
#include "ground.h"
#include "instance_buffer.h"
#include "parameters.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sunflower {

// A plant type's variety between its plants: yaw either side of facing +z (radians) and the range
// of the size factor (1, 1: all alike).
struct PlantVariety {
	float yaw_range = float(param::PLANT_YAW_RANGE.default_value);
	float scale_min = float(param::PLANT_SCALE_MIN.default_value);
	float scale_max = float(param::PLANT_SCALE_MAX.default_value);
	float brightness = float(param::PLANT_BRIGHTNESS_VARIATION.default_value);
	float tint = float(param::PLANT_TINT_VARIATION.default_value);

	// Sets the SunflowerPlant row p_spec of a type's variety (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, float p_value);

	bool operator==(const PlantVariety &p_other) const {
		return yaw_range == p_other.yaw_range && scale_min == p_other.scale_min && scale_max == p_other.scale_max &&
				brightness == p_other.brightness && tint == p_other.tint;
	}
};

struct LayoutParams {
	float cell_size = float(param::CELL_SIZE.default_value); // metres per map character (thesis: 0.5 m)
	uint64_t seed = 1;
	bool independent_jitter = false; // false: the same α on x and z, as in the thesis
	// α ∈ [0, jitter) in cells (thesis: 0.5), at most MAX_JITTER.
	float jitter = MAX_JITTER;
	// Every root lies in the first half of its cell: the impostor shader finds a plant's map cell from
	// its root (FieldSimulation::get_hidden_cells).
	static constexpr float MAX_JITTER = 0.5f;
	// Each species' variety (index: species).
	std::array<PlantVariety, FieldMap::MAX_SPECIES> varieties{};
	// Metres; the far representations are grouped in square chunks.
	float chunk_size = float(param::CHUNK_SIZE.default_value);
	// Where far tiles start to merge (param::TILE_MERGE_DISTANCE); 0: they never do. The layout
	// itself does not depend on it, the far tiles built from it do.
	float tile_merge_distance = float(param::TILE_MERGE_DISTANCE.default_value);

	// Sets the SunflowerField row p_spec of the layout, or the row of p_species' variety
	// (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, float p_value, uint32_t p_species);
	// These by the param:: rules, values they refuse kept from p_current (a size range never falls).
	LayoutParams sanitized(const LayoutParams &p_current) const;

	bool operator==(const LayoutParams &p_other) const {
		return cell_size == p_other.cell_size && seed == p_other.seed && independent_jitter == p_other.independent_jitter &&
				jitter == p_other.jitter && chunk_size == p_other.chunk_size &&
				tile_merge_distance == p_other.tile_merge_distance && varieties == p_other.varieties;
	}
};

// One per plant of the field, 28 bytes: what changes per frame is kept elsewhere, and only for the
// plants near the observer (FieldSimulation), so a million plants cost what this and the map cost.
struct Plant {
	glm::vec2 position{ 0.0f }; // x, z in the field's space, metres
	float ground = 0.0f; // y of the root: the ground's height there
	float yaw = 0.0f; // radians about +y
	float scale = 1.0f; // the plant's size factor (LayoutParams' scale range)
	uint32_t chunk = 0;

	glm::vec3 root() const { return glm::vec3(position.x, ground, position.y); }
	// The plant's up axis leaning towards the ground's normal: its horizontal part (x, z), zero for an
	// upright plant. Kept in the far records' steps (far_steps::SIGNED_STEPS): a plant leans alike as
	// a mesh and as an impostor.
	glm::vec2 lean() const { return glm::vec2(float(_lean[0]), float(_lean[1])) * (1.0f / far_steps::SIGNED_STEPS); }
	void set_lean(const glm::vec2 &p_lean) {
		_lean[0] = int8_t(far_steps::signed_unit(p_lean.x) - far_steps::SIGNED_STEPS);
		_lean[1] = int8_t(far_steps::signed_unit(p_lean.y) - far_steps::SIGNED_STEPS);
	}
	bool upright() const { return _lean[0] == 0 && _lean[1] == 0; }
	// The thesis' α ∈ [0, 1), also used for height variety (s' = s + α/10); kept in 1/65 536 steps.
	float alpha() const { return float(_alpha) * (1.0f / 65536.0f); }
	void set_alpha(float p_alpha) { _alpha = uint16_t(std::clamp(std::round(p_alpha * 65536.0f), 0.0f, 65535.0f)); }
	// Its tone under p_variety: brightness (1: as modelled) and warmth (−1 to 1; 0: as modelled),
	// seeded from its position, which its cell's seeded jitter makes its own.
	glm::vec2 tone(const PlantVariety &p_variety) const;
	// The instance colour it is drawn with under p_variety: tone_colour(tone(p_variety)).
	glm::vec4 color(const PlantVariety &p_variety) const;

private:
	int8_t _lean[2] = { 0, 0 };
	uint16_t _alpha = 0;
};
static_assert(sizeof(Plant) == 28, "a plant's layout stays 28 bytes (CPU memory per plant, README)");

// A tone's colour (brightness, warmth) → (b·(1 + w), b, b·(1 − w)). The impostor shader mirrors it
// for the static chunks' records (shaders/impostor.gdshader: keep them in step).
inline glm::vec4 tone_colour(const glm::vec2 &p_tone) {
	return glm::vec4(p_tone.x * (1.0f + p_tone.y), p_tone.x, p_tone.x * (1.0f - p_tone.y), 1.0f);
}

struct Chunk {
	glm::vec2 min{ 0.0f }; // x, z bounds of its plants' roots, metres
	glm::vec2 max{ 0.0f };
	float ground_min = 0.0f; // y bounds of its plants' roots
	float ground_max = 0.0f;
	float scale_max = 0.0f; // the largest size factor among its plants
	uint32_t species = 0; // every plant of a chunk is of one species
	uint32_t first = 0; // range in FieldLayout::chunk_plants
	uint32_t count = 0;

	// A chunk of p_species whose plants start at p_first in chunk_plants, holding none yet.
	static Chunk empty(uint32_t p_species, uint32_t p_first) {
		Chunk chunk;
		chunk.species = p_species;
		chunk.first = p_first;
		chunk.min = glm::vec2(INFINITY);
		chunk.max = glm::vec2(-INFINITY);
		chunk.ground_min = INFINITY;
		chunk.ground_max = -INFINITY;
		return chunk;
	}
	// Widens the bounds and the largest size to take p_plant in (its count is the caller's).
	void include(const Plant &p_plant) {
		min = glm::min(min, p_plant.position);
		max = glm::max(max, p_plant.position);
		ground_min = std::min(ground_min, p_plant.ground);
		ground_max = std::max(ground_max, p_plant.ground);
		scale_max = std::max(scale_max, p_plant.scale);
	}
};

struct FieldLayout {
	std::vector<Plant> plants; // in map order: row by row, column by column
	// Only chunks that hold plants: one per grid cell and species present there, cell by cell.
	std::vector<Chunk> chunks;
	std::vector<uint32_t> chunk_plants; // plant indices grouped by chunk
	glm::vec2 size{ 0.0f }; // columns·cell, rows·cell
	// The square grid the chunks come from: cell g = z·grid_x + x holds chunks [grid_chunks[g],
	// grid_chunks[g + 1]) (none where no plant stands). Lets per-frame work visit only the chunks near
	// a point.
	// At most MAX_CHUNK_CELLS cells: a larger field's chunks are made larger (by doubling) to fit.
	static constexpr int MAX_CHUNK_CELLS = 65536;
	int grid_x = 0;
	int grid_z = 0;
	float chunk_size = 16.0f;
	std::vector<uint32_t> grid_chunks;
	// The grid cell (z·grid_x + x) a root (x, z) lies in; the last row or column for one on the far edge.
	uint32_t grid_cell(const glm::vec2 &p_root) const {
		const int x = std::clamp(static_cast<int>(p_root.x / chunk_size), 0, std::max(grid_x - 1, 0));
		const int z = std::clamp(static_cast<int>(p_root.y / chunk_size), 0, std::max(grid_z - 1, 0));
		return static_cast<uint32_t>(z * std::max(grid_x, 1) + x);
	}
	// Plant cells of the map with no ground under their plant (so no plant).
	uint32_t cells_without_ground = 0;
	// The ground's height under each of the map's objects (its cell's centre), in map order; NaN where
	// there is none.
	std::vector<float> object_ground;
};

// Where the ground is asked for: every plant cell's plant root (x, z) in map order, then every object's
// cell centre. The HEIGHTS ground lists one height per point, in this order.
void ground_points(const FieldMap &p_map, const LayoutParams &p_params, std::vector<glm::vec2> &r_points);

// The root (x, z) of the plant of map cell (p_column, p_row), where build_layout places it.
glm::vec2 plant_root_at(const FieldMap &p_map, const LayoutParams &p_params, int p_column, int p_row);

// The plant of species p_species in map cell (p_column, p_row) as build_layout lays it out, but for
// its ground (0, upright) and its chunk (0): its randomness follows the cell, whatever its species.
Plant lay_plant(const FieldMap &p_map, const LayoutParams &p_params, uint32_t p_species, int p_column, int p_row);

// Fills r_layout from p_map on p_ground. Deterministic: the same map, params, seed and ground give the
// same layout; a plant's randomness follows its cell's place in the map, so a hole or a painted cell
// elsewhere changes no other plant.
void build_layout(const FieldMap &p_map, const LayoutParams &p_params, const Ground &p_ground, FieldLayout &r_layout);

} // namespace sunflower
