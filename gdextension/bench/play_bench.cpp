// Play's changes, no engine: the cost, in the frame they land in, of 1 000 changes to a field of a
// million plants (1 000 × 1 000 cells of 0.5 m): the changes themselves (the plants' states and the
// hidden-cells mask: no far tile is written again), the mask's bytes copied for the engine (as the
// binding's get_hidden_cells does; the engine's upload of that texture is not counted), and the frame's
// update. Four shapes of change: a scythe's circle by the observer, a trail across the field, cells
// scattered over all of it, one cell far away. Prints medians of 21 runs (cut, then given back: each
// run changes every plant listed).
#include "bench_maps.h"
#include "field_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace sunflower;
using sunflower_bench::rect_map;

namespace {

constexpr int SIDE = 1000;
constexpr int RUNS = 21;

double median(std::vector<double> p_values) {
	std::sort(p_values.begin(), p_values.end());
	return p_values[p_values.size() / 2];
}

double since(const std::chrono::steady_clock::time_point &p_start) {
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p_start).count();
}

struct Cost {
	double frame_ms = 0.0; // the changes, the mask copied, the update
	double change_ms = 0.0; // change_cells alone
};

Cost land(FieldSimulation &r_sim, const std::vector<uint32_t> &p_cells, FieldSimulation::CellAction p_action, double p_now,
		std::vector<uint8_t> &r_engine) {
	Cost cost;
	const auto start = std::chrono::steady_clock::now();
	const uint32_t version = r_sim.get_hidden_version();
	std::vector<uint32_t> changed;
	r_sim.change_cells(p_cells, p_action, p_now, changed);
	cost.change_ms = since(start);
	if (r_sim.get_hidden_version() != version) {
		r_engine.assign(r_sim.get_hidden_cells().begin(), r_sim.get_hidden_cells().end());
	}
	r_sim.update(1.0f / 60.0f);
	cost.frame_ms = since(start);
	return cost;
}

void measure(FieldSimulation &r_sim, const char *p_name, const std::vector<uint32_t> &p_cells) {
	std::vector<double> frames;
	std::vector<double> changes;
	std::vector<double> quiet;
	std::vector<uint8_t> engine;
	double now = 0.0;
	for (int run = 0; run < RUNS; ++run) {
		const Cost cost = land(r_sim, p_cells, FieldSimulation::CellAction::CUT, now += 1.0, engine);
		frames.push_back(cost.frame_ms);
		changes.push_back(cost.change_ms);
		const auto start = std::chrono::steady_clock::now();
		r_sim.update(1.0f / 60.0f); // a frame with no change
		quiet.push_back(since(start));
		land(r_sim, p_cells, FieldSimulation::CellAction::RESTORE, now += 1.0, engine);
	}
	std::printf("| %-34s | %5zu | %9.3f | %9.3f | %9.3f | %9.3f |\n", p_name, p_cells.size(), median(frames), median(quiet),
			median(frames) - median(quiet), median(changes));
}

// Plants of another type put in p_cells (then given back), as measure() does: the frame they land in,
// and a frame with them standing (added plants are drawn by the near field at every distance: that
// frame's extra cost lasts while they stand).
void measure_puts(FieldSimulation &r_sim, const char *p_name, const std::vector<uint32_t> &p_cells) {
	std::vector<double> frames;
	std::vector<double> quiet;
	std::vector<double> standing;
	double now = 0.0;
	for (int run = 0; run < RUNS; ++run) {
		auto start = std::chrono::steady_clock::now();
		r_sim.update(1.0f / 60.0f);
		quiet.push_back(since(start));
		start = std::chrono::steady_clock::now();
		std::vector<uint32_t> changed;
		r_sim.put_cells(p_cells, 1, changed);
		now += 1.0;
		r_sim.update(1.0f / 60.0f);
		frames.push_back(since(start));
		start = std::chrono::steady_clock::now();
		r_sim.update(1.0f / 60.0f);
		standing.push_back(since(start));
		changed.clear();
		r_sim.change_cells(p_cells, FieldSimulation::CellAction::RESTORE, now += 1.0, changed);
		r_sim.update(1.0f / 60.0f);
	}
	std::printf("| %-34s | %5zu | %9.3f | %9.3f | %9.3f | %9.3f |\n", p_name, p_cells.size(), median(frames), median(quiet),
			median(frames) - median(quiet), median(standing) - median(quiet));
}

