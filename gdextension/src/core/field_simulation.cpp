#include "field_simulation.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sunflower {

FieldSimulation::FieldSimulation() {
	_rebuilt();
}

bool FieldSimulation::load_map(const std::string &p_text, const std::u32string &p_legend, const std::string &p_source,
		const MapLimits &p_limits, MapError &r_error) {
	return load_map(p_text, p_legend, std::u32string(), p_source, p_limits, r_error);
}

bool FieldSimulation::load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, MapError &r_error) {
	if (!_plants.load_map(p_text, p_legend, p_plant_symbols, p_source, p_limits, r_error)) {
		return false;
	}
	_rebuilt();
	return true;
}

void FieldSimulation::clear() {
	replace_map(FieldMap{});
}

void FieldSimulation::replace_map(FieldMap p_map) {
	_plants.replace_map(std::move(p_map));
	_rebuilt();
}

void FieldSimulation::paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density,
		uint64_t p_seed, bool p_relayout, std::vector<int> &r_changed, const CellWeights *p_weights) {
	if (_plants.paint_map(p_center, p_radius, p_content, p_density, p_seed, p_relayout, r_changed, p_weights)) {
		_rebuilt();
	}
}

ParameterSpec::Cost FieldSimulation::set_setting(const ParameterSpec &p_spec, const float *p_values, uint32_t p_species) {
	if (p_species >= FieldMap::MAX_SPECIES) {
		return ParameterSpec::FREE;
	}
	// What is taken at the next update.
	WindParams wind = _near.get_wind().get_params();
	if (wind.set(p_spec, p_values) != RowSet::OTHER) {
		_near.set_wind(wind);
		return ParameterSpec::FREE;
	}
	LodParams lod = _near.get_lod_params();
	if (lod.set(p_spec, p_values) != RowSet::OTHER) {
		_near.set_lod(lod);
		return ParameterSpec::FREE;
	}
	if (_near.get_pushes().set(p_spec, p_values[0]) != RowSet::OTHER) {
		return ParameterSpec::FREE;
	}
	Regrowth regrowth = _regrowth[p_species];
	if (regrowth.set(p_spec, double(p_values[0])) != RowSet::OTHER) {
		std::array<Regrowth, FieldMap::MAX_SPECIES> all = _regrowth;
		all[p_species] = regrowth;
		set_regrowth(all);
		return ParameterSpec::FREE;
	}
	if (&p_spec == &param::WORKER_THREADS) {
		_near.set_worker_threads(uint32_t(sanitize(p_spec, double(p_values[0]), double(_near.get_worker_threads()))));
		return ParameterSpec::FREE;
	}
	if (&p_spec == &param::PLANT_STUMP_HEIGHT) {
		_near.set_stump_height(p_species, p_values[0]);
		return ParameterSpec::FREE;
	}
	// What the layout depends on: taken while no map is read, else left to a new build.
	const bool laid_out = _plants.get_map().columns > 0;
	LayoutParams layout = _plants.get_layout_params();
	const RowSet layout_set = layout.set(p_spec, p_values[0], p_species);
	if (layout_set != RowSet::OTHER) {
		if (layout_set == RowSet::SAME) {
			return ParameterSpec::FREE;
		}
		if (laid_out) {
			return ParameterSpec::REBUILD;
		}
		set_layout_params(layout);
		return ParameterSpec::FREE;
	}
	PlantShape shape = _plants.get_shape(p_species);
	const float metres = shape.part_scale * shape.parts_height();
	if (&p_spec == &param::PLANT_HEIGHT) {
		if (sanitize(p_spec, p_values[0], metres) == metres) {
			return ParameterSpec::FREE;
		}
		if (laid_out) {
			return ParameterSpec::REBUILD;
		}
		set_plant_height(p_values[0], p_species);
		return ParameterSpec::FREE;
	}
	const RowSet shape_set = shape.set(p_spec, p_values);
	if (shape_set == RowSet::CHANGED) {
		if (laid_out) {
			return ParameterSpec::REBUILD;
		}
		set_shape(shape, p_species);
		set_plant_height(metres, p_species); // a new form keeps the plant's height
		return ParameterSpec::FREE;
	}
	if (shape_set == RowSet::SAME || !laid_out) {
		return ParameterSpec::FREE;
	}
	// A row no unit here owns (the engine side applies it): the table's cost, as the core cannot
	// tell whether it changed.
	return p_spec.cost;
}

bool FieldSimulation::set_layout_params(const LayoutParams &p_params) {
	if (!_plants.set_layout_params(p_params)) {
		return false;
	}
	_rebuilt();
	return true;
}

void FieldSimulation::set_ground(Ground p_ground) {
	_plants.set_ground(std::move(p_ground));
	_rebuilt();
}

