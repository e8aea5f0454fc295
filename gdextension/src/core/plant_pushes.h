#pragma once
// Bodies the plants part around. A plant within a pusher's radius bends away from its centre (whole
// plant from the ground, the bottom part most, like a stalk) by up to the push strength (a bend, as
// the wind's), added to the wind's; once free it springs back, critically damped, settling within
// the recovery time. Only plants being pushed or springing back hold any state (a slot here, named by
// their PlantWind::push_slot), so a field without pushers costs nothing. Only plants of active chunks
// (those with a wind state: near_field.h) are pushed; impostors show no push.
#include "field_plants.h"
#include "parameters.h"
#include "wind_model.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace sunflower {

// A body that plants part around: a point in the field's space and the radius it reaches.
struct Pusher {
	glm::vec3 position{ 0.0f };
	float radius = float(param::PUSHER_RADIUS.default_value);
};

class PlantPushes {
public:
	// The wind state of a plant of an active chunk, nullptr for any other plant.
	using WindOf = std::function<PlantWind *(uint32_t p_plant)>;

	// Bodies from the next update on.
	void set_pushers(const Pusher *p_pushers, size_t p_count) { _pushers.assign(p_pushers, p_pushers + p_count); }
	const std::vector<Pusher> &get_pushers() const { return _pushers; }
	// Invalid values keep the current ones (param::PUSH_STRENGTH, param::PUSH_RECOVERY).
	void set_params(float p_strength, float p_recovery_seconds);
	// Sets the SunflowerField row p_spec of the pushes (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, float p_value);
	// Plants pushed now or springing back.
	uint32_t get_pushed_count() const { return static_cast<uint32_t>(_pushed.size()); }
	// The push's bend of a plant now (zero when it is not pushed).
	glm::vec2 get_offset(const PlantWind &p_wind) const {
		return p_wind.push_slot == 0 ? glm::vec2(0.0f) : _pushed[p_wind.push_slot - 1u].offset;
	}

	// One frame: the pushers' targets, then every pushed plant's spring; settled plants let go.
	void update(float p_delta, const FieldPlants &p_plants, const WindOf &p_wind_of);
	// Lets go of a chunk's plants (it turns inactive: their wind states go).
	void drop_chunk(uint32_t p_chunk, const FieldLayout &p_layout, const WindOf &p_wind_of);
	// Lets go of every plant of index p_first or above (the plants play added: their chunks are made
	// anew, their wind states go), whatever chunk they are in now.
	void drop_plants_from(uint32_t p_first, const WindOf &p_wind_of);
	// Lets go of every plant, without touching their wind states (the layout was rebuilt).
	void clear() { _pushed.clear(); }

	size_t get_memory_bytes() const;

private:
	struct PushState {
		uint32_t plant = 0;
		glm::vec2 offset{ 0.0f }; // the push's bend now
		glm::vec2 velocity{ 0.0f };
		glm::vec2 target{ 0.0f }; // where the pushers want it this frame
	};

	std::vector<Pusher> _pushers;
	std::vector<PushState> _pushed; // PlantWind::push_slot - 1 indexes this
	std::vector<uint32_t> _near; // scratch
	float _strength = float(param::PUSH_STRENGTH.default_value);
	float _recovery = float(param::PUSH_RECOVERY.default_value);
};

} // namespace sunflower
