#pragma once
// Helpers shared by the asset tests (OBJ, glTF, primitives, textures): the
// invariants every loaded mesh must satisfy, measures of triangles computed
// here rather than borrowed from the code under test, and writers for the
// small PNG and glTF files the tests feed to the loaders.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "assets/mesh.hpp"
#include "core/image.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

namespace facet::test {

// assimp's test models, installed with the system packages; the tests on real
// files read them from here.
inline const std::string kAssimpModels = "/usr/share/assimp/models/";

// --- Measuring triangles ----------------------------------------------------

inline glm::vec3 corner(const MeshPart& p, size_t t, int k) {
    return p.positions[p.indices[3 * t + k]];
}

// Twice-area vector of triangle t: its direction is the counter-clockwise normal.
inline glm::vec3 face_cross(const MeshPart& p, size_t t) {
    glm::vec3 a = corner(p, t, 0), b = corner(p, t, 1), c = corner(p, t, 2);
    return glm::cross(b - a, c - a);
}

inline glm::vec3 centroid(const MeshPart& p, size_t t) {
    return (corner(p, t, 0) + corner(p, t, 1) + corner(p, t, 2)) / 3.0f;
}

inline double surface_area(const MeshPart& part) {
    double sum = 0;
    for (size_t t = 0; t < part.triangle_count(); ++t)
        sum += 0.5 * glm::length(face_cross(part, t));
    return sum;
}

inline float total_area(const Mesh& mesh) {
    double sum = 0;
    for (const auto& part : mesh.parts) sum += surface_area(part);
    return static_cast<float>(sum);
}

// The corners of every triangle, in order, over all parts.
inline std::vector<glm::vec3> all_corners(const Mesh& mesh) {
    std::vector<glm::vec3> out;
    for (const auto& part : mesh.parts)
        for (uint32_t i : part.indices) out.push_back(part.positions[i]);
    return out;
}

inline const Material& material_of(const Mesh& mesh, const MeshPart& part) {
    return mesh.materials.at(part.material);
}

// Area vector (Newell) of a closed planar polygon: normal times area.
inline glm::vec3 polygon_area_vector(const std::vector<glm::vec3>& pts) {
    glm::vec3 sum(0);
    for (size_t i = 0; i < pts.size(); ++i) sum += glm::cross(pts[i], pts[(i + 1) % pts.size()]);
    return 0.5f * sum;
}

// --- Checks -----------------------------------------------------------------

// Invariants every loaded mesh must satisfy, whatever the file looked like.
inline void check_sane(const Mesh& mesh) {
    REQUIRE(mesh.triangle_count() > 0);
    for (const auto& part : mesh.parts) {
        REQUIRE(part.indices.size() % 3 == 0);
        REQUIRE(part.normals.size() == part.positions.size());
        REQUIRE((part.uvs.empty() || part.uvs.size() == part.positions.size()));
        REQUIRE(part.material < mesh.materials.size());
        for (uint32_t i : part.indices) REQUIRE(i < part.positions.size());
        for (const auto& p : part.positions)
            REQUIRE((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
        for (const auto& n : part.normals) REQUIRE(glm::length(n) == Approx(1.0f).margin(1e-4));
        for (const auto& uv : part.uvs) REQUIRE((std::isfinite(uv.x) && std::isfinite(uv.y)));
    }
    for (const auto& m : mesh.materials)
        if (m.base_color_map.texture)
            REQUIRE(m.base_color_map.texture->level(0).bytes8.size() +
                        m.base_color_map.texture->level(0).half.size() ==
                    static_cast<size_t>(m.base_color_map.texture->width) *
                        m.base_color_map.texture->height);
    Bounds b = mesh.bounds();
    REQUIRE_FALSE(b.empty());
    for (int k = 0; k < 3; ++k) {
        REQUIRE(std::isfinite(b.min[k]));
        REQUIRE(std::isfinite(b.max[k]));
    }
}

inline void require_bounds(const Mesh& mesh, glm::vec3 lo, glm::vec3 hi, float eps = 1e-5f) {
    Bounds b = mesh.bounds();
    for (int k = 0; k < 3; ++k) {
        CHECK(b.min[k] == Approx(lo[k]).margin(eps));
        CHECK(b.max[k] == Approx(hi[k]).margin(eps));
    }
}

inline void require_vec3(glm::vec3 got, glm::vec3 want, float eps = 1e-5f) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ") want (" << want.x << ", "
                 << want.y << ", " << want.z << ")");
    CHECK(glm::length(got - want) <= eps);
}

// Every vertex normal points to the same side as its triangle's own winding
// (by more than `min_dot`). Triangles of zero area have no side and are skipped.
inline void require_normals_agree_with_winding(const MeshPart& part, float min_dot = 0.0f) {
    for (size_t t = 0; t < part.triangle_count(); ++t) {
        glm::vec3 c = face_cross(part, t);
        if (glm::length(c) == 0) continue;
        glm::vec3 f = glm::normalize(c);
        for (int k = 0; k < 3; ++k) {
            INFO("triangle " << t << " corner " << k);
            CHECK(glm::dot(part.normals[part.indices[3 * t + k]], f) > min_dot);
        }
    }
}

inline void require_normals_agree_with_winding(const Mesh& mesh, float min_dot = 0.0f) {
    for (const auto& part : mesh.parts) require_normals_agree_with_winding(part, min_dot);
}

struct Topology {
    size_t vertices = 0, edges = 0, faces = 0;
};

// Welds positions within `eps` (quadratic, fine for test meshes): returns
// each vertex's index in `welded`, which gains the new positions.
inline std::vector<size_t> weld_positions(const MeshPart& part, float eps,
                                          std::vector<glm::vec3>& welded) {
    std::vector<size_t> id(part.positions.size());
    for (size_t i = 0; i < part.positions.size(); ++i) {
        id[i] = welded.size();
        for (size_t j = 0; j < welded.size(); ++j)
            if (glm::length(welded[j] - part.positions[i]) <= eps) {
                id[i] = j;
                break;
            }
        if (id[i] == welded.size()) welded.push_back(part.positions[i]);
    }
    return id;
}

// Welds positions within `eps` and requires every undirected edge to be used
// by exactly two triangles, once in each direction (closed and consistently
// wound). Returns the welded counts, for checks of the Euler characteristic.
inline Topology require_closed_and_oriented(const Mesh& mesh, float eps = 1e-5f) {
    std::vector<glm::vec3> welded;
    std::map<std::pair<size_t, size_t>, int> directed;
    size_t faces = 0;
    for (const auto& part : mesh.parts) {
        std::vector<size_t> id = weld_positions(part, eps, welded);
        for (size_t t = 0; t < part.triangle_count(); ++t)
            for (int k = 0; k < 3; ++k)
                ++directed[{id[part.indices[3 * t + k]], id[part.indices[3 * t + (k + 1) % 3]]}];
        faces += part.triangle_count();
    }
    for (const auto& [edge, count] : directed) {
        INFO("edge " << edge.first << "-" << edge.second);
        REQUIRE(count == 1);
        auto back = directed.find({edge.second, edge.first});
        REQUIRE(back != directed.end());
        REQUIRE(back->second == 1);
    }
    return {welded.size(), directed.size() / 2, faces};
}

// Every warning of the mesh, one a line, for INFO.
inline std::string all_warnings(const Mesh& mesh) {
    std::string all;
    for (const Warning& w : mesh.warnings) all += w.describe() + "\n";
    return all;
}

// Whether a warning of the mesh says `part`.
inline bool warns(const Mesh& mesh, const std::string& part) {
    return std::any_of(mesh.warnings.begin(), mesh.warnings.end(), [&](const Warning& w) {
        return w.describe().find(part) != std::string::npos;
    });
}

// --- PNG files --------------------------------------------------------------

inline std::vector<uint8_t> png_bytes(const ColorImage& image) {
    return encode_png_color(image, 6);
}

inline std::string write_png(const std::string& path, const ColorImage& image) {
    return write_bytes(path, png_bytes(image));
}

// An 8-bit PNG of `channels` channels, its samples given row by row, as
// they are: no transfer curve (data maps, or colour already in sRGB bytes).
inline std::vector<uint8_t> png_of(int width, int height, int channels,
                                   std::vector<uint8_t> samples) {
    PngSamples png;
    png.width = width;
    png.height = height;
    png.channels = channels;
    png.bytes = std::move(samples);
    return encode_png(png, 6);
}

// Mid-grey: read as a number 0.502, as sRGB colour 0.2158, far apart, so a
// map read with the wrong meaning shows.
constexpr uint8_t kMidByte = 128;

// A 2 x 2 RGB PNG every sample of which is `byte`.
inline std::vector<uint8_t> flat_png(uint8_t byte) {
    return png_of(2, 2, 3, std::vector<uint8_t>(12, byte));
}

// --- glTF files -------------------------------------------------------------

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
              kFloat = 5126;

inline std::string base64(const std::vector<uint8_t>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        uint32_t v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i + 1 == data.size()) {
        uint32_t v = data[i] << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == data.size()) {
        uint32_t v = (data[i] << 16) | (data[i + 1] << 8);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

template <typename T>
std::vector<uint8_t> bytes_of(const std::vector<T>& values) {
    std::vector<uint8_t> out(values.size() * sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), values.data(), out.size());
    return out;
}

// Builds a .gltf with one buffer held in a base64 data URI.
struct Gltf {
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};

