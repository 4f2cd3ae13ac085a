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
#include "assets/corner_weld.hpp"
#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "assets/normal_map_tangents.hpp"
#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/parallel_sort.hpp"
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

// Items (vertices, triangles) handled on one thread at a time.
constexpr size_t kRange = 16384;

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
// The vertex is the last key, so no two keys tie and the sort is the same
// on any number of threads.
std::vector<uint32_t> weld_by_position(const std::vector<glm::vec3>& positions, size_t& count,
                                       ThreadPool* pool) {
    struct Key {
        uint32_t x, y, z, vertex;
        auto tie() const { return std::tie(x, y, z, vertex); }
    };
    std::vector<Key> keys(positions.size());
    run_ranges(pool, positions.size(), kRange, [&](size_t first, size_t last) {
        for (size_t i = first; i < last; ++i)
            keys[i] = {float_order(positions[i].x), float_order(positions[i].y),
                       float_order(positions[i].z), static_cast<uint32_t>(i)};
    });
    parallel_sort(
        keys, [](const Key& a, const Key& b) { return a.tie() < b.tie(); }, pool);
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

// A stable counting sort, so the same on any number of threads: each
// thread counts and places the corners of one slice, after the corners of
// the slices before it at each vertex. Slices are few: each counts every
// vertex.
CornersAtVertex corners_at_vertices(const std::vector<uint32_t>& indices,
                                    const std::vector<uint32_t>& weld_id, size_t welded,
                                    ThreadPool* pool) {
    constexpr size_t kMaxSlices = 8, kMinSlice = size_t(1) << 16;
    const size_t n = indices.size();
    const size_t slices =
        std::clamp<size_t>(std::min<size_t>(pool ? pool->size() : 1, n / kMinSlice), 1, kMaxSlices);
    const size_t slice_size = (n + slices - 1) / slices;
    // fill[s][w]: corners of vertex w in slice s, then where the slice's next one goes.
    std::vector<std::vector<uint32_t>> fill(slices, std::vector<uint32_t>(welded, 0));
    run_each(pool, slices, [&](size_t s) {
        const size_t end = std::min(n, (s + 1) * slice_size);
        for (size_t i = s * slice_size; i < end; ++i) ++fill[s][weld_id[indices[i]]];
    });
    CornersAtVertex c;
    c.start.resize(welded + 1);
    uint32_t total = 0;
    for (size_t w = 0; w < welded; ++w) {
        c.start[w] = total;
        for (size_t s = 0; s < slices; ++s) {
            const uint32_t here = fill[s][w];
            fill[s][w] = total;
            total += here;
        }
    }
    c.start[welded] = total;
    c.corner.resize(n);
    run_each(pool, slices, [&](size_t s) {
        const size_t end = std::min(n, (s + 1) * slice_size);
        for (size_t i = s * slice_size; i < end; ++i)
            c.corner[fill[s][weld_id[indices[i]]]++] = static_cast<uint32_t>(i);
    });
    return c;
}

bool same_bits(const glm::vec3& a, const glm::vec3& b) {
    return float_bits(a.x) == float_bits(b.x) && float_bits(a.y) == float_bits(b.y) &&
           float_bits(a.z) == float_bits(b.z);
}

// The part's vertices split by normal: one per distinct (vertex, normal
// bits), numbered in order of first use (assets/corner_weld.hpp: most
// vertices have one normal, a smooth surface, so each corner is compared
// with the first corner at its vertex).
WeldedCorners weld_by_normal(const std::vector<uint32_t>& idx, size_t vertex_count,
                             const std::vector<glm::vec3>& corner_normal, ThreadPool* pool) {
    auto key = [&](uint32_t c) {
        const glm::vec3& n = corner_normal[c];
        return std::tuple(idx[c], float_bits(n.x), float_bits(n.y), float_bits(n.z), c);
    };
    return weld_corners(
        idx.size(), vertex_count, [&](size_t c) { return idx[c]; },
        [&](uint32_t a, uint32_t b) { return same_bits(corner_normal[a], corner_normal[b]); },
        [&](uint32_t a, uint32_t b) { return key(a) < key(b); }, pool);
}

// The part rebuilt with one vertex per distinct (vertex, normal), numbered
// in order of first use. Returns the steps taken besides sorting.
uint64_t split_by_normal(MeshPart& part, const std::vector<glm::vec3>& corner_normal,
                         std::vector<uint32_t>* source_vertex, ThreadPool* pool) {
    WeldedCorners welded = weld_by_normal(part.indices, part.positions.size(), corner_normal, pool);
    const size_t vertices = welded.first_corner.size();
    MeshPart out;
    out.material = part.material;
    out.positions.resize(vertices);
    out.normals.resize(vertices);
    auto resize_if = [&](const auto& in, auto& attribute) {
        if (!in.empty()) attribute.resize(vertices);
    };
    resize_if(part.uvs, out.uvs);
    resize_if(part.uvs1, out.uvs1);
    resize_if(part.tangents, out.tangents);
    resize_if(part.colors, out.colors);
    if (source_vertex) source_vertex->resize(vertices);
    run_ranges(pool, vertices, kRange, [&](size_t first, size_t last) {
        for (size_t n = first; n < last; ++n) {
            const uint32_t c = welded.first_corner[n], v = part.indices[c];
            out.positions[n] = part.positions[v];
            out.normals[n] = corner_normal[c];
            if (!out.uvs.empty()) out.uvs[n] = part.uvs[v];
            if (!out.uvs1.empty()) out.uvs1[n] = part.uvs1[v];
            if (!out.tangents.empty()) out.tangents[n] = part.tangents[v];
            if (!out.colors.empty()) out.colors[n] = part.colors[v];
            if (source_vertex) (*source_vertex)[n] = v;
        }
    });
    out.indices = std::move(welded.vertex);
    part = std::move(out);
    return 2 * static_cast<uint64_t>(corner_normal.size());
}

// What smoothing reads about the part's triangles, shared by every vertex.
struct SmoothingInput {
    const std::vector<uint32_t>& idx;
    const std::vector<uint32_t>& weld_id;
    const CornersAtVertex& at;
    // Length: twice the area. The unit normals are worked out round each
    // vertex instead of stored: a second array of triangles read at random
    // cost more in cache misses than the square roots do.
    std::vector<glm::vec3> face_normal;
    float cos_crease;
};

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float len = glm::length(v);
    return len > 0 ? v / len : glm::vec3(0);
}

