#pragma once
// SunflowerPlacement: the engine-facing face of the core's placement by rules (core/placement.h).
// The addon's SunflowerPlacementRules resource fills it layer by layer and asks it for cells; it
// holds no engine object and may run on a worker thread while another cancels it.
#include "binding/godot_api.h"
#include "core/placement.h"

#include <atomic>

class SunflowerPlacement {
public:
	static constexpr const char *CLASS = "SunflowerPlacement";
	static void bind_methods();

	// The names of a layer row's numbers, in order, separated by commas.
	static gdx::String get_layer_fields();
	void set_field(int64_t p_columns, int64_t p_rows, double p_cell_size, int64_t p_seed);
	void set_heights(const gdx::PackedFloat32Array &p_heights);
	void clear_layers();
	// Adds a layer; returns what is wrong with the row's shape, or "".
	gdx::String add_layer(const gdx::PackedFloat32Array &p_row, const gdx::PackedFloat32Array &p_lines,
			const gdx::PackedFloat32Array &p_footprints, const gdx::PackedByteArray &p_mask);
	// What keeps the rules from running ("layer 2: slope: …"), or "".
	gdx::String check() const;
	// The cells of a rectangle (0 empty, 1 + the plant type), on p_threads threads (0: the machine's
	// cores, at most 8); empty when the rules do not check or cancel() was called meanwhile.
	gdx::PackedByteArray generate(int64_t p_column, int64_t p_row, int64_t p_columns, int64_t p_rows, int64_t p_threads);
	// The filters' weight (0–1) of layer p_layer (0-based) at every cell of a rectangle, row by row
	// (core placement_layer_weights; p_map: the whole map's cells as read_map_cells gives them, for
	// the layer's spacing, or empty). Empty when the layer or rectangle is not there or the rules do
	// not check.
	gdx::PackedFloat32Array layer_weights(int64_t p_layer, int64_t p_column, int64_t p_row, int64_t p_columns, int64_t p_rows,
			const gdx::PackedByteArray &p_map) const;
	// Stops a generate() running now, from any thread.
	void cancel();
	// Cells (columns × rows) as a map's text in canonical form: '*' for plant type 0 and
	// p_plant_symbols' characters for 1, 2, …; '.' for an empty cell. The comment lines and objects
	// of the map p_previous (its text; empty: none) are kept, an object's cell holding no plant; its
	// comments, or else p_header's lines, come first. Empty when p_cells is not columns × rows or
	// p_previous does not parse.
	static gdx::PackedByteArray write_map(const gdx::PackedByteArray &p_cells, int64_t p_columns, int64_t p_rows,
			const gdx::String &p_plant_symbols, const gdx::String &p_header, const gdx::PackedByteArray &p_previous);
	// A map's cells (0 empty or an object, 1 + the plant type), row by row, its plant types '*' and
	// p_plant_symbols (its columns and rows: SunflowerFieldMap.check). Empty when it does not parse.
	static gdx::PackedByteArray read_map_cells(const gdx::PackedByteArray &p_text, const gdx::String &p_plant_symbols);
	// core keep_hand_edits: the edited cells of p_edited (where it differs from p_generated_before)
	// over p_generated_now; empty when the three differ in size.
	static gdx::PackedByteArray keep_hand_edits(const gdx::PackedByteArray &p_generated_before,
			const gdx::PackedByteArray &p_edited, const gdx::PackedByteArray &p_generated_now);

private:
	sunflower::PlacementRules _rules;
	std::atomic<bool> _cancel{ false };
};
