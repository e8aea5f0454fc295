// Core benchmark, no engine: per-frame update time (wind + LOD + buffer writes) along a scripted
// walk over fields of several sizes. Prints medians and 99th percentiles, not pass/fail.
#include "core/field_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace sunflower;

namespace {

std::string rect_map(int p_columns, int p_rows) {
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	const std::string row(static_cast<size_t>(p_columns), '*');
	for (int r = 0; r < p_rows; ++r) {
		text += row;
		text += '\n';
	}
	return text;
}

double percentile(std::vector<double> p_values, double p_q) {
	std::sort(p_values.begin(), p_values.end());
	return p_values[std::min(p_values.size() - 1, static_cast<size_t>(p_q * double(p_values.size())))];
}

struct Result {
	double median = 0.0;
	double p99 = 0.0;
};

// p_radius < 0: a circle of 0.3 × the field's size around its centre; else this circle around p_centre.
Result run(const char *p_name, const std::string &p_text, int p_frames, glm::vec2 p_centre = glm::vec2(0.0f), float p_radius = -1.0f) {
	FieldSimulation sim;
	MapError error;
	const auto load_start = std::chrono::steady_clock::now();
	if (!sim.load_map(p_text, U"", p_name, MapLimits{}, error)) {
		std::printf("%s: %s\n", p_name, error.to_string().c_str());
		return Result{};
	}
	const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
	const glm::vec2 size = sim.get_layout().size;
	// A camera 1.7 m high walking a circle around the field's centre, looking along its path
	// (a 90° frustum, as a Camera3D gives it: outward planes).
	std::vector<double> times;
	times.reserve(static_cast<size_t>(p_frames));
	for (int frame = 0; frame < p_frames; ++frame) {
		const float angle = float(frame) * 0.004f;
		const float radius = p_radius < 0.0f ? std::min(size.x, size.y) * 0.3f : p_radius;
		const glm::vec2 centre = p_radius < 0.0f ? size * 0.5f : p_centre;
		const glm::vec3 eye(centre.x + radius * std::cos(angle), 1.7f, centre.y + radius * std::sin(angle));
		const glm::vec3 forward(-std::sin(angle), 0.0f, std::cos(angle));
		const glm::vec3 right(forward.z, 0.0f, -forward.x);
		const glm::vec4 planes[4] = {
			glm::vec4(-forward, glm::dot(-forward, eye)), // near plane: nothing behind the eye
			glm::vec4(glm::normalize(right - forward), glm::dot(glm::normalize(right - forward), eye)),
			glm::vec4(glm::normalize(-right - forward), glm::dot(glm::normalize(-right - forward), eye)),
			glm::vec4(0.0f, 1.0f, 0.0f, 1000.0f),
		};
		sim.get_frustum().set_planes(planes, 4);
		sim.set_observer(eye);
		const auto start = std::chrono::steady_clock::now();
		sim.update(1.0f / 60.0f);
		times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
	}
	const Result result{ percentile(times, 0.5), percentile(times, 0.99) };
	const double mb = double(sim.get_memory_bytes()) / 1e6;
	std::printf("| %-18s | %9u | %8.1f | %9.3f | %8.3f | %8.1f | %9.1f |\n", p_name, sim.get_plant_count(), load_ms,
			result.median, result.p99, mb, double(sim.get_memory_bytes()) / sim.get_plant_count());
	return result;
}

} // namespace

int main() {
	std::printf("Core alone (no engine): wind + LOD + buffer writes per frame, a camera walking a circle, 600 frames.\n\n");
	std::printf("| field              |    plants |  load ms | median ms |  p99 ms |  CPU MB | B / plant |\n");
	std::printf("|--------------------|-----------|----------|-----------|---------|---------|-----------|\n");
	run("demo 40x30", rect_map(40, 30), 600);
	run("thesis 50x30", rect_map(50, 30), 600);
	run("large 400x300", rect_map(400, 300), 600);
	// 1M and 4M along the same absolute path (a 100 m circle around (250, 250) m).
	const Result one = run("1M 1000x1000", rect_map(1000, 1000), 1200, glm::vec2(250.0f), 100.0f);
	const Result four = run("4M 2000x2000", rect_map(2000, 2000), 1200, glm::vec2(250.0f), 100.0f);
	std::printf("\n4M vs 1M per frame, same path, same run: median %.2fx, p99 %.2fx\n", four.median / one.median,
			four.p99 / one.p99);
	return 0;
}
