#pragma once
// SunflowerParameters: the core's parameter table (core/parameters.h) for the addon's setters and
// inspector: each setting's limits, default, cost and values, and the rules a value is judged by.
// Static methods only; nothing to make.
#include "binding/godot_api.h"

class SunflowerParameters {
public:
	static constexpr const char *CLASS = "SunflowerParameters";
	static void bind_methods();

	static double sanitize_parameter(const gdx::String &p_name, double p_value, double p_current);
	static gdx::String explain_parameter(const gdx::String &p_name, double p_value, double p_used);
	// A row's cost column (0 free, 1 a rebuild: ParameterSpec::Cost) and its count of values; -1
	// for a name not in the table.
	static int64_t get_parameter_cost(const gdx::String &p_name);
	static int64_t get_parameter_components(const gdx::String &p_name);
	static double get_parameter_default(const gdx::String &p_name);
	static double get_parameter_limit(const gdx::String &p_name, bool p_upper);
	static gdx::String get_parameter_names();
	static gdx::String check_lod_distances(const gdx::PackedFloat32Array &p_distances);
	static gdx::Vector2 sanitize_wind_direction(gdx::Vector2 p_direction);
};
