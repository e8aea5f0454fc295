#pragma once
// SunflowerChanges: play's changes to the plants of a SunflowerSimulation (attach): cells stood,
// flattened, cut, removed or planted at run time on the field's clock, the pushers' trampling,
// regrowth, and the save of what play changed. Shown at the simulation's next update, without a
// rebuild.
#include "binding/class_binder.h"
#include "sunflower_simulation.h"

class SunflowerChanges {
public:
	static constexpr const char *CLASS = "SunflowerChanges";
	static void bind_methods();

	// Changes p_simulation's plants from now on.
	void attach(gdx::Instance<SunflowerSimulation> p_simulation);

	// p_action (0 stand, 1 flatten, 2 cut, 3 remove, 4 as the map has it) on map cells (row × columns
	// + column) at the field's clock p_now (core field_changes.h, FieldSimulation::change_cells);
	// returns the cells changed.
	gdx::PackedInt32Array change_cells(const gdx::PackedInt32Array &p_cells, int64_t p_action, double p_now);
	// Puts a standing plant of type p_species in each of p_cells (FieldSimulation::put_cells); returns
	// the cells changed. Cells whose ground height is not known wait: get_unplaced_cells, whose roots
	// (get_cell_roots: x, z pairs in the field's space) a caller casts rays under and hands back to
	// set_cell_heights.
	gdx::PackedInt32Array put_cells(const gdx::PackedInt32Array &p_cells, int64_t p_species);
	gdx::PackedInt32Array get_unplaced_cells() const;
	gdx::PackedFloat32Array get_cell_roots(const gdx::PackedInt32Array &p_cells) const;
	void set_cell_heights(const gdx::PackedInt32Array &p_cells, const gdx::PackedFloat32Array &p_heights);
	// Moves the changes' clock: returns the cells whose plants stood again.
	gdx::PackedInt32Array advance_changes(double p_now);
	// A cell after play: x its plant (0 none, 1 + plant type), y its state (0 standing, 1 flattened,
	// 2 cut), z the clock when it took it.
	gdx::Vector3 get_cell_change(int64_t p_cell) const;
	int64_t get_change_count() const;
	gdx::PackedInt32Array get_cells_in_circle(gdx::Vector2 p_center, double p_radius) const;
	gdx::PackedInt32Array get_cells_in_rect(gdx::Vector2 p_min, gdx::Vector2 p_max) const;
	// The pushers flatten the standing plants within p_share of their radius (FieldSimulation::trample):
	// two ints each trampled plant, its cell and the pusher's index in set_pushers' order.
	gdx::PackedInt32Array trample(double p_share, double p_now);
	// A plant's map cell, or -1 (also for a plant gone: removed, or under a plant of another type).
	int64_t get_plant_cell(int64_t p_plant) const;
	// The cells whose plant play took down, a bit each (FieldSimulation::get_hidden_cells), and the
	// version that changes with them.
	gdx::PackedByteArray get_hidden_cells() const;
	int64_t get_hidden_version() const;
	gdx::PackedByteArray save_changes(double p_now);
	// "" (and get_loaded_clock() the save's clock) or what is wrong, nothing changed.
	gdx::String load_changes(const gdx::PackedByteArray &p_bytes);
	double get_loaded_clock() const { return _loaded_clock; }

private:
	// The attached simulation's core, or null after an error naming p_method.
	sunflower::FieldSimulation *_core(const char *p_method) const;

	gdx::Held<SunflowerSimulation> _simulation;
	double _loaded_clock = 0.0;
};
