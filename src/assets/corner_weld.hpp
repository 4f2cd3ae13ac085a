#pragma once
// Vertices from the corners of triangles: corners that are alike become one
// vertex, and vertices are numbered in the order of their first corner.
// Shared by the OBJ loader (corners alike in position, texture coordinate
// and normal index) and normal smoothing (corners of one vertex alike in
// normal).
//
// Corners fall into buckets (a position, a vertex) in which most corners
// are alike: each corner is compared with the first corner of its bucket,
// and only the others (seams, creases) are sorted. No hashing: a file
// cannot make this slow, whatever it holds; O(n + k log k) for k corners
// unlike the first of their bucket. Every step runs over fixed ranges of
// corners, on a pool's threads when there is one; the result is the same
// for any thread count.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/parallel_sort.hpp"
#include "core/thread_pool.hpp"

namespace facet {

struct WeldedCorners {
    std::vector<uint32_t> vertex;        // per corner: its vertex
    std::vector<uint32_t> first_corner;  // per vertex: the corner it is made from
};

namespace corner_weld_detail {

constexpr uint32_t kNone = ~0u;
constexpr size_t kRange = size_t(1) << 16;

// The first corner of each bucket: the least corner that falls in it.
// Threads lower a bucket's entry in turn; the least wins whatever the order.
template <class Bucket>
std::vector<uint32_t> first_in_buckets(size_t count, size_t bucket_count, const Bucket& bucket,
                                       ThreadPool* pool) {
    std::vector<uint32_t> first(bucket_count, kNone);
    run_ranges(pool, count, kRange, [&](size_t begin, size_t end) {
        for (size_t c = begin; c < end; ++c) {
            std::atomic_ref<uint32_t> at(first[bucket(c)]);
            uint32_t seen = at.load(std::memory_order_relaxed);
            const auto corner = static_cast<uint32_t>(c);
            while (corner < seen &&
                   !at.compare_exchange_weak(seen, corner, std::memory_order_relaxed)) {
            }
        }
    });
    return first;
}

// Numbers the corners that are their own first (first[c] == c) in corner
// order, then gives every other corner its first's number, in place: on
// return first[c] is corner c's vertex. Returns each vertex's corner.
inline std::vector<uint32_t> number_first_uses(std::vector<uint32_t>& first, ThreadPool* pool) {
    const size_t count = first.size();
    const size_t ranges = (count + kRange - 1) / kRange;
    std::vector<uint32_t> before(ranges + 1, 0);  // vertices made before each range
    run_each(pool, ranges, [&](size_t r) {
        const size_t end = std::min(count, (r + 1) * kRange);
        for (size_t c = r * kRange; c < end; ++c) before[r + 1] += first[c] == c;
    });
    for (size_t r = 0; r < ranges; ++r) before[r + 1] += before[r];
    std::vector<uint32_t> first_corner(before[ranges]);
    // A corner that is not its own first keeps its first's index (larger
    // than any vertex number only by chance): `is_first` tells them apart.
    std::vector<uint8_t> is_first(count);
    run_each(pool, ranges, [&](size_t r) {
        uint32_t next = before[r];
        const size_t end = std::min(count, (r + 1) * kRange);
        for (size_t c = r * kRange; c < end; ++c) {
            is_first[c] = first[c] == c;
            if (!is_first[c]) continue;
            first_corner[next] = static_cast<uint32_t>(c);
            first[c] = next++;
        }
    });
    // A first lies before its corners and was numbered above.
    run_ranges(pool, count, kRange, [&](size_t begin, size_t end) {
        for (size_t c = begin; c < end; ++c)
            if (!is_first[c]) first[c] = first[first[c]];
    });
    return first_corner;
}

}  // namespace corner_weld_detail

// The vertices of `count` corners. bucket(c): corner c's bucket, below
// `bucket_count`. same(a, b): whether corners a and b of one bucket are
// alike. less(a, b): a strict total order that keeps alike corners of a
// bucket next to each other (by bucket, then by what makes them alike,
// then by corner).
template <class Bucket, class Same, class Less>
WeldedCorners weld_corners(size_t count, size_t bucket_count, const Bucket& bucket,
                           const Same& same, const Less& less, ThreadPool* pool) {
    using namespace corner_weld_detail;
    const std::vector<uint32_t> first_in = first_in_buckets(count, bucket_count, bucket, pool);
    WeldedCorners out;
    std::vector<uint32_t>& first = out.vertex;
    first.resize(count);
    const size_t ranges = (count + kRange - 1) / kRange;
    std::vector<std::vector<uint32_t>> unlike(ranges);  // unlike their bucket's first
    run_each(pool, ranges, [&](size_t r) {
        const size_t end = std::min(count, (r + 1) * kRange);
        for (size_t c = r * kRange; c < end; ++c) {
            const uint32_t at = first_in[bucket(c)];
            if (same(at, c))
                first[c] = at;
            else
                unlike[r].push_back(static_cast<uint32_t>(c));
        }
    });
    std::vector<uint32_t> others;
    for (const std::vector<uint32_t>& u : unlike) others.insert(others.end(), u.begin(), u.end());
    parallel_sort(others, less, pool);
    for (size_t i = 0; i < others.size(); ++i) {
        const uint32_t c = others[i];
        const bool alike = i > 0 && bucket(others[i - 1]) == bucket(c) && same(others[i - 1], c);
        first[c] = alike ? first[others[i - 1]] : c;
    }
    out.first_corner = number_first_uses(first, pool);
    return out;
}

}  // namespace facet
