// Placement by rules, no engine: the time to generate a map of 1 M and 16 M cells from four layers
// (trees by noise away from a road and a building, grass by slope kept 1.5 m from the trees,
// flowers by height and an image mask, clearings erased by noise), on every core of the machine.
// Prints the median of several runs and the share of each plant type.
#include "placement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

using namespace sunflower;

namespace {

PlacementRules hillside(int p_side) {
	PlacementRules rules;
	rules.columns = rules.rows = p_side;
	rules.cell_size = 0.5f;
	rules.seed = 20081;
	rules.heights.reserve(static_cast<size_t>(p_side) * static_cast<size_t>(p_side));
	for (int r = 0; r < p_side; r++) {
		for (int c = 0; c < p_side; c++) {
			const float x = static_cast<float>(c) * 0.5f;
			const float z = static_cast<float>(r) * 0.5f;
			rules.heights.push_back(12.0f * std::sin(x * 0.01f) * std::cos(z * 0.013f) + 0.05f * x);
		}
	}
	const float side = static_cast<float>(p_side) * 0.5f;
	PlacementLayer trees;
	trees.species = 1;
	trees.density = 0.05f;
	trees.noise = NoiseFilter{ true, 40.0f, 3, 0.55f, 0.1f, 1, false };
	trees.paths.enabled = true;
	trees.paths.lines = { { 0.0f, side * 0.3f, side * 0.4f, side * 0.5f, side * 0.7f, side * 0.45f, side, side * 0.8f } };
	trees.paths.half_width = 3.0f;
	trees.paths.falloff = 4.0f;
	trees.exclusion.enabled = true;
	trees.exclusion.footprints = { { side * 0.5f, side * 0.2f, side * 0.5f + 20.0f, side * 0.2f, side * 0.5f + 20.0f,
			side * 0.2f + 12.0f, side * 0.5f, side * 0.2f + 12.0f } };
	trees.exclusion.falloff = 2.0f;
	PlacementLayer grass;
	grass.species = 0;
	grass.mode = PlacementLayer::FILL;
	grass.density = 0.9f;
	grass.slope = RangeFilter{ true, 0.0f, 25.0f, 5.0f, false };
	grass.paths = trees.paths;
	grass.paths.falloff = 0.5f;
	grass.spacing = SpacingFilter{ true, 0, 1.5f };
	PlacementLayer flowers;
	flowers.species = 2;
	flowers.density = 0.2f;
	flowers.height = RangeFilter{ true, -5.0f, 6.0f, 2.0f, false };
	flowers.mask.enabled = true;
	flowers.mask.width = flowers.mask.height = 64;
	for (int i = 0; i < 64 * 64; i++) {
		flowers.mask.values.push_back(static_cast<uint8_t>((i * 37) % 256));
	}
	flowers.mask.size_x = flowers.mask.size_z = side;
	flowers.spacing = SpacingFilter{ true, 0, 1.0f };
	PlacementLayer clearings;
	clearings.mode = PlacementLayer::ERASE;
	clearings.noise = NoiseFilter{ true, 15.0f, 2, 0.8f, 0.0f, 2, false };
	rules.layers = { trees, grass, flowers, clearings };
	return rules;
}

double median(std::vector<double> p_values) {
	std::sort(p_values.begin(), p_values.end());
	return p_values[p_values.size() / 2];
}

} // namespace

int main() {
	const uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
	WorkerPool pool(threads);
	std::printf("Placement by rules (4 layers: noise, paths, a footprint, slope, height, a mask, spacing), %u threads:\n\n",
			threads);
	std::printf("| cells | runs | median s | fastest s | grass / trees / flowers / empty |\n|---|---|---|---|---|\n");
	for (const int side : { 1000, 4000 }) {
		const PlacementRules rules = hillside(side);
		std::vector<double> seconds;
		std::vector<uint8_t> cells;
		const int runs = side <= 1000 ? 7 : 3;
		for (int run = 0; run < runs; run++) {
			const auto start = std::chrono::steady_clock::now();
			if (!generate_placement(rules, CellRect{ 0, 0, side, side }, &pool, cells)) {
				std::printf("the rules do not check: %s\n", check_placement(rules).c_str());
				return 1;
			}
			seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
		}
		double counts[4] = { 0.0, 0.0, 0.0, 0.0 };
		for (uint8_t cell : cells) {
			counts[std::min<uint8_t>(cell, 3)] += 1.0;
		}
		const double n = static_cast<double>(cells.size());
		std::printf("| %d M (%d × %d) | %d | %.3f | %.3f | %.2f / %.3f / %.3f / %.2f |\n", side * side / 1000000, side, side, runs,
				median(seconds), *std::min_element(seconds.begin(), seconds.end()), counts[1] / n, counts[2] / n,
				counts[3] / n, counts[0] / n);
	}
	return 0;
}
