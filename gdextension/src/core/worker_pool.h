#pragma once
// A small fixed pool of threads that runs one parallel loop at a time; the calling thread takes
// part. The threads are made once, in the constructor, and joined in the destructor: running a
// loop creates no thread and allocates nothing.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace sunflower {

class WorkerPool {
public:
	using Task = void (*)(void *p_context, uint32_t p_index);

	// p_threads: threads in all, the caller included (1: no extra thread, loops run on the caller).
	explicit WorkerPool(uint32_t p_threads);
	~WorkerPool();
	WorkerPool(const WorkerPool &) = delete;
	WorkerPool &operator=(const WorkerPool &) = delete;

	uint32_t get_thread_count() const { return static_cast<uint32_t>(_threads.size()) + 1; }

	// Calls p_task(p_context, i) once for every i in [0, p_count), spread over the threads, and
	// returns when all calls have returned. Not reentrant: one loop at a time, from one thread.
	void run(uint32_t p_count, Task p_task, void *p_context);

	// The same for a callable taking the index (kept by reference, so no allocation).
	template <typename F>
	void run(uint32_t p_count, F &p_function) {
		run(p_count, [](void *p_context, uint32_t p_index) { (*static_cast<F *>(p_context))(p_index); }, &p_function);
	}

private:
	void _work();
	void _take_tasks();

	std::vector<std::thread> _threads;
	std::mutex _mutex;
	std::condition_variable _wake;
	std::condition_variable _done;
	uint64_t _generation = 0; // counts loops; a worker wakes when it changes
	uint32_t _busy = 0; // workers not yet finished with the current loop
	bool _stop = false;

	Task _task = nullptr;
	void *_context = nullptr;
	uint32_t _count = 0;
	std::atomic<uint32_t> _next{ 0 };
};

} // namespace sunflower
