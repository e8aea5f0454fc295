#include "lod_selector.h"

#include <algorithm>
#include <limits>

namespace sunflower {

namespace {

// The levels' settings of one float each, by their table rows.
constexpr FloatRow<LodParams> LOD_ROWS[] = { { &param::LOD_HYSTERESIS, &LodParams::hysteresis },
	{ &param::LOD_INTERVAL, &LodParams::interval }, { &param::LOD_FADE, &LodParams::fade } };

} // namespace

RowSet LodParams::set(const ParameterSpec &p_spec, const float *p_values) {
	if (&p_spec == &param::FORCE_LOD) {
		return set_row_value(force_level, p_spec, double(p_values[0]));
	}
	if (&p_spec == &param::LOD_DISTANCES) {
		if (!check_lod_distances(p_values, distances.size()).empty() || std::equal(distances.begin(), distances.end(), p_values)) {
			return RowSet::SAME; // distances that fail the check keep the current ones
		}
		std::copy_n(p_values, distances.size(), distances.begin());
		return RowSet::CHANGED;
	}
	return set_float_row(*this, LOD_ROWS, p_spec, p_values[0]);
}

LodParams LodSelector::sanitized(const LodParams &p_params, const LodParams &p_current) {
	LodParams params = p_params;
	if (!check_lod_distances(p_params.distances.data(), p_params.distances.size()).empty()) {
		params.distances = p_current.distances;
	}
	for (const FloatRow<LodParams> &row : LOD_ROWS) {
		params.*row.member = sanitize(*row.spec, p_params.*row.member, p_current.*row.member);
	}
	params.force_level = int(sanitize(param::FORCE_LOD, double(p_params.force_level), double(p_current.force_level)));
	return params;
}

void LodSelector::configure(const LodParams &p_params) {
	_params = sanitized(p_params, _params);
	for (size_t i = 0; i < 4; ++i) {
		const float d = _params.distances[i];
		const float finer = std::max(0.0f, d - _params.hysteresis);
		_plain_sq[i] = d * d;
		_coarser_sq[i] = (d + _params.hysteresis) * (d + _params.hysteresis);
		_finer_sq[i] = finer * finer;
	}
	for (size_t i = 0; i < 3; ++i) {
		const float fade_end = std::max(0.0f, _params.distances[i] - _params.hysteresis);
		_fade_length[i] = _params.fade * _params.distances[i] / _params.distances[2];
		_fade_start[i] = std::max(0.0f, fade_end - _fade_length[i]);
		_fade_start_sq[i] = _fade_length[i] > 0.0f ? _fade_start[i] * _fade_start[i] : std::numeric_limits<float>::infinity();
	}
}

uint8_t LodSelector::select(float p_distance_sq) const {
	uint8_t level = 0;
	while (level < 4 && p_distance_sq >= _plain_sq[level]) {
		++level;
	}
	return level;
}

uint8_t LodSelector::update(uint8_t p_current, float p_distance_sq) const {
	uint8_t level = std::min<uint8_t>(p_current, LOD_BILLBOARD);
	while (level < 4 && p_distance_sq >= _coarser_sq[level]) {
		++level;
	}
	while (level > 0 && p_distance_sq < _finer_sq[level - 1]) {
		--level;
	}
	return level;
}

} // namespace sunflower
