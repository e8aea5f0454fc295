#include "wind_model.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace sunflower;

namespace {

// The default form at p_scale metres per model unit.
PlantShape unit_shape(float p_scale = 1.0f) {
	PlantShape shape;
	shape.part_scale = p_scale;
	return shape;
}

WindModel make_wind(float p_power, glm::vec2 p_direction, float p_gust_share = 0.0f) {
	WindParams params;
	params.model = WIND_THESIS; // the thesis' equations, exactly
	params.power = p_power;
	params.direction = p_direction;
	params.gust_share = p_gust_share;
	WindModel wind;
	wind.configure(params);
	return wind;
}

void check_vec(const glm::vec3 &p_actual, const glm::vec3 &p_expected) {
	CHECK(p_actual.x == doctest::Approx(p_expected.x).epsilon(1e-5));
	CHECK(p_actual.y == doctest::Approx(p_expected.y).epsilon(1e-5));
	CHECK(p_actual.z == doctest::Approx(p_expected.z).epsilon(1e-5));
}

} // namespace

TEST_CASE("eq. 6: the phase rate is p_w·π up to 1, (p_w/20 + 1)·π above") {
	CHECK(make_wind(0.5f, { 1, 0 }).get_phase_rate() == doctest::Approx(0.5f * PI));
	CHECK(make_wind(1.0f, { 1, 0 }).get_phase_rate() == doctest::Approx(PI));
	CHECK(make_wind(10.0f, { 1, 0 }).get_phase_rate() == doctest::Approx(1.5f * PI));
	CHECK(make_wind(0.0f, { 1, 0 }).get_phase_rate() == 0.0f);
	CHECK(make_wind(NAN, { 1, 0 }).get_params().power == 0.0f); // non-finite power is calm
	CHECK(make_wind(500.0f, { 1, 0 }).get_params().power == 100.0f);
}

TEST_CASE("eq. 5: the bend force is p_w·h·sin φ, clamped") {
	const WindModel wind = make_wind(1.0f, { 1, 0 });
	PlantWind state;
	state.phase = PI / 2.0f;
	CHECK(wind.bend(state, 0.0f, 0.0f) == doctest::Approx(PI / 12.0f));
	state.phase = PI / 6.0f;
	CHECK(wind.bend(state, 0.0f, 0.0f) == doctest::Approx(PI / 12.0f * 0.5f));
	state.phase = 3.0f * PI / 2.0f;
	CHECK(wind.bend(state, 0.0f, 0.0f) == doctest::Approx(-PI / 12.0f));

	const WindModel storm = make_wind(100.0f, { 1, 0 });
	state.phase = PI / 2.0f;
	// p/d1 + p/d2 = p·(1/1.5 + 1/3) = p: the clamp on the summed tilt is the clamp on p.
	CHECK(storm.bend(state, 0.0f, 0.0f) == doctest::Approx(storm.get_params().max_bend));
}

TEST_CASE("eq. 4: part ends move by m2 and m1 + m2 along the wind, vertical extents y2 and y1") {
	const float p = PI / 12.0f;
	const float m1 = std::sin(p / 1.5f), m2 = std::sin(p / 3.0f);
	const float y1 = std::cos(p / 1.5f), y2 = std::cos(p / 3.0f);
	Plant plant; // at the origin, α = 0, no yaw
	PartTransforms parts;

	SUBCASE("wind blowing towards +x") {
		make_wind(1.0f, { 1, 0 }).part_transforms(plant, p, unit_shape(), parts);
		check_vec(parts.origin[0], { 0, 0, 0 });
		check_vec(parts.origin[1], { m2, y2, 0 });
		check_vec(parts.origin[2], { m1 + m2, y1 + y2, 0 });
	}
	SUBCASE("wind blowing towards +z: (w_x, w_z) = (1, 0) so Z1 = Z1' + w_x·(m1 + m2)") {
		make_wind(1.0f, { 0, 3 }).part_transforms(plant, p, unit_shape(), parts);
		check_vec(parts.origin[1], { 0, y2, m2 });
		check_vec(parts.origin[2], { 0, y1 + y2, m1 + m2 });
	}
	SUBCASE("a diagonal wind leans the plant along it") {
		make_wind(1.0f, { 1, 1 }).part_transforms(plant, p, unit_shape(), parts);
		const float s = std::sqrt(0.5f);
		check_vec(parts.origin[2], { (m1 + m2) * s, y1 + y2, (m1 + m2) * s });
	}
}

