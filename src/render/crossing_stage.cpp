#include "render/crossing_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet {
namespace {

struct Box {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    void add(glm::vec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    bool overlaps(const Box& o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y &&
               lo.z <= o.hi.z && o.lo.z <= hi.z;
    }
    float size() const { return glm::length(hi - lo); }
};

using Triangle = std::array<glm::vec3, 3>;

Triangle triangle_at(const World& world, const TransformedVertices& v, uint32_t t) {
    const uint32_t* c = &world.indices[3 * static_cast<size_t>(t)];
    return {v.world_position[c[0]], v.world_position[c[1]], v.world_position[c[2]]};
}

Box box_of(const Triangle& t) {
    Box b;
    for (const glm::vec3& p : t) b.add(p);
    return b;
}

// Where triangle `t` meets the plane (n, d) along direction `axis`: the
// interval of the projections of its crossing points. False unless it has
// vertices strictly on both sides (beyond eps).
bool crossing_interval(const Triangle& t, glm::vec3 n, float d, glm::vec3 axis, float eps,
                       float& lo, float& hi) {
    float dist[3];
    bool above = false, below = false;
    for (int i = 0; i < 3; ++i) {
        dist[i] = glm::dot(n, t[i]) - d;
        above = above || dist[i] > eps;
        below = below || dist[i] < -eps;
    }
    if (!above || !below) return false;
    lo = INFINITY, hi = -INFINITY;
    auto take = [&](glm::vec3 p) {
        const float s = glm::dot(axis, p);
        lo = std::min(lo, s), hi = std::max(hi, s);
    };
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (std::fabs(dist[i]) <= eps) take(t[i]);
        const bool opposite =
            (dist[i] > eps && dist[j] < -eps) || (dist[i] < -eps && dist[j] > eps);
        if (opposite) take(t[i] + (t[j] - t[i]) * (dist[i] / (dist[i] - dist[j])));
    }
    return lo <= hi;
}

bool triangles_cross(const Triangle& a, const Triangle& b, float eps) {
    glm::vec3 na = glm::cross(a[1] - a[0], a[2] - a[0]);
    glm::vec3 nb = glm::cross(b[1] - b[0], b[2] - b[0]);
    const float la = glm::length(na), lb = glm::length(nb);
    if (!(la > 0.0f) || !(lb > 0.0f)) return false;
    na /= la, nb /= lb;
    const glm::vec3 axis = glm::cross(na, nb);
    if (!(glm::dot(axis, axis) > 1e-12f)) return false;  // parallel planes touch at most
    float a_lo, a_hi, b_lo, b_hi;
    if (!crossing_interval(a, nb, glm::dot(nb, b[0]), axis, eps, a_lo, a_hi)) return false;
    if (!crossing_interval(b, na, glm::dot(na, a[0]), axis, eps, b_lo, b_hi)) return false;
    // The segments must share more than a point.
    return std::min(a_hi, b_hi) - std::max(a_lo, b_lo) > eps * glm::length(axis);
}

// The triangles of an object that reach into `region`.
std::vector<uint32_t> triangles_in(const World& world, const TransformedVertices& v,
                                   const std::vector<uint32_t>& triangles, const Box& region) {
    std::vector<uint32_t> out;
    for (uint32_t t : triangles)
        if (box_of(triangle_at(world, v, t)).overlaps(region)) out.push_back(t);
    return out;
}

// Whether any triangle of `a` crosses any of `b`, both already cut to the
// region where their boxes overlap. `b`'s triangles go into a grid over the
// region, so each of `a`'s meets only its neighbours.
bool objects_cross(const World& world, const TransformedVertices& v, const std::vector<uint32_t>& a,
                   const std::vector<uint32_t>& b, const Box& region, float eps) {
    const int cells = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(b.size()))), 1, 32);
    const glm::vec3 extent = glm::max(region.hi - region.lo, glm::vec3(1e-9f));
    auto cell_of = [&](glm::vec3 p, int axis) {
        const float f = (p[axis] - region.lo[axis]) / extent[axis] * static_cast<float>(cells);
        return std::clamp(static_cast<int>(std::floor(std::clamp(f, -1.0f, cells + 1.0f))), 0,
                          cells - 1);
    };
    std::vector<std::vector<uint32_t>> grid(static_cast<size_t>(cells) * cells * cells);
    auto for_cells = [&](const Box& box, auto&& visit) {
        for (int z = cell_of(box.lo, 2); z <= cell_of(box.hi, 2); ++z)
            for (int y = cell_of(box.lo, 1); y <= cell_of(box.hi, 1); ++y)
                for (int x = cell_of(box.lo, 0); x <= cell_of(box.hi, 0); ++x)
                    visit(grid[(static_cast<size_t>(z) * cells + y) * cells + x]);
    };
    for (uint32_t i = 0; i < b.size(); ++i)
        for_cells(box_of(triangle_at(world, v, b[i])),
                  [&](std::vector<uint32_t>& cell) { cell.push_back(i); });
    std::vector<uint32_t> tested_by(b.size(), 0xffffffffu);  // last `a` triangle tested
    for (uint32_t k = 0; k < a.size(); ++k) {
        const Triangle ta = triangle_at(world, v, a[k]);
        bool found = false;
        for_cells(box_of(ta), [&](std::vector<uint32_t>& cell) {
            for (uint32_t i : cell) {
                if (found || tested_by[i] == k) continue;
                tested_by[i] = k;
                found = triangles_cross(ta, triangle_at(world, v, b[i]), eps);
            }
        });
        if (found) return true;
    }
    return false;
}

}  // namespace

std::vector<uint64_t> crossing_object_pairs(const World& world,
                                            const TransformedVertices& vertices) {
    std::vector<std::vector<uint32_t>> triangles;
    std::vector<Box> boxes;
    for (uint32_t t = 0; t < world.triangle_count(); ++t) {
        const uint32_t object = world.draws[world.triangle_draw[t]].object;
        if (object >= triangles.size()) triangles.resize(object + 1), boxes.resize(object + 1);
        triangles[object].push_back(t);
        for (const glm::vec3& p : triangle_at(world, vertices, t)) boxes[object].add(p);
    }
    std::vector<uint64_t> pairs;
    for (uint32_t i = 0; i < triangles.size(); ++i)
        for (uint32_t j = i + 1; j < triangles.size(); ++j) {
            if (triangles[i].empty() || triangles[j].empty()) continue;
            if (!boxes[i].overlaps(boxes[j])) continue;
            const Box region{glm::max(boxes[i].lo, boxes[j].lo),
                             glm::min(boxes[i].hi, boxes[j].hi)};
            const float eps = 1e-4f * std::min(boxes[i].size(), boxes[j].size());
            Box grown = region;
            grown.lo -= glm::vec3(eps), grown.hi += glm::vec3(eps);
            const auto a = triangles_in(world, vertices, triangles[i], grown);
            const auto b = triangles_in(world, vertices, triangles[j], grown);
            if (a.empty() || b.empty()) continue;
            if (objects_cross(world, vertices, a, b, grown, eps))
                pairs.push_back(object_pair_key(i, j));
        }
    return pairs;  // made in increasing key order
}

}  // namespace facet
