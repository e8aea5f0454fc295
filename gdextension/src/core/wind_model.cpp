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

// Natural wind's per-plant hash, of where the plant stands (a 1/64 m grid): cheap, as it runs for
// every near plant every frame, and in 32-bit integer steps the impostor shader repeats exactly.
// Its low 16 bits set the plant's phase offset, its high 16 bits its pace.
uint32_t natural_hash(const glm::vec2 &p_position) {
	const uint32_t x = uint32_t(int32_t(std::floor(p_position.x * 64.0f)));
	const uint32_t z = uint32_t(int32_t(std::floor(p_position.y * 64.0f)));
	uint32_t h = x * 0x8da6b343u ^ z * 0xd8163841u;
	h ^= h >> 16;
	h *= 0x7feb352du;
	h ^= h >> 15;
	return h;
}

// A smooth saturation like tanh, cheaper: the Padé form x(27 + x²)/(27 + 9x²), which reaches ±1 at
// |x| = 3 with zero slope, and ±1 beyond. Monotone, odd, slope 1 at 0.
float soft_clip(float p_x) {
	const float x = std::clamp(p_x, -3.0f, 3.0f);
	return x * (27.0f + x * x) / (27.0f + 9.0f * x * x);
}

glm::mat3 yaw_scale(float p_yaw, float p_scale_xz, float p_scale_y) {
	const float c = std::cos(p_yaw);
	const float s = std::sin(p_yaw);
	return glm::mat3(glm::vec3(c, 0.0f, -s) * p_scale_xz, glm::vec3(0.0f, p_scale_y, 0.0f),
			glm::vec3(s, 0.0f, c) * p_scale_xz);
}

} // namespace

glm::mat3 lean_rotation(const glm::vec2 &p_lean) {
	const float size = std::min(glm::length(p_lean), 1.0f);
	if (!(size > 1e-9f)) {
		return glm::mat3(1.0f);
	}
	return rotation_about_horizontal(glm::vec2(p_lean.y, -p_lean.x) / glm::length(p_lean), std::asin(size));
}

// Natural wind: the size of a gust cell on the ground, metres.
constexpr float GUST_CELL = 8.0f;

// The wind's settings of one float each, by their table rows (set and configure apply their rules).
constexpr FloatRow<WindParams> WIND_ROWS[] = { { &param::WIND_POWER, &WindParams::power },
	{ &param::WIND_STIFFNESS_MIDDLE, &WindParams::d1 }, { &param::WIND_STIFFNESS_BOTTOM, &WindParams::d2 },
	{ &param::WIND_BEND_PER_POWER, &WindParams::h }, { &param::WIND_MAX_BEND, &WindParams::max_bend },
	{ &param::WIND_FLIP_INTERVAL, &WindParams::flip_interval }, { &param::WIND_FLIP_CHANCE, &WindParams::flip_chance },
	{ &param::WIND_GUST_SPEED, &WindParams::gust_speed }, { &param::WIND_GUST_SHARE, &WindParams::gust_share },
	{ &param::WIND_EASE_TIME, &WindParams::ease_time } };

RowSet WindParams::set(const ParameterSpec &p_spec, const float *p_values) {
	if (&p_spec == &param::WIND_MODEL) {
		return set_row_value(model, p_spec, double(p_values[0]));
	}
	if (&p_spec == &param::WIND_DIRECTION) {
		const glm::vec2 value = sanitize_wind_direction(glm::vec2(p_values[0], p_values[1]));
		const bool changed = value != direction;
		direction = value;
		return changed ? RowSet::CHANGED : RowSet::SAME;
	}
	return set_float_row(*this, WIND_ROWS, p_spec, p_values[0]);
}

void WindModel::configure(const WindParams &p_params) {
	const WindParams previous = _params;
	_params = p_params;
	_params.model = int(sanitize(param::WIND_MODEL, double(p_params.model), double(previous.model)));
	_params.direction = sanitize_wind_direction(p_params.direction);
	for (const FloatRow<WindParams> &row : WIND_ROWS) {
		_params.*row.member = sanitize(*row.spec, p_params.*row.member, previous.*row.member);
	}
	_bend_limit = _params.max_bend / (1.0f / _params.d1 + 1.0f / _params.d2);
	if (_params.model == WIND_THESIS || !_advanced) {
		// The thesis' wind changes at once; natural wind starts where it is configured before it moves.
		_power = _params.power;
		_lean = glm::normalize(_params.direction);
	}
	// Natural wind eases a change in at a steady rate that takes ease_time (0: at once).
	const glm::vec2 target = glm::normalize(_params.direction);
	const float ease = std::max(_params.ease_time, 1e-6f);
	_power_rate = std::abs(_params.power - _power) / ease;
	_turn_rate = std::abs(std::remainder(std::atan2(target.y, target.x) - std::atan2(_lean.y, _lean.x), TAU)) / ease;
	_derive();
}

void WindModel::_derive() {
	const float p_w = _power;
	_rate = (p_w <= 1.0f ? p_w : p_w / 20.0f + 1.0f) * PI; // eq. 6
	_amplitude = _bend_limit > 0.0f ? _bend_limit * (1.0f - std::exp(-p_w * _params.h / _bend_limit)) : 0.0f;
}

