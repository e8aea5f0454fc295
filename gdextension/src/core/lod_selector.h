#pragma once
// Five discrete levels of detail chosen by distance (thesis 3.2, Tab. 1), compared squared,
// with a hysteresis margin on every threshold so plants near a threshold do not flicker.
#include "parameters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace sunflower {

enum Lod : uint8_t {
	LOD_MESH_1 = 0,
	LOD_MESH_2 = 1,
	LOD_MESH_3 = 2,
	LOD_SPRITE = 3,
	LOD_BILLBOARD = 4,
	LOD_COUNT = 5,
	LOD_MESH_COUNT = 3,
};

struct LodParams {
	// Switch distances in metres: mesh 1→2, 2→3, 3→sprite, sprite→billboard (thesis: 6/10/20/25).
	std::array<float, 4> distances{ { 6.0f, 10.0f, 20.0f, 25.0f } };
	// Metres: switch to less detail this much later, to more detail this much earlier.
	float hysteresis = float(param::LOD_HYSTERESIS.default_value);
	float interval = float(param::LOD_INTERVAL.default_value); // seconds between LOD updates (thesis 3.3.2)
	float fade = float(param::LOD_FADE.default_value); // metres of mesh 3 → impostor cross-fade
	// 0–4: draw every plant in this representation (benchmarks, debugging); -1: by distance.
	int force_level = int(param::FORCE_LOD.default_value);

	// Sets the SunflowerField row p_spec of the levels of detail from its values
	// (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, const float *p_values);
};

class LodSelector {
public:
	// Takes the parameters the param:: rules accept; distances that fail check_lod_distances() keep
	// the current ones.
	void configure(const LodParams &p_params);
	// p_params by the param:: rules, values they refuse kept from p_current.
	static LodParams sanitized(const LodParams &p_params, const LodParams &p_current);
	const LodParams &get_params() const { return _params; }

	// The level for a plant first seen at squared distance p_distance_sq (no history).
	uint8_t select(float p_distance_sq) const;
	// The level for a plant that was at p_current: hysteresis applies.
	uint8_t update(uint8_t p_current, float p_distance_sq) const;
	// How much of a plant at the finer level of switch p_switch (0: mesh 1 → 2, 1: mesh 2 → 3,
	// 2: mesh 3 → impostor) at squared distance p_distance_sq the coarser level draws, 0–1: the
	// cross-fade ends at the switch distance less the hysteresis, so a plant on either side of the
	// switch looks the same whichever level it is at. It runs over `fade` metres before the sprite
	// switch, and over a share of it as large as the switch distance's share of the sprite
	// switch's before the mesh switches (1.5 m at 10 m with the defaults).
	float fade_share(uint32_t p_switch, float p_distance_sq) const {
		if (p_distance_sq <= _fade_start_sq[p_switch]) {
			return 0.0f;
		}
		return std::min(1.0f, (std::sqrt(p_distance_sq) - _fade_start[p_switch]) / _fade_length[p_switch]);
	}
	// The mesh 3 → impostor share (fade_share(2, …)).
	float impostor_share(float p_distance_sq) const { return fade_share(2, p_distance_sq); }

private:
	LodParams _params;
	std::array<float, 4> _plain_sq{};
	std::array<float, 4> _coarser_sq{}; // (d + margin)²: leave level i for i + 1 beyond this
	std::array<float, 4> _finer_sq{}; // (d - margin)²: leave level i + 1 for i below this
	// Per switch (mesh 1 → 2, 2 → 3, 3 → impostor): metres where the finer level starts to dither
	// into the coarser, over how many metres; the start squared is infinite without a fade.
	std::array<float, 3> _fade_start{};
	std::array<float, 3> _fade_length{};
	std::array<float, 3> _fade_start_sq{};
};

} // namespace sunflower
