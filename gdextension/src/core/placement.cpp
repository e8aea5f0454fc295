#include "placement.h"

#include "random_hash.h"

#include <algorithm>
#include <cmath>
#include <cstring>

// The same rules give the same map on every platform: no multiply-add may be fused into one
// rounding (clang fuses them by default where the processor has the instruction, as on arm64).
#if defined(__clang__)
#pragma clang fp contract(off)
#endif

namespace sunflower {

namespace {

constexpr float DEGREES_PER_RADIAN = 57.295779513082320876f;
constexpr int MAX_OCTAVES = 8;
constexpr size_t MAX_LAYERS = 254; // a cell's owner is a byte: 0 for none, 1 + the layer

bool finite(float p_value) {
	return std::isfinite(p_value);
}

// atan for p_x ≥ 0, in plain arithmetic (a library's atan may differ by an ulp between platforms):
// a polynomial on [0, 1] (error under 2e-5 rad, about 0.001°) and atan(x) = π/2 − atan(1/x) above.
float atan_positive(float p_x) {
	const bool above = p_x > 1.0f;
	const float x = above ? 1.0f / p_x : p_x;
	const float x2 = x * x;
	const float a = x *
			(0.99997726f +
					x2 * (-0.33262347f + x2 * (0.19354346f + x2 * (-0.11643287f + x2 * (0.05265332f + x2 * -0.01172120f)))));
	return above ? 1.57079632679f - a : a;
}

float range_weight(const RangeFilter &p_filter, float p_value) {
	float weight;
	if (p_value >= p_filter.low && p_value <= p_filter.high) {
		weight = 1.0f;
	} else if (p_filter.falloff <= 0.0f) {
		weight = 0.0f;
	} else {
		const float outside = p_value < p_filter.low ? p_filter.low - p_value : p_value - p_filter.high;
		weight = std::max(0.0f, 1.0f - outside / p_filter.falloff);
	}
	return p_filter.invert ? 1.0f - weight : weight;
}

// 0 below p_edge, 1 from p_edge + p_falloff on, linear between (a step when p_falloff is 0).
float ramp(float p_value, float p_edge, float p_falloff) {
	if (p_falloff <= 0.0f) {
		return p_value >= p_edge ? 1.0f : 0.0f;
	}
	return std::clamp((p_value - p_edge) / p_falloff, 0.0f, 1.0f);
}

float lattice(uint64_t p_seed, int64_t p_x, int64_t p_z) {
	const uint64_t key = static_cast<uint64_t>(p_x) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(p_z) * 0xC2B2AE3D27D4EB4Full;
	return unit_float(mix64(p_seed ^ mix64(key)));
}

float value_noise(uint64_t p_seed, float p_x, float p_z) {
	const float fx = std::floor(p_x);
	const float fz = std::floor(p_z);
	const int64_t ix = static_cast<int64_t>(fx);
	const int64_t iz = static_cast<int64_t>(fz);
	float tx = p_x - fx;
	float tz = p_z - fz;
	tx = tx * tx * (3.0f - 2.0f * tx);
	tz = tz * tz * (3.0f - 2.0f * tz);
	const float a = lattice(p_seed, ix, iz);
	const float b = lattice(p_seed, ix + 1, iz);
	const float c = lattice(p_seed, ix, iz + 1);
	const float d = lattice(p_seed, ix + 1, iz + 1);
	const float low = a + (b - a) * tx;
	const float high = c + (d - c) * tx;
	return low + (high - low) * tz;
}

float mask_weight(const MaskFilter &p_mask, float p_x, float p_z) {
	// Pixel centres sit at (i + 0.5) / width of the rectangle.
	const float u = (p_x - p_mask.x) / p_mask.size_x;
	const float v = (p_z - p_mask.z) / p_mask.size_z;
	float weight;
	if (!(u >= 0.0f && u <= 1.0f && v >= 0.0f && v <= 1.0f)) {
		weight = p_mask.outside;
	} else {
		const float px = std::clamp(u * static_cast<float>(p_mask.width) - 0.5f, 0.0f, static_cast<float>(p_mask.width - 1));
		const float pz = std::clamp(v * static_cast<float>(p_mask.height) - 0.5f, 0.0f, static_cast<float>(p_mask.height - 1));
		const int x0 = static_cast<int>(px);
		const int z0 = static_cast<int>(pz);
		const int x1 = std::min(x0 + 1, p_mask.width - 1);
		const int z1 = std::min(z0 + 1, p_mask.height - 1);
		const float tx = px - static_cast<float>(x0);
		const float tz = pz - static_cast<float>(z0);
		auto at = [&](int p_px, int p_pz) {
			return static_cast<float>(p_mask.values[static_cast<size_t>(p_pz) * static_cast<size_t>(p_mask.width) + static_cast<size_t>(p_px)]) *
					(1.0f / 255.0f);
		};
		const float low = at(x0, z0) + (at(x1, z0) - at(x0, z0)) * tx;
		const float high = at(x0, z1) + (at(x1, z1) - at(x0, z1)) * tx;
		weight = low + (high - low) * tz;
	}
	return p_mask.invert ? 1.0f - weight : weight;
}

struct Segment {
	float x0, z0, x1, z1;
	float min_x, max_x, min_z, max_z; // its box grown by the filter's reach
};

float segment_distance(const Segment &p_segment, float p_x, float p_z) {
	const float dx = p_segment.x1 - p_segment.x0;
	const float dz = p_segment.z1 - p_segment.z0;
	const float length2 = dx * dx + dz * dz;
	float t = length2 > 0.0f ? ((p_x - p_segment.x0) * dx + (p_z - p_segment.z0) * dz) / length2 : 0.0f;
	t = std::clamp(t, 0.0f, 1.0f);
	const float ex = p_x - (p_segment.x0 + dx * t);
	const float ez = p_z - (p_segment.z0 + dz * t);
	return std::sqrt(ex * ex + ez * ez);
}

struct Footprint {
	std::vector<float> points;
	float min_x, max_x, min_z, max_z; // grown by the falloff
	float turn; // +1 or −1: the side of its edges its inside lies on
};

// Distance from a convex footprint (0 inside).
float footprint_distance(const Footprint &p_footprint, float p_x, float p_z) {
	const std::vector<float> &p = p_footprint.points;
	const size_t n = p.size() / 2;
	bool inside = true;
	float nearest = INFINITY;
	for (size_t i = 0; i < n; i++) {
		const size_t j = (i + 1) % n;
		const float ex = p[2 * j] - p[2 * i];
		const float ez = p[2 * j + 1] - p[2 * i + 1];
		const float cross = ex * (p_z - p[2 * i + 1]) - ez * (p_x - p[2 * i]);
		if (cross * p_footprint.turn < 0.0f) {
			inside = false;
		}
		const Segment edge{ p[2 * i], p[2 * i + 1], p[2 * j], p[2 * j + 1], 0, 0, 0, 0 };
		nearest = std::min(nearest, segment_distance(edge, p_x, p_z));
	}
	return inside ? 0.0f : nearest;
}

// A layer made ready to run: its paths as segments and footprints with their boxes.
struct PreparedLayer {
	const PlacementLayer *layer = nullptr;
	std::vector<Segment> segments;
	std::vector<Footprint> footprints;
	uint64_t noise_seed = 0;
	int spacing_cells = 0; // the spacing's reach in cells
};

PreparedLayer prepare(const PlacementRules &p_rules, size_t p_index) {
	PreparedLayer prepared;
	const PlacementLayer &layer = p_rules.layers[p_index];
	prepared.layer = &layer;
	if (layer.paths.enabled) {
		const float reach = layer.paths.half_width + layer.paths.falloff;
		for (const std::vector<float> &line : layer.paths.lines) {
			for (size_t i = 0; i + 3 < line.size(); i += 2) {
				Segment s{ line[i], line[i + 1], line[i + 2], line[i + 3], 0, 0, 0, 0 };
				s.min_x = std::min(s.x0, s.x1) - reach;
				s.max_x = std::max(s.x0, s.x1) + reach;
				s.min_z = std::min(s.z0, s.z1) - reach;
				s.max_z = std::max(s.z0, s.z1) + reach;
				prepared.segments.push_back(s);
			}
		}
	}
	if (layer.exclusion.enabled) {
		for (const std::vector<float> &points : layer.exclusion.footprints) {
			Footprint f;
			f.points = points;
			f.min_x = f.max_x = points[0];
			f.min_z = f.max_z = points[1];
			float area2 = 0.0f;
			const size_t n = points.size() / 2;
			for (size_t i = 0; i < n; i++) {
				const size_t j = (i + 1) % n;
				f.min_x = std::min(f.min_x, points[2 * i]);
				f.max_x = std::max(f.max_x, points[2 * i]);
				f.min_z = std::min(f.min_z, points[2 * i + 1]);
				f.max_z = std::max(f.max_z, points[2 * i + 1]);
				area2 += points[2 * i] * points[2 * j + 1] - points[2 * j] * points[2 * i + 1];
			}
			f.min_x -= layer.exclusion.falloff;
			f.max_x += layer.exclusion.falloff;
			f.min_z -= layer.exclusion.falloff;
			f.max_z += layer.exclusion.falloff;
			f.turn = area2 >= 0.0f ? 1.0f : -1.0f;
			prepared.footprints.push_back(std::move(f));
		}
	}
	prepared.noise_seed = mix64(p_rules.seed ^ (uint64_t(layer.noise.seed) << 32) ^ 0x6E6F697365ull);
	if (layer.spacing.enabled) {
		prepared.spacing_cells = static_cast<int>(std::floor(layer.spacing.distance / p_rules.cell_size));
	}
	return prepared;
}

float height_at(const PlacementRules &p_rules, int p_column, int p_row) {
	return p_rules.heights[static_cast<size_t>(p_row) * static_cast<size_t>(p_rules.columns) + static_cast<size_t>(p_column)];
}

// The slope at a cell in degrees, from its neighbours' heights (one-sided at the field's edges).
float slope_at(const PlacementRules &p_rules, int p_column, int p_row) {
	if (p_rules.heights.empty()) {
		return 0.0f;
	}
	const int left = std::max(p_column - 1, 0);
	const int right = std::min(p_column + 1, p_rules.columns - 1);
	const int up = std::max(p_row - 1, 0);
	const int down = std::min(p_row + 1, p_rules.rows - 1);
	const float gx = right > left ? (height_at(p_rules, right, p_row) - height_at(p_rules, left, p_row)) /
					(static_cast<float>(right - left) * p_rules.cell_size)
								  : 0.0f;
	const float gz = down > up ? (height_at(p_rules, p_column, down) - height_at(p_rules, p_column, up)) /
					(static_cast<float>(down - up) * p_rules.cell_size)
							   : 0.0f;
	return atan_positive(std::sqrt(gx * gx + gz * gz)) * DEGREES_PER_RADIAN;
}

// p_chance times the weights of the layer's height, slope, mask, noise, path and exclusion filters
// at the cell, in that order, stopping as soon as it falls to p_draw or below (the cell is not
// taken then; a negative p_draw never stops it, giving the whole product).
float filtered_chance(const PlacementRules &p_rules, const PreparedLayer &p_prepared, int p_column, int p_row, float p_chance,
		float p_draw) {
	const PlacementLayer &layer = *p_prepared.layer;
	float chance = p_chance;
	const float x = (static_cast<float>(p_column) + 0.5f) * p_rules.cell_size;
	const float z = (static_cast<float>(p_row) + 0.5f) * p_rules.cell_size;
	if (layer.height.enabled) {
		const float height = p_rules.heights.empty() ? 0.0f : height_at(p_rules, p_column, p_row);
		chance *= range_weight(layer.height, height);
		if (p_draw >= chance) {
			return chance;
		}
	}
	if (layer.slope.enabled) {
		chance *= range_weight(layer.slope, slope_at(p_rules, p_column, p_row));
		if (p_draw >= chance) {
			return chance;
		}
	}
	if (layer.mask.enabled) {
		chance *= mask_weight(layer.mask, x, z);
		if (p_draw >= chance) {
			return chance;
		}
	}
	if (layer.noise.enabled) {
		const float value = placement_noise(p_prepared.noise_seed, x / layer.noise.scale, z / layer.noise.scale, layer.noise.octaves);
		const float weight = ramp(value, layer.noise.threshold, layer.noise.falloff);
		chance *= layer.noise.invert ? 1.0f - weight : weight;
		if (p_draw >= chance) {
			return chance;
		}
	}
	if (layer.paths.enabled) {
		float nearest = INFINITY;
		for (const Segment &s : p_prepared.segments) {
			if (x >= s.min_x && x <= s.max_x && z >= s.min_z && z <= s.max_z) {
				nearest = std::min(nearest, segment_distance(s, x, z));
			}
		}
		const float weight = ramp(nearest, layer.paths.half_width, layer.paths.falloff);
		chance *= layer.paths.invert ? 1.0f - weight : weight;
		if (p_draw >= chance) {
			return chance;
		}
	}
	if (layer.exclusion.enabled) {
		for (const Footprint &f : p_prepared.footprints) {
			if (x >= f.min_x && x <= f.max_x && z >= f.min_z && z <= f.max_z) {
				const float distance = footprint_distance(f, x, z);
				chance *= distance <= 0.0f ? 0.0f : ramp(distance, 0.0f, layer.exclusion.falloff);
				if (p_draw >= chance) {
					return chance;
				}
			}
		}
	}
	return chance;
}

// Whether a cell within the layer's spacing of (p_column, p_row) holds p_other in p_cells (the
// cells of p_area, row-major).
bool spaced_out(const PlacementRules &p_rules, const PreparedLayer &p_prepared, int p_column, int p_row, uint8_t p_other,
		const std::vector<uint8_t> &p_cells, const CellRect &p_area) {
	const int reach = p_prepared.spacing_cells;
	const float distance = p_prepared.layer->spacing.distance;
	const float distance2 = distance * distance;
	const float s2 = p_rules.cell_size * p_rules.cell_size;
	for (int dr = -reach; dr <= reach; dr++) {
		const int row = p_row + dr - p_area.row;
		if (row < 0 || row >= p_area.rows) {
			continue;
		}
		for (int dc = -reach; dc <= reach; dc++) {
			const int column = p_column + dc - p_area.column;
			if (column < 0 || column >= p_area.columns || static_cast<float>(dr * dr + dc * dc) * s2 > distance2) {
				continue;
			}
			if (p_cells[static_cast<size_t>(row) * static_cast<size_t>(p_area.columns) + static_cast<size_t>(column)] == p_other) {
				return true;
			}
		}
	}
	return false;
}

// Whether p_rect lies inside the field.
bool inside(const PlacementRules &p_rules, const CellRect &p_rect) {
	return p_rect.columns >= 0 && p_rect.rows >= 0 && p_rect.column >= 0 && p_rect.row >= 0 &&
			p_rect.column + p_rect.columns <= p_rules.columns && p_rect.row + p_rect.rows <= p_rules.rows;
}

// Whether layer p_index takes cell (p_column, p_row), reading the owners before it (p_before, over
// p_area) for its spacing.
bool takes(const PlacementRules &p_rules, const PreparedLayer &p_prepared, size_t p_index, int p_column, int p_row,
		const std::vector<uint8_t> &p_before, const CellRect &p_area) {
	const PlacementLayer &layer = *p_prepared.layer;
	const uint64_t cell = static_cast<uint64_t>(p_row) * static_cast<uint64_t>(p_rules.columns) + static_cast<uint64_t>(p_column);
	const float draw = unit_float(hash_plant(p_rules.seed, cell, STREAM_PLACEMENT, p_index));
	if (draw >= layer.density || draw >= filtered_chance(p_rules, p_prepared, p_column, p_row, layer.density, draw)) {
		return false;
	}
	return !layer.spacing.enabled ||
			!spaced_out(p_rules, p_prepared, p_column, p_row, static_cast<uint8_t>(layer.spacing.layer + 1), p_before, p_area);
}

std::string check_range(const RangeFilter &p_filter, const char *p_name) {
	if (!p_filter.enabled) {
		return "";
	}
	if (!finite(p_filter.low) || !finite(p_filter.high) || !finite(p_filter.falloff)) {
		return std::string(p_name) + ": its range and falloff must be finite numbers";
	}
	if (p_filter.low > p_filter.high) {
		return std::string(p_name) + ": its low end is above its high end";
	}
	if (p_filter.falloff < 0.0f) {
		return std::string(p_name) + ": its falloff is negative";
	}
	return "";
}

std::string check_layer(const PlacementRules &p_rules, size_t p_index) {
	const PlacementLayer &layer = p_rules.layers[p_index];
	if (layer.species < 0 || layer.species >= 8) {
		return "its plant type " + std::to_string(layer.species) + " is not 0–7 ('*' and the legend's seven)";
	}
	if (!finite(layer.density) || layer.density < 0.0f || layer.density > 1.0f) {
		return "its density is not a number from 0 to 1";
	}
	std::string problem = check_range(layer.height, "height");
	if (problem.empty()) {
		problem = check_range(layer.slope, "slope");
	}
	if (!problem.empty()) {
		return problem;
	}
	const NoiseFilter &noise = layer.noise;
	if (noise.enabled && (!finite(noise.scale) || noise.scale <= 0.0f || noise.octaves < 1 || noise.octaves > MAX_OCTAVES ||
								 !finite(noise.threshold) || !finite(noise.falloff) || noise.falloff < 0.0f)) {
		return "noise: needs a scale above 0, 1–8 octaves, a finite threshold and a falloff of 0 or more";
	}
	const MaskFilter &mask = layer.mask;
	if (mask.enabled) {
		if (mask.width < 1 || mask.height < 1 ||
				mask.values.size() != static_cast<size_t>(mask.width) * static_cast<size_t>(mask.height)) {
			return "mask: its image is empty or its values are not width × height";
		}
		if (!finite(mask.x) || !finite(mask.z) || !finite(mask.size_x) || !finite(mask.size_z) || mask.size_x <= 0.0f ||
				mask.size_z <= 0.0f || !finite(mask.outside)) {
			return "mask: its rectangle needs finite corners and a size above 0";
		}
	}
	if (layer.paths.enabled) {
		if (!finite(layer.paths.half_width) || layer.paths.half_width < 0.0f || !finite(layer.paths.falloff) ||
				layer.paths.falloff < 0.0f) {
			return "paths: the half width and falloff must be 0 or more";
		}
		for (size_t i = 0; i < layer.paths.lines.size(); i++) {
			const std::vector<float> &line = layer.paths.lines[i];
			if (line.size() < 4 || line.size() % 2 != 0 || !std::all_of(line.begin(), line.end(), finite)) {
				return "paths: line " + std::to_string(i + 1) + " needs two or more points with finite coordinates";
			}
		}
	}
	if (layer.exclusion.enabled) {
		if (!finite(layer.exclusion.falloff) || layer.exclusion.falloff < 0.0f) {
			return "exclusion: the falloff must be 0 or more";
		}
		for (size_t i = 0; i < layer.exclusion.footprints.size(); i++) {
			const std::vector<float> &points = layer.exclusion.footprints[i];
			if (points.size() < 6 || points.size() % 2 != 0 || !std::all_of(points.begin(), points.end(), finite)) {
				return "exclusion: footprint " + std::to_string(i + 1) + " needs three or more points with finite coordinates";
			}
		}
	}
	if (layer.spacing.enabled) {
		if (layer.spacing.layer < 0 || static_cast<size_t>(layer.spacing.layer) >= p_index) {
			return "spacing: it must name an earlier layer (1–" + std::to_string(p_index) + ")";
		}
		if (!finite(layer.spacing.distance) || layer.spacing.distance < 0.0f ||
				layer.spacing.distance > 64.0f * p_rules.cell_size) {
			return "spacing: the distance must be 0 to 64 cells";
		}
	}
	return "";
}

struct LayerField {
	const char *name;
	void (*set)(PlacementLayer &, float);
};

bool on(float p_value) {
	return p_value != 0.0f;
}

int whole_number(float p_value) {
	return std::isfinite(p_value) && std::fabs(p_value) < 1e9f ? static_cast<int>(std::lround(p_value)) : -1;
}

// The row's columns: each name once, with where its number goes.
const LayerField LAYER_FIELDS[] = {
	{ "mode", [](PlacementLayer &l, float v) { l.mode = static_cast<PlacementLayer::Mode>(std::clamp(whole_number(v), 0, 2)); } },
	{ "species", [](PlacementLayer &l, float v) { l.species = whole_number(v); } },
	{ "density", [](PlacementLayer &l, float v) { l.density = v; } },
	{ "height_on", [](PlacementLayer &l, float v) { l.height.enabled = on(v); } },
	{ "height_low", [](PlacementLayer &l, float v) { l.height.low = v; } },
	{ "height_high", [](PlacementLayer &l, float v) { l.height.high = v; } },
	{ "height_falloff", [](PlacementLayer &l, float v) { l.height.falloff = v; } },
	{ "height_invert", [](PlacementLayer &l, float v) { l.height.invert = on(v); } },
	{ "slope_on", [](PlacementLayer &l, float v) { l.slope.enabled = on(v); } },
	{ "slope_low", [](PlacementLayer &l, float v) { l.slope.low = v; } },
	{ "slope_high", [](PlacementLayer &l, float v) { l.slope.high = v; } },
	{ "slope_falloff", [](PlacementLayer &l, float v) { l.slope.falloff = v; } },
	{ "slope_invert", [](PlacementLayer &l, float v) { l.slope.invert = on(v); } },
	{ "noise_on", [](PlacementLayer &l, float v) { l.noise.enabled = on(v); } },
	{ "noise_scale", [](PlacementLayer &l, float v) { l.noise.scale = v; } },
	{ "noise_octaves", [](PlacementLayer &l, float v) { l.noise.octaves = whole_number(v); } },
	{ "noise_threshold", [](PlacementLayer &l, float v) { l.noise.threshold = v; } },
	{ "noise_falloff", [](PlacementLayer &l, float v) { l.noise.falloff = v; } },
	{ "noise_seed", [](PlacementLayer &l, float v) { l.noise.seed = static_cast<uint32_t>(std::max(whole_number(v), 0)); } },
	{ "noise_invert", [](PlacementLayer &l, float v) { l.noise.invert = on(v); } },
	{ "mask_on", [](PlacementLayer &l, float v) { l.mask.enabled = on(v); } },
	{ "mask_width", [](PlacementLayer &l, float v) { l.mask.width = whole_number(v); } },
	{ "mask_height", [](PlacementLayer &l, float v) { l.mask.height = whole_number(v); } },
	{ "mask_x", [](PlacementLayer &l, float v) { l.mask.x = v; } },
	{ "mask_z", [](PlacementLayer &l, float v) { l.mask.z = v; } },
	{ "mask_size_x", [](PlacementLayer &l, float v) { l.mask.size_x = v; } },
	{ "mask_size_z", [](PlacementLayer &l, float v) { l.mask.size_z = v; } },
	{ "mask_outside", [](PlacementLayer &l, float v) { l.mask.outside = v; } },
	{ "mask_invert", [](PlacementLayer &l, float v) { l.mask.invert = on(v); } },
	{ "mask_channel", [](PlacementLayer &l, float v) { l.mask_channel = whole_number(v); } },
	{ "paths_on", [](PlacementLayer &l, float v) { l.paths.enabled = on(v); } },
	{ "paths_half_width", [](PlacementLayer &l, float v) { l.paths.half_width = v; } },
	{ "paths_falloff", [](PlacementLayer &l, float v) { l.paths.falloff = v; } },
	{ "paths_invert", [](PlacementLayer &l, float v) { l.paths.invert = on(v); } },
	{ "exclusion_on", [](PlacementLayer &l, float v) { l.exclusion.enabled = on(v); } },
	{ "exclusion_falloff", [](PlacementLayer &l, float v) { l.exclusion.falloff = v; } },
	{ "spacing_on", [](PlacementLayer &l, float v) { l.spacing.enabled = on(v); } },
	{ "spacing_layer", [](PlacementLayer &l, float v) { l.spacing.layer = whole_number(v); } },
	{ "spacing_distance", [](PlacementLayer &l, float v) { l.spacing.distance = v; } },
};

// Shapes from a list of (count, x, z, x, z, …); false when the list does not divide into them.
bool shapes_from(const std::vector<float> &p_list, std::vector<std::vector<float>> &r_shapes) {
	r_shapes.clear();
	size_t i = 0;
	while (i < p_list.size()) {
		const int count = whole_number(p_list[i]);
		if (count < 0 || i + 1 + 2 * static_cast<size_t>(count) > p_list.size()) {
			return false;
		}
		r_shapes.emplace_back(p_list.begin() + static_cast<std::ptrdiff_t>(i + 1),
				p_list.begin() + static_cast<std::ptrdiff_t>(i + 1 + 2 * static_cast<size_t>(count)));
		i += 1 + 2 * static_cast<size_t>(count);
	}
	return true;
}

} // namespace

std::vector<std::string> placement_layer_fields() {
	// Made on each call: a function-local static with a destructor would be destroyed at the
	// process's exit, after the engine has unloaded the library (a crash at quit).
	std::vector<std::string> names;
	for (const LayerField &field : LAYER_FIELDS) {
		names.emplace_back(field.name);
	}
	return names;
}

std::string placement_layer_from(const std::vector<float> &p_row, const std::vector<float> &p_lines,
		const std::vector<float> &p_footprints, const std::vector<uint8_t> &p_mask, PlacementLayer &r_layer) {
	constexpr size_t COUNT = sizeof(LAYER_FIELDS) / sizeof(LAYER_FIELDS[0]);
	if (p_row.size() != COUNT) {
		return "the layer's row has " + std::to_string(p_row.size()) + " numbers, not " + std::to_string(COUNT);
	}
	PlacementLayer layer;
	for (size_t i = 0; i < COUNT; i++) {
		LAYER_FIELDS[i].set(layer, p_row[i]);
	}
	if (!shapes_from(p_lines, layer.paths.lines)) {
		return "the paths' points do not divide into lines of (count, x, z, …)";
	}
	if (!shapes_from(p_footprints, layer.exclusion.footprints)) {
		return "the footprints' points do not divide into polygons of (count, x, z, …)";
	}
	const size_t pixels = layer.mask.width > 0 && layer.mask.height > 0
			? static_cast<size_t>(layer.mask.width) * static_cast<size_t>(layer.mask.height)
			: 0;
	if (layer.mask_channel >= 0 && layer.mask_channel < 4 && pixels > 0 && p_mask.size() == 4 * pixels) {
		layer.mask.values.resize(pixels);
		for (size_t i = 0; i < pixels; i++) {
			layer.mask.values[i] = p_mask[4 * i + static_cast<size_t>(layer.mask_channel)];
		}
	} else {
		layer.mask.values = p_mask;
	}
	r_layer = std::move(layer);
	return "";
}

float placement_noise(uint64_t p_seed, float p_x, float p_z, int p_octaves) {
	float sum = 0.0f;
	float weight = 1.0f;
	float total = 0.0f;
	float frequency = 1.0f;
	for (int octave = 0; octave < p_octaves; octave++) {
		sum += weight * value_noise(p_seed + static_cast<uint64_t>(octave), p_x * frequency, p_z * frequency);
		total += weight;
		weight *= 0.5f;
		frequency *= 2.0f;
	}
	return sum / total;
}

std::string check_placement(const PlacementRules &p_rules) {
	if (p_rules.columns < 1 || p_rules.rows < 1) {
		return "the field has no cells";
	}
	if (!finite(p_rules.cell_size) || p_rules.cell_size <= 0.0f) {
		return "the cell size must be above 0";
	}
	const size_t cells = static_cast<size_t>(p_rules.columns) * static_cast<size_t>(p_rules.rows);
	if (!p_rules.heights.empty()) {
		if (p_rules.heights.size() != cells) {
			return "the ground's heights are not one per cell";
		}
		const auto bad = std::find_if(p_rules.heights.begin(), p_rules.heights.end(), [](float h) { return !finite(h); });
		if (bad != p_rules.heights.end()) {
			const size_t at = static_cast<size_t>(bad - p_rules.heights.begin());
			return "the ground's height at cell " + std::to_string(at % static_cast<size_t>(p_rules.columns)) + ", " +
					std::to_string(at / static_cast<size_t>(p_rules.columns)) + " is not a finite number";
		}
	}
	if (p_rules.layers.size() > MAX_LAYERS) {
		return "more than " + std::to_string(MAX_LAYERS) + " layers";
	}
	for (size_t i = 0; i < p_rules.layers.size(); i++) {
		const std::string problem = check_layer(p_rules, i);
		if (!problem.empty()) {
			return "layer " + std::to_string(i + 1) + ": " + problem;
		}
	}
	return "";
}

bool generate_placement(const PlacementRules &p_rules, const CellRect &p_rect, WorkerPool *p_pool,
		std::vector<uint8_t> &r_cells, const std::atomic<bool> *p_cancel) {
	if (!check_placement(p_rules).empty() || !inside(p_rules, p_rect)) {
		return false;
	}
	// A cell's owner depends on the cells within the spacings' reach of it, through every layer
	// before: the layers run over the rectangle grown by all their reaches, so its cells come out as
	// in the whole field.
	std::vector<PreparedLayer> prepared;
	int margin = 0;
	for (size_t i = 0; i < p_rules.layers.size(); i++) {
		prepared.push_back(prepare(p_rules, i));
		margin += prepared.back().spacing_cells;
	}
	CellRect area;
	area.column = std::max(p_rect.column - margin, 0);
	area.row = std::max(p_rect.row - margin, 0);
	area.columns = std::min(p_rect.column + p_rect.columns + margin, p_rules.columns) - area.column;
	area.rows = std::min(p_rect.row + p_rect.rows + margin, p_rules.rows) - area.row;
	const size_t area_cells = static_cast<size_t>(area.columns) * static_cast<size_t>(area.rows);
	std::vector<uint8_t> before(area_cells, 0);
	std::vector<uint8_t> after(area_cells, 0);
	for (size_t i = 0; i < prepared.size(); i++) {
		after = before;
		const PreparedLayer &layer = prepared[i];
		const PlacementLayer::Mode mode = layer.layer->mode;
		auto row_task = [&](uint32_t p_row) {
			if (p_cancel && p_cancel->load(std::memory_order_relaxed)) {
				return;
			}
			const int row = area.row + static_cast<int>(p_row);
			for (int c = 0; c < area.columns; c++) {
				const size_t at = static_cast<size_t>(p_row) * static_cast<size_t>(area.columns) + static_cast<size_t>(c);
				if (mode == PlacementLayer::FILL && before[at] != 0) {
					continue;
				}
				if (mode == PlacementLayer::ERASE && before[at] == 0) {
					continue;
				}
				if (takes(p_rules, layer, i, area.column + c, row, before, area)) {
					after[at] = mode == PlacementLayer::ERASE ? 0 : static_cast<uint8_t>(i + 1);
				}
			}
		};
		if (p_pool) {
			p_pool->run(static_cast<uint32_t>(area.rows), row_task);
		} else {
			for (int r = 0; r < area.rows; r++) {
				row_task(static_cast<uint32_t>(r));
			}
		}
		if (p_cancel && p_cancel->load()) {
			return false;
		}
		std::swap(before, after);
	}
	r_cells.assign(static_cast<size_t>(p_rect.columns) * static_cast<size_t>(p_rect.rows), 0);
	for (int r = 0; r < p_rect.rows; r++) {
		const size_t from = static_cast<size_t>(p_rect.row + r - area.row) * static_cast<size_t>(area.columns) +
				static_cast<size_t>(p_rect.column - area.column);
		for (int c = 0; c < p_rect.columns; c++) {
			const uint8_t owner = before[from + static_cast<size_t>(c)];
			r_cells[static_cast<size_t>(r) * static_cast<size_t>(p_rect.columns) + static_cast<size_t>(c)] =
					owner == 0 ? 0 : static_cast<uint8_t>(p_rules.layers[owner - 1].species + 1);
		}
	}
	return true;
}

bool placement_layer_weights(const PlacementRules &p_rules, size_t p_layer, const CellRect &p_rect,
		const std::vector<uint8_t> &p_map, std::vector<float> &r_weights) {
	if (p_layer >= p_rules.layers.size() || !check_placement(p_rules).empty() || !inside(p_rules, p_rect)) {
		return false;
	}
	const PreparedLayer prepared = prepare(p_rules, p_layer);
	const PlacementLayer &layer = p_rules.layers[p_layer];
	const CellRect whole{ 0, 0, p_rules.columns, p_rules.rows };
	const bool spacing = layer.spacing.enabled &&
			p_map.size() == static_cast<size_t>(p_rules.columns) * static_cast<size_t>(p_rules.rows);
	const uint8_t other = spacing ? static_cast<uint8_t>(p_rules.layers[static_cast<size_t>(layer.spacing.layer)].species + 1) : 0;
	r_weights.assign(static_cast<size_t>(p_rect.columns) * static_cast<size_t>(p_rect.rows), 0.0f);
	for (int r = 0; r < p_rect.rows; r++) {
		for (int c = 0; c < p_rect.columns; c++) {
			const int column = p_rect.column + c;
			const int row = p_rect.row + r;
			if (spacing && spaced_out(p_rules, prepared, column, row, other, p_map, whole)) {
				continue;
			}
			r_weights[static_cast<size_t>(r) * static_cast<size_t>(p_rect.columns) + static_cast<size_t>(c)] =
					filtered_chance(p_rules, prepared, column, row, 1.0f, -1.0f);
		}
	}
	return true;
}

std::vector<uint8_t> keep_hand_edits(const std::vector<uint8_t> &p_generated_before,
		const std::vector<uint8_t> &p_edited, const std::vector<uint8_t> &p_generated_now) {
	std::vector<uint8_t> result(p_generated_now);
	const size_t n = std::min({ p_generated_before.size(), p_edited.size(), p_generated_now.size() });
	for (size_t i = 0; i < n; i++) {
		if (p_edited[i] != p_generated_before[i]) {
			result[i] = p_edited[i];
		}
	}
	return result;
}

} // namespace sunflower
