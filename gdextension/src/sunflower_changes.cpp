// SunflowerChanges: play's changes to an attached simulation's plants: cut, flattened, removed and
// standing again at run time, their regrowth and the save of what play changed (core
// field_changes.h through FieldSimulation).
#include "sunflower_changes.h"

#include "binding/class_binder.h"
#include "binding/error_macros.h"
#include "convert.h"

#include <cmath>

using namespace sunflower;

namespace {

// The cells of p_cells, or an error (of p_method) naming the first that is not one of the map's p_limit cells.
std::string cells_from(const char *p_method, const gdx::PackedInt32Array &p_cells, size_t p_limit, std::vector<uint32_t> &r_cells) {
	const int32_t *data = p_cells.data();
	r_cells.reserve(size_t(p_cells.size()));
	for (int64_t i = 0; i < p_cells.size(); ++i) {
		if (data[i] < 0 || static_cast<size_t>(data[i]) >= p_limit) {
			return std::string(p_method) + ": cell " + std::to_string(data[i]) + " (at " + std::to_string(i) +
					" in the list) is not one of the map's " + std::to_string(p_limit) + " cells; nothing was changed";
		}
		r_cells.push_back(static_cast<uint32_t>(data[i]));
	}
	return "";
}

size_t cell_count(const FieldSimulation &p_sim) {
	const FieldMap &map = p_sim.plants().get_map();
	return static_cast<size_t>(map.columns) * static_cast<size_t>(map.rows);
}

} // namespace

void SunflowerChanges::bind_methods() {
	gdx::bind_method(CLASS, "attach", &SunflowerChanges::attach, { "simulation" });
	gdx::bind_method(CLASS, "change_cells", &SunflowerChanges::change_cells, { "cells", "action", "now" });
	gdx::bind_method(CLASS, "put_cells", &SunflowerChanges::put_cells, { "cells", "species" });
	gdx::bind_method(CLASS, "get_unplaced_cells", &SunflowerChanges::get_unplaced_cells);
	gdx::bind_method(CLASS, "get_cell_roots", &SunflowerChanges::get_cell_roots, { "cells" });
	gdx::bind_method(CLASS, "set_cell_heights", &SunflowerChanges::set_cell_heights, { "cells", "heights" });
	gdx::bind_method(CLASS, "advance_changes", &SunflowerChanges::advance_changes, { "now" });
	gdx::bind_method(CLASS, "get_cell_change", &SunflowerChanges::get_cell_change, { "cell" });
	gdx::bind_method(CLASS, "get_change_count", &SunflowerChanges::get_change_count);
	gdx::bind_method(CLASS, "get_cells_in_circle", &SunflowerChanges::get_cells_in_circle, { "center", "radius" });
	gdx::bind_method(CLASS, "get_cells_in_rect", &SunflowerChanges::get_cells_in_rect, { "min", "max" });
	gdx::bind_method(CLASS, "trample", &SunflowerChanges::trample, { "share", "now" });
	gdx::bind_method(CLASS, "get_plant_cell", &SunflowerChanges::get_plant_cell, { "plant" });
	gdx::bind_method(CLASS, "get_hidden_cells", &SunflowerChanges::get_hidden_cells);
	gdx::bind_method(CLASS, "get_hidden_version", &SunflowerChanges::get_hidden_version);
	gdx::bind_method(CLASS, "save_changes", &SunflowerChanges::save_changes, { "now" });
	gdx::bind_method(CLASS, "load_changes", &SunflowerChanges::load_changes, { "bytes" });
	gdx::bind_method(CLASS, "get_loaded_clock", &SunflowerChanges::get_loaded_clock);
}

void SunflowerChanges::attach(gdx::Instance<SunflowerSimulation> p_simulation) {
	SF_FAIL_COND_MSG(!p_simulation.instance, "attach: takes a SunflowerSimulation");
	_simulation = gdx::Held<SunflowerSimulation>(p_simulation);
	_loaded_clock = 0.0;
}

FieldSimulation *SunflowerChanges::_core(const char *p_method) const {
	SunflowerSimulation *simulation = _simulation.get();
	SF_FAIL_COND_V_MSG(!simulation, nullptr,
			std::string(p_method) + ": no simulation to change (attach one; the one attached may be gone)");
	return &simulation->core();
}

int64_t SunflowerChanges::get_hidden_version() const {
	const FieldSimulation *core = _core("get_hidden_version");
	return core ? int64_t(core->get_hidden_version()) : 0;
}

