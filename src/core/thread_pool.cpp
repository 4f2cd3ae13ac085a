#include "core/thread_pool.hpp"

#include <sched.h>

#include <algorithm>

namespace facet {

unsigned available_cores() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return static_cast<unsigned>(CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}

ThreadPool::ThreadPool(unsigned threads) {
    if (threads == 0) threads = available_cores();
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (auto& worker : workers_) worker.join();
}

void ThreadPool::run_tasks() {
    for (;;) {
        size_t i = next_.fetch_add(1, std::memory_order_relaxed);
        if (i >= count_) return;
        try {
            (*task_)(i);
        } catch (...) {
            std::lock_guard lock(mutex_);
            if (!failure_) failure_ = std::current_exception();
            next_.store(count_, std::memory_order_relaxed);  // stop handing out work
        }
    }
}

void ThreadPool::worker_loop() {
    unsigned seen = 0;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
        }
        run_tasks();
        {
            std::lock_guard lock(mutex_);
            if (--busy_ == 0) done_.notify_all();
        }
    }
}

void ThreadPool::parallel_for(size_t count, const std::function<void(size_t)>& task) {
    if (count == 0) return;
    if (workers_.empty() || count == 1) {
        for (size_t i = 0; i < count; ++i) task(i);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        task_ = &task;
        count_ = count;
        next_.store(0);
        busy_ = workers_.size();
        failure_ = nullptr;
        ++generation_;
    }
    wake_.notify_all();
    run_tasks();
    std::exception_ptr failure;
    {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return busy_ == 0; });
        failure = failure_;
        task_ = nullptr;
    }
    if (failure) std::rethrow_exception(failure);
}

void ThreadPool::parallel_for_chunks(size_t count, size_t chunk_size,
                                     const std::function<void(size_t, size_t)>& task) {
    const size_t chunks = (count + chunk_size - 1) / chunk_size;
    parallel_for(chunks, [&](size_t chunk) {
        const size_t first = chunk * chunk_size;
        task(first, std::min(first + chunk_size, count));
    });
}

void run_each(ThreadPool* pool, size_t count, const std::function<void(size_t)>& task) {
    if (pool && count > 1) {
        pool->parallel_for(count, task);
    } else {
        for (size_t i = 0; i < count; ++i) task(i);
    }
}

void run_ranges(ThreadPool* pool, size_t count, size_t range_size,
                const std::function<void(size_t, size_t)>& task) {
    if (pool && count > range_size)
        pool->parallel_for_chunks(count, range_size, task);
    else
        task(0, count);
}

}  // namespace facet
