#include "field_simulation.h"
#include "parameters.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

using namespace sunflower;

TEST_CASE("parameters: clamp rules, fallbacks for non-finite values and kept values") {
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	CHECK(sanitize(param::WIND_POWER, 5.0, 1.0) == 5.0);
	CHECK(sanitize(param::WIND_POWER, -3.0, 1.0) == 0.0);
	CHECK(sanitize(param::WIND_POWER, 300.0, 1.0) == 100.0);
	CHECK(sanitize(param::WIND_POWER, nan, 7.0) == 0.0); // NaN wind is calm, not the default
	CHECK(sanitize(param::WIND_GUST_SPEED, inf, 9.0) == 3.0); // the default, as the inspector shows it
	CHECK(sanitize(param::CELL_SIZE, 0.0, 0.7) == 0.7); // refused: the current value stays
	CHECK(sanitize(param::CELL_SIZE, -1.0, 0.7) == 0.7);
	CHECK(sanitize(param::CELL_SIZE, nan, 0.7) == 0.7);
	CHECK(sanitize(param::CELL_SIZE, 0.25, 0.7) == 0.25);
	CHECK(sanitize(param::FORCE_LOD, 9.0, -1.0) == 4.0);
	CHECK(sanitize(param::WORKER_THREADS, 99.0, 0.0) == double(param::MAX_THREADS));
}

TEST_CASE("parameters: warnings say what was wrong and what is used") {
	CHECK(explain_sanitized(param::WIND_POWER, 5.0, 5.0).empty());
	CHECK(explain_sanitized(param::WIND_POWER, std::nan(""), 0.0) == "nan is not a finite number; using 0");
	CHECK(explain_sanitized(param::WIND_POWER, -3.0, 0.0) == "-3 is outside 0–100; using 0");
	CHECK(explain_sanitized(param::CELL_SIZE, 0.0, 0.5) == "0 is below 0.001; keeping 0.5");
	CHECK(explain_sanitized(param::WIND_BEND_PER_POWER, std::numeric_limits<double>::infinity(), 0.5) ==
			"inf is not a finite number; using 0.5");
}

TEST_CASE("parameters: every name is unique and found; defaults lie in range") {
	std::set<std::string> names;
	for (const ParameterSpec *spec : param::ALL) {
		CHECK(names.insert(spec->name).second);
		CHECK(find_parameter(spec->name) == spec);
		CHECK(spec->default_value >= spec->min);
		CHECK(spec->default_value <= spec->max);
		CHECK(sanitize(*spec, spec->default_value, spec->default_value) == spec->default_value);
	}
	CHECK(find_parameter("SunflowerWind.nothing") == nullptr);
}

TEST_CASE("parameters: the core's own structures start at the table's defaults") {
	const WindParams wind;
	CHECK(wind.power == float(param::WIND_POWER.default_value));
	CHECK(wind.d1 == float(param::WIND_STIFFNESS_MIDDLE.default_value));
	CHECK(wind.gust_speed == float(param::WIND_GUST_SPEED.default_value));
	const LodParams lod;
	CHECK(lod.hysteresis == float(param::LOD_HYSTERESIS.default_value));
	CHECK(lod.interval == float(param::LOD_INTERVAL.default_value));
	CHECK(lod.force_level == int(param::FORCE_LOD.default_value));
	const LayoutParams layout;
	CHECK(layout.cell_size == float(param::CELL_SIZE.default_value));
	CHECK(layout.chunk_size == float(param::CHUNK_SIZE.default_value));
	const PlantShape shape;
	CHECK(shape.part_scale * shape.parts_height() == doctest::Approx(param::PLANT_HEIGHT.default_value));
}

TEST_CASE("parameters: the models apply the rules themselves") {
	WindModel wind;
	WindParams params;
	params.power = std::nanf("");
	params.gust_speed = -1.0f;
	params.direction = glm::vec2(0.0f);
	wind.configure(params);
	CHECK(wind.get_params().power == 0.0f);
	CHECK(wind.get_params().gust_speed == 0.0f);
	CHECK(wind.get_params().direction == glm::vec2(1.0f, 0.0f));

	LodSelector lod;
	LodParams bad;
	bad.distances = { { 6.0f, 5.0f, 20.0f, 25.0f } };
	bad.hysteresis = -1.0f;
	lod.configure(bad);
	CHECK(lod.get_params().distances[1] == 10.0f); // refused: the current distances stay
	CHECK(lod.get_params().hysteresis == 0.0f);

	FieldSimulation sim;
	sim.set_plant_height(-2.0f);
	CHECK(sim.plants().get_shape().part_scale * sim.plants().get_shape().parts_height() == doctest::Approx(2.0f));
	sim.set_plant_height(3.0f);
	CHECK(sim.plants().get_shape().part_scale == doctest::Approx(1.0f));
}

TEST_CASE("parameters: LOD distances must be four positive increasing numbers") {
	const float good[4] = { 6.0f, 10.0f, 20.0f, 25.0f };
	CHECK(check_lod_distances(good, 4).empty());
	CHECK(check_lod_distances(good, 2) == "needs 4 distances, got 2");
	const float decreasing[4] = { 6.0f, 5.0f, 20.0f, 25.0f };
	CHECK(check_lod_distances(decreasing, 4) == "distances must increase (5 after 6)");
	const float negative[4] = { -1.0f, 5.0f, 20.0f, 25.0f };
	CHECK(check_lod_distances(negative, 4) == "distance 1 (-1) is not a positive number");
}

