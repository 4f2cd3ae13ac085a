// Shared mesh building steps: bounds, normals, validation, and loading by extension.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "assets/mesh.hpp"
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

struct Vec3Hash {
    size_t operator()(const glm::vec3& v) const {
        uint32_t bits[3];
        std::memcpy(bits, &v, sizeof bits);
        return (size_t(bits[0]) * 73856093u) ^ (size_t(bits[1]) * 19349663u) ^
               (size_t(bits[2]) * 83492791u);
    }
};

struct CornerKey {
    uint32_t vertex;
    glm::vec3 normal;
    bool operator==(const CornerKey& o) const {
        return vertex == o.vertex && std::memcmp(&normal, &o.normal, sizeof normal) == 0;
    }
};

struct CornerHash {
    size_t operator()(const CornerKey& k) const {
        return Vec3Hash{}(k.normal) ^ (size_t(k.vertex) * 2654435761u);
    }
};

}  // namespace

void compute_normals(MeshPart& part, float crease_degrees, std::vector<uint32_t>* source_vertex) {
    const size_t triangles = part.indices.size() / 3;
    // Weld by exact position so faces that share a corner in space, but not
    // an index (because their UVs differ), still smooth across each other.
    std::unordered_map<glm::vec3, uint32_t, Vec3Hash> weld;
    std::vector<uint32_t> weld_id(part.positions.size());
    for (size_t i = 0; i < part.positions.size(); ++i)
        weld_id[i] =
            weld.emplace(part.positions[i], static_cast<uint32_t>(weld.size())).first->second;

    std::vector<glm::vec3> face_normal(triangles), face_unit(triangles);
    std::vector<uint32_t> incident_start(weld.size() + 1, 0);
    for (size_t t = 0; t < triangles; ++t) {
        const glm::vec3& a = part.positions[part.indices[3 * t]];
        const glm::vec3& b = part.positions[part.indices[3 * t + 1]];
        const glm::vec3& c = part.positions[part.indices[3 * t + 2]];
        face_normal[t] = glm::cross(b - a, c - a);  // length = twice the area: area weighting
        float len = glm::length(face_normal[t]);
        face_unit[t] = len > 0 ? face_normal[t] / len : glm::vec3(0);
        for (int k = 0; k < 3; ++k) ++incident_start[weld_id[part.indices[3 * t + k]] + 1];
    }
    for (size_t i = 1; i < incident_start.size(); ++i) incident_start[i] += incident_start[i - 1];
    std::vector<uint32_t> incident(incident_start.back());
    std::vector<uint32_t> fill(incident_start.begin(), incident_start.end() - 1);
    for (size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k)
            incident[fill[weld_id[part.indices[3 * t + k]]]++] = uint32_t(t);

    const float cos_crease = std::cos(glm::radians(std::clamp(crease_degrees, 0.0f, 180.0f)));
    MeshPart out;
    out.material = part.material;
    std::unordered_map<CornerKey, uint32_t, CornerHash> corners;
    out.indices.reserve(part.indices.size());
    if (source_vertex) source_vertex->clear();
    for (size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            uint32_t v = part.indices[3 * t + k];
            uint32_t w = weld_id[v];
            glm::vec3 sum(0);
            for (uint32_t i = incident_start[w]; i < incident_start[w + 1]; ++i) {
                uint32_t g = incident[i];
                if (g == t || glm::dot(face_unit[t], face_unit[g]) >= cos_crease)
                    sum += face_normal[g];
            }
            float len = glm::length(sum);
            glm::vec3 n = len > 0
                              ? sum / len
                              : (glm::length(face_unit[t]) > 0 ? face_unit[t] : glm::vec3(0, 1, 0));
            auto [it, added] = corners.emplace(CornerKey{v, n}, uint32_t(out.positions.size()));
            if (added) {
                out.positions.push_back(part.positions[v]);
                out.normals.push_back(n);
                if (!part.uvs.empty()) out.uvs.push_back(part.uvs[v]);
                if (source_vertex) source_vertex->push_back(v);
            }
            out.indices.push_back(it->second);
        }
    }
    part = std::move(out);
}

void validate_part(const MeshPart& part, const std::string& source) {
    if (part.indices.size() % 3 != 0)
        throw Error(ExitCode::invalid_input, source + ": index count is not a multiple of 3");
    if (part.normals.size() != part.positions.size() ||
        (!part.uvs.empty() && part.uvs.size() != part.positions.size()))
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

Mesh load_mesh(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".obj") return load_obj(path);
    if (ext == ".gltf" || ext == ".glb") return load_gltf(path);
    throw Error(ExitCode::invalid_input,
                path + ": unsupported mesh format '" + ext + "' (use .obj, .gltf or .glb)");
}

}  // namespace facet
