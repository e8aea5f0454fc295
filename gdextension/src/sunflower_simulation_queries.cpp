// SunflowerSimulation's queries: plants and their levels, counts, pushes and costs.
#include "sunflower_simulation.h"

#include "convert.h"
#include "binding/error_macros.h"

#include <algorithm>
#include <cmath>

using namespace sunflower;

bool SunflowerSimulation::_is_plant(int64_t p_plant) const {
	SF_FAIL_COND_V_MSG(p_plant < 0 || p_plant >= int64_t(_sim.plants().get_plant_count()), false,
			"plant index " + std::to_string(p_plant) + " is out of range (the field has " +
					std::to_string(_sim.plants().get_plant_count()) + " plants)");
	return true;
}

int64_t SunflowerSimulation::get_plant_count() const {
	return _sim.plants().get_plant_count();
}

gdx::PackedInt32Array SunflowerSimulation::get_lod_counts_by_species() const {
	std::vector<int32_t> values;
	for (uint32_t species = 0; species < _sim.plants().get_species_count(); ++species) {
		for (int64_t count : _sim.near().get_lod_counts(species)) {
			values.push_back(static_cast<int32_t>(count));
		}
	}
	gdx::PackedInt32Array out;
	out.assign(values.data(), values.size());
	return out;
}

gdx::PackedInt32Array SunflowerSimulation::get_lod_counts() const {
	const auto counts = _sim.near().get_lod_counts();
	int32_t values[LOD_COUNT];
	for (size_t i = 0; i < LOD_COUNT; ++i) {
		values[i] = static_cast<int32_t>(counts[i]);
	}
	gdx::PackedInt32Array out;
	out.assign(values, LOD_COUNT);
	return out;
}

gdx::Vector3 SunflowerSimulation::get_plant_position(int64_t p_plant) const {
	if (!_is_plant(p_plant)) {
		return gdx::Vector3{};
	}
	return gdx::to_godot(_sim.plants().get_layout().plants[size_t(p_plant)].root());
}

gdx::Vector2 SunflowerSimulation::get_plant_stalk(int64_t p_plant) const {
	return _is_plant(p_plant) ? gdx::to_godot(_sim.plants().get_stalk(uint32_t(p_plant))) : gdx::Vector2{};
}

int64_t SunflowerSimulation::get_plant_lod(int64_t p_plant) const {
	return _is_plant(p_plant) ? _sim.near().get_plant_lod(uint32_t(p_plant)) : -1;
}

int64_t SunflowerSimulation::get_plant_tile_level(int64_t p_plant) const {
	return _is_plant(p_plant) ? int64_t(_sim.tiles().plant_tile_level(_sim.plants().get_layout().plants[size_t(p_plant)])) : -1;
}

gdx::PackedFloat32Array SunflowerSimulation::get_plant_parts(int64_t p_plant) const {
	gdx::PackedFloat32Array out;
	if (!_is_plant(p_plant)) {
		return out;
	}
	PartTransforms parts;
	_sim.near().get_plant_parts(uint32_t(p_plant), parts);
	out.resize(PART_COUNT * TRANSFORM_FLOATS);
	float *data = out.data();
	for (uint32_t part = 0; part < PART_COUNT; ++part) {
		write_transform(data + part * TRANSFORM_FLOATS, parts.basis[part], parts.origin[part]);
	}
	return out;
}

int64_t SunflowerSimulation::get_last_update_usec() const {
	return _last_update_usec;
}

int64_t SunflowerSimulation::get_pushed_count() const {
	return _sim.near().get_pushes().get_pushed_count();
}

gdx::PackedInt32Array SunflowerSimulation::get_plants_near(gdx::Vector3 p_position, double p_radius, bool p_standing_only) const {
	std::vector<uint32_t> plants;
	_sim.plants().find_plants_near(gdx::to_core_ground(p_position), float(p_radius), plants);
	// A cut or removed plant is not there; a flattened one lies there, not standing.
	const auto gone = [&](uint32_t p_plant) {
		const PlantState state = _sim.plants().get_plant_state(p_plant);
		return state == PlantState::CUT || state == PlantState::GONE || (p_standing_only && state == PlantState::FLATTENED);
	};
	plants.erase(std::remove_if(plants.begin(), plants.end(), gone), plants.end());
	return gdx::to_godot_indices(plants);
}

int64_t SunflowerSimulation::get_memory_bytes() const {
	return static_cast<int64_t>(_sim.get_memory_bytes());
}