// Buffers reused from vertex to vertex by one thread.
struct SmoothingScratch {
    struct Edge {
        uint32_t other;  // welded vertex at the edge's far end
        uint32_t local;  // the corner's place round this vertex
    };
    std::vector<Edge> edges;
    CornerSets sets;
    std::vector<glm::vec3> sums;
    std::vector<glm::vec3> face_normal, face_unit;  // of each corner's triangle
};

// The normals of the corners round welded vertex w: the faces of each
// smooth group summed, area weighted. Returns the steps taken.
uint64_t smooth_corners_at(const SmoothingInput& in, uint32_t w, SmoothingScratch& scratch,
                           std::vector<glm::vec3>& corner_normal) {
    const uint32_t first = in.at.start[w], count = in.at.start[w + 1] - first;
    auto& edges = scratch.edges;
    edges.clear();
    scratch.face_normal.resize(count);
    scratch.face_unit.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t c = in.at.corner[first + i], t = c / 3, k = c % 3;
        scratch.face_normal[i] = in.face_normal[t];
        scratch.face_unit[i] = unit_or_zero(scratch.face_normal[i]);
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
        const glm::vec3& a = scratch.face_unit[edges[e - 1].local];
        const glm::vec3& b = scratch.face_unit[edges[e].local];
        if (glm::dot(a, b) >= in.cos_crease) sets.join(edges[e - 1].local, edges[e].local);
    }
    scratch.sums.assign(count, glm::vec3(0));
    for (uint32_t i = 0; i < count; ++i) scratch.sums[sets.find(i)] += scratch.face_normal[i];
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 sum = scratch.sums[sets.find(i)];
        const float len = glm::length(sum);
        const glm::vec3& unit = scratch.face_unit[i];
        corner_normal[in.at.corner[first + i]] =
            len > 0 ? sum / len : (glm::length(unit) > 0 ? unit : glm::vec3(0, 1, 0));
    }
    return count + edges.size();
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
    const std::vector<uint32_t> weld_id = weld_by_position(part.positions, welded, pool);
    const CornersAtVertex at = corners_at_vertices(idx, weld_id, welded, pool);
    SmoothingInput in{idx, weld_id, at, std::vector<glm::vec3>(triangles),
                      std::cos(glm::radians(std::clamp(crease_degrees, 0.0f, 180.0f)))};
    run_ranges(pool, triangles, kRange, [&](size_t first, size_t last) {
        for (size_t t = first; t < last; ++t) {
            const glm::vec3& a = part.positions[idx[3 * t]];
            const glm::vec3& b = part.positions[idx[3 * t + 1]];
            const glm::vec3& c = part.positions[idx[3 * t + 2]];
            // Length = twice the area: area weighting.
            in.face_normal[t] = glm::cross(b - a, c - a);
        }
    });
    std::vector<glm::vec3> corner_normal(idx.size());
    std::atomic<uint64_t> steps{0};
    run_ranges(pool, welded, kRange, [&](size_t first, size_t last) {
        SmoothingScratch scratch;
        uint64_t range_steps = 0;
        for (size_t w = first; w < last; ++w)
            range_steps += smooth_corners_at(in, static_cast<uint32_t>(w), scratch, corner_normal);
        steps += range_steps;
    });
    const uint64_t split_steps = split_by_normal(part, corner_normal, source_vertex, pool);
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
    for (const auto& p : part.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(ExitCode::invalid_input, source + ": a vertex position is not finite");
        // As far as scene lengths go: beyond, the rasterizer's fixed point
        // cannot place a triangle, and it would be lost without a word.
        const float largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        if (largest > kMaxCoordinate)
            throw Error(ExitCode::invalid_input,
                        source + ": a vertex is at " + format_number(largest) +
                            " from the origin, past the largest coordinate facet draws (" +
                            format_number(kMaxCoordinate) +
                            "); a node's scale or the file's units are off");
    }
}

