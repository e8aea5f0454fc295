#pragma once
// Wind that makes the plants sway, in two models.
//
// THESIS (thesis 5.4, equations 4–6, exact, for reproduction): per plant a phase φ and a direction
// b ∈ {+1, −1}. φ advances at b·ω(p_w) (eq. 6); every flip_interval seconds (staggered per plant) b
// reverses with probability flip_chance; φ never goes negative (b is set back to +1) and wraps at
// 2π. The bend force is p = p_w·h·sin φ (eq. 5), mixed with a travelling component sin(Ψ(t − s/c))
// where s is the plant's downwind coordinate, clamped so the summed tilt stays within max_bend.
// It swings symmetrically about upright: plants lean upwind half the time.
//
// NATURAL (the default, for games): the plant leans downwind by a mean that grows with the power,
// sways about it, and gusts roll over the field. With A = L·(1 − e^(−p·h/L)) (L the bend that tilts
// the plant by max_bend): lean = 0.55·A + 0.35·A·sin φ + gust_share·0.5·A·g(s − c·t, q), smoothly
// saturated as L·soft_clip(lean/L) (a tanh-like curve), so it never pins at the limit. g is a smooth
// noise of gust strength in [0, 1] over the field (8 m cells), scrolling downwind at the wind's
// speed c = p_w m/s. φ = φ₀ + pace·Φ: Φ is the field's sway phase, advancing at ω(p_w); φ₀ and the
// pace (0.84–1.16) come from a hash of where the plant stands, so a plant's sway is a function of
// its place and the field's state alone: the impostor shader (shaders/impostor.gdshader) computes the
// same bend for far plants, with no per-plant data. Power and direction changes ease in at a steady
// rate over half a second. The lean never goes upwind. (b is the thesis model's alone.)
//
// Both: the bottom part tilts p/d2 and the middle part p/d1 (eq. 4), about the horizontal axis
// across the lean; the head sits rigidly on the middle. A bend is a vector on the ground (x, z):
// its length the bend force, its direction the lean, so pushes from bodies add to the wind's.
#include "field_layout.h"
#include "instance_buffer.h"
#include "plant_shape.h"
#include "parameters.h"

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>

namespace sunflower {

// Defaults and limits: param::WIND_* (parameters.h).
enum WindKind : int {
	WIND_THESIS = 0,
	WIND_NATURAL = 1,
};

struct WindParams {
	int model = int(param::WIND_MODEL.default_value); // WindKind
	float power = float(param::WIND_POWER.default_value); // p_w in [0, 100]; 1.0 ≈ 1 m/s
	glm::vec2 direction{ 1.0f, 0.0f }; // x, z: where the wind blows to (need not be normalised)
	float d1 = float(param::WIND_STIFFNESS_MIDDLE.default_value); // stiffness of the middle part
	float d2 = float(param::WIND_STIFFNESS_BOTTOM.default_value); // stiffness of the bottom part
	float h = float(param::WIND_BEND_PER_POWER.default_value); // maximum bend per unit of power
	float max_bend = float(param::WIND_MAX_BEND.default_value); // clamp on the summed tilt of bottom and middle, radians
	float flip_interval = float(param::WIND_FLIP_INTERVAL.default_value); // seconds between redraws of b
	float flip_chance = float(param::WIND_FLIP_CHANCE.default_value); // probability that b reverses at a redraw
	float gust_speed = float(param::WIND_GUST_SPEED.default_value); // m/s the bend travels downwind; 0: no gust
	float gust_share = float(param::WIND_GUST_SHARE.default_value); // 0: each plant on its own; 1: only the gust
	float ease_time = float(param::WIND_EASE_TIME.default_value); // natural wind: seconds a change takes to ease in

	// Sets the SunflowerWind row p_spec from its values (FieldSimulation::set_setting).
	RowSet set(const ParameterSpec &p_spec, const float *p_values);
};

struct PlantWind {
	float phase = 0.0f; // φ ∈ [0, 2π)
	int8_t direction = 1; // b
	uint16_t push_slot = 0; // FieldSimulation: 1 + the plant's slot among pushed plants, 0 if none
	uint32_t next_flip = 0; // index k of the next redraw at t = offset + k·flip_interval
};
static_assert(sizeof(PlantWind) == 12, "per-plant wind state stays 12 bytes");

// The rotation that stands a plant on sloping ground: +y to the up axis whose horizontal part is
// p_lean (Plant::lean), about the horizontal axis across it.
glm::mat3 lean_rotation(const glm::vec2 &p_lean);

// The three part transforms of one plant: linear part and origin (the part's root), bottom to top.
struct PartTransforms {
	glm::mat3 basis[3];
	glm::vec3 origin[3];
};

// The three part transforms a whole-plant record stands for, as the whole-plant shader places them
// (shaders/plant_bend.gdshaderinc mirrors this: keep the two in step). p_part_lengths: model units
// from each part's root to the next one's (PlantShape::part_lengths).
void assemble_parts(const WholePlant &p_plant, const glm::vec3 &p_part_lengths, PartTransforms &r_parts);

class WindModel {
public:
	void configure(const WindParams &p_params);
	const WindParams &get_params() const { return _params; }

