// MikkTSpace-style tangent frames (Mikkelsen 2008); the steps are listed in
// tangent_frames.hpp. Sums are in double, angles from atan2_turns, and
// every order (welding, grouping, summing) comes from sorting by values
// and corner numbers, so the result is the same bits on every machine and
// for every thread count.
#include "assets/tangent_frames.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <tuple>

#include <glm/geometric.hpp>

#include "assets/corner_sets.hpp"
#include "core/exact_trig.hpp"

namespace facet {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

// The arrays one surface is made of; `indices` minus `index_base` index the others.
struct Surface {
    std::span<const glm::vec3> positions, normals;
    std::span<const glm::vec2> uvs;  // empty: no triangle has a direction
    std::span<const uint32_t> indices;
    uint32_t index_base = 0;
    uint32_t vertex(size_t corner) const { return indices[corner] - index_base; }
    size_t corner_count() const { return indices.size() / 3 * 3; }
};

Surface surface_of(const MeshPart& part, int uv_set) {
    return {part.positions, part.normals, tangent_uvs(part, uv_set), part.indices, 0};
}

// A triangle's direction of increasing u, times the magnitude of twice its
// area in texture space, and the sign of that area; orientation 0 when the
// triangle has no area in space or in texture space, or is not finite.
struct TriangleDirection {
    glm::dvec3 tangent{0.0};
    int orientation = 0;
};

TriangleDirection triangle_direction(const Surface& s, size_t t) {
    if (s.uvs.empty()) return {};
    const uint32_t a = s.vertex(3 * t), b = s.vertex(3 * t + 1), c = s.vertex(3 * t + 2);
    const glm::dvec3 p0(s.positions[a]);
    const glm::dvec3 d1 = glm::dvec3(s.positions[b]) - p0, d2 = glm::dvec3(s.positions[c]) - p0;
    const double space_area = glm::length(glm::cross(d1, d2));
    if (!(space_area > 0) || !std::isfinite(space_area)) return {};
    // (u, up): facet's v grows down the image, and the bitangent points up it.
    const glm::dvec2 uv0(s.uvs[a]);
    const double s1 = s.uvs[b].x - uv0.x, t1 = uv0.y - s.uvs[b].y;
    const double s2 = s.uvs[c].x - uv0.x, t2 = uv0.y - s.uvs[c].y;
    const double area = s1 * t2 - s2 * t1;
    if (!(area != 0) || !std::isfinite(area)) return {};
    // p = p0 + T s + B t over the triangle: solving d1 and d2 for T gives
    // (t2 d1 - t1 d2) / area; the sign of the area is kept apart.
    const int orientation = area > 0 ? 1 : -1;
    const glm::dvec3 tangent = (t2 * d1 - t1 * d2) * static_cast<double>(orientation);
    const double length = glm::length(tangent);
    if (!(length > 0) || !std::isfinite(length)) return {};
    return {tangent, orientation};
}

std::vector<TriangleDirection> triangle_directions(const Surface& s) {
    std::vector<TriangleDirection> out(s.corner_count() / 3);
    for (size_t t = 0; t < out.size(); ++t) out[t] = triangle_direction(s, t);
    return out;
}

// `v` without its component along the unit normal `n`.
glm::dvec3 flatten(const glm::dvec3& v, const glm::dvec3& n) {
    return v - n * glm::dot(n, v);
}

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}

