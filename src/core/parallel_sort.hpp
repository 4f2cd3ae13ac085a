#pragma once
// A sort that uses a pool's threads: runs sorted in parallel, then merged in
// pairs, each pair on its own thread. `less` must be a strict total order
// (no two items tie, e.g. an index as the last key): then the result is
// the one sorted order, whatever the runs, so it does not depend on the
// thread count.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/thread_pool.hpp"

namespace facet {

template <class T, class Less>
void parallel_sort(std::vector<T>& items, Less less, ThreadPool* pool) {
    // Below this, starting the threads costs more than they save.
    constexpr size_t kParallelItems = size_t(1) << 15;
    const size_t n = items.size();
    if (!pool || pool->size() < 2 || n < kParallelItems) {
        std::sort(items.begin(), items.end(), less);
        return;
    }
    size_t runs = 1;
    while (runs < pool->size()) runs *= 2;
    size_t width = (n + runs - 1) / runs;
    pool->parallel_for(runs, [&](size_t r) {
        const size_t first = std::min(n, r * width), last = std::min(n, first + width);
        std::sort(items.begin() + first, items.begin() + last, less);
    });
    std::vector<T> merged(n);
    for (; width < n; width *= 2) {
        const size_t pairs = (n + 2 * width - 1) / (2 * width);
        pool->parallel_for(pairs, [&](size_t p) {
            const size_t first = p * 2 * width, middle = std::min(n, first + width),
                         last = std::min(n, first + 2 * width);
            std::merge(items.begin() + first, items.begin() + middle, items.begin() + middle,
                       items.begin() + last, merged.begin() + first, less);
        });
        items.swap(merged);
    }
}

}  // namespace facet