	// The field-wide motion of one frame: the thesis' gust phase Ψ advances; natural wind eases power
	// and direction towards the configured ones and scrolls its gusts.
	void advance(float p_delta);

	// ω: the rate of φ in rad/s for the configured power (eq. 6 without b).
	float get_phase_rate() const { return _rate; }
	// The unit vector the plants lean towards, and the axis they rotate about (thesis (w_x, w_z)).
	glm::vec2 get_lean_direction() const { return _lean; }
	// The power the plants feel now (natural: eased towards the configured power).
	float get_effective_power() const { return _power; }
	// The bend force that tilts a plant by max_bend (bottom p/d2 plus middle p/d1).
	float get_bend_limit() const { return _bend_limit; }
	// Natural wind: the gust strength in [0, 1] at a point now (0 for the thesis model).
	float gust_strength(const glm::vec2 &p_position) const;
	// Natural wind: the sway phase φ of a plant standing at p_position now.
	float sway_phase(const glm::vec2 &p_position) const;
	// Natural wind: the field-wide state the impostor shader computes every far plant's bend from
	// (shaders/impostor.gdshader mirrors bend_vector() and sway_phase() on it).
	struct ShaderState {
		glm::vec2 lean; // the lean direction now
		float amplitude; // A
		float bend_limit; // L
		float gust_share;
		float gust_scroll; // gust cells scrolled downwind
		float sway; // Φ, wrapped at 2π × PACE_STEPS
		float moving; // 1 for natural wind, 0 for the thesis' (whose far plants stand still)
	};
	ShaderState shader_state() const;
	// The pace of the sway is m / PACE_STEPS for a whole m: Φ can wrap at 2π × PACE_STEPS unseen.
	static constexpr int PACE_STEPS = 64;
	// The pace steps plants draw from: m in [PACE_LOW, PACE_LOW + PACE_SPAN).
	static constexpr uint32_t PACE_LOW = 54;
	static constexpr uint32_t PACE_SPAN = 21;
	// The bend of a plant now, as a vector on the ground (x, z), in either model.
	glm::vec2 bend_vector(const PlantWind &p_wind, const glm::vec2 &p_position) const;

	void init_plant(PlantWind &r_wind, uint64_t p_seed, uint32_t p_plant, double p_time) const;
	// Whether advance_plant() does anything: natural wind keeps no state per plant (its sway is a
	// function of place and time).
	bool advances_plants() const { return _params.model != WIND_NATURAL; }
	// Advances φ by p_delta seconds ending at p_time, redrawing b where a redraw time was passed.
	void advance_plant(PlantWind &r_wind, uint64_t p_seed, uint32_t p_plant, double p_time, float p_delta) const;
	// The clamped bend force p of a plant at downwind coordinate p_downwind, given the field's gust phase Ψ.
	float bend(const PlantWind &p_wind, float p_downwind, float p_gust_phase) const;
	// Downwind coordinate s of a point: its distance along the wind direction.
	float downwind(const glm::vec2 &p_position) const { return p_position.x * _lean.x + p_position.y * _lean.y; }

	// Part transforms for bend p along the lean direction (eq. 4). p_part_scale: metres per model unit
	// (parts are 1 unit tall).
	void part_transforms(const Plant &p_plant, float p_bend, const PlantShape &p_shape, PartTransforms &r_parts) const;
	// Part transforms for a bend vector on the ground (x, z): tilted by its length, towards it.
	void part_transforms(const Plant &p_plant, const glm::vec2 &p_bend, const PlantShape &p_shape, PartTransforms &r_parts) const;

	// The same plant bent by p_bend as one whole-plant record: its frame, and its parts' tilts and
	// stretch in that frame (assemble_parts() gives back what part_transforms() gives).
	void whole_plant(const Plant &p_plant, const glm::vec2 &p_bend, const PlantShape &p_shape, WholePlant &r_plant) const;

	// A flip offset in [0, flip_interval) for a plant, so redraws are staggered across the field.
	float flip_offset(uint64_t p_seed, uint32_t p_plant) const;

private:
	void _derive();

	WindParams _params;
	float _rate = 0.0f; // ω at the power felt now
	float _bend_limit = 0.0f; // limit on p so that p/d1 + p/d2 ≤ max_bend
	glm::vec2 _lean{ 1.0f, 0.0f }; // the lean direction now (natural: eased)
	float _power = 0.0f; // the power felt now (natural: eased)
	float _power_rate = 0.0f; // natural: how fast _power moves to the configured power, per second
	float _turn_rate = 0.0f; // natural: how fast the lean turns to the configured direction, rad/s
	float _amplitude = 0.0f; // natural: A for the power felt now
	float _gust_phase = 0.0f; // thesis: Ψ
	float _gust_scroll_cells = 0.0f; // natural: gust cells the pattern has moved downwind (mod 2^16)
	double _sway = 0.0; // natural: Φ, wrapped at 2π × PACE_STEPS
	// natural: (m / PACE_STEPS)·Φ wrapped at 2π for each pace step m, made when Φ moves (a double
	// fmod per pace per frame instead of per near plant).
	std::array<float, PACE_SPAN> _pace_phase{};
	bool _advanced = false; // natural wind eases changes only once it moves
};

} // namespace sunflower
