#include "field_simulation.h"

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
	_near.rebuild();
	_tiles.build();
	++_mask_version;
	++_records_version;
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

} // namespace sunflower
