// libFuzzer target: the map parser, the canonical writer, a brush stroke, the layout and one
// simulation step, under ASan + UBSan.
// Any crash, sanitizer report or broken invariant below is a finding.
#include "field_simulation.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

using namespace sunflower;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *p_data, size_t p_size) {
	const std::string text(reinterpret_cast<const char *>(p_data), p_size);
	MapLimits limits;
	limits.max_cells = int64_t(1) << 22; // keep allocations small; the limit logic is what is tested
	limits.max_plants = 200'000;
	FieldMap map;
	MapError error;
	if (!parse_field_map(text, U"S#", U"m", "fuzz.field", limits, map, error)) {
		// An error must point into the file (or at the whole file) and say something.
		if (error.message.empty() || error.line < 0 || error.column < 0 || error.to_string().empty()) {
			std::abort();
		}
		return 0;
	}
	if (map.columns <= 0 || map.rows <= 0 || int64_t(map.plants.size()) != int64_t(map.columns) * map.rows) {
		std::abort();
	}
	// The canonical text reads back as the same map, and is its own canonical form.
	const std::string canonical = write_field_map(map, U"m");
	FieldMap again;
	if (!parse_field_map(canonical, U"S#", U"m", "canonical.field", limits, again, error) || again.plants != map.plants ||
			again.plant_count != map.plant_count || again.objects.size() != map.objects.size() ||
			write_field_map(again, U"m") != canonical) {
		std::abort();
	}
	// A stroke keeps the count in step with the cells.
	std::vector<int> changed;
	const float radius = float(p_size % 7);
	paint_cells(again, float(map.columns) * 0.5f, float(map.rows) * 0.5f, radius, CellContent{ CellContent::PLANT, 1, 0 }, 0.5f,
			p_size, changed);
	int64_t counted = 0;
	for (uint8_t cell : again.plants) {
		counted += cell != 0 ? 1 : 0;
	}
	if (counted != again.plant_count) {
		std::abort();
	}
	FieldSimulation sim;
	if (!sim.load_map(text, U"S#", U"m", "fuzz.field", limits, error) || sim.plants().get_plant_count() != map.plant_count) {
		std::abort();
	}
	sim.near().set_observer({ float(map.columns) * 0.25f, 1.7f, float(map.rows) * 0.25f });
	sim.update(0.016f);
	int64_t total = 0;
	for (int64_t count : sim.near().get_lod_counts()) {
		total += count;
	}
	if (total != map.plant_count) {
		std::abort();
	}
	return 0;
}