// What one corner adds to its vertex's tangent: its triangle's direction
// in the plane of the vertex normal, unit, times the corner's angle in that
// plane (MikkTSpace's weighting: a vertex's share of each face it touches,
// whatever the tessellation).
glm::dvec3 corner_contribution(const Surface& s, size_t corner, const glm::dvec3& direction) {
    const size_t first = corner - corner % 3, k = corner % 3;
    const glm::dvec3 n(s.normals[s.vertex(corner)]);
    const glm::dvec3 along = unit_or_zero(flatten(direction, n));
    if (along == glm::dvec3(0.0)) return along;
    const glm::dvec3 p(s.positions[s.vertex(corner)]);
    const glm::dvec3 next = glm::dvec3(s.positions[s.vertex(first + (k + 1) % 3)]) - p;
    const glm::dvec3 previous = glm::dvec3(s.positions[s.vertex(first + (k + 2) % 3)]) - p;
    glm::dvec3 e1 = unit_or_zero(flatten(next, n)), e2 = unit_or_zero(flatten(previous, n));
    // An edge along the normal has no extent in its plane: measure in space.
    if (e1 == glm::dvec3(0.0) || e2 == glm::dvec3(0.0))
        e1 = unit_or_zero(next), e2 = unit_or_zero(previous);
    return along * (2.0 * std::numbers::pi) *
           atan2_turns(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
}

glm::vec4 frame_from_sum(const glm::dvec3& sum, const glm::vec3& normal, int orientation) {
    const glm::dvec3 unit = unit_or_zero(sum);
    const glm::vec3 tangent = unit == glm::dvec3(0.0) ? any_perpendicular(normal) : glm::vec3(unit);
    return {tangent, orientation < 0 ? -1.0f : 1.0f};
}

// An integer with the float's order, -0 and +0 alike, for sorting by value.
uint32_t float_order(float f) {
    if (f == 0.0f) f = 0.0f;
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

// For each vertex, an id shared by every vertex with the same position,
// normal and coordinates (MikkTSpace welds by value, not by index);
// `count` receives the number of ids. Sorted, not hashed, so no file can
// make it slow.
std::vector<uint32_t> weld_vertices(const Surface& s, size_t vertex_count, size_t& count) {
    using Key = std::array<uint32_t, 9>;  // 8 attribute values, then the vertex
    std::vector<Key> keys(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
        const glm::vec3& p = s.positions[v];
        const glm::vec3& n = s.normals[v];
        const glm::vec2 uv = s.uvs.empty() ? glm::vec2(0) : s.uvs[v];
        keys[v] = {float_order(p.x),  float_order(p.y),  float_order(p.z),
                   float_order(n.x),  float_order(n.y),  float_order(n.z),
                   float_order(uv.x), float_order(uv.y), static_cast<uint32_t>(v)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<uint32_t> id(vertex_count);
    count = 0;
    for (size_t i = 0; i < keys.size(); ++i) {
        if (i > 0 && !std::equal(keys[i].begin(), keys[i].end() - 1, keys[i - 1].begin())) ++count;
        id[keys[i].back()] = static_cast<uint32_t>(count);
    }
    if (!keys.empty()) ++count;
    return id;
}

// Corners of welded vertex w are corner[start[w] .. start[w + 1]), in
// increasing order (a counting sort).
struct CornersAtVertex {
    std::vector<uint32_t> start, corner;
};

CornersAtVertex corners_at_vertices(const Surface& s, const std::vector<uint32_t>& weld,
                                    size_t welded) {
    CornersAtVertex at;
    at.start.assign(welded + 1, 0);
    for (size_t c = 0; c < s.corner_count(); ++c) ++at.start[weld[s.vertex(c)] + 1];
    for (size_t i = 1; i < at.start.size(); ++i) at.start[i] += at.start[i - 1];
    at.corner.resize(s.corner_count());
    std::vector<uint32_t> fill(at.start.begin(), at.start.end() - 1);
    for (size_t c = 0; c < s.corner_count(); ++c)
        at.corner[fill[weld[s.vertex(c)]]++] = static_cast<uint32_t>(c);
    return at;
}

// Per corner, its group (step 3 and 5), numbered from 0 in order of the
// groups' lowest corners; `count` receives the number of groups.
std::vector<uint32_t> group_corners(const Surface& s, const std::vector<TriangleDirection>& tri,
                                    const std::vector<uint32_t>& weld, size_t welded,
                                    size_t& count) {
    const CornersAtVertex at = corners_at_vertices(s, weld, welded);
    std::vector<uint32_t> root_corner(s.corner_count());
    struct Edge {
        uint32_t other, local;  // the edge's far welded vertex; the corner's place here
    };
    std::vector<Edge> edges;
    std::vector<uint32_t> adopted;  // per degenerate corner: a neighbour that has a direction
    CornerSets sets;
    for (size_t w = 0; w < welded; ++w) {
        const uint32_t first = at.start[w], n = at.start[w + 1] - first;
        auto orientation = [&](uint32_t local) {
            return tri[at.corner[first + local] / 3].orientation;
        };
        edges.clear();
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t c = at.corner[first + i], t0 = c - c % 3;
            for (uint32_t step : {1u, 2u}) {
                const uint32_t other = weld[s.vertex(t0 + (c % 3 + step) % 3)];
                if (other != w) edges.push_back({other, i});
            }
        }
        std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
            return std::tie(a.other, a.local) < std::tie(b.other, b.local);
        });
        sets.parent.resize(n);
        for (uint32_t i = 0; i < n; ++i) sets.parent[i] = i;
        adopted.assign(n, kNone);
        // A run of equal `other`: the triangles sharing one edge at w.
        for (size_t e = 0; e < edges.size();) {
            size_t end = e;
            uint32_t first_of[3] = {kNone, kNone, kNone};  // by orientation + 1
            for (; end < edges.size() && edges[end].other == edges[e].other; ++end) {
                const uint32_t local = edges[end].local;
                uint32_t& first_like = first_of[orientation(local) + 1];
                if (first_like == kNone) first_like = local;
                if (orientation(local) != 0) sets.join(first_like, local);
            }
            const uint32_t usable = std::min(first_of[0], first_of[2]);
            for (size_t i = e; i < end && usable != kNone; ++i)
                if (orientation(edges[i].local) == 0 && adopted[edges[i].local] == kNone)
                    adopted[edges[i].local] = usable;
            e = end;
        }
        uint32_t any_usable = kNone, any_degenerate = kNone;
        for (uint32_t i = 0; i < n; ++i) {
            if (orientation(i) != 0 && any_usable == kNone) any_usable = i;
            if (orientation(i) == 0 && any_degenerate == kNone) any_degenerate = i;
        }
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t member = i;
            if (orientation(i) == 0)
                member = adopted[i] != kNone   ? adopted[i]
                         : any_usable != kNone ? any_usable
                                               : any_degenerate;
            root_corner[at.corner[first + i]] = at.corner[first + sets.find(member)];
        }
    }
    // Number the groups by their root corners, in corner order.
    std::vector<uint32_t> group(s.corner_count()), number(s.corner_count(), kNone);
    count = 0;
    for (size_t c = 0; c < s.corner_count(); ++c) {
        uint32_t& id = number[root_corner[c]];
        if (id == kNone) id = static_cast<uint32_t>(count++);
        group[c] = id;
    }
    return group;
}

