#pragma once
// Every value a user sets on a field or its wind, defined once: its default, its range and what
// happens to a value outside it. The core applies these rules itself; the engine side reads the
// same table (by name) to validate inspector values and word their warnings, so no limit or
// default is typed twice. Names are the user-facing properties ("SunflowerWind.power").
#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace sunflower {

constexpr float PI = 3.14159265358979323846f;
constexpr float TAU = 2.0f * PI;

struct ParameterSpec {
	enum Rule : uint8_t {
		CLAMP, // out of range: the nearest bound; not finite: `fallback`
		KEEP, // out of range or not finite: the current value stays
	};
	// What changing the value costs a field whose map is laid out (FieldSimulation::set_setting).
	enum Cost : uint8_t {
		FREE, // taken at the next update (or applied by the engine side)
		REBUILD, // the layout depends on it: the field is built anew
	};
	const char *name;
	double default_value;
	double min;
	double max;
	Rule rule;
	double fallback; // CLAMP: what a non-finite value becomes
	Cost cost = FREE;
	// Values the setting holds (a direction 2, the switch distances 4); the rules apply to each.
	uint8_t components = 1;
};

namespace param {

constexpr double NO_MAX = std::numeric_limits<float>::max();
constexpr double NO_MIN = -NO_MAX;

// Wind (thesis 5.4): power p_w, the stiffnesses d1 / d2, h, and this addon's clamp, flips and gust.
// A NaN power becomes calm (0), not the default: a broken input should not start a wind.
// 0: the thesis' equations, exactly (reproduction); 1: natural wind for games (wind_model.h).
inline constexpr ParameterSpec WIND_MODEL{ "SunflowerWind.model", 1.0, 0.0, 1.0, ParameterSpec::CLAMP, 1.0 };
inline constexpr ParameterSpec WIND_POWER{ "SunflowerWind.power", 1.0, 0.0, 100.0, ParameterSpec::CLAMP, 0.0 };
inline constexpr ParameterSpec WIND_INCREMENT{ "SunflowerWind.increment", 0.1, 0.0, 100.0, ParameterSpec::CLAMP, 0.1 };
inline constexpr ParameterSpec WIND_STIFFNESS_MIDDLE{ "SunflowerWind.stiffness_middle", 1.5, 0.1, NO_MAX, ParameterSpec::CLAMP, 1.5 };
inline constexpr ParameterSpec WIND_STIFFNESS_BOTTOM{ "SunflowerWind.stiffness_bottom", 3.0, 0.1, NO_MAX, ParameterSpec::CLAMP, 3.0 };
inline constexpr ParameterSpec WIND_BEND_PER_POWER{ "SunflowerWind.bend_per_power", PI / 12.0, NO_MIN, NO_MAX, ParameterSpec::CLAMP, PI / 12.0 };
inline constexpr ParameterSpec WIND_MAX_BEND{ "SunflowerWind.max_bend", PI / 4.0, 0.0, PI, ParameterSpec::CLAMP, PI / 4.0 };
inline constexpr ParameterSpec WIND_FLIP_INTERVAL{ "SunflowerWind.flip_interval", 2.0, 0.05, NO_MAX, ParameterSpec::CLAMP, 2.0 };
inline constexpr ParameterSpec WIND_FLIP_CHANCE{ "SunflowerWind.flip_chance", 0.5, 0.0, 1.0, ParameterSpec::CLAMP, 0.5 };
inline constexpr ParameterSpec WIND_GUST_SPEED{ "SunflowerWind.gust_speed", 3.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 3.0 };
inline constexpr ParameterSpec WIND_GUST_SHARE{ "SunflowerWind.gust_share", 0.5, 0.0, 1.0, ParameterSpec::CLAMP, 0.5 };
// Natural wind: the seconds a change of power or direction takes to ease in (0: at once).
inline constexpr ParameterSpec WIND_EASE_TIME{ "SunflowerWind.ease_time", 0.5, 0.0, 600.0, ParameterSpec::CLAMP, 0.5 };
// Where the wind blows to (x, z; need not be normalised): a zero or non-finite one is +x
// (sanitize_wind_direction), not a per-value rule.
inline constexpr ParameterSpec WIND_DIRECTION{ "SunflowerWind.direction", 1.0, NO_MIN, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::FREE, 2 };

// Layout: a bad size is refused and the field keeps the one it has (a rebuild would be wasted).
inline constexpr ParameterSpec CELL_SIZE{ "SunflowerField.cell_size", 0.5, 0.001, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_HEIGHT{ "SunflowerPlant.height", 2.0, 0.001, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD };
// A plant type's variety: yaw either side of facing +z (radians), size factor range, middle stretch.
inline constexpr ParameterSpec PLANT_YAW_RANGE{ "SunflowerPlant.yaw_range", 0.35, 0.0, PI, ParameterSpec::CLAMP, 0.35, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_SCALE_MIN{ "SunflowerPlant.scale_min", 1.0, 0.01, 100.0, ParameterSpec::CLAMP, 1.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_SCALE_MAX{ "SunflowerPlant.scale_max", 1.0, 0.01, 100.0, ParameterSpec::CLAMP, 1.0, ParameterSpec::REBUILD };
// A plant type's colour variety: the instance colour multiplies the albedo by 1 ± brightness and
// tints it warmer or cooler by up to ± tint (red up and blue down, or the other way).
inline constexpr ParameterSpec PLANT_BRIGHTNESS_VARIATION{ "SunflowerPlant.brightness_variation", 0.0, 0.0, 1.0, ParameterSpec::CLAMP, 0.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_TINT_VARIATION{ "SunflowerPlant.tint_variation", 0.0, 0.0, 1.0, ParameterSpec::CLAMP, 0.0, ParameterSpec::REBUILD };
// A plant type's form in model units (plant_shape.h): each part's length (0 for an empty slot above
// the plant's top part; lengths of no height together keep the current ones), the height the
// impostors frame, the culling radius. Out of range or not finite: the current value stays.
inline constexpr ParameterSpec PLANT_PART_LENGTH{ "SunflowerPlant.part_lengths", 1.0, 0.0, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD, 3 };
inline constexpr ParameterSpec PLANT_HEIGHT_UNITS{ "SunflowerPlant.height_units", 3.2, 1e-4, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_CULL_RADIUS_UNITS{ "SunflowerPlant.cull_radius_units", 1.9, 1e-4, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec PLANT_STIFFNESS{ "SunflowerPlant.stiffness", 1.0, 0.05, 20.0, ParameterSpec::CLAMP, 1.0, ParameterSpec::REBUILD };
// A plant of one part's leaves in the wind (shaders/plant_bend.gdshaderinc): its upper part moves about
// its bent place by up to this share of the bend's own sway at the top (0: still, the sunflower's).
inline constexpr ParameterSpec PLANT_FLUTTER{ "SunflowerPlant.flutter", 0.0, 0.0, 1.0, ParameterSpec::CLAMP, 0.0 };
// A plant type's far shadows: in the shadow pass its impostor casts from the depth the plant has at
// each pixel, moved this share of its frame towards the light (0.03 suits the sunflower: a field of
// its impostors is then about as bright as its meshes, tools/measure_lod.sh).
inline constexpr ParameterSpec PLANT_IMPOSTOR_SHADOW_SHIFT{ "SunflowerPlant.impostor_shadow_shift", 0.03, 0.0, 0.5, ParameterSpec::CLAMP, 0.03 };
// A plant type's far glow: its emission atlas holds the light its parts give off divided by this, so
// that 8-bit colours keep energies up to it. The baker picks the smallest of 8, 64, 512 … in which no
// pixel of the atlas saturates.
inline constexpr ParameterSpec PLANT_IMPOSTOR_EMISSION_RANGE{ "SunflowerPlant.impostor_emission_range", 8.0, 1.0, 32768.0, ParameterSpec::CLAMP, 8.0 };
inline constexpr ParameterSpec PLANT_MIDDLE_VARIATION{ "SunflowerPlant.middle_variation", 0.1, 0.0, 10.0, ParameterSpec::CLAMP, 0.1, ParameterSpec::REBUILD };
inline constexpr ParameterSpec CHUNK_SIZE{ "SunflowerField.chunk_size", 16.0, 0.5, 4096.0, ParameterSpec::KEEP, 0.0, ParameterSpec::REBUILD };
// 0 means the parser's own limit (MapLimits::max_plants).
inline constexpr ParameterSpec MAX_PLANTS{ "SunflowerField.max_plants", 4'000'000, 0.0, 100'000'000, ParameterSpec::CLAMP, 4'000'000, ParameterSpec::REBUILD };

// Levels of detail (thesis 3.2–3.3: 0.25 s between updates; the hysteresis is this addon's).
// The switch distances, metres: mesh 1 → 2, 2 → 3, 3 → sprite, sprite → billboard (thesis: 6, 10,
// 20, 25); four that fail check_lod_distances keep the current ones. The default is the first's.
inline constexpr ParameterSpec LOD_DISTANCES{ "SunflowerField.lod_distances", 6.0, 0.0, NO_MAX, ParameterSpec::KEEP, 0.0, ParameterSpec::FREE, 4 };
inline constexpr ParameterSpec LOD_HYSTERESIS{ "SunflowerField.lod_hysteresis", 0.5, 0.0, NO_MAX, ParameterSpec::CLAMP, 0.5 };
inline constexpr ParameterSpec LOD_INTERVAL{ "SunflowerField.lod_interval", 0.25, 0.0, NO_MAX, ParameterSpec::CLAMP, 0.25 };
// Metres over which a plant leaving mesh 3 dithers into its impostor, ending where the sprite takes
// over however the plant last switched (the switch distance less the hysteresis); 0: no fade.
inline constexpr ParameterSpec LOD_FADE{ "SunflowerField.lod_fade", 3.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 3.0 };
inline constexpr ParameterSpec FORCE_LOD{ "SunflowerField.force_lod", -1.0, -1.0, 4.0, ParameterSpec::CLAMP, -1.0 };

// Drawing (applied by the engine side: shader parameters and visibility ranges).
inline constexpr ParameterSpec ALPHA_SCISSOR{ "SunflowerField.alpha_scissor", 190.0 / 255.0, 0.0, 1.0, ParameterSpec::CLAMP, 190.0 / 255.0 };
inline constexpr ParameterSpec THINNING_DISTANCE{ "SunflowerField.thinning_distance", 0.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 0.0 };
inline constexpr ParameterSpec THINNING_MIN_DENSITY{ "SunflowerField.thinning_min_density", 0.25, 0.01, 1.0, ParameterSpec::CLAMP, 0.25 };
// Far tiles merge with distance: plants this far from the observer are drawn by tiles of 2 × 2
// tiles holding a quarter of their plants, from twice it 4 × 4 with a sixteenth, and so on, fading
// in over the half octave before (FieldSimulation::choose_tile_level); 0: tiles never merge.
inline constexpr ParameterSpec TILE_MERGE_DISTANCE{ "SunflowerField.tile_merge_distance", 200.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 200.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec MAX_DRAW_DISTANCE{ "SunflowerField.max_draw_distance", 0.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 0.0 };

// Performance, machine-wide (Project Settings). 0 threads: the machine's cores, at most MAX_AUTO_THREADS.
inline constexpr ParameterSpec BUILD_BUDGET_MS{ "ProjectSettings.sunflower_field/performance/build_budget_ms", 8.0, 1.0, 100.0, ParameterSpec::CLAMP, 8.0 };
constexpr uint32_t MAX_AUTO_THREADS = 4;
constexpr uint32_t MAX_THREADS = 16;
inline constexpr ParameterSpec WORKER_THREADS{ "ProjectSettings.sunflower_field/performance/worker_threads", 0.0, 0.0, MAX_THREADS, ParameterSpec::CLAMP, 0.0 };
// A frame budget (field_budget.gd), machine-wide: a cap on a viewport's near meshes' triangles a frame
// and a target for its GPU time (0: none), and the least share of their distances its fields go down to.
inline constexpr ParameterSpec BUDGET_PRIMITIVES{ "ProjectSettings.sunflower_field/frame_budget/max_primitives", 0.0, 0.0, 2e9, ParameterSpec::CLAMP, 0.0 };
inline constexpr ParameterSpec BUDGET_GPU_MS{ "ProjectSettings.sunflower_field/frame_budget/gpu_ms", 0.0, 0.0, 10000.0, ParameterSpec::CLAMP, 0.0 };
inline constexpr ParameterSpec BUDGET_MIN_QUALITY{ "ProjectSettings.sunflower_field/frame_budget/min_quality", 0.25, 0.05, 1.0, ParameterSpec::CLAMP, 0.25 };

// Plants that part around bodies: the largest push (as a bend, radians of tilt at the bottom part
// times its stiffness: the same unit as the wind's), and the seconds a plant takes to spring back.
inline constexpr ParameterSpec PUSH_STRENGTH{ "SunflowerField.push_strength", 1.2, 0.0, 10.0, ParameterSpec::CLAMP, 1.2 };
inline constexpr ParameterSpec PUSH_RECOVERY{ "SunflowerField.push_recovery_time", 1.5, 0.05, 60.0, ParameterSpec::CLAMP, 1.5 };
inline constexpr ParameterSpec PUSHER_RADIUS{ "SunflowerField.pusher_radius", 0.6, 0.01, 20.0, ParameterSpec::CLAMP, 0.6 };
// Pushers push over (trample: flatten) the standing plants whose roots lie within this share of their
// radius; 0: they only bend them.
inline constexpr ParameterSpec TRAMPLE_SHARE{ "SunflowerField.trample_share", 0.0, 0.0, 1.0, ParameterSpec::CLAMP, 0.0 };
// A plant type's recovery on the field's clock: seconds until a flattened plant stands again and
// until a cut one has grown again; 0: never.
inline constexpr ParameterSpec PLANT_RECOVER_AFTER{ "SunflowerPlant.recover_after", 0.0, 0.0, 1.0e7, ParameterSpec::CLAMP, 0.0 };
inline constexpr ParameterSpec PLANT_REGROW_AFTER{ "SunflowerPlant.regrow_after", 0.0, 0.0, 1.0e7, ParameterSpec::CLAMP, 0.0 };
// What a cut plant of a type leaves: a stump this many metres tall (its bottom part, shortened; at
// most that part's length), drawn near as a mesh; 0: nothing.
inline constexpr ParameterSpec PLANT_STUMP_HEIGHT{ "SunflowerPlant.stump_height", 0.0, 0.0, 100.0, ParameterSpec::CLAMP, 0.0 };

// Stalk colliders stand within this reach of each pusher and of the observer; 0: none.
inline constexpr ParameterSpec COLLISION_REACH{ "SunflowerField.collision_reach", 0.0, 0.0, 1000.0, ParameterSpec::CLAMP, 0.0 };

// Ground: how far plants lean towards the ground's normal; where rays for colliders start and end.
inline constexpr ParameterSpec GROUND_TILT{ "SunflowerField.ground_tilt", 0.0, 0.0, 1.0, ParameterSpec::CLAMP, 0.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec GROUND_RAY_ABOVE{ "SunflowerField.ground_ray_above", 100.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 100.0, ParameterSpec::REBUILD };
inline constexpr ParameterSpec GROUND_RAY_BELOW{ "SunflowerField.ground_ray_below", 100.0, 0.0, NO_MAX, ParameterSpec::CLAMP, 100.0, ParameterSpec::REBUILD };

inline constexpr std::array<const ParameterSpec *, 56> ALL{ { &WIND_MODEL, &WIND_DIRECTION, &LOD_DISTANCES, &WIND_EASE_TIME, &WIND_POWER, &WIND_INCREMENT, &WIND_STIFFNESS_MIDDLE,
		&WIND_STIFFNESS_BOTTOM, &WIND_BEND_PER_POWER, &WIND_MAX_BEND, &WIND_FLIP_INTERVAL, &WIND_FLIP_CHANCE,
		&WIND_GUST_SPEED, &WIND_GUST_SHARE, &CELL_SIZE, &PLANT_HEIGHT, &CHUNK_SIZE, &MAX_PLANTS, &LOD_HYSTERESIS,
		&LOD_INTERVAL, &LOD_FADE, &FORCE_LOD, &ALPHA_SCISSOR, &THINNING_DISTANCE, &THINNING_MIN_DENSITY, &TILE_MERGE_DISTANCE, &MAX_DRAW_DISTANCE,
		&BUILD_BUDGET_MS, &WORKER_THREADS, &BUDGET_PRIMITIVES, &BUDGET_GPU_MS, &BUDGET_MIN_QUALITY, &PUSH_STRENGTH, &PUSH_RECOVERY, &PUSHER_RADIUS, &TRAMPLE_SHARE,
		&COLLISION_REACH, &GROUND_TILT, &GROUND_RAY_ABOVE, &GROUND_RAY_BELOW, &PLANT_YAW_RANGE, &PLANT_SCALE_MIN, &PLANT_SCALE_MAX,
		&PLANT_MIDDLE_VARIATION, &PLANT_BRIGHTNESS_VARIATION, &PLANT_TINT_VARIATION, &PLANT_STIFFNESS, &PLANT_FLUTTER,
		&PLANT_IMPOSTOR_SHADOW_SHIFT, &PLANT_IMPOSTOR_EMISSION_RANGE, &PLANT_PART_LENGTH, &PLANT_HEIGHT_UNITS,
		&PLANT_CULL_RADIUS_UNITS, &PLANT_RECOVER_AFTER, &PLANT_REGROW_AFTER, &PLANT_STUMP_HEIGHT } };

} // namespace param

// The spec called p_name, or null.
const ParameterSpec *find_parameter(std::string_view p_name);
// Whether a setting is a plant type's (set per species) rather than the field's or its wind's.
bool is_plant_setting(const ParameterSpec &p_spec);
// The value the core uses when asked for p_value while p_current is set.
double sanitize(const ParameterSpec &p_spec, double p_value, double p_current);
inline float sanitize(const ParameterSpec &p_spec, float p_value, float p_current) {
	return static_cast<float>(sanitize(p_spec, double(p_value), double(p_current)));
}
// Why p_value became p_used, for a warning: "nan is not a finite number; using 0". Empty when
// p_value was taken as it is.
std::string explain_sanitized(const ParameterSpec &p_spec, double p_value, double p_used);

// A unit's settings of one float each: the member of its parameters (Params) a table row sets.
template <class Params>
struct FloatRow {
	const ParameterSpec *spec;
	float Params::*member;
};
// What setting a row did to a unit's parameters (set_float_row, the units' set functions).
enum class RowSet : uint8_t {
	OTHER, // not the unit's row
	SAME, // the value, by the row's rules, is the one held
	CHANGED,
};
// Sets r_held, a unit's value of row p_spec (a float, an int, a double), to p_value by the row's
// rules.
template <class T>
RowSet set_row_value(T &r_held, const ParameterSpec &p_spec, double p_value) {
	const T value = T(sanitize(p_spec, p_value, double(r_held)));
	if (value == r_held) {
		return RowSet::SAME;
	}
	r_held = value;
	return RowSet::CHANGED;
}

// Sets r_params' member of row p_spec among p_rows to p_value by the row's rules.
template <class Params, size_t N>
RowSet set_float_row(Params &r_params, const FloatRow<Params> (&p_rows)[N], const ParameterSpec &p_spec, float p_value) {
	for (const FloatRow<Params> &row : p_rows) {
		if (row.spec == &p_spec) {
			return set_row_value(r_params.*row.member, p_spec, double(p_value));
		}
	}
	return RowSet::OTHER;
}

// The wind direction (x, z): a zero or non-finite vector means +x.
glm::vec2 sanitize_wind_direction(const glm::vec2 &p_direction);
// What is wrong with LOD switch distances (four, positive, increasing), or empty when nothing is.
std::string check_lod_distances(const float *p_distances, size_t p_count);

} // namespace sunflower