// The process' resident memory in kB (Linux's /proc; 0 elsewhere).
long resident_kb() {
	std::ifstream status("/proc/self/status");
	std::string key;
	long value = 0;
	while (status >> key) {
		if (key == "VmRSS:") {
			status >> value;
			return value;
		}
	}
	return 0;
}

} // namespace

int main() {
	FieldSimulation sim;
	MapError error;
	// (A second plant type in the legend, which the map does not use: what play puts.)
	if (!sim.load_map(rect_map(SIDE, SIDE), U"m", U"m", "1M", MapLimits{}, error)) {
		std::printf("1M: %s\n", error.to_string().c_str());
		return 1;
	}
	sim.near().set_worker_threads(1);
	LodParams lod;
	lod.distances = { 6.0f, 10.0f, 30.0f, 35.0f };
	sim.near().set_lod(lod);
	const glm::vec3 eye(250.0f, 1.7f, 250.0f);
	sim.near().set_observer(eye);
	for (int frame = 0; frame < 30; ++frame) {
		sim.update(1.0f / 60.0f);
	}
	std::printf("Play's changes landing in one frame, 1M field (%u plants), one thread, median of %d runs:\n\n",
			sim.plants().get_plant_count(), RUNS);
	std::printf("| changes                            | cells | frame ms  | quiet ms  | added ms  | change ms |\n");
	std::printf("|------------------------------------|-------|-----------|-----------|-----------|-----------|\n");
	const float cell = sim.plants().get_layout_params().cell_size;
	std::vector<uint32_t> cells;
	cells_in_circle(SIDE, SIDE, cell, glm::vec2(eye.x + 4.0f, eye.z), 8.92f, cells);
	cells.resize(std::min<size_t>(cells.size(), 1000));
	measure(sim, "a scythe's circle by the observer", cells);
	cells.clear();
	for (int column = 0; column < SIDE; ++column) {
		cells.push_back(uint32_t(700 * SIDE + column)); // a row 100 m off, across the field
	}
	measure(sim, "a trail across the field", cells);
	cells.clear();
	std::mt19937 random(2008);
	std::uniform_int_distribution<uint32_t> any(0, SIDE * SIDE - 1);
	while (cells.size() < 1000) {
		cells.push_back(any(random));
	}
	std::sort(cells.begin(), cells.end());
	cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
	measure(sim, "scattered over the whole field", cells);
	const std::vector<uint32_t> scattered = cells;
	cells.assign(1, uint32_t(950 * SIDE + 950)); // 350 m off
	measure(sim, "one cell far away", cells);
	std::printf("\nPlants of another type put (then given back), 1M field, median of %d runs:\n\n", RUNS);
	std::printf("| plants put                         | cells | frame ms  | quiet ms  | added ms  | after ms  |\n");
	std::printf("|------------------------------------|-------|-----------|-----------|-----------|-----------|\n");
	cells.clear();
	cells_in_circle(SIDE, SIDE, cell, glm::vec2(eye.x + 4.0f, eye.z), 8.92f, cells);
	cells.resize(std::min<size_t>(cells.size(), 1000));
	measure_puts(sim, "a circle sown by the observer", cells);
	measure_puts(sim, "scattered over the whole field", scattered);
	// What each changed cell holds while it differs from the map: every cell of the field removed.
	FieldMap map;
	map.columns = SIDE;
	map.rows = SIDE;
	map.plants.assign(size_t(SIDE) * SIDE, 1);
	map.plant_count = int64_t(SIDE) * SIDE;
	FieldChanges every;
	every.reset(map);
	const long before = resident_kb();
	for (uint32_t c = 0; c < uint32_t(SIDE * SIDE); ++c) {
		every.remove(c);
	}
	const long after = resident_kb();
	std::printf("\nEvery one of the %d cells removed: %.1f bytes of memory a changed cell (resident, Linux).\n", SIDE * SIDE,
			double(after - before) * 1024.0 / (double(SIDE) * SIDE));
	std::printf("\nframe ms: the frame the changes land in (the changes, the hidden-cells mask of %zu bytes copied for\n"
				"the engine, the update); quiet ms: a frame with no change; added ms: the difference; change ms: the\n"
				"changes alone. No far tile is written again: the impostor shader reads the mask. Plants put: after ms,\n"
				"what a frame costs more while they stand (the near field draws them at every distance).\n",
			sim.get_hidden_cells().size());
	return 0;
}