TEST_CASE("settings by table row: each row reaches the unit that owns it; a laid-out field leaves the layout's to a rebuild") {
	FieldSimulation sim;
	const float power = 7.0f;
	CHECK(sim.set_setting(param::WIND_POWER, &power) == ParameterSpec::FREE);
	CHECK(sim.near().get_wind().get_params().power == 7.0f);
	const float direction[2] = { 0.0f, 0.0f }; // a zero direction is +x
	sim.set_setting(param::WIND_DIRECTION, direction);
	CHECK(sim.near().get_wind().get_params().direction == glm::vec2(1.0f, 0.0f));
	const float distances[4] = { 3.0f, 5.0f, 8.0f, 9.0f };
	sim.set_setting(param::LOD_DISTANCES, distances);
	CHECK(sim.near().get_lod().get_params().distances[2] == 8.0f);
	const float falling[4] = { 3.0f, 2.0f, 8.0f, 9.0f }; // fails check_lod_distances: kept
	sim.set_setting(param::LOD_DISTANCES, falling);
	CHECK(sim.near().get_lod().get_params().distances[1] == 5.0f);
	const float force = 9.0f; // clamped by the row's rule
	sim.set_setting(param::FORCE_LOD, &force);
	CHECK(sim.near().get_lod().get_params().force_level == 4);
	const float recover = 12.0f;
	sim.set_setting(param::PLANT_RECOVER_AFTER, &recover, 2);
	CHECK(sim.get_regrowth()[2].flattened_seconds == 12.0);
	CHECK(sim.get_regrowth()[0].flattened_seconds == 0.0);
	const float stump = 0.3f;
	sim.set_setting(param::PLANT_STUMP_HEIGHT, &stump, 1);
	CHECK(sim.near().get_stump_height(1) == doctest::Approx(0.3f));
	const float threads = 1.0f;
	sim.set_setting(param::WORKER_THREADS, &threads);
	CHECK(sim.near().get_worker_threads() == 1);

	// Before a map is laid out, the layout's rows are taken as they come.
	const float cell = 0.8f;
	CHECK(sim.set_setting(param::CELL_SIZE, &cell) == ParameterSpec::FREE);
	CHECK(sim.plants().get_layout_params().cell_size == 0.8f);
	const float yaw = 0.1f;
	CHECK(sim.set_setting(param::PLANT_YAW_RANGE, &yaw, 1) == ParameterSpec::FREE);
	CHECK(sim.plants().get_layout_params().varieties[1].yaw_range == 0.1f);
	const float lengths[3] = { 2.0f, 1.0f, 1.0f };
	sim.set_setting(param::PLANT_PART_LENGTH, lengths);
	CHECK(sim.plants().get_shape(0).part_lengths.x == 2.0f);
	const float height = 3.0f;
	sim.set_setting(param::PLANT_HEIGHT, &height);
	CHECK(sim.plants().get_shape(0).part_scale * sim.plants().get_shape(0).parts_height() == doctest::Approx(3.0f));

	MapError error;
	REQUIRE(sim.load_map("3 1\n***\n", U"", "rows", MapLimits{}, error));
	// Laid out: a new value of a row the layout depends on is not applied and costs a rebuild; the
	// value held, a value the rules refuse, and a row taken at the next update cost nothing.
	const float other_cell = 0.6f;
	CHECK(sim.set_setting(param::CELL_SIZE, &other_cell) == ParameterSpec::REBUILD);
	CHECK(sim.plants().get_layout_params().cell_size == 0.8f);
	CHECK(sim.set_setting(param::CELL_SIZE, &cell) == ParameterSpec::FREE);
	const float refused = -1.0f; // CELL_SIZE keeps its value
	CHECK(sim.set_setting(param::CELL_SIZE, &refused) == ParameterSpec::FREE);
	CHECK(sim.set_setting(param::PLANT_YAW_RANGE, &yaw, 1) == ParameterSpec::FREE);
	CHECK(sim.set_setting(param::PLANT_YAW_RANGE, &cell, 1) == ParameterSpec::REBUILD);
	CHECK(sim.set_setting(param::PLANT_HEIGHT, &height) == ParameterSpec::FREE);
	CHECK(sim.set_setting(param::PLANT_HEIGHT, &cell) == ParameterSpec::REBUILD);
	const float stiff = 2.0f;
	CHECK(sim.set_setting(param::PLANT_STIFFNESS, &stiff) == ParameterSpec::REBUILD);
	CHECK(sim.set_setting(param::WIND_POWER, &cell) == ParameterSpec::FREE);
	CHECK(sim.near().get_wind().get_params().power == 0.8f);
	// A row the engine side applies costs what the table says (the core cannot tell a change).
	CHECK(sim.set_setting(param::GROUND_RAY_ABOVE, &cell) == ParameterSpec::REBUILD);
	CHECK(param::GROUND_RAY_ABOVE.cost == ParameterSpec::REBUILD);
}
