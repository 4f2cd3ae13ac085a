#pragma once
// Storage for the large arrays a frame streams through (images, per-vertex
// and per-triangle records): each starts on a cache line, so threads writing
// neighbouring parts never share a line where their parts meet, and large
// ones sit on huge pages where the kernel allows them for the asking
// (transparent_hugepage "madvise"). A 64-pixel tile touches 64 rows of an
// image and a million triangles spread their records over tens of
// megabytes: with 4 KiB pages the TLB misses cost more than the work.
#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace facet {

void* allocate_bulk(size_t bytes);
void free_bulk(void* p, size_t bytes);

template <typename T>
struct BulkAllocator {
    using value_type = T;
    BulkAllocator() = default;
    template <typename U>
    BulkAllocator(const BulkAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(allocate_bulk(n * sizeof(T))); }
    void deallocate(T* p, size_t n) { free_bulk(p, n * sizeof(T)); }
    // resize(n) without a value leaves trivial elements uninitialised: a
    // frame's buffers are written in full before they are read, and zeroing
    // 40 MB a frame first costs more than it saves.
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    friend bool operator==(const BulkAllocator&, const BulkAllocator&) { return true; }
};

template <typename T>
using BulkVector = std::vector<T, BulkAllocator<T>>;

}  // namespace facet
