#include "lod_selector.h"

#include <algorithm>
#include <limits>

namespace sunflower {

void LodSelector::configure(const LodParams &p_params) {
	const LodParams previous = _params;
	_params = p_params;
	if (!check_lod_distances(p_params.distances.data(), p_params.distances.size()).empty()) {
		_params.distances = previous.distances;
	}
	_params.hysteresis = sanitize(param::LOD_HYSTERESIS, p_params.hysteresis, previous.hysteresis);
	_params.interval = sanitize(param::LOD_INTERVAL, p_params.interval, previous.interval);
	_params.fade = sanitize(param::LOD_FADE, p_params.fade, previous.fade);
	_params.force_level = int(sanitize(param::FORCE_LOD, double(p_params.force_level), double(previous.force_level)));
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