// Step 4: each group's frame.
std::vector<glm::vec4> group_frames(const Surface& s, const std::vector<TriangleDirection>& tri,
                                    const std::vector<uint32_t>& group, size_t count) {
    std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
    std::vector<int> orientation(count, 0);
    std::vector<uint32_t> vertex(count, kNone);
    for (size_t c = 0; c < group.size(); ++c) {
        const uint32_t g = group[c];
        if (vertex[g] == kNone) vertex[g] = s.vertex(c);
        const TriangleDirection& d = tri[c / 3];
        if (d.orientation == 0) continue;
        orientation[g] = d.orientation;
        sum[g] += corner_contribution(s, c, d.tangent);
    }
    std::vector<glm::vec4> frames(count);
    for (size_t g = 0; g < count; ++g)
        frames[g] = frame_from_sum(sum[g], s.normals[vertex[g]], orientation[g]);
    return frames;
}

template <typename T>
void append_copies(std::vector<T>& values, const std::vector<uint32_t>& source_vertex,
                   size_t kept) {
    if (values.empty()) return;
    values.reserve(source_vertex.size());
    for (size_t i = kept; i < source_vertex.size(); ++i) values.push_back(values[source_vertex[i]]);
}

// Step 6: one copy of a vertex per distinct frame among its corners. The
// frame of its lowest corner keeps the vertex's index; the others are
// appended in the order of their own lowest corners. Only the corners of
// vertices that need copies are sorted: usually there are few.
void split_by_frame(MeshPart& part, const std::vector<glm::vec4>& corner_frame,
                    std::vector<uint32_t>& source_vertex) {
    const size_t vertex_count = part.positions.size(), corners = corner_frame.size();
    std::vector<uint32_t> lowest(vertex_count, kNone);
    for (size_t c = 0; c < corners; ++c)
        if (lowest[part.indices[c]] == kNone) lowest[part.indices[c]] = static_cast<uint32_t>(c);
    std::vector<glm::vec4> tangents(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v)
        tangents[v] = lowest[v] == kNone ? glm::vec4(any_perpendicular(part.normals[v]), 1.0f)
                                         : corner_frame[lowest[v]];
    std::vector<uint32_t> apart;  // corners whose frame is not their vertex's
    for (size_t c = 0; c < corners; ++c)
        if (corner_frame[c] != tangents[part.indices[c]]) apart.push_back(static_cast<uint32_t>(c));
    auto key = [&](uint32_t c) {
        const glm::vec4& f = corner_frame[c];
        return std::tuple(part.indices[c], float_order(f.x), float_order(f.y), float_order(f.z),
                          float_order(f.w), c);
    };
    std::sort(apart.begin(), apart.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    // Runs of one vertex and one frame, each first at its lowest corner.
    std::vector<size_t> run_start;
    for (size_t i = 0; i < apart.size(); ++i)
        if (i == 0 || part.indices[apart[i]] != part.indices[apart[i - 1]] ||
            corner_frame[apart[i]] != corner_frame[apart[i - 1]])
            run_start.push_back(i);
    std::sort(run_start.begin(), run_start.end(),
              [&](size_t a, size_t b) { return apart[a] < apart[b]; });
    source_vertex.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) source_vertex[v] = static_cast<uint32_t>(v);
    std::vector<uint32_t> copy_of(apart.size());  // per sorted position: the new vertex
    for (size_t start : run_start) {
        const uint32_t copy = static_cast<uint32_t>(source_vertex.size());
        const uint32_t v = part.indices[apart[start]];
        source_vertex.push_back(v);
        tangents.push_back(corner_frame[apart[start]]);
        for (size_t i = start; i < apart.size() && part.indices[apart[i]] == v &&
                               corner_frame[apart[i]] == corner_frame[apart[start]];
             ++i)
            copy_of[i] = copy;
    }
    for (size_t i = 0; i < apart.size(); ++i) part.indices[apart[i]] = copy_of[i];
    for (auto* values : {&part.positions, &part.normals})
        append_copies(*values, source_vertex, vertex_count);
    for (auto* values : {&part.uvs, &part.uvs1})
        append_copies(*values, source_vertex, vertex_count);
    append_copies(part.colors, source_vertex, vertex_count);
    part.tangents = std::move(tangents);
}