void FieldSimulation::set_shape(const PlantShape &p_shape, uint32_t p_species) {
	++_records_version;
	if (_plants.set_shape(p_shape, p_species)) {
		_near.make_buckets();
	}
	_near.reshape();
	_near.request_lod_update();
}

void FieldSimulation::set_plant_height(float p_metres, uint32_t p_species) {
	if (p_species < FieldMap::MAX_SPECIES) {
		set_shape(_plants.shape_of_height(p_metres, p_species), p_species);
	}
}

void FieldSimulation::_rebuilt() {
	if (_changes_ready && _changes.fingerprint() != map_fingerprint(_plants.get_map())) {
		_changes_ready = false; // another map: its changes are gone
		_changes = FieldChanges();
		_cell_heights.clear();
		_unplaced.clear();
		_hidden.clear();
		++_hidden_version;
	}
	_near.rebuild();
	_tiles.build(); // (from the map's plants: before those play added)
	if (_changes_ready) {
		_unplaced.clear();
		for (const auto &change : _changes.changes()) {
			_show_cell(change.first); // (the plants' states are new with the layout, the added plants gone)
		}
		_group_added();
	}
	++_mask_version;
	++_records_version;
}

void FieldSimulation::_group_added() {
	if (_plants.added_grouped()) {
		return;
	}
	_near.drop_added();
	_plants.group_added();
	_near.take_added();
}

void FieldSimulation::update(float p_delta) {
	_tiles.follow_observer(_near.get_observer());
	if (_near.update(p_delta)) {
		++_mask_version;
	}
}

bool FieldSimulation::is_tile_drawn(uint32_t p_tile) const {
	for (uint32_t k = 0; k < _tiles.get_tile(p_tile).count; ++k) {
		if (!_near.is_chunk_active(_tiles.get_tile_chunk(p_tile, k))) {
			return true;
		}
	}
	return false;
}

size_t FieldSimulation::get_memory_bytes() const {
	return _plants.get_memory_bytes() + _near.get_memory_bytes() + _tiles.get_memory_bytes();
}

void FieldSimulation::_ready_changes() {
	if (!_changes_ready) {
		_changes.reset(_plants.get_map());
		_changes.set_regrowth(_regrowth);
		_changes_ready = true;
		const FieldMap &map = _plants.get_map();
		_hidden.assign(size_t(hidden_row_bytes()) * size_t(map.rows), 0);
		++_hidden_version;
	}
}

const FieldChanges &FieldSimulation::changes() {
	_ready_changes();
	return _changes;
}

CellState FieldSimulation::get_cell_state(uint32_t p_cell) const {
	if (_changes_ready) {
		return _changes.get(p_cell);
	}
	CellState state;
	const std::vector<uint8_t> &plants = _plants.get_map().plants;
	state.plant = p_cell < plants.size() ? plants[p_cell] : 0;
	return state;
}

void FieldSimulation::_show_cell(uint32_t p_cell) {
	const CellState state = _changes.get(p_cell);
	const std::vector<uint8_t> &map_plants = _plants.get_map().plants;
	// The map's own plant type there (or none, as the map has it): its plant shows the state. Another:
	// the map's plant is hidden and an added plant stands in.
	const bool map_type = p_cell < map_plants.size() && state.plant == map_plants[p_cell];
	const uint32_t plant = _plants.plant_at_cell(p_cell);
	if (plant != FieldPlants::NO_PLANT) {
		const PlantState shown = map_type && state.plant != 0 ? state.state : PlantState::GONE;
		_plants.set_plant_state(plant, shown);
		const uint32_t columns = uint32_t(_plants.get_map().columns);
		const size_t byte = size_t(p_cell / columns) * hidden_row_bytes() + (p_cell % columns) / 8;
		const uint8_t bit = uint8_t(1u << ((p_cell % columns) % 8));
		if (byte < _hidden.size() && bool(_hidden[byte] & bit) != (shown != PlantState::STANDING)) {
			_hidden[byte] ^= bit;
			++_hidden_version;
		}
	}
	_unplaced.erase(p_cell);
	if (map_type || state.plant == 0) {
		_plants.take_plant(_plants.added_plant_at_cell(p_cell));
		return;
	}
	const auto height = _cell_heights.find(p_cell);
	const uint32_t added =
			_plants.add_plant(p_cell, uint32_t(state.plant - 1), height != _cell_heights.end() ? height->second : NAN, plant);
	if (added == FieldPlants::NO_PLANT) {
		_unplaced.insert(p_cell); // no ground known there: see set_cell_heights
		return;
	}
	_plants.set_plant_state(added, state.state);
}

void FieldSimulation::put_cells(const std::vector<uint32_t> &p_cells, uint32_t p_species, std::vector<uint32_t> &r_changed) {
	_ready_changes();
	for (uint32_t cell : p_cells) {
		if (_changes.put(cell, int(p_species))) {
			r_changed.push_back(cell);
			_show_cell(cell);
		}
	}
	_group_added();
}