TEST_CASE("joints chain exactly: each part's root is the previous part's tip, head rigid on the middle") {
	Plant plant;
	plant.position = { 3.0f, -2.0f };
	plant.set_alpha(0.4f);
	plant.yaw = 0.3f;
	PartTransforms parts;
	const WindModel wind = make_wind(3.0f, { 0.3f, -1.0f });
	wind.part_transforms(plant, 0.37f, unit_shape(0.7f), parts);
	for (int part = 0; part < 2; ++part) {
		const glm::vec3 tip = parts.origin[part] + parts.basis[part] * glm::vec3(0, 1, 0);
		check_vec(parts.origin[part + 1], tip);
	}
	// The middle part is stretched by s' = s + α/10 along its own y only.
	CHECK(glm::length(parts.basis[1][1]) == doctest::Approx(0.7f * (1.0f + 0.04f)));
	CHECK(glm::length(parts.basis[1][0]) == doctest::Approx(0.7f));
	CHECK(glm::length(parts.basis[2][1]) == doctest::Approx(0.7f));
	// Head and middle share one rotation.
	const glm::vec3 head_up = glm::normalize(parts.basis[2][1]);
	const glm::vec3 middle_up = glm::normalize(parts.basis[1][1]);
	check_vec(head_up, middle_up);
}

TEST_CASE("no wind: the plant stands upright") {
	Plant plant;
	plant.position = { 1.0f, 1.0f };
	PartTransforms parts;
	make_wind(0.0f, { 1, 0 }).part_transforms(plant, 0.0f, unit_shape(), parts);
	check_vec(parts.origin[1], { 1, 1, 1 });
	check_vec(parts.origin[2], { 1, 2, 1 });
}

TEST_CASE("φ advances at b·ω, wraps at 2π and never goes negative") {
	WindParams params;
	params.model = WIND_THESIS; // the thesis' equations, exactly
	params.power = 1.0f;
	params.flip_chance = 0.0f;
	WindModel wind;
	wind.configure(params);
	PlantWind state;
	state.phase = 1.0f;
	state.direction = 1;
	state.next_flip = 1000;
	wind.advance_plant(state, 1, 0, 0.1, 0.1f);
	CHECK(state.phase == doctest::Approx(1.0f + PI * 0.1f));
	state.phase = TAU - 0.05f;
	wind.advance_plant(state, 1, 0, 0.2, 0.1f);
	CHECK(state.phase == doctest::Approx(PI * 0.1f - 0.05f));
	state.direction = -1;
	state.phase = 0.1f;
	wind.advance_plant(state, 1, 0, 0.3, 0.1f); // would reach 0.1 − 0.314
	CHECK(state.phase >= 0.0f);
	CHECK(state.direction == 1);
}

TEST_CASE("b is redrawn every 2 s, staggered, reversing about half the time") {
	const WindModel wind = make_wind(1.0f, { 1, 0 });
	int reversed = 0;
	const int plants = 4000;
	float min_offset = 10.0f, max_offset = -1.0f;
	for (uint32_t i = 0; i < static_cast<uint32_t>(plants); ++i) {
		PlantWind state;
		wind.init_plant(state, 7, i, 0.0);
		const int8_t before = state.direction;
		const float offset = wind.flip_offset(7, i);
		min_offset = std::min(min_offset, offset);
		max_offset = std::max(max_offset, offset);
		wind.advance_plant(state, 7, i, double(offset) - 0.001, 0.0f); // just before its redraw
		CHECK(state.direction == before);
		wind.advance_plant(state, 7, i, double(offset) + 0.001, 0.0f); // just after
		reversed += state.direction != before ? 1 : 0;
		if (state.phase < 0.0f) {
			FAIL("negative phase");
		}
	}
	CHECK(min_offset < 0.1f);
	CHECK(max_offset > 1.9f);
	CHECK(max_offset < 2.0f);
	CHECK(reversed > plants * 45 / 100);
	CHECK(reversed < plants * 55 / 100);
}