// Per vertex, the sum of its corners' contributions whose orientation is
// the vertex's w, made a frame (steps 1, 4 and 5 without welding).
void frames_per_vertex(const Surface& s, std::span<glm::vec4> tangents) {
    std::vector<glm::dvec3> sum(tangents.size(), glm::dvec3(0.0));
    for (size_t c = 0; c < s.corner_count(); ++c) {
        const TriangleDirection d = triangle_direction(s, c / 3);
        const uint32_t v = s.vertex(c);
        if (d.orientation != 0 && static_cast<float>(d.orientation) == tangents[v].w)
            sum[v] += corner_contribution(s, c, d.tangent);
    }
    for (size_t v = 0; v < tangents.size(); ++v)
        tangents[v] = frame_from_sum(sum[v], s.normals[v], tangents[v].w < 0 ? -1 : 1);
}

}  // namespace

const std::vector<glm::vec2>& tangent_uvs(const MeshPart& part, int uv_set) {
    return uv_set == 1 && !part.uvs1.empty() ? part.uvs1 : part.uvs;
}

glm::vec3 any_perpendicular(const glm::vec3& normal) {
    const glm::vec3 a = glm::abs(normal);
    const int axis = a.x <= a.y && a.x <= a.z ? 0 : a.y <= a.z ? 1 : 2;
    glm::dvec3 e(0.0);
    e[axis] = 1.0;
    const glm::dvec3 n(normal);
    const glm::dvec3 t = unit_or_zero(flatten(e, n));
    return glm::vec3(t == glm::dvec3(0.0) ? e : t);
}

void add_tangent_frames(MeshPart& part, int uv_set, std::vector<uint32_t>* source_vertex) {
    const Surface s = surface_of(part, uv_set);
    const std::vector<TriangleDirection> triangles = triangle_directions(s);
    size_t welded = 0, groups = 0;
    const std::vector<uint32_t> weld = weld_vertices(s, part.positions.size(), welded);
    const std::vector<uint32_t> group = group_corners(s, triangles, weld, welded, groups);
    const std::vector<glm::vec4> frames = group_frames(s, triangles, group, groups);
    std::vector<glm::vec4> corner_frame(group.size());
    for (size_t c = 0; c < group.size(); ++c) corner_frame[c] = frames[group[c]];
    std::vector<uint32_t> sources;
    split_by_frame(part, corner_frame, source_vertex ? *source_vertex : sources);
}

void add_tangent_frames_in_place(MeshPart& part, int uv_set) {
    const Surface s = surface_of(part, uv_set);
    std::vector<double> vote(part.positions.size(), 0.0);
    for (size_t c = 0; c < s.corner_count(); ++c) {
        const TriangleDirection d = triangle_direction(s, c / 3);
        if (d.orientation != 0)
            vote[s.vertex(c)] += d.orientation * glm::length(corner_contribution(s, c, d.tangent));
    }
    part.tangents.assign(part.positions.size(), glm::vec4(0, 0, 0, 1));
    for (size_t v = 0; v < vote.size(); ++v) part.tangents[v].w = vote[v] < 0 ? -1.0f : 1.0f;
    frames_per_vertex(s, part.tangents);
}

void refresh_tangent_directions(std::span<const glm::vec3> positions,
                                std::span<const glm::vec3> normals, std::span<const glm::vec2> uvs,
                                std::span<const uint32_t> indices, uint32_t index_base,
                                std::span<glm::vec4> tangents) {
    frames_per_vertex({positions, normals, uvs, indices, index_base}, tangents);
}

}  // namespace facet
