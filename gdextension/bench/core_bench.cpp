// Core benchmark, no engine: per-frame update time (wind + LOD + buffer writes) along a scripted
// walk over fields of several sizes. Prints medians and 99th percentiles, not pass/fail.
#include "bench_maps.h"
#include "field_simulation.h"
#include "tile_reorder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

using namespace sunflower;
using sunflower_bench::rect_map;

namespace {

double percentile(std::vector<double> p_values, double p_q) {
	std::sort(p_values.begin(), p_values.end());
	return p_values[std::min(p_values.size() - 1, static_cast<size_t>(p_q * double(p_values.size())))];
}

struct Result {
	double median = 0.0;
	double p99 = 0.0;
};

struct Walk {
	glm::vec2 centre{ 0.0f };
	float radius = -1.0f; // < 0: a circle of 0.3 × the field's size around its centre
	uint32_t threads = 1; // worker threads, the caller included
	float mesh_reach = 20.0f; // the mesh 3 → sprite distance: how far the near work reaches
	bool print = true;
	int wind_model = WIND_NATURAL;
	int pushers = 0; // bodies walking with the camera, 0.6 m radius, on a 2 m ring around it
	bool whole = true; // near plants drawn whole, as the node draws the built-in plants; else part by part
};

struct Run {
	Result result;
	uint32_t active_plants = 0;
};

// A camera 1.7 m high walking a circle, looking along its path (a 90° frustum, as a Camera3D
// gives it: outward planes); the per-frame update timed.
Run walk(FieldSimulation &r_sim, int p_frames, const Walk &p_walk) {
	PlantShape shape = r_sim.plants().get_shape();
	shape.whole = p_walk.whole;
	r_sim.set_shape(shape);
	const glm::vec2 size = r_sim.plants().get_layout().size;
	std::vector<double> times;
	times.reserve(static_cast<size_t>(p_frames));
	uint64_t active = 0;
	for (int frame = 0; frame < p_frames; ++frame) {
		const float angle = float(frame) * 0.004f;
		const float radius = p_walk.radius < 0.0f ? std::min(size.x, size.y) * 0.3f : p_walk.radius;
		const glm::vec2 centre = p_walk.radius < 0.0f ? size * 0.5f : p_walk.centre;
		const glm::vec3 eye(centre.x + radius * std::cos(angle), 1.7f, centre.y + radius * std::sin(angle));
		const glm::vec3 forward(-std::sin(angle), 0.0f, std::cos(angle));
		const glm::vec3 right(forward.z, 0.0f, -forward.x);
		const glm::vec4 planes[4] = {
			glm::vec4(-forward, glm::dot(-forward, eye)), // near plane: nothing behind the eye
			glm::vec4(glm::normalize(right - forward), glm::dot(glm::normalize(right - forward), eye)),
			glm::vec4(glm::normalize(-right - forward), glm::dot(glm::normalize(-right - forward), eye)),
			glm::vec4(0.0f, 1.0f, 0.0f, 1000.0f),
		};
		r_sim.near().get_frustum().set_planes(planes, 4);
		r_sim.near().set_observer(eye);
		std::vector<Pusher> bodies;
		for (int b = 0; b < p_walk.pushers; ++b) {
			const float around = float(b) * TAU / float(p_walk.pushers);
			bodies.push_back(Pusher{ eye + glm::vec3(2.0f * std::cos(around), -0.7f, 2.0f * std::sin(around)), 0.6f });
		}
		r_sim.near().get_pushes().set_pushers(bodies.data(), bodies.size());
		const auto start = std::chrono::steady_clock::now();
		r_sim.update(1.0f / 60.0f);
		times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
		active += r_sim.near().get_active_plant_count();
	}
	return Run{ Result{ percentile(times, 0.5), percentile(times, 0.99) }, static_cast<uint32_t>(active / uint64_t(p_frames)) };
}

Result run(const char *p_name, const std::string &p_text, int p_frames, const Walk &p_walk = Walk{}) {
	FieldSimulation sim;
	MapError error;
	const auto load_start = std::chrono::steady_clock::now();
	if (!sim.load_map(p_text, U"", p_name, MapLimits{}, error)) {
		std::printf("%s: %s\n", p_name, error.to_string().c_str());
		return Result{};
	}
	const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
	sim.near().set_worker_threads(p_walk.threads);
	WindParams wind;
	wind.model = p_walk.wind_model;
	wind.power = 3.0f;
	sim.near().set_wind(wind);
	LodParams lod;
	lod.distances = { 6.0f, 10.0f, p_walk.mesh_reach, p_walk.mesh_reach + 5.0f };
	sim.near().set_lod(lod);
	const Result result = walk(sim, p_frames, p_walk).result;
	if (!p_walk.print) {
		return result;
	}
	const double mb = double(sim.get_memory_bytes()) / 1e6;
	std::printf("| %-18s | %9u | %8.1f | %9.3f | %8.3f | %8.1f | %9.1f |\n", p_name, sim.plants().get_plant_count(), load_ms,
			result.median, result.p99, mb, double(sim.get_memory_bytes()) / sim.plants().get_plant_count());
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
	// 1M and 4M along the same absolute path (a 100 m circle around (250, 250) m), with the node's
	// default threads (0: the machine's cores, at most 4; split from 32768 near plants).
	Walk path;
	path.centre = glm::vec2(250.0f);
	path.radius = 100.0f;
	path.threads = 0;
	const Result one = run("1M 1000x1000", rect_map(1000, 1000), 1200, path);
	const Result four = run("4M 2000x2000", rect_map(2000, 2000), 1200, path);
	std::printf("\n4M vs 1M per frame, same path, same run: median %.2fx, p99 %.2fx\n", four.median / one.median,
			four.p99 / one.p99);

	// The wind models' cost per near plant, and what pushers add, on one thread along the 1M walk.
	std::printf("\nWind models, parts and pushers (1M field, power 3, one thread, 1200 frames each; plants drawn whole\n"
				"unless said):\n\n");
	std::printf("| run | median ms | p99 ms | near plants | ns per near plant |\n|---|---|---|---|---|\n");
	Walk one_thread = path;
	one_thread.threads = 1;
	one_thread.print = false;
	double per_plant[2] = { 0.0, 0.0 };
	Result no_pushers;
	for (int model : { WIND_THESIS, WIND_NATURAL }) {
		FieldSimulation sim;
		MapError error;
		sim.load_map(rect_map(1000, 1000), U"", "1M", MapLimits{}, error);
		sim.near().set_worker_threads(1);
		WindParams wind;
		wind.model = model;
		wind.power = 3.0f;
		sim.near().set_wind(wind);
		const Run result = walk(sim, 1200, one_thread);
		per_plant[model] = result.result.median * 1e6 / result.active_plants;
		no_pushers = result.result;
		std::printf("| %s wind | %.3f | %.3f | %u | %.1f |\n", model == WIND_THESIS ? "thesis" : "natural",
				result.result.median, result.result.p99, result.active_plants, per_plant[model]);
	}
	{
		FieldSimulation sim;
		MapError error;
		sim.load_map(rect_map(1000, 1000), U"", "1M", MapLimits{}, error);
		sim.near().set_worker_threads(1);
		Walk parts = one_thread;
		parts.whole = false;
		const Run result = walk(sim, 1200, parts);
		std::printf("| natural wind, part by part | %.3f | %.3f | %u | %.1f |\n", result.result.median, result.result.p99,
				result.active_plants, result.result.median * 1e6 / result.active_plants);
	}
	{
		FieldSimulation sim;
		MapError error;
		sim.load_map(rect_map(1000, 1000), U"", "1M", MapLimits{}, error);
		sim.near().set_worker_threads(1);
		Walk pushed = one_thread;
		pushed.pushers = 10;
		const Run result = walk(sim, 1200, pushed);
		std::printf("| natural wind + 10 pushers | %.3f | %.3f | %u | (%u plants pushed or springing back) |\n",
				result.result.median, result.result.p99, result.active_plants, sim.near().get_pushes().get_pushed_count());
		std::printf("\nnatural vs thesis per near plant: %.2fx; 10 pushers add %.3f ms to the median frame\n",
				per_plant[WIND_NATURAL] / per_plant[WIND_THESIS], result.result.median - no_pushers.median);
	}

	// Where a second thread pays: the same walk over the 1M field with the near work grown by
	// pushing the mesh → sprite distance out, on one thread and on two (the split forced on).
	std::printf("\nNear work on one thread and on two (1M field, %u hardware threads), 600 frames each:\n\n",
			std::thread::hardware_concurrency());
	std::printf("| mesh reach m | near plants | 1 thread median / p99 ms | 2 threads median / p99 ms | 2 vs 1 median |\n");
	std::printf("|--------------|-------------|--------------------------|---------------------------|---------------|\n");
	const std::string million = rect_map(1000, 1000);
	for (float reach : { 8.0f, 12.0f, 20.0f, 30.0f, 45.0f, 60.0f }) {
		Run runs[2];
		for (uint32_t threads = 1; threads <= 2; ++threads) {
			FieldSimulation sim;
			MapError error;
			sim.load_map(million, U"", "1M", MapLimits{}, error);
			sim.near().set_worker_threads(threads);
			sim.near().set_parallel_min_plants(0);
			LodParams lod;
			lod.distances = { std::min(6.0f, reach * 0.4f), std::min(10.0f, reach * 0.7f), reach, reach + 5.0f };
			sim.near().set_lod(lod);
			runs[threads - 1] = walk(sim, 600, path);
		}
		std::printf("| %12.0f | %11u | %11.3f / %-10.3f | %12.3f / %-10.3f | %12.2fx |\n", double(reach),
				runs[0].active_plants, runs[0].result.median, runs[0].result.p99, runs[1].result.median, runs[1].result.p99,
				runs[1].result.median / runs[0].result.median);
	}
	// Ground: laying out a 1M field (what a build's worker does) flat, on a height map and on listed
	// heights (the collider rays' results), five times each; and the memory per plant on the map.
	{
		std::printf("\nGround placement of the 1M field (1000 x 1000 cells, 500 x 500 m), layout on one thread, 5 runs:\n\n");
		std::printf("| ground | median ms | min ms | B / plant |\n|---|---|---|---|\n");
		FieldSimulation sim;
		MapError error;
		sim.load_map(rect_map(1000, 1000), U"", "1M", MapLimits{}, error);
		Ground grid;
		grid.kind = Ground::GRID;
		grid.grid.width = grid.grid.depth = 1025; // half a metre between samples
		grid.grid.size = glm::vec2(500.0f);
		for (int z = 0; z < 1025; ++z) {
			for (int x = 0; x < 1025; ++x) {
				grid.grid.heights.push_back(6.0f * std::sin(float(x) * 0.011f) * std::cos(float(z) * 0.013f));
			}
		}
		std::vector<glm::vec2> points;
		ground_points(sim.plants().get_map(), sim.plants().get_layout_params(), points);
		Ground listed;
		listed.kind = Ground::HEIGHTS;
		for (const glm::vec2 &point : points) {
			listed.heights.push_back(grid.grid.sample(point));
		}
		const std::pair<const char *, const Ground *> grounds[] = { { "flat", nullptr }, { "height map 1025 x 1025", &grid },
			{ "listed heights (colliders)", &listed } };
		for (const auto &[name, ground] : grounds) {
			std::vector<double> times;
			for (int r = 0; r < 5; ++r) {
				const auto start = std::chrono::steady_clock::now();
				sim.set_ground(ground ? *ground : Ground{});
				times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
			}
			std::printf("| %s | %.1f | %.1f | %.1f |\n", name, percentile(times, 0.5), *std::min_element(times.begin(), times.end()),
					double(sim.get_memory_bytes()) / sim.plants().get_plant_count());
		}
	}
	// Far tiles written again nearest the observer first as the binding does it (TileReorder, one tile
	// at a time, 1 024 plants a frame) along the 1M field's 100 m circle: 0.4 m a frame.
	{
		FieldSimulation sim;
		MapError error;
		sim.load_map(rect_map(1000, 1000), U"", "1M", MapLimits{}, error);
		const FarTiles &tiles = sim.tiles();
		TileReorder reorder;
		reorder.resize(tiles.get_tile_count());
		std::vector<float> buffer;
		std::vector<double> frame_times;
		uint32_t completed = 0;
		const int frames = 1200;
		for (int frame = 0; frame < frames; ++frame) {
			const float angle = float(frame) * 0.004f;
			const glm::vec3 eye(250.0f + 100.0f * std::cos(angle), 1.7f, 250.0f + 100.0f * std::sin(angle));
			const auto start = std::chrono::steady_clock::now();
			const uint32_t begun = reorder.begin(tiles, eye);
			if (begun != FarTiles::NO_TILE) {
				buffer.resize(size_t(tiles.get_tile(begun).plants) * FAR_FLOATS_PER_INSTANCE);
			}
			completed += reorder.advance(tiles, buffer.data(), 1024) ? 1 : 0;
			frame_times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
		}
		std::printf("\nFar tiles ordered nearest the observer first, 1 024 plants a frame, along the 1M field's 100 m circle\n"
					"(0.4 m a frame, %d frames, %u tiles): %u tiles written again; the frame's share median %.4f ms, p99 %.3f ms,\n"
					"the most %.3f ms\n",
				frames, tiles.get_tile_count(), completed, percentile(frame_times, 0.5), percentile(frame_times, 0.99),
				*std::max_element(frame_times.begin(), frame_times.end()));
	}
	return 0;
}
