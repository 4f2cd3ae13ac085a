// Shared mesh building steps: bounds, normals, validation, and loading by format.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "assets/corner_sets.hpp"
#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "assets/normal_map_tangents.hpp"
#include "core/error.hpp"
#include "core/thread_pool.hpp"

namespace facet {

void Bounds::add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
}

size_t Mesh::triangle_count() const {
    size_t n = 0;
    for (const auto& part : parts) n += part.triangle_count();
    return n;
}

size_t Mesh::vertex_count() const {
    size_t n = 0;
    for (const auto& part : parts) n += part.positions.size();
    return n;
}

Bounds Mesh::bounds() const {
    Bounds b;
    for (const auto& part : parts)
        for (const auto& p : part.positions) b.add(p);
    return b;
}

namespace {

// An integer with the float's order (-0 and +0 alike; NaNs after +inf), so
// that positions and normals sort without hashing: a file cannot make
// sorting slow the way colliding keys make a hash table slow.
uint32_t float_order(float f) {
    if (f == 0.0f) f = 0.0f;  // -0 == +0
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

uint32_t float_bits(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

// For each vertex, an id shared by every vertex at exactly the same
// position; `count` receives the number of ids. O(n log n).
std::vector<uint32_t> weld_by_position(const std::vector<glm::vec3>& positions, size_t& count) {
    struct Key {
        uint32_t x, y, z, vertex;
        auto tie() const { return std::tie(x, y, z, vertex); }
    };
    std::vector<Key> keys(positions.size());
    for (size_t i = 0; i < positions.size(); ++i)
        keys[i] = {float_order(positions[i].x), float_order(positions[i].y),
                   float_order(positions[i].z), static_cast<uint32_t>(i)};
    std::sort(keys.begin(), keys.end(),
              [](const Key& a, const Key& b) { return a.tie() < b.tie(); });
    std::vector<uint32_t> id(positions.size());
    count = 0;
    for (size_t i = 0; i < keys.size(); ++i) {
        if (i > 0 && (keys[i].x != keys[i - 1].x || keys[i].y != keys[i - 1].y ||
                      keys[i].z != keys[i - 1].z))
            ++count;
        id[keys[i].vertex] = static_cast<uint32_t>(count);
    }
    if (!keys.empty()) ++count;
    return id;
}

// The corners round each welded vertex, as a counting sort: corners of
// vertex w are corner[start[w] .. start[w + 1]); a corner is 3 t + k.
struct CornersAtVertex {
    std::vector<uint32_t> start, corner;
};

CornersAtVertex corners_at_vertices(const std::vector<uint32_t>& indices,
                                    const std::vector<uint32_t>& weld_id, size_t welded) {
    CornersAtVertex c;
    c.start.assign(welded + 1, 0);
    for (uint32_t v : indices) ++c.start[weld_id[v] + 1];
    for (size_t i = 1; i < c.start.size(); ++i) c.start[i] += c.start[i - 1];
    c.corner.resize(indices.size());
    std::vector<uint32_t> fill(c.start.begin(), c.start.end() - 1);
    for (size_t i = 0; i < indices.size(); ++i)
        c.corner[fill[weld_id[indices[i]]]++] = static_cast<uint32_t>(i);
    return c;
}

bool same_bits(const glm::vec3& a, const glm::vec3& b) {
    return float_bits(a.x) == float_bits(b.x) && float_bits(a.y) == float_bits(b.y) &&
           float_bits(a.z) == float_bits(b.z);
}

// For each corner, the first corner with the same vertex and normal bits.
// Most vertices have one normal (a smooth surface), so each corner is
// compared with the first corner at its vertex; only the others (at
// creases) are sorted. No hashing: O(n + k log k) for k such corners,
// whatever the file.
std::vector<uint32_t> first_same_corners(const std::vector<uint32_t>& idx, size_t vertex_count,
                                         const std::vector<glm::vec3>& corner_normal) {
    constexpr uint32_t kNone = ~0u;
    std::vector<uint32_t> first_at(vertex_count, kNone);
    std::vector<uint32_t> first(idx.size());
    std::vector<uint32_t> others;
    for (uint32_t c = 0; c < idx.size(); ++c) {
        uint32_t& at = first_at[idx[c]];
        if (at == kNone) at = c;
        if (same_bits(corner_normal[at], corner_normal[c]))
            first[c] = at;
        else
            others.push_back(c);
    }
    auto key = [&](uint32_t c) {
        const glm::vec3& n = corner_normal[c];
        return std::tuple(idx[c], float_bits(n.x), float_bits(n.y), float_bits(n.z), c);
    };
    std::sort(others.begin(), others.end(),
              [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    for (size_t i = 0; i < others.size(); ++i) {
        const uint32_t c = others[i], before = i > 0 ? others[i - 1] : kNone;
        const bool same = before != kNone && idx[before] == idx[c] &&
                          same_bits(corner_normal[before], corner_normal[c]);
        first[c] = same ? first[before] : c;
    }
    return first;
}

// The part rebuilt with one vertex per distinct (vertex, normal), numbered
// in order of first use. Returns the steps taken besides sorting.
uint64_t split_by_normal(MeshPart& part, const std::vector<glm::vec3>& corner_normal,
                         std::vector<uint32_t>* source_vertex) {
    const std::vector<uint32_t>& idx = part.indices;
    const std::vector<uint32_t> first_use =
        first_same_corners(idx, part.positions.size(), corner_normal);
    MeshPart out;
    out.material = part.material;
    out.indices.resize(idx.size());
    out.positions.reserve(part.positions.size());
    out.normals.reserve(part.positions.size());
    std::vector<uint32_t> new_index(idx.size());
    if (source_vertex) source_vertex->clear();
    for (size_t c = 0; c < idx.size(); ++c) {
        if (first_use[c] == c) {
            const uint32_t v = idx[c];
            new_index[c] = static_cast<uint32_t>(out.positions.size());
            out.positions.push_back(part.positions[v]);
            out.normals.push_back(corner_normal[c]);
            if (!part.uvs.empty()) out.uvs.push_back(part.uvs[v]);
            if (!part.uvs1.empty()) out.uvs1.push_back(part.uvs1[v]);
            if (!part.tangents.empty()) out.tangents.push_back(part.tangents[v]);
            if (!part.colors.empty()) out.colors.push_back(part.colors[v]);
            if (source_vertex) source_vertex->push_back(v);
        }
        out.indices[c] = new_index[first_use[c]];
    }
    part = std::move(out);
    return 2 * static_cast<uint64_t>(corner_normal.size());
}

// What smoothing reads about the part's triangles, shared by every vertex.
struct SmoothingInput {
    const std::vector<uint32_t>& idx;
    const std::vector<uint32_t>& weld_id;
    const CornersAtVertex& at;
    std::vector<glm::vec3> face_normal, face_unit;
    float cos_crease;
};

// Buffers reused from vertex to vertex by one thread.
struct SmoothingScratch {
    struct Edge {
        uint32_t other;  // welded vertex at the edge's far end
        uint32_t local;  // the corner's place round this vertex
    };
    std::vector<Edge> edges;
    CornerSets sets;
    std::vector<glm::vec3> sums;
};

// The normals of the corners round welded vertex w: the faces of each
// smooth group summed, area weighted. Returns the steps taken.
uint64_t smooth_corners_at(const SmoothingInput& in, uint32_t w, SmoothingScratch& scratch,
                           std::vector<glm::vec3>& corner_normal) {
    const uint32_t first = in.at.start[w], count = in.at.start[w + 1] - first;
    auto& edges = scratch.edges;
    edges.clear();
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t c = in.at.corner[first + i], t = c / 3, k = c % 3;
        for (uint32_t step : {1u, 2u}) {
            const uint32_t other = in.weld_id[in.idx[3 * t + (k + step) % 3]];
            if (other != w) edges.push_back({other, i});
        }
    }
    using Edge = SmoothingScratch::Edge;
    std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
        return a.other != b.other ? a.other < b.other : a.local < b.local;
    });
    CornerSets& sets = scratch.sets;
    sets.parent.resize(count);
    for (uint32_t i = 0; i < count; ++i) sets.parent[i] = i;
    for (size_t e = 1; e < edges.size(); ++e) {
        if (edges[e].other != edges[e - 1].other) continue;
        const uint32_t ta = in.at.corner[first + edges[e - 1].local] / 3;
        const uint32_t tb = in.at.corner[first + edges[e].local] / 3;
        if (glm::dot(in.face_unit[ta], in.face_unit[tb]) >= in.cos_crease)
            sets.join(edges[e - 1].local, edges[e].local);
    }
    scratch.sums.assign(count, glm::vec3(0));
    for (uint32_t i = 0; i < count; ++i)
        scratch.sums[sets.find(i)] += in.face_normal[in.at.corner[first + i] / 3];
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t c = in.at.corner[first + i], t = c / 3;
        const glm::vec3 sum = scratch.sums[sets.find(i)];
        const float len = glm::length(sum);
        corner_normal[c] =
            len > 0 ? sum / len
                    : (glm::length(in.face_unit[t]) > 0 ? in.face_unit[t] : glm::vec3(0, 1, 0));
    }
    return count + edges.size();
}

// Runs task(first, last) over [0, count) in fixed ranges, on the pool when
// there is one: each range's result depends on the range alone.
void for_ranges(ThreadPool* pool, size_t count, const std::function<void(size_t, size_t)>& task) {
    constexpr size_t kRange = 16384;
    if (pool && count > kRange)
        pool->parallel_for_chunks(count, kRange, task);
    else
        task(0, count);
}

}  // namespace

