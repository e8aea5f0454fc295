#pragma once
// The field's plants: the map they come from, the layout that stands them on the ground, each
// species' form, and what is derived from those alone (chunk bounds, grid cells, the far records
// and their signatures). The other units of the simulation (near_field.h, far_tiles.h) read the
// plants from here; only FieldSimulation changes them, and rebuilds the others when a call here says
// the layout was rebuilt (every plant index and chunk may then have changed).
#include "field_changes.h"
#include "field_layout.h"
#include "field_map.h"
#include "ground.h"
#include "instance_buffer.h"
#include "plant_shape.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace sunflower {

struct ChunkBounds {
	glm::vec3 min{ 0.0f };
	glm::vec3 max{ 0.0f };
	glm::vec3 center() const { return (min + max) * 0.5f; }
};

// The grid cells (chunk_size squares) within a reach of a point (x, z), clamped to the grid; empty
// (x1 < x0) for a field without plants.
struct GridRange {
	int x0 = 0, x1 = -1, z0 = 0, z1 = -1;
};

class FieldPlants {
public:
	// Reads a map with the legend's plant symbols (species 1, 2, …; '*' is species 0). On success
	// replaces the field and rebuilds the layout; on failure keeps the current field and fills r_error.
	bool load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
			const std::string &p_source, const MapLimits &p_limits, MapError &r_error);
	// Replaces the map (one already read, e.g. edited) and rebuilds the layout.
	void replace_map(FieldMap p_map);
	// A brush stroke on the map (see paint_cells; p_center and p_radius in cells): the changed cells are
	// appended to r_changed. Rebuilds the layout when p_relayout and anything changed; returns whether
	// it did.
	bool paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density, uint64_t p_seed,
			bool p_relayout, std::vector<int> &r_changed, const CellWeights *p_weights = nullptr);
	// Sanitises the parameters (an invalid value keeps the current one); rebuilds the layout and
	// returns true when they differ from the current ones.
	bool set_layout_params(const LayoutParams &p_params);
	// Stands the plants on p_ground (rebuilding the layout). Plants whose cells have no ground go.
	void set_ground(Ground p_ground);
	// A species' form (species 0: '*'); a value the parameter table refuses keeps the current one.
	// Returns whether the species is now drawn otherwise (whole or
	// part by part), which changes its buckets' records.
	bool set_shape(const PlantShape &p_shape, uint32_t p_species);
	// The form with the part scale for a plant p_metres tall from its root to the top of its parts
	// (param::PLANT_HEIGHT rules).
	PlantShape shape_of_height(float p_metres, uint32_t p_species) const;

	const FieldMap &get_map() const { return _map; }
	// The legend's plant symbols the map was read with (species 1, 2, …).
	const std::u32string &get_plant_symbols() const { return _plant_symbols; }
	const LayoutParams &get_layout_params() const { return _layout_params; }
	const Ground &get_ground() const { return _ground; }
	const FieldLayout &get_layout() const { return _layout; }
	const PlantShape &get_shape(uint32_t p_species = 0) const { return _shapes[p_species % _shapes.size()]; }
	uint32_t get_species_count() const { return uint32_t(_map.species_count); }
	// Plants and chunks: the map's, then those play added (add_plant).
	uint32_t get_plant_count() const { return static_cast<uint32_t>(_layout.plants.size()); }
	uint32_t get_chunk_count() const { return static_cast<uint32_t>(_layout.chunks.size()); }
	// The map's plants and chunks: indices [0, count). The far tiles draw these chunks only.
	uint32_t get_map_plant_count() const { return _map_plant_count; }
	uint32_t get_map_chunk_count() const { return _map_chunk_count; }
	// The species of a plant: its chunk's (a chunk holds one species); 0 for an added plant taken since.
	uint32_t species_of(const Plant &p_plant) const {
		return p_plant.chunk < _layout.chunks.size() ? _layout.chunks[p_plant.chunk].species : 0;
	}
	static constexpr uint32_t NO_CHUNK = UINT32_MAX;

	// The box that holds a chunk's plants at any bend (their culling spheres, up to their heads).
	ChunkBounds get_chunk_bounds(uint32_t p_chunk) const;
	// The grid cell a chunk lies in (FieldLayout: z·grid_x + x).
	uint32_t get_chunk_cell(uint32_t p_chunk) const { return _chunk_cells[p_chunk]; }
	GridRange grid_range(const glm::vec2 &p_center, float p_reach) const;
	// The plants whose roots lie within p_radius of p_center (x, z), appended to r_plants.
	void find_plants_near(const glm::vec2 &p_center, float p_radius, std::vector<uint32_t> &r_plants) const;
	// The farthest a plant of any species reaches from its root (culling radius × the largest size).
	float get_plant_reach() const;
	// The square distance from p_eye to a plant's middle: on the ground this is the thesis' distance.
	float plant_distance_sq(const Plant &p_plant, const glm::vec3 &p_eye) const;

	// A plant's stalk, upright, in metres: x its radius (PlantShape::STALK_RADIUS_SHARE of its parts'
	// height), y the height from its root to its head (the bottom part and the stretched middle one).
	glm::vec2 get_stalk(uint32_t p_plant) const;

	// A plant's compact impostor record (its cell left 0).
	FarInstance far_instance(const Plant &p_plant, uint32_t p_species) const;
	// The static records of p_count plants of chunk p_chunk (p_plants: their indices), each with the
	// chunk's cell and p_levels_above (FarInstance::levels_above: the plants are all of one level).
	void write_records(uint32_t p_chunk, const uint32_t *p_plants, uint32_t p_count, float *r_out, uint32_t p_levels_above = 0) const;
	// All of a chunk's records, compact: count × FAR_FLOATS_PER_INSTANCE floats into r_out.
	void write_chunk_instances(uint32_t p_chunk, float *r_out) const;
	// Where a chunk lies: grid cell × MAX_SPECIES + species (the same in any layout of the map's size).
	uint64_t get_chunk_key(uint32_t p_chunk) const;
	// A hash of a chunk's records: two chunks with equal keys and signatures draw the same, so a
	// rebuilt field can keep the old one's GPU buffers. Computed for every chunk by
	// compute_chunk_signatures() (a worker may call it), else on demand.
	uint64_t get_chunk_signature(uint32_t p_chunk) const;
	void compute_chunk_signatures();

	// What play did to a plant (field_changes.h): STANDING for every plant until one is set; a
	// rebuilt layout forgets them (FieldSimulation sets them again). The far records do not depend on
	// it (FieldSimulation::get_hidden_cells hides a plant's impostors).
	void set_plant_state(uint32_t p_plant, PlantState p_state);
	PlantState get_plant_state(uint32_t p_plant) const {
		return p_plant < _plant_states.size() ? static_cast<PlantState>(_plant_states[p_plant]) : PlantState::STANDING;
	}
	// The map's plant of map cell p_cell (row × columns + column), or NO_PLANT: none there, or no
	// ground under it. The cell of each plant is found once, at the first call after a rebuild.
	static constexpr uint32_t NO_PLANT = UINT32_MAX;
	uint32_t plant_at_cell(uint32_t p_cell) const;
	// The map cell of plant p_plant (row × columns + column), or NO_CELL for an index past the plants
	// or an added plant taken since.
	static constexpr uint32_t NO_CELL = UINT32_MAX;
	uint32_t cell_of_plant(uint32_t p_plant) const;

	// Plants play puts where the map has none of their species (FieldSimulation). Each is laid out
	// as the map's would be (lay_plant: its randomness follows the cell) and appended after the
	// plants there are, so no other plant's index changes; group_added() gives them chunks of their
	// own after the map's, which the near field keeps active at every distance (the far tiles, built
	// from the map, never draw them). A rebuilt layout forgets them (FieldSimulation adds them again).
	// Adds a standing plant of p_species to cell p_cell standing at the height p_height (NaN: the
	// ground of p_map_plant, the map's plant there (plant_at_cell), else the ground's), taking the one
	// added there before; returns its index,
	// or NO_PLANT (and nothing added) for a cell or species not the map's or a cell with no ground
	// known (a ground of measured points knows only the map's plants' cells). Ungrouped until
	// group_added().
	uint32_t add_plant(uint32_t p_cell, uint32_t p_species, float p_height, uint32_t p_map_plant);
	// The added plant of a cell, or NO_PLANT.
	uint32_t added_plant_at_cell(uint32_t p_cell) const;
	// An added plant gone (drawn nowhere, found by no query; its index is given to the next plant
	// added, so a game that sows and harvests does not grow the field). Ungrouped until group_added().
	void take_plant(uint32_t p_plant);
	// The added plants' chunks anew if plants were added or taken since; returns whether they were
	// (the near field must then take the new chunks: NearField::regroup).
	bool group_added();
	bool added_grouped() const { return _added_grouped; }

	// CPU memory held for the map, layout and ground, in bytes.
	size_t get_memory_bytes() const;

private:
	void _rebuild();
	// Makes _plant_cells for the layout if it is not (false: the layout is not this map's, never).
	bool _index_cells() const;

	FieldMap _map;
	std::u32string _plant_symbols;
	LayoutParams _layout_params;
	Ground _ground;
	FieldLayout _layout;
	std::array<PlantShape, FieldMap::MAX_SPECIES> _shapes{};
	std::vector<uint32_t> _chunk_cells;
	std::vector<uint64_t> _chunk_signatures; // 0: not computed
	std::vector<uint8_t> _plant_states; // PlantState a plant; empty until one is set
	mutable std::vector<uint32_t> _plant_cells; // each map plant's map cell, in plant order; made on first use
	uint32_t _map_plant_count = 0;
	uint32_t _map_chunk_count = 0;
	std::vector<uint32_t> _added_cells; // per added plant (index − map plants): its cell, NO_CELL once taken
	std::vector<uint32_t> _added_species; // per added plant: its species
	std::vector<uint32_t> _free_added; // the indices of added plants taken: used again first
	std::unordered_map<uint32_t, uint32_t> _added_at_cell; // cell → its added plant
	bool _added_grouped = true;
};

} // namespace sunflower