    std::vector<uint8_t> bin;
    std::string buffer_uri;  // written instead of the data URI when not empty

    int view(const std::vector<uint8_t>& data, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", data.size()}};
        if (stride) v["byteStride"] = stride;
        bin.insert(bin.end(), data.begin(), data.end());
        doc["bufferViews"].push_back(v);
        return static_cast<int>(doc["bufferViews"].size()) - 1;
    }
    int accessor(int view_index, int component, size_t count, const std::string& type,
                 size_t offset = 0, bool normalized = false) {
        nlohmann::json a = {{"componentType", component}, {"count", count}, {"type", type}};
        if (view_index >= 0) a["bufferView"] = view_index;
        if (offset) a["byteOffset"] = offset;
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return static_cast<int>(doc["accessors"].size()) - 1;
    }
    int floats(const std::vector<float>& values, const std::string& type) {
        int n = type == "VEC3" ? 3 : type == "VEC2" ? 2 : type == "VEC4" ? 4 : 1;
        return accessor(view(bytes_of(values)), kFloat, values.size() / n, type);
    }
    template <typename T>
    int indices(const std::vector<T>& values, int component) {
        return accessor(view(bytes_of(values)), component, values.size(), "SCALAR");
    }
    // Makes `count` values of `target` sparse substitutions: indices of type
    // `index_component` in view `index_view`, values in view `value_view`.
    void sparse(int target, size_t count, int index_view, int index_component, int value_view) {
        doc["accessors"][target]["sparse"] = {
            {"count", count},
            {"indices", {{"bufferView", index_view}, {"componentType", index_component}}},
            {"values", {{"bufferView", value_view}}}};
    }
    int mesh(const nlohmann::json& primitive) {
        doc["meshes"].push_back({{"primitives", nlohmann::json::array({primitive})}});
        return static_cast<int>(doc["meshes"].size()) - 1;
    }
    int node(nlohmann::json n) {
        doc["nodes"].push_back(std::move(n));
        return static_cast<int>(doc["nodes"].size()) - 1;
    }
    void scene(const std::vector<int>& roots) {
        doc["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }
    // The scene is one node (with `node_extra`, such as a transform) showing
    // a mesh of this one primitive.
    void one_node_scene(const nlohmann::json& primitive,
                        nlohmann::json node_extra = nlohmann::json::object()) {
        node_extra["mesh"] = mesh(primitive);
        scene({node(std::move(node_extra))});
    }
    // The scene is a 2 x 2 quad facing +Z, with normals and texture
    // coordinates, showing material 0.
    void one_quad_scene() {
        Gltf& g = *this;
        g.one_node_scene(
            {{"attributes",
              {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
               {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
               {"TEXCOORD_0", g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2")}}},
             {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort)},
             {"material", 0}});
    }
    std::string write(const std::string& path) {
        if (!bin.empty())
            doc["buffers"] = nlohmann::json::array(
                {{{"byteLength", bin.size()},
                  {"uri", buffer_uri.empty() ? "data:application/octet-stream;base64," + base64(bin)
                                             : buffer_uri}}});
        return write_text(path, doc.dump(1));
    }
};

inline const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// One node showing one mesh made of `positions`, drawn with `mode`.
inline std::string single_mesh_file(const std::string& path, const std::vector<float>& positions,
                                    nlohmann::json node_extra = nlohmann::json::object(),
                                    int mode = 4) {
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(positions, "VEC3")}}}, {"mode", mode}},
                     std::move(node_extra));
    return g.write(path);
}

}  // namespace facet::test
