#pragma once
// Disjoint sets over one vertex's corners (union by index, path halving):
// the root of a set is its lowest corner, so grouping does not depend on
// the order of the joins. Shared by normal smoothing (mesh_build.cpp) and
// tangent frames (tangent_frames.cpp).
#include <algorithm>
#include <cstdint>
#include <vector>

namespace facet {

struct CornerSets {
    std::vector<uint32_t> parent;
    uint32_t find(uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(uint32_t a, uint32_t b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

}  // namespace facet