TEST_CASE("the gust travels downwind: a plant s metres downwind bends as its upwind neighbour did s/c earlier") {
	const WindModel wind = make_wind(1.0f, { 0, 1 }, 1.0f);
	const float c = wind.get_params().gust_speed;
	const float omega = wind.get_phase_rate();
	PlantWind state; // the plant's own phase has no weight with gust_share = 1
	const float s = 4.5f;
	const float tau = s / c;
	for (float psi : { 0.3f, 1.2f, 2.9f }) {
		const float upwind_then = wind.bend(state, 0.0f, psi);
		const float downwind_later = wind.bend(state, s, psi + omega * tau);
		CHECK(downwind_later == doctest::Approx(upwind_then).epsilon(1e-4));
	}
	CHECK(wind.downwind({ 2.0f, 5.0f }) == doctest::Approx(5.0f));
}

namespace {

WindModel natural_wind(float p_power, glm::vec2 p_direction = { 1, 0 }) {
	WindParams params; // the default model is the natural one
	params.power = p_power;
	params.direction = p_direction;
	WindModel wind;
	wind.configure(params);
	return wind;
}

} // namespace

TEST_CASE("natural wind: plants lean downwind, never upwind, from power 1 upward") {
	REQUIRE(WindParams{}.model == WIND_NATURAL);
	for (float power : { 1.0f, 2.0f, 5.0f, 10.0f, 30.0f, 100.0f }) {
		WindModel wind = natural_wind(power, { 0.6f, 0.8f });
		int upwind = 0;
		int samples = 0;
		float mean = 0.0f;
		std::vector<PlantWind> plants(40);
		for (uint32_t i = 0; i < plants.size(); ++i) {
			wind.init_plant(plants[i], 7, i, 0.0);
		}
		for (int frame = 1; frame <= 60 * 20; ++frame) {
			wind.advance(1.0f / 60.0f);
			for (uint32_t i = 0; i < plants.size(); ++i) {
				wind.advance_plant(plants[i], 7, i, frame / 60.0, 1.0f / 60.0f);
				const float along = glm::dot(wind.bend_vector(plants[i], glm::vec2(float(i) * 1.7f, float(i % 5) * 3.1f)),
						wind.get_lean_direction());
				upwind += along < 0.0f ? 1 : 0;
				mean += along;
				++samples;
			}
		}
		INFO("power ", power, ": mean lean ", mean / float(samples));
		CHECK(float(upwind) / float(samples) < 0.05f);
		CHECK(mean / float(samples) > 0.0f);
		CHECK(mean / float(samples) < wind.get_bend_limit()); // saturates below the limit: never pinned
	}
}

TEST_CASE("natural wind: the mean lean grows with power and saturates smoothly") {
	float previous = 0.0f;
	for (float power : { 0.5f, 1.0f, 3.0f, 10.0f, 100.0f }) {
		WindModel wind = natural_wind(power);
		PlantWind still; // the plant at the origin, at Φ = 0: the same sway phase at every power
		const float lean = glm::length(wind.bend_vector(still, { 0.0f, 0.0f }));
		CHECK(lean > previous);
		CHECK(lean < wind.get_bend_limit());
		previous = lean;
	}
}

