#pragma once
// What play changes in a field, kept apart from its map (the map file never changes by play): cells
// whose plant was cut, flattened or removed, and cells given a plant the map does not have, each with
// the time on the field's clock it happened at, for regrowth. Only what differs from the map is held,
// so the cost follows the changes, not the field; a save (save_field_changes) holds the same, checked
// against the map it was made on when it is loaded.
#include "field_map.h"
#include "parameters.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <queue>
#include <string>
#include <vector>

namespace sunflower {

enum class PlantState : uint8_t {
	STANDING = 0,
	FLATTENED = 1, // lies bent: pushed over (trampled), until it recovers
	CUT = 2, // cut down (a stump or nothing, as its plant type says), until it regrows
	// Drawn nowhere, found by nothing, no stump: a plant removed, the map's plant of a cell given
	// another type, a plant put and taken again. How FieldPlants shows such a plant; never a cell's.
	GONE = 3,
};

// What a cell holds after play.
struct CellState {
	uint8_t plant = 0; // as FieldMap::plants: 0 no plant, 1 + the species of the one there
	PlantState state = PlantState::STANDING; // STANDING for a cell with no plant
	double since = 0.0; // the field's clock (seconds) when its plant took that state

	bool operator==(const CellState &p_other) const {
		return plant == p_other.plant && state == p_other.state && since == p_other.since;
	}
};

// How a plant type recovers: seconds on the field's clock until a flattened plant stands again and a
// cut one has grown again; 0: never.
struct Regrowth {
	double flattened_seconds = 0.0;
	double cut_seconds = 0.0;

	// Sets the SunflowerPlant row p_spec of a type's recovery (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, double p_value);
};

class FieldChanges {
public:
	// Forgets every change; from now on they are made to p_map (its size and plants are kept as its
	// fingerprint: see map_fingerprint).
	void reset(const FieldMap &p_map);
	// The regrowth of each species; cells already flattened or cut recover on the new timing.
	void set_regrowth(const std::array<Regrowth, FieldMap::MAX_SPECIES> &p_regrowth);

	// The fingerprint of the map the changes are made to (map_fingerprint).
	uint64_t fingerprint() const { return _fingerprint; }
	int columns() const { return _columns; }
	int rows() const { return _rows; }
	// What cell p_cell (row × columns + column) holds now: its change, or the map's plant standing.
	CellState get(uint32_t p_cell) const;
	// Whether the cell differs from the map.
	bool is_changed(uint32_t p_cell) const { return _changes.count(p_cell) != 0; }
	// The changed cells, in cell order.
	const std::map<uint32_t, CellState> &changes() const { return _changes; }

	// Gives cell p_cell the state p_state (its plant as it is), since p_now. Returns whether anything
	// changed: a cell with no plant, or already in that state, is left (a second cut is not a cut).
	bool set_state(uint32_t p_cell, PlantState p_state, double p_now);
	// Takes the cell's plant away (nothing grows back); returns whether there was one.
	bool remove(uint32_t p_cell);
	// Puts a standing plant of p_species in the cell, over what is there; returns whether anything
	// changed. False (and nothing done) for a species the map was not read with.
	bool put(uint32_t p_cell, int p_species);
	// The cell back to what the map says; returns whether it was changed.
	bool restore(uint32_t p_cell);

	// Moves the field's clock to p_now: every flattened or cut plant whose recovery is due stands
	// again, its cell appended to r_recovered. Costs nothing but a comparison while none is due.
	void advance(double p_now, std::vector<uint32_t> &r_recovered);

	// The save of the changes at the clock p_now (see save_field_changes).
	std::vector<uint8_t> save(double p_now) const;
	// Replaces the changes by those of p_bytes, a save of this same map; returns "" and the save's
	// clock in r_clock, or what is wrong (a corrupt save, another map's, a newer version's), changing
	// nothing.
	std::string load(const std::vector<uint8_t> &p_bytes, double &r_clock);

private:
	struct Due {
		double at = 0.0;
		uint32_t cell = 0;
		bool operator>(const Due &p_other) const { return at > p_other.at || (at == p_other.at && cell > p_other.cell); }
	};
	void _set(uint32_t p_cell, const CellState &p_state);
	void _schedule(uint32_t p_cell, const CellState &p_state);

	int _columns = 0;
	int _rows = 0;
	int _species_count = 1;
	uint64_t _fingerprint = 0;
	std::vector<uint8_t> _map_plants; // the map's plant byte a cell
	std::map<uint32_t, CellState> _changes;
	std::array<Regrowth, FieldMap::MAX_SPECIES> _regrowth{};
	std::priority_queue<Due, std::vector<Due>, std::greater<Due>> _due;
};

// The cells of a map of p_columns × p_rows cells of p_cell_size metres whose centre lies within
// p_radius metres of p_center (the field's x, z), in cell order, appended to r_cells.
void cells_in_circle(int p_columns, int p_rows, float p_cell_size, const glm::vec2 &p_center, float p_radius,
		std::vector<uint32_t> &r_cells);
// The same for the cells whose centre lies in the rectangle from p_min to p_max (x, z metres).
void cells_in_rect(int p_columns, int p_rows, float p_cell_size, const glm::vec2 &p_min, const glm::vec2 &p_max,
		std::vector<uint32_t> &r_cells);

// A map's fingerprint: its size and every cell's plant byte, hashed (FNV-1a, 64 bits). Two maps with
// one fingerprint have the same plants in the same cells (but for a one-in-2^64 accident).
uint64_t map_fingerprint(const FieldMap &p_map);

// The save format (little-endian, versioned; about 3–7 bytes a changed cell):
//   "SFCH", u16 version (1), u16 flags (0), u32 columns, u32 rows, u64 map fingerprint, f64 clock,
//   u32 count, then per changed cell in cell order: varint (cell − previous cell − 1; the first: the
//   cell), u8 (plant | state << 4), and for a flattened or cut plant varint (clock − since, ms);
//   last a u32 CRC-32 of every byte before it.
constexpr uint16_t FIELD_CHANGES_VERSION = 1;

} // namespace sunflower