gdx::PackedInt32Array SunflowerChanges::change_cells(const gdx::PackedInt32Array &p_cells, int64_t p_action, double p_now) {
	FieldSimulation *core = _core("change_cells");
	if (!core) {
		return {};
	}
	FieldSimulation &sim = *core;
	SF_FAIL_COND_V_MSG(p_action < 0 || p_action > int64_t(FieldSimulation::CellAction::RESTORE), gdx::PackedInt32Array(),
			"change_cells: the action must be 0 (stand), 1 (flatten), 2 (cut), 3 (remove) or 4 (restore); got " +
					std::to_string(p_action));
	SF_FAIL_COND_V_MSG(!std::isfinite(p_now), gdx::PackedInt32Array(), "change_cells: the field's clock is not a number");
	std::vector<uint32_t> cells;
	const std::string error = cells_from("change_cells", p_cells, cell_count(sim), cells);
	SF_FAIL_COND_V_MSG(!error.empty(), gdx::PackedInt32Array(), error);
	std::vector<uint32_t> changed;
	sim.change_cells(cells, static_cast<FieldSimulation::CellAction>(p_action), p_now, changed);
	return gdx::to_godot_indices(changed);
}

gdx::PackedInt32Array SunflowerChanges::put_cells(const gdx::PackedInt32Array &p_cells, int64_t p_species) {
	FieldSimulation *core = _core("put_cells");
	if (!core) {
		return {};
	}
	FieldSimulation &sim = *core;
	SF_FAIL_COND_V_MSG(p_species < 0 || p_species >= int64_t(sim.plants().get_species_count()), gdx::PackedInt32Array(),
			"put_cells: the field has no plant type " + std::to_string(p_species) + " (its map has " +
					std::to_string(sim.plants().get_species_count()) + "); nothing was changed");
	std::vector<uint32_t> cells;
	const std::string error = cells_from("put_cells", p_cells, cell_count(sim), cells);
	SF_FAIL_COND_V_MSG(!error.empty(), gdx::PackedInt32Array(), error);
	std::vector<uint32_t> changed;
	sim.put_cells(cells, uint32_t(p_species), changed);
	return gdx::to_godot_indices(changed);
}

gdx::PackedInt32Array SunflowerChanges::get_unplaced_cells() const {
	const FieldSimulation *core = _core("get_unplaced_cells");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	return gdx::to_godot_indices(sim.get_unplaced_cells());
}

gdx::PackedFloat32Array SunflowerChanges::get_cell_roots(const gdx::PackedInt32Array &p_cells) const {
	const FieldSimulation *core = _core("get_cell_roots");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedFloat32Array out;
	const FieldMap &map = sim.plants().get_map();
	out.resize(p_cells.size() * 2);
	float *data = out.data();
	for (int64_t i = 0; i < p_cells.size(); ++i) {
		const int32_t cell = p_cells.data()[i];
		const bool valid = cell >= 0 && static_cast<size_t>(cell) < cell_count(sim);
		const glm::vec2 root = valid ? plant_root_at(map, sim.plants().get_layout_params(), cell % map.columns, cell / map.columns)
									 : glm::vec2(NAN);
		data[2 * i] = root.x;
		data[2 * i + 1] = root.y;
	}
	return out;
}

void SunflowerChanges::set_cell_heights(const gdx::PackedInt32Array &p_cells, const gdx::PackedFloat32Array &p_heights) {
	FieldSimulation *core = _core("set_cell_heights");
	if (!core) {
		return;
	}
	FieldSimulation &sim = *core;
	SF_FAIL_COND_MSG(p_cells.size() != p_heights.size(), "set_cell_heights: " + std::to_string(p_cells.size()) + " cells but " +
					std::to_string(p_heights.size()) + " heights");
	std::vector<uint32_t> cells;
	const std::string error = cells_from("set_cell_heights", p_cells, cell_count(sim), cells);
	SF_FAIL_COND_MSG(!error.empty(), error);
	sim.set_cell_heights(cells, std::vector<float>(p_heights.data(), p_heights.data() + p_heights.size()));
}

gdx::PackedInt32Array SunflowerChanges::advance_changes(double p_now) {
	FieldSimulation *core = _core("advance_changes");
	if (!core) {
		return {};
	}
	FieldSimulation &sim = *core;
	std::vector<uint32_t> recovered;
	if (std::isfinite(p_now)) {
		sim.advance_changes(p_now, recovered);
	}
	return gdx::to_godot_indices(recovered);
}

