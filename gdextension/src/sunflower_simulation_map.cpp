// SunflowerSimulation's map: reading it, and what the field drawn asks of it.
#include "sunflower_map.h"
#include "sunflower_simulation.h"

#include "convert.h"

using namespace sunflower;

gdx::String SunflowerSimulation::load_map(const gdx::PackedByteArray &p_text, const gdx::String &p_source,
		const gdx::String &p_legend, const gdx::String &p_plant_symbols, int64_t p_max_plants) {
	const MapLimits limits = SunflowerMap::limits_for(p_max_plants);
	MapError error;
	if (!_sim.load_map(gdx::to_core(p_text), decode_utf8_text(p_legend.utf8()), decode_utf8_text(p_plant_symbols.utf8()),
				p_source.utf8(), limits, error)) {
		return gdx::String(error.to_string());
	}
	++_chunks_version; // the old field's chunks no longer exist
	return gdx::String();
}

int64_t SunflowerSimulation::get_map_columns() const {
	return _sim.plants().get_map().columns;
}

int64_t SunflowerSimulation::get_map_rows() const {
	return _sim.plants().get_map().rows;
}

gdx::PackedInt32Array SunflowerSimulation::get_map_objects() const {
	return SunflowerMap::objects_of(_sim.plants().get_map());
}