std::shared_ptr<const Mesh> with_variant(std::shared_ptr<const Mesh> mesh,
                                         const std::string& variant) {
    const auto named = std::find(mesh->variants.begin(), mesh->variants.end(), variant);
    if (named == mesh->variants.end()) return mesh;
    const size_t index = static_cast<size_t>(named - mesh->variants.begin());
    auto drawn = [&](const MeshPart& part) {
        return index < part.variant_materials.size() ? part.variant_materials[index]
                                                     : part.material;
    };
    if (std::all_of(mesh->parts.begin(), mesh->parts.end(),
                    [&](const MeshPart& part) { return drawn(part) == part.material; }))
        return mesh;
    auto chosen = std::make_shared<Mesh>(*mesh);
    for (MeshPart& part : chosen->parts) part.material = drawn(part);
    return chosen;
}

namespace {

// The loader the file's format calls for.
Mesh load_by_format(const MeshFile& file, const AssetContext& context) {
    if (file.format == MeshFormat::obj) return load_obj(file, context);
    if (file.format == MeshFormat::gltf || file.format == MeshFormat::glb)
        return load_gltf(file, context);
    return load_assimp(file, context);
}

}  // namespace

MeshFile read_mesh_file(const std::string& path, const AssetContext& context) {
    MeshFile file{path, read_input_file(path, "mesh", context.paths.max_file_bytes)};
    const std::optional<MeshFormat> format = mesh_format_of_bytes(file.bytes, file.bytes.size());
    const std::optional<MeshFormat> named = mesh_format_of_name(path);
    if (!format && !named) {
        const std::string ext = std::filesystem::path(path).extension().string();
        throw Error(ExitCode::invalid_input,
                    path + ": not a mesh format facet reads (" +
                        (ext.empty() ? std::string("no extension") : "'" + ext + "'") +
                        ", and its content is none of " + mesh_formats_read() + ")");
    }
    file.format = format ? *format : *named;
    return file;
}

Mesh load_mesh(const MeshFile& file, const AssetContext& context) {
    Mesh mesh;
    try {
        mesh = load_by_format(file, context);
    } catch (const std::bad_alloc&) {
        // The loaders check their estimates first (core/memory.hpp); past
        // them, the file is still named.
        throw Error(ExitCode::runtime_failure, file.path + ": out of memory while loading it (" +
                                                   describe_bytes(file.bytes.size()) + " on disk)");
    }
    // Once the file's materials are known, whichever format gave them.
    add_normal_map_tangents(mesh, mesh.materials, mesh.warnings);
    return mesh;
}

Mesh load_mesh(const std::string& path, const AssetContext& context) {
    return load_mesh(read_mesh_file(path, context), context);
}

}  // namespace facet
