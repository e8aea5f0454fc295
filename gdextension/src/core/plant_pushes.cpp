#include "plant_pushes.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace sunflower {

void PlantPushes::set_params(float p_strength, float p_recovery_seconds) {
	_strength = sanitize(param::PUSH_STRENGTH, p_strength, _strength);
	_recovery = sanitize(param::PUSH_RECOVERY, p_recovery_seconds, _recovery);
}

RowSet PlantPushes::set(const ParameterSpec &p_spec, float p_value) {
	static constexpr FloatRow<PlantPushes> ROWS[] = { { &param::PUSH_STRENGTH, &PlantPushes::_strength },
		{ &param::PUSH_RECOVERY, &PlantPushes::_recovery } };
	return set_float_row(*this, ROWS, p_spec, p_value);
}

void PlantPushes::drop_chunk(uint32_t p_chunk, const FieldLayout &p_layout, const WindOf &p_wind_of) {
	for (size_t i = 0; i < _pushed.size();) {
		if (p_layout.plants[_pushed[i].plant].chunk != p_chunk) {
			++i;
			continue;
		}
		if (i + 1 < _pushed.size()) {
			_pushed[i] = _pushed.back(); // looked at next: dropped too if it is the chunk's
			if (p_layout.plants[_pushed[i].plant].chunk != p_chunk) {
				p_wind_of(_pushed[i].plant)->push_slot = static_cast<uint16_t>(i + 1);
			}
		}
		_pushed.pop_back();
	}
}

void PlantPushes::drop_plants_from(uint32_t p_first, const WindOf &p_wind_of) {
	size_t kept = 0;
	for (size_t i = 0; i < _pushed.size(); ++i) {
		if (_pushed[i].plant >= p_first) {
			continue;
		}
		if (kept != i) {
			_pushed[kept] = _pushed[i];
			p_wind_of(_pushed[kept].plant)->push_slot = static_cast<uint16_t>(kept + 1);
		}
		++kept;
	}
	_pushed.resize(kept);
}

void PlantPushes::update(float p_delta, const FieldPlants &p_plants, const WindOf &p_wind_of) {
	const FieldLayout &layout = p_plants.get_layout();
	if (_pushers.empty() && _pushed.empty()) {
		return;
	}
	for (PushState &state : _pushed) {
		state.target = glm::vec2(0.0f);
	}
	for (const Pusher &pusher : _pushers) {
		if (!(pusher.radius > 0.0f)) {
			continue;
		}
		const glm::vec2 center(pusher.position.x, pusher.position.z);
		_near.clear();
		p_plants.find_plants_near(center, pusher.radius, _near);
		for (uint32_t index : _near) {
			const Plant &plant = layout.plants[index];
			const float above_root = pusher.position.y - plant.ground;
			const PlantShape &shape = p_plants.get_shape(p_plants.species_of(plant));
			if (above_root - pusher.radius > shape.height * shape.part_scale * plant.scale || above_root + pusher.radius < 0.0f) {
				continue; // flying over the plant, or under its ground
			}
			PlantWind *const state = p_wind_of(index);
			if (state == nullptr) {
				continue; // not near: drawn as an impostor, which shows no push
			}
			PlantWind &wind = *state;
			if (wind.push_slot == 0) {
				if (_pushed.size() >= 0xFFFFu) {
					continue; // more than 65 535 plants pushed at once: the rest stay as they are
				}
				_pushed.push_back(PushState{ index, glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f) });
				wind.push_slot = static_cast<uint16_t>(_pushed.size());
			}
			const glm::vec2 away = layout.plants[index].position - center;
			const float distance = glm::length(away);
			const glm::vec2 direction = distance > 1e-4f ? away / distance : glm::vec2(1.0f, 0.0f);
			_pushed[wind.push_slot - 1u].target += direction * (_strength * (1.0f - distance / pusher.radius));
		}
	}
	// Critically damped springs towards the targets, solved exactly (stable for any frame time):
	// with e = offset − target, e(t) = (e₀ + (v₀ + ω·e₀)·t)·e^(−ω·t). ω makes a released plant settle
	// to 0.1 % of its push ((1 + 9.2)·e^(−9.2)) in the recovery time, when its state is dropped.
	const float omega = 9.2f / _recovery;
	const float decay = std::exp(-omega * p_delta);
	for (size_t i = 0; i < _pushed.size();) {
		PushState &state = _pushed[i];
		const glm::vec2 e0 = state.offset - state.target;
		const glm::vec2 v0 = state.velocity;
		const glm::vec2 c = v0 + omega * e0;
		state.offset = state.target + (e0 + c * p_delta) * decay;
		state.velocity = (v0 - omega * c * p_delta) * decay;
		const bool settled = state.target == glm::vec2(0.0f) && glm::dot(state.offset, state.offset) < 4e-6f &&
				glm::dot(state.velocity, state.velocity) < 4e-4f;
		if (!settled) {
			++i;
			continue;
		}
		p_wind_of(state.plant)->push_slot = 0;
		if (i + 1 < _pushed.size()) {
			state = _pushed.back();
			p_wind_of(state.plant)->push_slot = static_cast<uint16_t>(i + 1);
		}
		_pushed.pop_back();
	}
}

size_t PlantPushes::get_memory_bytes() const {
	return _pushed.capacity() * sizeof(PushState) + _pushers.capacity() * sizeof(Pusher) + _near.capacity() * sizeof(uint32_t);
}

} // namespace sunflower
