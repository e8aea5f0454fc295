#include "parameters.h"

#include <cmath>
#include <cstdio>

namespace sunflower {

namespace {

std::string format(double p_value) {
	if (std::isnan(p_value)) {
		return "nan";
	}
	if (std::isinf(p_value)) {
		return p_value > 0.0 ? "inf" : "-inf";
	}
	char text[32];
	std::snprintf(text, sizeof(text), "%.6g", p_value);
	return text;
}

std::string describe_range(const ParameterSpec &p_spec) {
	const bool has_min = p_spec.min > param::NO_MIN;
	const bool has_max = p_spec.max < param::NO_MAX;
	if (has_min && has_max) {
		return "outside " + format(p_spec.min) + "–" + format(p_spec.max);
	}
	if (has_min) {
		return "below " + format(p_spec.min);
	}
	return "above " + format(p_spec.max);
}

} // namespace

const ParameterSpec *find_parameter(std::string_view p_name) {
	for (const ParameterSpec *spec : param::ALL) {
		if (p_name == spec->name) {
			return spec;
		}
	}
	return nullptr;
}

bool is_plant_setting(const ParameterSpec &p_spec) {
	return std::string_view(p_spec.name).rfind("SunflowerPlant.", 0) == 0;
}

double sanitize(const ParameterSpec &p_spec, double p_value, double p_current) {
	if (!std::isfinite(p_value)) {
		return p_spec.rule == ParameterSpec::KEEP ? p_current : p_spec.fallback;
	}
	if (p_value >= p_spec.min && p_value <= p_spec.max) {
		return p_value;
	}
	if (p_spec.rule == ParameterSpec::KEEP) {
		return p_current;
	}
	return p_value < p_spec.min ? p_spec.min : p_spec.max;
}

std::string explain_sanitized(const ParameterSpec &p_spec, double p_value, double p_used) {
	if (p_value == p_used) {
		return std::string();
	}
	const std::string problem = std::isfinite(p_value) ? " is " + describe_range(p_spec) : " is not a finite number";
	const std::string outcome = p_spec.rule == ParameterSpec::KEEP ? "; keeping " : "; using ";
	return format(p_value) + problem + outcome + format(p_used);
}

glm::vec2 sanitize_wind_direction(const glm::vec2 &p_direction) {
	const bool usable = std::isfinite(p_direction.x) && std::isfinite(p_direction.y) &&
			(std::abs(p_direction.x) > 1e-5f || std::abs(p_direction.y) > 1e-5f);
	return usable ? p_direction : glm::vec2(1.0f, 0.0f);
}

std::string check_lod_distances(const float *p_distances, size_t p_count) {
	if (p_count != 4) {
		return "needs 4 distances, got " + std::to_string(p_count);
	}
	for (size_t i = 0; i < 4; ++i) {
		if (!std::isfinite(p_distances[i]) || p_distances[i] <= 0.0f) {
			return "distance " + std::to_string(i + 1) + " (" + format(p_distances[i]) + ") is not a positive number";
		}
		if (i > 0 && p_distances[i] <= p_distances[i - 1]) {
			return "distances must increase (" + format(p_distances[i]) + " after " + format(p_distances[i - 1]) + ")";
		}
	}
	return std::string();
}

} // namespace sunflower
