#include "worker_pool.h"

namespace sunflower {

WorkerPool::WorkerPool(uint32_t p_threads) {
	for (uint32_t i = 1; i < p_threads; ++i) {
		_threads.emplace_back([this] { _work(); });
	}
}

WorkerPool::~WorkerPool() {
	{
		std::lock_guard<std::mutex> lock(_mutex);
		_stop = true;
	}
	_wake.notify_all();
	for (std::thread &thread : _threads) {
		thread.join();
	}
}

void WorkerPool::run(uint32_t p_count, Task p_task, void *p_context) {
	if (p_count == 0) {
		return;
	}
	if (_threads.empty() || p_count == 1) {
		for (uint32_t i = 0; i < p_count; ++i) {
			p_task(p_context, i);
		}
		return;
	}
	{
		std::lock_guard<std::mutex> lock(_mutex);
		_task = p_task;
		_context = p_context;
		_count = p_count;
		_next.store(0, std::memory_order_relaxed);
		_busy = static_cast<uint32_t>(_threads.size());
		++_generation;
	}
	_wake.notify_all();
	_take_tasks();
	std::unique_lock<std::mutex> lock(_mutex);
	_done.wait(lock, [this] { return _busy == 0; });
}

void WorkerPool::_take_tasks() {
	for (uint32_t i = _next.fetch_add(1, std::memory_order_relaxed); i < _count; i = _next.fetch_add(1, std::memory_order_relaxed)) {
		_task(_context, i);
	}
}

void WorkerPool::_work() {
	uint64_t seen = 0;
	for (;;) {
		{
			std::unique_lock<std::mutex> lock(_mutex);
			_wake.wait(lock, [this, seen] { return _stop || _generation != seen; });
			if (_stop) {
				return;
			}
			seen = _generation;
		}
		_take_tasks();
		bool last = false;
		{
			std::lock_guard<std::mutex> lock(_mutex);
			last = --_busy == 0;
		}
		if (last) {
			_done.notify_one();
		}
	}
}

} // namespace sunflower
