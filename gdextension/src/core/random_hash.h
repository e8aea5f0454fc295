#pragma once
// Deterministic per-plant randomness: a counter-based hash, so every value depends only on
// (seed, plant, stream, step) and never on the order in which plants are visited.
#include <cstdint>

namespace sunflower {

constexpr uint64_t mix64(uint64_t p_x) {
	p_x += 0x9E3779B97F4A7C15ull;
	p_x = (p_x ^ (p_x >> 30)) * 0xBF58476D1CE4E5B9ull;
	p_x = (p_x ^ (p_x >> 27)) * 0x94D049BB133111EBull;
	return p_x ^ (p_x >> 31);
}

constexpr uint64_t hash_plant(uint64_t p_seed, uint64_t p_plant, uint64_t p_stream, uint64_t p_step = 0) {
	return mix64(mix64(mix64(p_seed ^ (p_stream << 56)) ^ p_plant) ^ p_step);
}

// A float uniformly distributed in [0, 1).
constexpr float unit_float(uint64_t p_hash) {
	return static_cast<float>(p_hash >> 40) * (1.0f / 16777216.0f);
}

enum RandomStream : uint64_t {
	STREAM_ALPHA = 1,
	STREAM_ALPHA_Z = 2,
	STREAM_YAW = 3,
	STREAM_PHASE = 4,
	STREAM_FLIP_OFFSET = 5,
	STREAM_FLIP = 6,
	STREAM_DIRECTION = 7,
	STREAM_SCALE = 8,
	STREAM_COLOR = 9,
	STREAM_PAINT = 10,
	STREAM_TILE_LEVEL = 11,
	STREAM_PLACEMENT = 12,
};

} // namespace sunflower
