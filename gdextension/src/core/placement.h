#pragma once
// Placement by rules: an ordered list of layers, each placing one plant type with a density shaped
// by filters that multiply (ground height and slope, seeded noise, an image mask, distance from
// paths, exclusion footprints, spacing from an earlier layer's plants), turned into map cells.
//
// Every cell's outcome depends only on the rules, the seed and the cells around it (never on the
// order cells are visited or on the region asked for), so any rectangle of cells generated alone
// equals the same rectangle of the whole, on every platform: the arithmetic is plain IEEE (no
// fused multiply-add, no library function but sqrt and floor per cell).
#include "worker_pool.h"

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace sunflower {

// A weight from a value: 1 inside [low, high], falling linearly to 0 over p_falloff outside it
// (0: a step). Inverted, 1 - that.
struct RangeFilter {
	bool enabled = false;
	float low = 0.0f;
	float high = 0.0f;
	float falloff = 0.0f;
	bool invert = false;
};

// Seeded value noise in [0, 1] (octaves of half the size and half the weight each), a weight of 0
// below threshold, 1 above threshold + falloff, linear between (falloff 0: a step).
struct NoiseFilter {
	bool enabled = false;
	float scale = 10.0f; // metres across a feature of the first octave
	int octaves = 1; // 1–8
	float threshold = 0.5f;
	float falloff = 0.0f;
	uint32_t seed = 0; // added to the rules' seed
	bool invert = false;
};

// One channel of an image laid over a rectangle of the field: the weight is its value (0–255 read
// as 0–1), bilinear between pixel centres; outside the rectangle, p_outside.
struct MaskFilter {
	bool enabled = false;
	int width = 0;
	int height = 0;
	std::vector<uint8_t> values; // width × height, row-major, row 0 at the rectangle's low z
	float x = 0.0f; // the rectangle in the field's metres: low corner and size
	float z = 0.0f;
	float size_x = 0.0f;
	float size_z = 0.0f;
	float outside = 0.0f;
	bool invert = false;
};

// Distance from centre lines (roads, rivers): 0 within half_width of any, 1 from half_width +
// falloff on, linear between. Inverted: plants only near the lines.
struct PathFilter {
	bool enabled = false;
	std::vector<std::vector<float>> lines; // each x0, z0, x1, z1, … in the field's metres
	float half_width = 1.0f;
	float falloff = 0.0f;
	bool invert = false;
};

// Footprints nothing grows in (buildings, rocks): convex polygons, 0 inside, 1 from falloff
// outside on, linear between.
struct ExclusionFilter {
	bool enabled = false;
	std::vector<std::vector<float>> footprints; // each a convex polygon x0, z0, x1, z1, … (either turn)
	float falloff = 0.0f;
};

// No plant of this layer within distance metres (centre to centre) of a plant that layer `layer`
// (an earlier one) placed and that still stands when this layer runs.
struct SpacingFilter {
	bool enabled = false;
	int layer = 0;
	float distance = 0.0f;
};

struct PlacementLayer {
	enum Mode : uint8_t {
		PLACE, // its plants take the cells they pass, over what earlier layers placed
		FILL, // its plants take only cells still empty
		ERASE, // cells it passes are emptied
	};
	Mode mode = PLACE;
	int species = 0; // the map's plant type: 0 '*', 1… the legend's plants in order
	float density = 1.0f; // 0–1: the share of cells it takes where every filter gives 1
	RangeFilter height;
	RangeFilter slope; // degrees from level
	NoiseFilter noise;
	MaskFilter mask;
	PathFilter paths;
	ExclusionFilter exclusion;
	SpacingFilter spacing;
	// How placement_layer_from reads a mask of four bytes a pixel: the channel it takes (0–3).
	int mask_channel = 0;
};

struct PlacementRules {
	int columns = 0;
	int rows = 0;
	float cell_size = 1.0f; // metres; cell (c, r)'s centre is ((c + 0.5) s, (r + 0.5) s)
	uint64_t seed = 0;
	// The ground's height at every cell's centre, row-major (columns × rows), or empty for level
	// ground at 0. The slope at a cell is that of the heights around it (central differences).
	std::vector<float> heights;
	std::vector<PlacementLayer> layers;
};

struct CellRect {
	int column = 0;
	int row = 0;
	int columns = 0;
	int rows = 0;
};

// An empty string when the rules can run, else what is wrong, naming the layer ("layer 2: …",
// 1-based) and the setting.
std::string check_placement(const PlacementRules &p_rules);

// Cells of p_rect (inside the field) as the rules place them, row-major, each 0 (empty) or 1 +
// its plant type, into r_cells. Runs its rows on p_pool (may be null: on the caller). Returns false,
// with r_cells unspecified, when p_cancel (may be null) became true meanwhile or the rules do not
// check (check_placement first to know why).
bool generate_placement(const PlacementRules &p_rules, const CellRect &p_rect, WorkerPool *p_pool,
		std::vector<uint8_t> &r_cells, const std::atomic<bool> *p_cancel = nullptr);

// The weight (0–1) of layer p_layer's filters at every cell of p_rect, row-major, into r_weights:
// the product of its height, slope, mask, noise, path and exclusion weights (not its density), and
// 0 within its spacing of a cell of p_map that holds the plant type of the layer its spacing names.
// p_map: the whole field's cells as generate_placement gives them (empty: the spacing is not read).
// What a brush painting "by a layer" multiplies its density by. False when the layer or rectangle
// is not there or the rules do not check.
bool placement_layer_weights(const PlacementRules &p_rules, size_t p_layer, const CellRect &p_rect,
		const std::vector<uint8_t> &p_map, std::vector<float> &r_weights);

// Hand edits kept through a regeneration: every cell where p_edited (the map as the user left it)
// differs from p_generated_before (what the rules gave then) keeps its edited value; every other
// cell takes p_generated_now. All three of one size; returns the result.
std::vector<uint8_t> keep_hand_edits(const std::vector<uint8_t> &p_generated_before,
		const std::vector<uint8_t> &p_edited, const std::vector<uint8_t> &p_generated_now);

// A layer's settings as one row of numbers (what the engine's face passes): the names of the row's
// columns in order, e.g. "mode", "species", "density", "height_on", "height_low", … (booleans 0 or 1).
std::vector<std::string> placement_layer_fields();

// The layer from a row of placement_layer_fields().size() numbers, its paths and footprints as
// lists of shapes (each shape: its point count, then x, z of each point) and its mask's bytes (one a
// pixel, or RGBA8, four a pixel, of which the row's mask_channel is taken).
// Returns what is wrong with the row's shape (not its values: check_placement judges those).
std::string placement_layer_from(const std::vector<float> &p_row, const std::vector<float> &p_lines,
		const std::vector<float> &p_footprints, const std::vector<uint8_t> &p_mask, PlacementLayer &r_layer);

// Value noise in [0, 1] at (p_x, p_z) in units of the first octave's feature, for p_seed.
float placement_noise(uint64_t p_seed, float p_x, float p_z, int p_octaves);

} // namespace sunflower
