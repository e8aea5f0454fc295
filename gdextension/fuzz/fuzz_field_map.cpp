// libFuzzer target: the map parser, the layout and one simulation step, under ASan + UBSan.
// Any crash, sanitizer report or broken invariant below is a finding.
#include "field_simulation.h"

#include <cstdint>
#include <cstdlib>
#include <string>

using namespace sunflower;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *p_data, size_t p_size) {
	const std::string text(reinterpret_cast<const char *>(p_data), p_size);
	MapLimits limits;
	limits.max_cells = int64_t(1) << 22; // keep allocations small; the limit logic is what is tested
	limits.max_plants = 200'000;
	FieldMap map;
	MapError error;
	if (!parse_field_map(text, U"S#", "fuzz.field", limits, map, error)) {
		// An error must point into the file (or at the whole file) and say something.
		if (error.message.empty() || error.line < 0 || error.column < 0 || error.to_string().empty()) {
			std::abort();
		}
		return 0;
	}
	if (map.columns <= 0 || map.rows <= 0 || int64_t(map.plants.size()) != int64_t(map.columns) * map.rows) {
		std::abort();
	}
	FieldSimulation sim;
	if (!sim.load_map(text, U"S#", "fuzz.field", limits, error) || sim.get_plant_count() != map.plant_count) {
		std::abort();
	}
	sim.set_observer({ float(map.columns) * 0.25f, 1.7f, float(map.rows) * 0.25f });
	sim.update(0.016f);
	int64_t total = 0;
	for (int64_t count : sim.get_lod_counts()) {
		total += count;
	}
	if (total != map.plant_count) {
		std::abort();
	}
	return 0;
}