TEST_CASE("natural wind: no frame-to-frame jump beyond what the smooth motion allows, through power and direction changes") {
	// The bound, from the model's rates at the largest power used (10): the sway 0.35·A·sin φ with φ
	// at up to 1.15·ω; gusts 0.5·share·A·g with g's slope at most 1.5 per cell (smoothstep) on both
	// axes, scrolling at c = p m/s over 8 m cells; A's change with the eased power (dA/dp ≤ h); the
	// lean direction turning at most π·k per frame; power and direction changes ease in at a steady
	// rate over 0.5 s (k = dt / 0.5 of the change per frame). The soft clip's slope is at most 1.
	const float dt = 1.0f / 60.0f;
	const float k = dt / 0.5f;
	WindModel strong = natural_wind(10.0f);
	const float a_max = strong.get_bend_limit() * (1.0f - std::exp(-10.0f * PI / 12.0f / strong.get_bend_limit()));
	const float omega_max = strong.get_phase_rate() * 1.15f;
	const float sway = 0.35f * a_max * omega_max * dt;
	const float gust = 0.5f * 0.5f * a_max * 1.5f * std::sqrt(2.0f) * (10.0f / 8.0f) * dt;
	const float power_step = (0.55f + 0.35f + 0.25f) * (PI / 12.0f) * (10.0f - 1.0f) * k;
	const float turn = strong.get_bend_limit() * PI * k;
	const float bound = sway + gust + power_step + turn;

	auto largest_jump = [&](int p_model) {
		WindParams params;
		params.model = p_model;
		params.power = 1.0f;
		params.flip_interval = 0.3f; // many flips (the thesis model's)
		WindModel wind;
		wind.configure(params);
		std::vector<PlantWind> plants(30);
		for (uint32_t i = 0; i < plants.size(); ++i) {
			wind.init_plant(plants[i], 3, i, 0.0);
		}
		std::vector<glm::vec2> before(plants.size());
		float largest = 0.0f;
		for (int frame = 1; frame <= 60 * 15; ++frame) {
			if (frame == 60 * 5) {
				params.power = 10.0f;
				wind.configure(params);
			}
			if (frame == 60 * 10) {
				params.direction = { -1.0f, 0.0f };
				wind.configure(params);
			}
			wind.advance(dt);
			for (uint32_t i = 0; i < plants.size(); ++i) {
				wind.advance_plant(plants[i], 3, i, frame * double(dt), dt);
				const glm::vec2 now = wind.bend_vector(plants[i], glm::vec2(float(i) * 2.3f, 1.0f));
				if (frame > 1) {
					largest = std::max(largest, glm::length(now - before[i]));
				}
				before[i] = now;
			}
		}
		return largest;
	};
	const float natural = largest_jump(WIND_NATURAL);
	INFO("largest per-frame change: natural ", natural, ", bound ", bound);
	CHECK(natural <= bound);
	CHECK(largest_jump(WIND_THESIS) > bound); // the thesis' flips, power and direction steps jump
}

TEST_CASE("natural wind: a plant's sway is a function of its place and the field's phase, seamless where the phase wraps") {
	WindModel wind = natural_wind(1.0f); // ω = π: Φ wraps at 2π × 64 after 128 s
	PlantWind fresh;
	PlantWind old;
	old.phase = 2.0f; // per-plant state the natural model does not use
	old.direction = -1;
	const glm::vec2 place{ 12.34f, -5.67f };
	// Plants at other places sway at other phases and paces.
	WindModel later = wind;
	later.advance(0.5f);
	std::vector<float> paces;
	for (int i = 0; i < 40; ++i) {
		const glm::vec2 other{ float(i) * 0.37f, float(i % 7) * 1.1f };
		paces.push_back(std::remainder(later.sway_phase(other) - wind.sway_phase(other), TAU) / (PI * 0.5f));
	}
	const auto [slowest, fastest] = std::minmax_element(paces.begin(), paces.end());
	CHECK(*slowest >= 54.0f / 64.0f - 1e-3f);
	CHECK(*fastest <= 74.0f / 64.0f + 1e-3f);
	CHECK(*fastest - *slowest > 0.1f);
	const float dt = 1.0f / 60.0f;
	float largest_step = 0.0f;
	for (int frame = 0; frame < 60 * 140; ++frame) {
		const float before = wind.sway_phase(place);
		wind.advance(dt);
		CHECK(wind.bend_vector(fresh, place) == wind.bend_vector(old, place));
		largest_step = std::max(largest_step, std::abs(std::remainder(wind.sway_phase(place) - before, TAU)));
	}
	// Through the wrap at 128 s the phase moves by pace·ω·dt a frame, never more.
	CHECK(largest_step <= 74.0f / 64.0f * PI * dt * 1.001f);
	CHECK(largest_step >= 54.0f / 64.0f * PI * dt * 0.999f);
}

TEST_CASE("natural wind: gusts arrive downwind later in proportion to the distance") {
	WindModel wind = natural_wind(4.0f); // gusts travel at 4 m/s
	const float dt = 1.0f / 60.0f;
	std::vector<float> here, there;
	for (int frame = 0; frame < 60 * 30; ++frame) {
		wind.advance(dt);
		here.push_back(wind.gust_strength({ 0.0f, 2.0f }));
		there.push_back(wind.gust_strength({ 12.0f, 2.0f })); // 12 m downwind
	}
	CHECK(*std::max_element(here.begin(), here.end()) - *std::min_element(here.begin(), here.end()) > 0.2f);
	int best_lag = -1;
	float best_error = 1e30f;
	for (int lag = 0; lag <= 60 * 6; ++lag) {
		float error = 0.0f;
		for (size_t t = size_t(lag); t < here.size(); ++t) {
			error += std::abs(there[t] - here[t - size_t(lag)]);
		}
		if (error < best_error) {
			best_error = error;
			best_lag = lag;
		}
	}
	CHECK(best_lag == doctest::Approx(3.0 * 60.0).epsilon(0.02)); // 12 m at 4 m/s: 3 s
}