void WindModel::advance(float p_delta) {
	_advanced = true;
	if (_params.model == WIND_THESIS) {
		_gust_phase = std::fmod(_gust_phase + _rate * p_delta, TAU);
		return;
	}
	const float step = _power_rate * p_delta;
	_power = std::abs(_params.power - _power) <= step ? _params.power : _power + std::copysign(step, _params.power - _power);
	const float now = std::atan2(_lean.y, _lean.x);
	const glm::vec2 target = glm::normalize(_params.direction);
	const float turn = std::remainder(std::atan2(target.y, target.x) - now, TAU); // the shorter way round
	const float turn_step = _turn_rate * p_delta;
	_lean = std::abs(turn) <= turn_step ? target
										: glm::vec2(std::cos(now + std::copysign(turn_step, turn)), std::sin(now + std::copysign(turn_step, turn)));
	_derive();
	_sway = std::fmod(_sway + double(_rate) * double(p_delta), double(TAU) * PACE_STEPS);
	for (uint32_t m = 0; m < PACE_SPAN; ++m) {
		_pace_phase[m] = float(std::fmod(double(PACE_LOW + m) * _sway / PACE_STEPS, double(TAU)));
	}
	// Gusts travel with the wind (p_w ≈ m/s). Kept in cells, wrapped every 2^16 cells (524 km) so a
	// float keeps its precision; the lattice hash repeats there too, so the wrap is seamless.
	_gust_scroll_cells = float(std::fmod(double(_gust_scroll_cells) + double(_power) * double(p_delta) / double(GUST_CELL), 65536.0));
}

float WindModel::gust_strength(const glm::vec2 &p_position) const {
	if (_params.model == WIND_THESIS) {
		return 0.0f;
	}
	// Smooth value noise over (downwind, crosswind) cells, scrolled downwind.
	constexpr float PER_CELL = 1.0f / GUST_CELL;
	const float u = downwind(p_position) * PER_CELL - _gust_scroll_cells;
	const float v = (p_position.y * _lean.x - p_position.x * _lean.y) * PER_CELL;
	const float fu = std::floor(u);
	const float fv = std::floor(v);
	const auto corner = [](int32_t p_u, int32_t p_v) {
		// A cheap 32-bit lattice hash: it runs four times per near plant per frame.
		uint32_t h = uint32_t(p_u) * 0x27d4eb2du ^ uint32_t(p_v) * 0x165667b1u;
		h ^= h >> 15;
		h *= 0x2c1b3c6du;
		h ^= h >> 12;
		return float(h >> 8) * (1.0f / 16777216.0f);
	};
	const int32_t iu = int32_t(fu);
	const int32_t iv = int32_t(fv);
	const float a = corner(iu, iv);
	const float b = corner(iu + 1, iv);
	const float c = corner(iu, iv + 1);
	const float d = corner(iu + 1, iv + 1);
	const float tu = (u - fu) * (u - fu) * (3.0f - 2.0f * (u - fu)); // smoothstep
	const float tv = (v - fv) * (v - fv) * (3.0f - 2.0f * (v - fv));
	const float top = a + (b - a) * tu;
	const float bottom = c + (d - c) * tu;
	return top + (bottom - top) * tv;
}

glm::vec2 WindModel::bend_vector(const PlantWind &p_wind, const glm::vec2 &p_position) const {
	if (_params.model == WIND_THESIS) {
		return bend(p_wind, downwind(p_position), _gust_phase) * _lean;
	}
	if (_bend_limit <= 0.0f) {
		return glm::vec2(0.0f);
	}
	const float gust = _params.gust_share * 0.5f * _amplitude * gust_strength(p_position);
	const float lean = 0.55f * _amplitude + 0.35f * _amplitude * std::sin(sway_phase(p_position)) + gust;
	return _bend_limit * soft_clip(lean / _bend_limit) * _lean;
}

float WindModel::sway_phase(const glm::vec2 &p_position) const {
	const uint32_t h = natural_hash(p_position);
	const float offset = float(h & 0xFFFFu) * (TAU / 65536.0f);
	// φ₀ + (m / PACE_STEPS)·Φ, wrapped: m·(Φ / PACE_STEPS) is exact to float precision at any Φ.
	return offset + _pace_phase[(h >> 16) % PACE_SPAN];
}