// Smooth groups round each vertex, as modelling tools define them: two
// faces at a vertex share a normal when they share an edge there and meet
// within the crease angle, and so on through the fan. Every step is linear
// in the corners or a sort of them, whatever the file: a million copies of
// one triangle cost what a million distinct triangles cost. Each vertex's
// corners are smoothed on their own, so vertices run in parallel.
void compute_normals(MeshPart& part, float crease_degrees, std::vector<uint32_t>* source_vertex,
                     uint64_t* work, ThreadPool* pool) {
    const std::vector<uint32_t>& idx = part.indices;
    const size_t triangles = idx.size() / 3;
    // Weld by exact position so faces that share a corner in space, but not
    // an index (because their UVs differ), still smooth across each other.
    size_t welded = 0;
    const std::vector<uint32_t> weld_id = weld_by_position(part.positions, welded);
    const CornersAtVertex at = corners_at_vertices(idx, weld_id, welded);
    SmoothingInput in{idx,
                      weld_id,
                      at,
                      std::vector<glm::vec3>(triangles),
                      std::vector<glm::vec3>(triangles),
                      std::cos(glm::radians(std::clamp(crease_degrees, 0.0f, 180.0f)))};
    for_ranges(pool, triangles, [&](size_t first, size_t last) {
        for (size_t t = first; t < last; ++t) {
            const glm::vec3& a = part.positions[idx[3 * t]];
            const glm::vec3& b = part.positions[idx[3 * t + 1]];
            const glm::vec3& c = part.positions[idx[3 * t + 2]];
            // Length = twice the area: area weighting.
            in.face_normal[t] = glm::cross(b - a, c - a);
            const float len = glm::length(in.face_normal[t]);
            in.face_unit[t] = len > 0 ? in.face_normal[t] / len : glm::vec3(0);
        }
    });
    std::vector<glm::vec3> corner_normal(idx.size());
    std::atomic<uint64_t> steps{0};
    for_ranges(pool, welded, [&](size_t first, size_t last) {
        SmoothingScratch scratch;
        uint64_t range_steps = 0;
        for (size_t w = first; w < last; ++w)
            range_steps += smooth_corners_at(in, static_cast<uint32_t>(w), scratch, corner_normal);
        steps += range_steps;
    });
    const uint64_t split_steps = split_by_normal(part, corner_normal, source_vertex);
    if (work) *work += steps + split_steps;
}

