// SunflowerParameters: the core's parameter table, read by name.
#include "sunflower_parameters.h"

#include "binding/class_binder.h"
#include "binding/error_macros.h"
#include "convert.h"
#include "core/parameters.h"

using namespace sunflower;

void SunflowerParameters::bind_methods() {
	gdx::bind_method(CLASS, "sanitize_parameter", &SunflowerParameters::sanitize_parameter, { "name", "value", "current" });
	gdx::bind_method(CLASS, "explain_parameter", &SunflowerParameters::explain_parameter, { "name", "value", "used" });
	gdx::bind_method(CLASS, "get_parameter_default", &SunflowerParameters::get_parameter_default, { "name" });
	gdx::bind_method(CLASS, "get_parameter_limit", &SunflowerParameters::get_parameter_limit, { "name", "upper" });
	gdx::bind_method(CLASS, "get_parameter_cost", &SunflowerParameters::get_parameter_cost, { "name" });
	gdx::bind_method(CLASS, "get_parameter_components", &SunflowerParameters::get_parameter_components, { "name" });
	gdx::bind_method(CLASS, "get_parameter_names", &SunflowerParameters::get_parameter_names);
	gdx::bind_method(CLASS, "check_lod_distances", &SunflowerParameters::check_lod_distances, { "distances" });
	gdx::bind_method(CLASS, "sanitize_wind_direction", &SunflowerParameters::sanitize_wind_direction, { "direction" });
	gdx::bind_integer_constant(CLASS, "", "MAX_AUTO_THREADS", param::MAX_AUTO_THREADS);
	gdx::bind_integer_constant(CLASS, "", "MAX_THREADS", param::MAX_THREADS);
}

double SunflowerParameters::sanitize_parameter(const gdx::String &p_name, double p_value, double p_current) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, p_value, "no parameter is called '" + p_name.utf8() + "'");
	return sanitize(*spec, p_value, p_current);
}

gdx::String SunflowerParameters::explain_parameter(const gdx::String &p_name, double p_value, double p_used) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, gdx::String(), "no parameter is called '" + p_name.utf8() + "'");
	return gdx::String(explain_sanitized(*spec, p_value, p_used));
}

double SunflowerParameters::get_parameter_default(const gdx::String &p_name) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, 0.0, "no parameter is called '" + p_name.utf8() + "'");
	return spec->default_value;
}

double SunflowerParameters::get_parameter_limit(const gdx::String &p_name, bool p_upper) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	SF_FAIL_COND_V_MSG(spec == nullptr, 0.0, "no parameter is called '" + p_name.utf8() + "'");
	return p_upper ? spec->max : spec->min;
}

int64_t SunflowerParameters::get_parameter_cost(const gdx::String &p_name) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	return spec ? int64_t(spec->cost) : -1;
}

int64_t SunflowerParameters::get_parameter_components(const gdx::String &p_name) {
	const ParameterSpec *spec = find_parameter(p_name.utf8());
	return spec ? int64_t(spec->components) : -1;
}

gdx::String SunflowerParameters::get_parameter_names() {
	std::string names;
	for (const ParameterSpec *spec : param::ALL) {
		names += (names.empty() ? "" : ",") + std::string(spec->name);
	}
	return gdx::String(names);
}

gdx::String SunflowerParameters::check_lod_distances(const gdx::PackedFloat32Array &p_distances) {
	return gdx::String(sunflower::check_lod_distances(p_distances.data(), size_t(p_distances.size())));
}

gdx::Vector2 SunflowerParameters::sanitize_wind_direction(gdx::Vector2 p_direction) {
	return gdx::to_godot(sunflower::sanitize_wind_direction(gdx::to_core(p_direction)));
}
