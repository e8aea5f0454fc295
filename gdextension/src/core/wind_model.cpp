#include "wind_model.h"

#include "random_hash.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sunflower {

namespace {

// Rotation about a horizontal unit axis (a.x, 0, a.z) by p_angle (Rodrigues' formula).
glm::mat3 rotation_about_horizontal(const glm::vec2 &p_axis, float p_angle) {
	const float c = std::cos(p_angle);
	const float s = std::sin(p_angle);
	const float t = 1.0f - c;
	const float x = p_axis.x;
	const float z = p_axis.y;
	// Columns of R = c·I + s·[a]× + t·a·aᵀ with a = (x, 0, z).
	return glm::mat3(glm::vec3(c + t * x * x, s * z, t * x * z), // image of +x
			glm::vec3(-s * z, c, s * x), // image of +y
			glm::vec3(t * x * z, -s * x, c + t * z * z)); // image of +z
}

glm::mat3 yaw_scale(float p_yaw, float p_scale_xz, float p_scale_y) {
	const float c = std::cos(p_yaw);
	const float s = std::sin(p_yaw);
	return glm::mat3(glm::vec3(c, 0.0f, -s) * p_scale_xz, glm::vec3(0.0f, p_scale_y, 0.0f),
			glm::vec3(s, 0.0f, c) * p_scale_xz);
}

} // namespace

void WindModel::configure(const WindParams &p_params) {
	_params = p_params;
	_params.power = sanitize(param::WIND_POWER, p_params.power, _params.power);
	_params.direction = sanitize_wind_direction(p_params.direction);
	_params.d1 = sanitize(param::WIND_STIFFNESS_MIDDLE, p_params.d1, _params.d1);
	_params.d2 = sanitize(param::WIND_STIFFNESS_BOTTOM, p_params.d2, _params.d2);
	_params.h = sanitize(param::WIND_BEND_PER_POWER, p_params.h, _params.h);
	_params.max_bend = sanitize(param::WIND_MAX_BEND, p_params.max_bend, _params.max_bend);
	_params.flip_interval = sanitize(param::WIND_FLIP_INTERVAL, p_params.flip_interval, _params.flip_interval);
	_params.flip_chance = sanitize(param::WIND_FLIP_CHANCE, p_params.flip_chance, _params.flip_chance);
	_params.gust_speed = sanitize(param::WIND_GUST_SPEED, p_params.gust_speed, _params.gust_speed);
	_params.gust_share = sanitize(param::WIND_GUST_SHARE, p_params.gust_share, _params.gust_share);

	const float p_w = _params.power;
	_rate = (p_w <= 1.0f ? p_w : p_w / 20.0f + 1.0f) * PI; // eq. 6
	_lean = glm::normalize(_params.direction);
	_bend_limit = _params.max_bend / (1.0f / _params.d1 + 1.0f / _params.d2);
}

float WindModel::flip_offset(uint64_t p_seed, uint32_t p_plant) const {
	return unit_float(hash_plant(p_seed, p_plant, STREAM_FLIP_OFFSET)) * _params.flip_interval;
}

void WindModel::init_plant(PlantWind &r_wind, uint64_t p_seed, uint32_t p_plant, double p_time) const {
	r_wind.phase = unit_float(hash_plant(p_seed, p_plant, STREAM_PHASE)) * TAU;
	r_wind.direction = (hash_plant(p_seed, p_plant, STREAM_DIRECTION) & 1u) ? int8_t(1) : int8_t(-1);
	const double since = p_time - double(flip_offset(p_seed, p_plant));
	r_wind.next_flip = since < 0.0 ? 0u : static_cast<uint32_t>(std::floor(since / _params.flip_interval)) + 1u;
}

void WindModel::advance_plant(PlantWind &r_wind, uint64_t p_seed, uint32_t p_plant, double p_time, float p_delta) const {
	const double offset = double(flip_offset(p_seed, p_plant));
	while (offset + double(r_wind.next_flip) * double(_params.flip_interval) <= p_time) {
		if (unit_float(hash_plant(p_seed, p_plant, STREAM_FLIP, r_wind.next_flip)) < _params.flip_chance) {
			r_wind.direction = int8_t(-r_wind.direction);
		}
		++r_wind.next_flip;
	}
	float phase = r_wind.phase + float(r_wind.direction) * _rate * p_delta;
	if (phase < 0.0f) {
		phase = -phase; // φ never goes negative: turn back with b = +1
		r_wind.direction = 1;
	}
	phase = std::fmod(phase, TAU);
	r_wind.phase = phase;
}

float WindModel::bend(const PlantWind &p_wind, float p_downwind, float p_gust_phase) const {
	float sway = std::sin(p_wind.phase);
	if (_params.gust_share > 0.0f && _params.gust_speed > 0.0f) {
		// The gust phase the plant sees is the field's phase s/c seconds ago (steady wind: Ψ − ω·s/c).
		const float delayed = p_gust_phase - _rate * p_downwind / _params.gust_speed;
		sway = (1.0f - _params.gust_share) * sway + _params.gust_share * std::sin(delayed);
	}
	const float p = _params.power * _params.h * sway; // eq. 5
	return std::clamp(p, -_bend_limit, _bend_limit);
}

void WindModel::part_transforms(const Plant &p_plant, float p_bend, float p_part_scale, PartTransforms &r_parts) const {
	// The plant rotates about the horizontal axis perpendicular to the lean: (w_x, w_z) = (lean.z, −lean.x).
	const glm::vec2 axis(_lean.y, -_lean.x);
	const glm::mat3 bottom_tilt = rotation_about_horizontal(axis, p_bend / _params.d2);
	const glm::mat3 upper_tilt = rotation_about_horizontal(axis, p_bend / _params.d1);
	const float middle_height = 1.0f + p_plant.alpha / 10.0f; // s' = s + α/10

	const glm::mat3 shape = yaw_scale(p_plant.yaw, p_part_scale, p_part_scale);
	const glm::mat3 middle_shape = yaw_scale(p_plant.yaw, p_part_scale, p_part_scale * middle_height);

	r_parts.basis[0] = bottom_tilt * shape;
	r_parts.origin[0] = glm::vec3(p_plant.position.x, 0.0f, p_plant.position.y);
	r_parts.basis[1] = upper_tilt * middle_shape;
	r_parts.origin[1] = r_parts.origin[0] + r_parts.basis[0][1]; // the bottom part's tip: M·(0, 1, 0)
	r_parts.basis[2] = upper_tilt * shape;
	r_parts.origin[2] = r_parts.origin[1] + r_parts.basis[1][1];
}

} // namespace sunflower
