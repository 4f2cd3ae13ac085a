// Shared mesh building steps: bounds, normals, validation, and loading by format.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "assets/corner_sets.hpp"
#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "assets/normal_map_tangents.hpp"
#include "core/error.hpp"

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

// The part rebuilt with one vertex per distinct (vertex, normal), numbered
// in order of first use, found by sorting the corners rather than hashing
// them. Returns the steps taken besides sorting.
uint64_t split_by_normal(MeshPart& part, const std::vector<glm::vec3>& corner_normal,
                         std::vector<uint32_t>* source_vertex) {
    const std::vector<uint32_t>& idx = part.indices;
    struct CornerKey {
        uint32_t vertex, nx, ny, nz, corner;
        auto tie() const { return std::tie(vertex, nx, ny, nz, corner); }
    };
    std::vector<CornerKey> keys(idx.size());
    for (size_t c = 0; c < idx.size(); ++c)
        keys[c] = {idx[c], float_bits(corner_normal[c].x), float_bits(corner_normal[c].y),
                   float_bits(corner_normal[c].z), static_cast<uint32_t>(c)};
    std::sort(keys.begin(), keys.end(),
              [](const CornerKey& a, const CornerKey& b) { return a.tie() < b.tie(); });
    std::vector<uint32_t> first_use(idx.size());  // per corner: the first corner like it
    for (size_t i = 0; i < keys.size(); ++i) {
        const bool same = i > 0 && keys[i].vertex == keys[i - 1].vertex &&
                          keys[i].nx == keys[i - 1].nx && keys[i].ny == keys[i - 1].ny &&
                          keys[i].nz == keys[i - 1].nz;
        first_use[keys[i].corner] = same ? first_use[keys[i - 1].corner] : keys[i].corner;
    }
    MeshPart out;
    out.material = part.material;
    out.indices.resize(idx.size());
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

}  // namespace

// Smooth groups round each vertex, as modelling tools define them: two
// faces at a vertex share a normal when they share an edge there and meet
// within the crease angle, and so on through the fan. Every step is linear
// in the corners or a sort of them, whatever the file: a million copies of
// one triangle cost what a million distinct triangles cost.
void compute_normals(MeshPart& part, float crease_degrees, std::vector<uint32_t>* source_vertex,
                     uint64_t* work) {
    const std::vector<uint32_t>& idx = part.indices;
    const size_t triangles = idx.size() / 3;
    uint64_t steps = 0;
    // Weld by exact position so faces that share a corner in space, but not
    // an index (because their UVs differ), still smooth across each other.
    size_t welded = 0;
    const std::vector<uint32_t> weld_id = weld_by_position(part.positions, welded);

    std::vector<glm::vec3> face_normal(triangles), face_unit(triangles);
    for (size_t t = 0; t < triangles; ++t) {
        const glm::vec3& a = part.positions[idx[3 * t]];
        const glm::vec3& b = part.positions[idx[3 * t + 1]];
        const glm::vec3& c = part.positions[idx[3 * t + 2]];
        face_normal[t] = glm::cross(b - a, c - a);  // length = twice the area: area weighting
        const float len = glm::length(face_normal[t]);
        face_unit[t] = len > 0 ? face_normal[t] / len : glm::vec3(0);
    }
    const CornersAtVertex at = corners_at_vertices(idx, weld_id, welded);

    const float cos_crease = std::cos(glm::radians(std::clamp(crease_degrees, 0.0f, 180.0f)));
    std::vector<glm::vec3> corner_normal(idx.size());
    struct Edge {
        uint32_t other;  // welded vertex at the edge's far end
        uint32_t local;  // the corner's place round this vertex
    };
    std::vector<Edge> edges;
    CornerSets sets;
    std::vector<glm::vec3> sums;
    for (size_t w = 0; w < welded; ++w) {
        const uint32_t first = at.start[w], count = at.start[w + 1] - first;
        edges.clear();
        for (uint32_t i = 0; i < count; ++i) {
            const uint32_t c = at.corner[first + i], t = c / 3, k = c % 3;
            for (uint32_t step : {1u, 2u}) {
                const uint32_t other = weld_id[idx[3 * t + (k + step) % 3]];
                if (other != w) edges.push_back({other, i});
            }
        }
        std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
            return a.other != b.other ? a.other < b.other : a.local < b.local;
        });
        sets.parent.resize(count);
        for (uint32_t i = 0; i < count; ++i) sets.parent[i] = i;
        for (size_t e = 1; e < edges.size(); ++e) {
            if (edges[e].other != edges[e - 1].other) continue;
            const uint32_t ta = at.corner[first + edges[e - 1].local] / 3;
            const uint32_t tb = at.corner[first + edges[e].local] / 3;
            if (glm::dot(face_unit[ta], face_unit[tb]) >= cos_crease)
                sets.join(edges[e - 1].local, edges[e].local);
        }
        sums.assign(count, glm::vec3(0));
        for (uint32_t i = 0; i < count; ++i)
            sums[sets.find(i)] += face_normal[at.corner[first + i] / 3];
        for (uint32_t i = 0; i < count; ++i) {
            const uint32_t c = at.corner[first + i], t = c / 3;
            const glm::vec3 sum = sums[sets.find(i)];
            const float len = glm::length(sum);
            corner_normal[c] =
                len > 0 ? sum / len
                        : (glm::length(face_unit[t]) > 0 ? face_unit[t] : glm::vec3(0, 1, 0));
        }
        steps += count + edges.size();
    }

    steps += split_by_normal(part, corner_normal, source_vertex);
    if (work) *work += steps;
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