gdx::Vector3 SunflowerChanges::get_cell_change(int64_t p_cell) const {
	const FieldSimulation *core = _core("get_cell_change");
	if (!core) {
		return gdx::Vector3{ 0.0f, 0.0f, 0.0f };
	}
	const FieldSimulation &sim = *core;
	if (p_cell < 0 || static_cast<size_t>(p_cell) >= cell_count(sim)) {
		return gdx::Vector3{ 0.0f, 0.0f, 0.0f };
	}
	const CellState state = sim.get_cell_state(static_cast<uint32_t>(p_cell));
	return gdx::Vector3{ float(state.plant), float(state.state), float(state.since) };
}

int64_t SunflowerChanges::get_change_count() const {
	const FieldSimulation *core = _core("get_change_count");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	return int64_t(sim.get_change_count());
}

gdx::PackedInt32Array SunflowerChanges::get_cells_in_circle(gdx::Vector2 p_center, double p_radius) const {
	const FieldSimulation *core = _core("get_cells_in_circle");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	std::vector<uint32_t> cells;
	const FieldMap &map = sim.plants().get_map();
	cells_in_circle(map.columns, map.rows, sim.plants().get_layout_params().cell_size, gdx::to_core(p_center), float(p_radius),
			cells);
	return gdx::to_godot_indices(cells);
}

gdx::PackedInt32Array SunflowerChanges::get_cells_in_rect(gdx::Vector2 p_min, gdx::Vector2 p_max) const {
	const FieldSimulation *core = _core("get_cells_in_rect");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	std::vector<uint32_t> cells;
	const FieldMap &map = sim.plants().get_map();
	cells_in_rect(map.columns, map.rows, sim.plants().get_layout_params().cell_size, gdx::to_core(p_min), gdx::to_core(p_max), cells);
	return gdx::to_godot_indices(cells);
}

gdx::PackedInt32Array SunflowerChanges::trample(double p_share, double p_now) {
	FieldSimulation *core = _core("trample");
	if (!core) {
		return {};
	}
	FieldSimulation &sim = *core;
	std::vector<FieldSimulation::Trampled> trampled;
	if (std::isfinite(p_now)) {
		sim.trample(float(p_share), p_now, trampled);
	}
	gdx::PackedInt32Array out;
	out.resize(int64_t(trampled.size() * 2));
	int32_t *data = out.data();
	for (size_t i = 0; i < trampled.size(); ++i) {
		data[2 * i] = static_cast<int32_t>(trampled[i].cell);
		data[2 * i + 1] = static_cast<int32_t>(trampled[i].pusher);
	}
	return out;
}

int64_t SunflowerChanges::get_plant_cell(int64_t p_plant) const {
	const FieldSimulation *core = _core("get_plant_cell");
	if (!core) {
		return 0;
	}
	const FieldSimulation &sim = *core;
	if (p_plant < 0 || p_plant >= int64_t(sim.plants().get_plant_count()) ||
			sim.plants().get_plant_state(uint32_t(p_plant)) == PlantState::GONE) {
		return -1; // (a plant gone, e.g. the map's under a plant of another type put there, has no cell)
	}
	const uint32_t cell = sim.plants().cell_of_plant(uint32_t(p_plant));
	return cell == FieldPlants::NO_CELL ? -1 : int64_t(cell);
}

gdx::PackedByteArray SunflowerChanges::save_changes(double p_now) {
	FieldSimulation *core = _core("save_changes");
	if (!core) {
		return {};
	}
	FieldSimulation &sim = *core;
	const std::vector<uint8_t> bytes = sim.save_changes(std::isfinite(p_now) ? p_now : 0.0);
	gdx::PackedByteArray out;
	out.assign(bytes.data(), bytes.size());
	return out;
}

gdx::String SunflowerChanges::load_changes(const gdx::PackedByteArray &p_bytes) {
	FieldSimulation *core = _core("load_changes");
	if (!core) {
		return gdx::String("no simulation attached");
	}
	FieldSimulation &sim = *core;
	const uint8_t *data = p_bytes.data();
	const std::vector<uint8_t> bytes = data ? std::vector<uint8_t>(data, data + p_bytes.size()) : std::vector<uint8_t>();
	double clock = 0.0;
	const std::string error = sim.load_changes(bytes, clock);
	if (error.empty()) {
		_loaded_clock = clock;
	}
	return gdx::String(error);
}

gdx::PackedByteArray SunflowerChanges::get_hidden_cells() const {
	const FieldSimulation *core = _core("get_hidden_cells");
	if (!core) {
		return {};
	}
	const FieldSimulation &sim = *core;
	gdx::PackedByteArray out;
	out.assign(sim.get_hidden_cells().data(), sim.get_hidden_cells().size());
	return out;
}
