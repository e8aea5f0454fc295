#pragma once
// Everything that happens to a field after its map is read, composed of units with one job each:
// - FieldPlants (field_plants.h): the map, the layout that stands its plants on the ground, each
//   species' form, and the far records and chunk signatures derived from them;
// - NearField (near_field.h): the active chunks near the observer, each plant's LOD and wind, the
//   pushers, and the dynamic buckets written every frame;
// - FarTiles (far_tiles.h): the static impostor tiles that draw every other plant, merged with
//   distance.
// This class changes the plants and keeps the other two in step with them; read each unit through its
// accessor. Plain C++17 + GLM: no engine types.
#include "far_tiles.h"
#include "field_plants.h"
#include "near_field.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace sunflower {

class FieldSimulation {
public:
	FieldSimulation();
	// The units hold references to each other: a simulation stays where it was made.
	FieldSimulation(const FieldSimulation &) = delete;
	FieldSimulation &operator=(const FieldSimulation &) = delete;

	// Reads a map. On success replaces the field and rebuilds; on failure keeps the current field and
	// fills r_error. p_plant_symbols: the legend's plant types, species 1, 2, … ('*' is species 0).
	bool load_map(const std::string &p_text, const std::u32string &p_legend, const std::string &p_source,
			const MapLimits &p_limits, MapError &r_error);
	bool load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
			const std::string &p_source, const MapLimits &p_limits, MapError &r_error);
	void clear();
	// Replaces the map (one already read, e.g. edited) and rebuilds.
	void replace_map(FieldMap p_map);
	// A brush stroke on the map (FieldPlants::paint_map), then, when p_relayout, the field rebuilt if
	// anything changed. (A simulation that only edits a map, for a painter, skips the layout.)
	void paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density, uint64_t p_seed,
			bool p_relayout, std::vector<int> &r_changed, const CellWeights *p_weights = nullptr);
	// Sets the setting of table row p_spec (parameters.h) from its p_spec.components values (a plant
	// type's row: of p_species), by the row's rules, in the unit that owns it: the wind, the levels
	// of detail, the pushes, the worker threads, a type's recovery and stump, the layout and a
	// type's variety and form. Returns what the change costs: FREE (taken at the next update, or a
	// value the row's rules make the one held) or REBUILD: a row the layout depends on, set while a
	// map is read, is not applied, and the caller builds the field anew with it (a simulation never
	// rebuilds itself for a setting). A row no unit owns (the engine side applies it) costs its
	// ParameterSpec::cost once a map is read: the core cannot tell whether it changed.
	ParameterSpec::Cost set_setting(const ParameterSpec &p_spec, const float *p_values, uint32_t p_species = 0);
	// Rebuilds when the (sanitised) parameters differ from the current ones; returns whether it did.
	bool set_layout_params(const LayoutParams &p_params);
	// Stands the plants on p_ground (rebuilding). Plants whose cells have no ground go.
	void set_ground(Ground p_ground);
	// A species' form (species 0: '*').
	void set_shape(const PlantShape &p_shape, uint32_t p_species = 0);
	// Sets the part scale for a plant p_metres tall from its root to the top of its parts
	// (param::PLANT_HEIGHT rules).
	void set_plant_height(float p_metres, uint32_t p_species = 0);

	// What play changes (field_changes.h), shown at the next update without a rebuild: a cut or
	// removed plant is drawn nowhere, a flattened one lies bent near and is not drawn far. The near
	// field reads each plant's state every frame; the far tiles' records never change by play (no
	// tile is written again): their impostors are hidden by the hidden-cells mask (get_hidden_cells),
	// which the impostor shader reads. A new map forgets the changes; a layout rebuilt for the same
	// map keeps them.
	enum class CellAction : uint8_t {
		STAND, // a flattened or cut plant stands again
		FLATTEN,
		CUT,
		REMOVE, // no plant there any more, and none grows back
		RESTORE, // as the map has it
	};
	// Applies p_action at the field's clock p_now to each of p_cells (row × columns + column); appends
	// the cells it changed to r_changed.
	void change_cells(const std::vector<uint32_t> &p_cells, CellAction p_action, double p_now, std::vector<uint32_t> &r_changed);
	// Puts a standing plant of species p_species in each of p_cells (the map's own type gives the map's
	// plant back, standing), over what is there, and appends the cells it changed to r_changed. A plant
	// of a type the map does not have there is added (FieldPlants::add_plant): it stands on the map's
	// plant's ground, else on the ground's height there, else on a height set_cell_heights gave; a
	// cell with none of those (a ground of measured points, a cell the map left empty) waits for one:
	// get_unplaced_cells.
	// (A plant put stands: it needs no time on the field's clock.)
	void put_cells(const std::vector<uint32_t> &p_cells, uint32_t p_species, std::vector<uint32_t> &r_changed);
	// The ground's height (the field's space) under cells the ground does not know (NaN: forget it),
	// kept for the next layout of the map too; their plants are added now.
	void set_cell_heights(const std::vector<uint32_t> &p_cells, const std::vector<float> &p_heights);
	// Cells given a plant that stands nowhere yet for want of a ground height, in cell order.
	std::vector<uint32_t> get_unplaced_cells() const;
	// A standing plant pushed over by a pusher (trample) and the pusher's index (in set_pushers' order).
	struct Trampled {
		uint32_t cell = 0;
		uint32_t pusher = 0;
	};
	// The pushers (the near field's, as set last) flatten, at the clock p_now, every standing plant
	// whose root lies within p_share × their radius (param::TRAMPLE_SHARE) while they are within
	// their radius of its stalk's height span (from its root to its head), each plant once, by the
	// first pusher in order that reaches it; appends them to r_trampled. p_share 0: none.
	void trample(float p_share, double p_now, std::vector<Trampled> &r_trampled);
	// Each plant type's recovery; kept for the next map too.
	void set_regrowth(const std::array<Regrowth, FieldMap::MAX_SPECIES> &p_regrowth);
	const std::array<Regrowth, FieldMap::MAX_SPECIES> &get_regrowth() const { return _regrowth; }
	// Moves the changes' clock to p_now: plants whose recovery is due stand again (appended to r_recovered).
	void advance_changes(double p_now, std::vector<uint32_t> &r_recovered);
	// The changes, read; what a cell holds after play (its map's plant where play changed nothing).
	const FieldChanges &changes();
	CellState get_cell_state(uint32_t p_cell) const;
	size_t get_change_count() const { return _changes_ready ? _changes.changes().size() : 0; }
	// The save of the changes (FieldChanges::save) and its load, shown at once; see FieldChanges::load.
	std::vector<uint8_t> save_changes(double p_now);
	std::string load_changes(const std::vector<uint8_t> &p_bytes, double &r_clock);
	// The map's cells whose plant is not standing (cut, flattened or removed by play): a bit a cell,
	// row after row of hidden_row_bytes() bytes, bit (column % 8) of byte column / 8; empty until the
	// first change. The impostor shader finds a plant's cell from its root (x, z) / cell size: the
	// layout keeps each root in the first half of its cell (α < 0.5), so the cell is exact.
	const std::vector<uint8_t> &get_hidden_cells() const { return _hidden; }
	uint32_t hidden_row_bytes() const { return (uint32_t(_plants.get_map().columns) + 7u) / 8u; }
	// Changes whenever a bit of get_hidden_cells does.
	uint32_t get_hidden_version() const { return _hidden_version; }

	// One frame: the far tiles' counts follow the observer, then the near field moves (NearField::update).
	void update(float p_delta);
	// Whether a tile has a plant to draw now: false when all its chunks are active (its node is then
	// hidden, so that it costs no draw call).
	bool is_tile_drawn(uint32_t p_tile) const;
	// Changes whenever a chunk turns active or static, or the field is rebuilt.
	uint32_t get_mask_version() const { return _mask_version; }
	// Changes whenever the far records change: the field rebuilt or a plant type's shape set.
	uint32_t get_records_version() const { return _records_version; }
	// Every chunk's signature now (FieldPlants::get_chunk_signature), e.g. on a worker during a build.
	void compute_chunk_signatures() { _plants.compute_chunk_signatures(); }
	// CPU memory held for the field, in bytes (map cells, layout, per-plant state, tiles, buffers).
	size_t get_memory_bytes() const;

	const FieldPlants &plants() const { return _plants; }
	const FarTiles &tiles() const { return _tiles; }
	NearField &near() { return _near; }
	const NearField &near() const { return _near; }

private:
	// The near field and the tiles anew for the plants' new layout.
	void _rebuilt();
	// The changes made ready for the map (on first use: they cost nothing until then).
	void _ready_changes();
	// A changed cell's plant drawn as its change says: the map's plant's state and hidden-cells bit,
	// or an added plant (its chunks made by _group_added once a batch of changes is done).
	void _show_cell(uint32_t p_cell);
	void _group_added();

	FieldPlants _plants;
	NearField _near{ _plants };
	FarTiles _tiles{ _plants };
	uint32_t _mask_version = 0;
	uint32_t _records_version = 0;
	FieldChanges _changes;
	bool _changes_ready = false;
	std::array<Regrowth, FieldMap::MAX_SPECIES> _regrowth{};
	std::unordered_map<uint32_t, float> _cell_heights; // set_cell_heights
	std::unordered_set<uint32_t> _unplaced; // get_unplaced_cells
	std::vector<uint8_t> _hidden; // get_hidden_cells
	uint32_t _hidden_version = 0;
};

} // namespace sunflower
