#pragma once
// A fixed set of worker threads that run index ranges. Work is handed out
// as whole task indices; callers make results depend only on the index,
// never on which thread ran it, so output is the same for any thread count.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace facet {

// The cores this process may run on: its CPU affinity, which a batch
// scheduler (Slurm, Kubernetes, taskset) narrows to the cores it allotted,
// unlike std::thread::hardware_concurrency, which counts the whole machine.
unsigned available_cores();

class ThreadPool {
  public:
    // threads == 0 picks available_cores().
    explicit ThreadPool(unsigned threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

    // Runs task(i) for every i in [0, count), on all threads including the
    // caller, and returns when all are done. The first exception is rethrown.
    void parallel_for(size_t count, const std::function<void(size_t)>& task);

    // Runs task(first, last) over [0, count) cut into fixed chunks of
    // `chunk_size` items: the cut depends on the sizes alone, never on the
    // thread count.
    void parallel_for_chunks(size_t count, size_t chunk_size,
                             const std::function<void(size_t first, size_t last)>& task);

  private:
    void worker_loop();
    void run_tasks();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(size_t)>* task_ = nullptr;
    size_t count_ = 0;
    std::atomic<size_t> next_{0};
    size_t busy_ = 0;
    unsigned generation_ = 0;
    bool stopping_ = false;
    std::exception_ptr failure_;
};

// Runs task(i) for every i in [0, count): on the pool when there is one,
// else on the calling thread.
void run_each(ThreadPool* pool, size_t count, const std::function<void(size_t)>& task);

// Runs task(first, last) over [0, count) in fixed ranges of `range_size`
// items (as parallel_for_chunks): on the pool when there is one and the
// work is more than one range, else as one range on the calling thread.
// Callers make each item's result depend on the item alone.
void run_ranges(ThreadPool* pool, size_t count, size_t range_size,
                const std::function<void(size_t first, size_t last)>& task);

}  // namespace facet