TEST_CASE("a plant type's stiffness scales how far the wind bends it") {
	Plant plant;
	PartTransforms soft;
	PartTransforms stiff;
	PlantShape shape = unit_shape();
	const WindModel wind = make_wind(1.0f, { 1, 0 });
	wind.part_transforms(plant, 0.6f, shape, soft);
	shape.stiffness = 2.0f;
	wind.part_transforms(plant, 0.6f, shape, stiff);
	// The bottom part's tilt from upright halves (small angles: its up axis' horizontal part).
	const float soft_angle = std::acos(glm::normalize(soft.basis[0][1]).y);
	const float stiff_angle = std::acos(glm::normalize(stiff.basis[0][1]).y);
	CHECK(stiff_angle == doctest::Approx(soft_angle * 0.5f).epsilon(1e-4));
}

TEST_CASE("a plant drawn whole: its record gives back the part transforms, through the bytes the shader reads") {
	// Plants of every kind: turned, sized, stretched, leaning with the ground, stiff or soft, bent
	// every way or not at all, with parts of unequal lengths.
	PlantShape shape = unit_shape(0.8f);
	shape.part_lengths = glm::vec3(1.3f, 0.6f, 1.1f);
	shape.middle_variation = 0.2f;
	const WindModel wind = make_wind(2.0f, { 0.6f, 0.8f });
	int cases = 0;
	for (float yaw : { 0.0f, 0.7f, -2.5f }) {
		for (glm::vec2 lean : { glm::vec2(0.0f), glm::vec2(0.3f, -0.2f) }) {
			for (glm::vec2 bend : { glm::vec2(0.0f), glm::vec2(0.4f, 0.1f), glm::vec2(-0.2f, 0.5f) }) {
				for (float stiffness : { 1.0f, 2.5f }) {
					Plant plant;
					plant.position = { 4.0f, -7.0f };
					plant.ground = 1.5f;
					plant.set_alpha(0.35f);
					plant.yaw = yaw;
					plant.scale = 1.2f;
					plant.set_lean(lean);
					shape.stiffness = stiffness;
					PartTransforms expected;
					wind.part_transforms(plant, bend, shape, expected);
					WholePlant whole;
					wind.whole_plant(plant, bend, shape, whole);
					float record[WHOLE_FLOATS_PER_INSTANCE];
					write_whole_instance(record, whole, glm::vec4(1.0f));
					PartTransforms assembled;
					assemble_parts(read_whole_instance(record), shape.part_lengths, assembled);
					for (int part = 0; part < 3; ++part) {
						CAPTURE(part);
						for (int column = 0; column < 3; ++column) {
							check_vec(assembled.basis[part][column], expected.basis[part][column]);
						}
						check_vec(assembled.origin[part], expected.origin[part]);
					}
					++cases;
				}
			}
		}
	}
	CHECK(cases == 36);
}

TEST_CASE("natural wind: a change eases in over the wind's ease time, at once with 0") {
	for (const float ease : { 0.5f, 4.0f, 0.0f }) {
		WindModel wind = natural_wind(1.0f);
		wind.advance(0.1f); // started: a change now eases in
		WindParams params = wind.get_params();
		params.ease_time = ease;
		params.power = 5.0f;
		wind.configure(params);
		float seconds = 0.0f;
		const float dt = 1.0f / 60.0f;
		while (wind.get_effective_power() < 5.0f && seconds < 60.0f) {
			wind.advance(dt);
			seconds += dt;
		}
		CAPTURE(ease);
		CHECK(seconds == doctest::Approx(std::max(ease, dt)).epsilon(0.05));
	}
	WindParams params;
	params.ease_time = -3.0f; // below the row's 0: clamped
	WindModel wind;
	wind.configure(params);
	CHECK(wind.get_params().ease_time == 0.0f);
}
