#include "core/bulk_buffer.hpp"

#include <new>

#include <sys/mman.h>

namespace facet {
namespace {

constexpr size_t kCacheLine = 64;
constexpr size_t kHugePage = size_t(2) << 20;

}  // namespace

void* allocate_bulk(size_t bytes) {
    if (bytes < kHugePage) return ::operator new (bytes, std::align_val_t{kCacheLine});
    // Rounded up to whole huge pages and aligned to one, so that the kernel
    // can back it with huge pages when it allows them for the asking
    // (transparent_hugepage "madvise"); without, it is an ordinary buffer.
    const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = ::operator new (rounded, std::align_val_t{kHugePage});
    madvise(p, rounded, MADV_HUGEPAGE);
    return p;
}

void free_bulk(void* p, size_t bytes) {
    ::operator delete (p, std::align_val_t{bytes < kHugePage ? kCacheLine : kHugePage});
}

}  // namespace facet
