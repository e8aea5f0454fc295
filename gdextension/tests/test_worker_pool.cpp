#include "field_simulation.h"
#include "worker_pool.h"

#include <doctest/doctest.h>

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

using namespace sunflower;

TEST_CASE("the worker pool runs every index exactly once, loop after loop, on more than one thread") {
	WorkerPool pool(3);
	CHECK(pool.get_thread_count() == 3);
	std::vector<std::atomic<int>> hits(1000);
	std::atomic<int> on_other_threads{ 0 };
	const std::thread::id caller = std::this_thread::get_id();
	auto task = [&](uint32_t p_index) {
		hits[p_index].fetch_add(1);
		if (std::this_thread::get_id() != caller) {
			on_other_threads.fetch_add(1);
		}
		// A little work, so the other threads have time to join in.
		volatile double x = 0.0;
		for (int i = 0; i < 2000; ++i) {
			x = x + 1.0;
		}
	};
	for (int loop = 0; loop < 50; ++loop) {
		pool.run(static_cast<uint32_t>(hits.size()), task);
	}
	for (const std::atomic<int> &count : hits) {
		CHECK(count.load() == 50);
	}
	CHECK(on_other_threads.load() > 0);
	pool.run(0, task); // nothing to do is fine
	WorkerPool single(1);
	CHECK(single.get_thread_count() == 1);
	int serial = 0;
	auto count = [&](uint32_t) { ++serial; };
	single.run(7, count);
	CHECK(serial == 7);
}

namespace {

std::string square_map(int p_side) {
	std::string text = std::to_string(p_side) + " " + std::to_string(p_side) + "\n";
	for (int r = 0; r < p_side; ++r) {
		text += std::string(static_cast<size_t>(p_side), '*') + "\n";
	}
	return text;
}

void load(FieldSimulation &r_sim, uint32_t p_threads) {
	MapError error;
	REQUIRE(r_sim.load_map(square_map(120), U"", "pool", MapLimits{}, error));
	LayoutParams layout;
	layout.chunk_size = 4.0f;
	r_sim.set_layout_params(layout);
	WindParams wind;
	wind.power = 3.0f;
	r_sim.near().set_wind(wind);
	r_sim.near().set_worker_threads(p_threads);
	r_sim.near().set_parallel_min_plants(0);
}

} // namespace

TEST_CASE("near plants moved on two threads are written exactly as on one") {
	FieldSimulation serial;
	FieldSimulation parallel;
	load(serial, 1);
	load(parallel, 2);
	CHECK(serial.near().get_worker_threads() == 1);
	CHECK(parallel.near().get_worker_threads() == 2);
	for (int frame = 0; frame < 40; ++frame) {
		const glm::vec3 eye(10.0f + float(frame) * 0.7f, 1.7f, 30.0f);
		serial.near().set_observer(eye);
		parallel.near().set_observer(eye);
		serial.update(0.05f);
		parallel.update(0.05f);
		REQUIRE(parallel.near().get_last_task_count() == 2 * NearField::TASKS_PER_THREAD);
		CHECK(serial.near().get_last_task_count() == 1);
		for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
			const InstanceBuffer &one = serial.near().get_bucket(b);
			const InstanceBuffer &two = parallel.near().get_bucket(b);
			REQUIRE(one.get_count() == two.get_count());
			CHECK(std::memcmp(one.get_data(), two.get_data(), size_t(one.get_count()) * one.get_stride() * sizeof(float)) == 0);
			CHECK(one.get_bounds_low() == two.get_bounds_low()); // the tasks' boxes merged
			CHECK(one.get_bounds_high() == two.get_bounds_high());
		}
	}
	CHECK(serial.near().get_bucket(mesh_bucket(0, 0)).get_count() > 0);
}

TEST_CASE("small near work stays on one thread; the thread count can change and go back to one") {
	FieldSimulation sim;
	load(sim, 2);
	sim.near().set_parallel_min_plants(1u << 30);
	sim.near().set_observer({ 30.0f, 1.7f, 30.0f });
	sim.update(0.05f);
	CHECK(sim.near().get_active_plant_count() > 0);
	CHECK(sim.near().get_last_task_count() == 1);
	sim.near().set_parallel_min_plants(sim.near().get_active_plant_count());
	sim.update(0.05f);
	CHECK(sim.near().get_last_task_count() == 2 * NearField::TASKS_PER_THREAD);
	sim.near().set_worker_threads(3);
	CHECK(sim.near().get_worker_threads() == 3);
	sim.update(0.05f);
	CHECK(sim.near().get_last_task_count() == 3 * NearField::TASKS_PER_THREAD);
	sim.near().set_worker_threads(1);
	sim.update(0.05f);
	CHECK(sim.near().get_last_task_count() == 1);
	sim.near().set_worker_threads(0);
	CHECK(sim.near().get_worker_threads() >= 1);
	CHECK(sim.near().get_worker_threads() <= param::MAX_AUTO_THREADS);
}

TEST_CASE("parallel steady state allocates nothing") {
	FieldSimulation sim;
	load(sim, 2);
	const auto walk = [&]() {
		for (float x = 5.0f; x < 55.0f; x += 0.5f) {
			sim.near().set_observer({ x, 1.7f, 30.0f });
			sim.update(0.05f);
		}
	};
	// Warm up: the runs each task gets differ a little from walk to walk, so its buffers may grow
	// during the first walks; after that, nothing.
	for (int i = 0; i < 3; ++i) {
		walk();
	}
	const size_t bytes = sim.get_memory_bytes();
	std::vector<const float *> data;
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		data.push_back(sim.near().get_bucket(b).get_data());
	}
	walk();
	CHECK(sim.get_memory_bytes() == bytes);
	for (uint32_t b = 0; b < BUCKET_COUNT; ++b) {
		CHECK(sim.near().get_bucket(b).get_data() == data[b]);
	}
}