void validate_part(const MeshPart& part, const std::string& source) {
    if (part.indices.size() % 3 != 0)
        throw Error(ExitCode::invalid_input, source + ": index count is not a multiple of 3");
    if (part.normals.size() != part.positions.size() ||
        (!part.uvs.empty() && part.uvs.size() != part.positions.size()) ||
        (!part.uvs1.empty() && part.uvs1.size() != part.positions.size()) ||
        (!part.tangents.empty() && part.tangents.size() != part.positions.size()) ||
        (!part.colors.empty() && part.colors.size() != part.positions.size()))
        throw Error(ExitCode::invalid_input, source + ": vertex attribute counts differ");
    for (uint32_t i : part.indices)
        if (i >= part.positions.size())
            throw Error(ExitCode::invalid_input,
                        source + ": index " + std::to_string(i) + " is out of range (" +
                            std::to_string(part.positions.size()) + " vertices)");
    for (const auto& p : part.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(ExitCode::invalid_input, source + ": a vertex position is not finite");
}

namespace {

// The loader the file's bytes call for, or else its name's.
Mesh load_by_format(const std::string& path, const AssetContext& context) {
    const std::optional<MeshFormat> format = recognise_mesh_file(path);
    if (!format) {
        require_input_file(path, "mesh");
        std::string ext = std::filesystem::path(path).extension().string();
        throw Error(ExitCode::invalid_input,
                    path + ": not a mesh format facet reads (" +
                        (ext.empty() ? std::string("no extension") : "'" + ext + "'") +
                        ", and its content is none of " + mesh_formats_read() + ")");
    }
    if (*format == MeshFormat::obj) return load_obj(path, context);
    if (*format == MeshFormat::gltf || *format == MeshFormat::glb) return load_gltf(path, context);
    return load_assimp(path, context);
}

}  // namespace

Mesh load_mesh(const std::string& path, const AssetContext& context) {
    Mesh mesh = load_by_format(path, context);
    // Once the file's materials are known, whichever format gave them.
    add_normal_map_tangents(mesh, mesh.materials, mesh.warnings);
    return mesh;
}

}  // namespace facet