void FieldSimulation::set_cell_heights(const std::vector<uint32_t> &p_cells, const std::vector<float> &p_heights) {
	_ready_changes();
	for (size_t i = 0; i < p_cells.size() && i < p_heights.size(); ++i) {
		if (std::isfinite(p_heights[i])) {
			_cell_heights[p_cells[i]] = p_heights[i];
		} else {
			_cell_heights.erase(p_cells[i]);
		}
		if (_changes.is_changed(p_cells[i])) {
			_show_cell(p_cells[i]);
		}
	}
	_group_added();
}

std::vector<uint32_t> FieldSimulation::get_unplaced_cells() const {
	std::vector<uint32_t> cells(_unplaced.begin(), _unplaced.end());
	std::sort(cells.begin(), cells.end());
	return cells;
}

void FieldSimulation::change_cells(const std::vector<uint32_t> &p_cells, CellAction p_action, double p_now,
		std::vector<uint32_t> &r_changed) {
	_ready_changes();
	for (uint32_t cell : p_cells) {
		bool changed = false;
		switch (p_action) {
			case CellAction::STAND:
				changed = _changes.set_state(cell, PlantState::STANDING, p_now);
				break;
			case CellAction::FLATTEN:
				changed = _changes.set_state(cell, PlantState::FLATTENED, p_now);
				break;
			case CellAction::CUT:
				changed = _changes.set_state(cell, PlantState::CUT, p_now);
				break;
			case CellAction::REMOVE:
				changed = _changes.remove(cell);
				break;
			case CellAction::RESTORE:
				changed = _changes.restore(cell);
				break;
		}
		if (changed) {
			r_changed.push_back(cell);
			_show_cell(cell);
		}
	}
	_group_added();
}

void FieldSimulation::trample(float p_share, double p_now, std::vector<Trampled> &r_trampled) {
	const float share = sanitize(param::TRAMPLE_SHARE, p_share, 0.0f);
	const std::vector<Pusher> &pushers = _near.get_pushes().get_pushers();
	if (share <= 0.0f || pushers.empty() || _plants.get_plant_count() == 0) {
		return;
	}
	_ready_changes();
	std::vector<uint32_t> near;
	for (size_t i = 0; i < pushers.size(); ++i) {
		const Pusher &pusher = pushers[i];
		near.clear();
		_plants.find_plants_near(glm::vec2(pusher.position.x, pusher.position.z), pusher.radius * share, near);
		for (uint32_t plant : near) {
			if (_plants.get_plant_state(plant) != PlantState::STANDING) {
				continue;
			}
			const float ground = _plants.get_layout().plants[plant].ground;
			const float head = ground + _plants.get_stalk(plant).y;
			if (pusher.position.y + pusher.radius < ground || pusher.position.y - pusher.radius > head) {
				continue; // above or below the plant
			}
			const uint32_t cell = _plants.cell_of_plant(plant);
			if (cell != FieldPlants::NO_CELL && _changes.set_state(cell, PlantState::FLATTENED, p_now)) {
				r_trampled.push_back(Trampled{ cell, static_cast<uint32_t>(i) });
				_show_cell(cell);
			}
		}
	}
}

void FieldSimulation::set_regrowth(const std::array<Regrowth, FieldMap::MAX_SPECIES> &p_regrowth) {
	_regrowth = p_regrowth;
	if (_changes_ready) {
		_changes.set_regrowth(p_regrowth);
	}
}

void FieldSimulation::advance_changes(double p_now, std::vector<uint32_t> &r_recovered) {
	if (!_changes_ready) {
		return;
	}
	const size_t before = r_recovered.size();
	_changes.advance(p_now, r_recovered);
	for (size_t i = before; i < r_recovered.size(); ++i) {
		_show_cell(r_recovered[i]);
	}
	_group_added();
}

std::vector<uint8_t> FieldSimulation::save_changes(double p_now) {
	_ready_changes();
	return _changes.save(p_now);
}

std::string FieldSimulation::load_changes(const std::vector<uint8_t> &p_bytes, double &r_clock) {
	_ready_changes();
	std::vector<uint32_t> before;
	for (const auto &change : _changes.changes()) {
		before.push_back(change.first);
	}
	const std::string error = _changes.load(p_bytes, r_clock);
	if (!error.empty()) {
		return error;
	}
	for (uint32_t cell : before) {
		if (!_changes.is_changed(cell)) {
			_show_cell(cell); // back as the map has it
		}
	}
	for (const auto &change : _changes.changes()) {
		_show_cell(change.first);
	}
	_group_added();
	return "";
}


} // namespace sunflower