WindModel::ShaderState WindModel::shader_state() const {
	ShaderState state;
	state.lean = _lean;
	state.amplitude = _amplitude;
	state.bend_limit = _bend_limit;
	state.gust_share = _params.gust_share;
	state.gust_scroll = _gust_scroll_cells;
	state.sway = float(_sway);
	state.moving = _params.model == WIND_NATURAL ? 1.0f : 0.0f;
	return state;
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
	if (!advances_plants()) {
		return; // natural sway is a function of the plant's place and the field's phase
	}
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

void WindModel::part_transforms(const Plant &p_plant, float p_bend, const PlantShape &p_shape, PartTransforms &r_parts) const {
	part_transforms(p_plant, p_bend * _lean, p_shape, r_parts);
}

void WindModel::part_transforms(const Plant &p_plant, const glm::vec2 &p_bend, const PlantShape &p_shape, PartTransforms &r_parts) const {
	// The plant rotates about the horizontal axis across its lean: (w_x, w_z) = (lean.z, −lean.x).
	const float size = glm::length(p_bend);
	const glm::vec2 axis = size > 1e-9f ? glm::vec2(p_bend.y, -p_bend.x) / size : glm::vec2(0.0f, -1.0f);
	// The plant type's stiffness scales the wind's (thesis: d1, d2): a stiffer plant bends less.
	const glm::mat3 bottom_tilt = rotation_about_horizontal(axis, size / (_params.d2 * p_shape.stiffness));
	const glm::mat3 upper_tilt = rotation_about_horizontal(axis, size / (_params.d1 * p_shape.stiffness));
	const float middle_height = 1.0f + p_plant.alpha() * p_shape.middle_variation; // thesis: s' = s + α/10
	const float scale = p_shape.part_scale * p_plant.scale;

	const glm::mat3 shape = yaw_scale(p_plant.yaw, scale, scale);
	const glm::mat3 middle_shape = yaw_scale(p_plant.yaw, scale, scale * middle_height);

	if (p_plant.upright()) {
		r_parts.basis[0] = bottom_tilt * shape;
		r_parts.basis[1] = upper_tilt * middle_shape;
		r_parts.basis[2] = upper_tilt * shape;
	} else {
		const glm::mat3 lean = lean_rotation(p_plant.lean()); // the plant's upright, tilted with the ground
		r_parts.basis[0] = lean * bottom_tilt * shape;
		r_parts.basis[1] = lean * upper_tilt * middle_shape;
		r_parts.basis[2] = lean * upper_tilt * shape;
	}
	r_parts.origin[0] = p_plant.root();
	// Each part starts at the previous one's tip: M·(0, length, 0).
	r_parts.origin[1] = r_parts.origin[0] + r_parts.basis[0][1] * p_shape.part_lengths.x;
	r_parts.origin[2] = r_parts.origin[1] + r_parts.basis[1][1] * p_shape.part_lengths.y;
}

void WindModel::whole_plant(const Plant &p_plant, const glm::vec2 &p_bend, const PlantShape &p_shape, WholePlant &r_plant) const {
	// part_transforms() tilts each part about a horizontal axis before its yaw: R(a) · Y = Y · R(Yᵀa),
	// so the plant's frame takes the yaw and the size, and the tilts turn about the axis seen from it.
	const float size = glm::length(p_bend);
	const glm::vec2 axis = size > 1e-9f ? glm::vec2(p_bend.y, -p_bend.x) / size : glm::vec2(0.0f, -1.0f);
	const glm::mat3 yaw = yaw_scale(p_plant.yaw, 1.0f, 1.0f);
	// Yᵀa: the axis against the yawed frame's x and z columns.
	const glm::vec2 own_axis(yaw[0].x * axis.x + yaw[0].z * axis.y, yaw[2].x * axis.x + yaw[2].z * axis.y);
	const glm::mat3 frame = yaw * (p_shape.part_scale * p_plant.scale);
	r_plant.basis = p_plant.upright() ? frame : lean_rotation(p_plant.lean()) * frame;
	r_plant.origin = p_plant.root();
	r_plant.tilt = own_axis * (size / (_params.d2 * p_shape.stiffness));
	r_plant.upper = size / (_params.d1 * p_shape.stiffness);
	r_plant.middle = 1.0f + p_plant.alpha() * p_shape.middle_variation;
}

void assemble_parts(const WholePlant &p_plant, const glm::vec3 &p_part_lengths, PartTransforms &r_parts) {
	const float bottom = glm::length(p_plant.tilt);
	const glm::vec2 axis = bottom > 1e-9f ? p_plant.tilt / bottom : glm::vec2(0.0f, -1.0f);
	const glm::mat3 bottom_tilt = rotation_about_horizontal(axis, bottom);
	const glm::mat3 upper_tilt = rotation_about_horizontal(axis, p_plant.upper);
	const glm::mat3 stretch(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, p_plant.middle, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
	// In the plant's frame: each part turned by its tilt, starting at the previous one's tip.
	const glm::mat3 own[3] = { bottom_tilt, upper_tilt * stretch, upper_tilt };
	const glm::vec3 middle_root = bottom_tilt * glm::vec3(0.0f, p_part_lengths.x, 0.0f);
	const glm::vec3 head_root = middle_root + upper_tilt * glm::vec3(0.0f, p_plant.middle * p_part_lengths.y, 0.0f);
	const glm::vec3 roots[3] = { glm::vec3(0.0f), middle_root, head_root };
	for (int part = 0; part < 3; ++part) {
		r_parts.basis[part] = p_plant.basis * own[part];
		r_parts.origin[part] = p_plant.origin + p_plant.basis * roots[part];
	}
}

} // namespace sunflower
