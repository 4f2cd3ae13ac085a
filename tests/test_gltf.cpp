// glTF 2.0 loading (src/assets/gltf_loader.cpp): tiny files with known
// answers built here, and the real sample and broken files of assimp's test
// models.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "assets/mesh.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using facet::test::TempDir;
using facet::test::write_text;
using nlohmann::json;

namespace {

const std::string kGltfDir = "/usr/share/assimp/models/glTF2/";

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
              kFloat = 5126;

std::string base64(const std::vector<uint8_t>& data) {
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
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<uint8_t> bin;

    int view(const std::vector<uint8_t>& data, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", data.size()}};
        if (stride) v["byteStride"] = stride;
        bin.insert(bin.end(), data.begin(), data.end());
        doc["bufferViews"].push_back(v);
        return static_cast<int>(doc["bufferViews"].size()) - 1;
    }
    int accessor(int view_index, int component, size_t count, const std::string& type,
                 size_t offset = 0, bool normalized = false) {
        json a = {{"componentType", component}, {"count", count}, {"type", type}};
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
    int mesh(const json& primitive) {
        doc["meshes"].push_back({{"primitives", json::array({primitive})}});
        return static_cast<int>(doc["meshes"].size()) - 1;
    }
    int node(json n) {
        doc["nodes"].push_back(std::move(n));
        return static_cast<int>(doc["nodes"].size()) - 1;
    }
    void scene(const std::vector<int>& roots) {
        doc["scenes"] = json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }
    std::string write(const std::string& path) {
        if (!bin.empty())
            doc["buffers"] =
                json::array({{{"byteLength", bin.size()},
                              {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        return write_text(path, doc.dump(1));
    }
};

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

// One node showing one mesh made of `positions` (and optional extra attributes).
std::string single_mesh_file(const std::string& path, const std::vector<float>& positions,
                             json node_extra = json::object(), int mode = 4) {
    Gltf g;
    json prim = {{"attributes", {{"POSITION", g.floats(positions, "VEC3")}}}, {"mode", mode}};
    json n = {{"mesh", g.mesh(prim)}};
    n.update(node_extra);
    g.scene({g.node(n)});
    return g.write(path);
}

glm::vec3 corner(const facet::MeshPart& p, size_t t, int k) {
    return p.positions[p.indices[3 * t + k]];
}

glm::vec3 face_cross(const facet::MeshPart& p, size_t t) {
    glm::vec3 a = corner(p, t, 0), b = corner(p, t, 1), c = corner(p, t, 2);
    return glm::cross(b - a, c - a);
}

float total_area(const facet::Mesh& mesh) {
    double sum = 0;
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t)
            sum += 0.5 * glm::length(face_cross(part, t));
    return static_cast<float>(sum);
}

std::vector<glm::vec3> all_corners(const facet::Mesh& mesh) {
    std::vector<glm::vec3> out;
    for (const auto& part : mesh.parts)
        for (uint32_t i : part.indices) out.push_back(part.positions[i]);
    return out;
}

void check_sane(const facet::Mesh& mesh) {
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
        if (m.texture)
            REQUIRE(m.texture->texels.size() ==
                    static_cast<size_t>(m.texture->width) * m.texture->height);
    facet::Bounds b = mesh.bounds();
    REQUIRE_FALSE(b.empty());
    for (int k = 0; k < 3; ++k) {
        REQUIRE(std::isfinite(b.min[k]));
        REQUIRE(std::isfinite(b.max[k]));
    }
}

template <typename F>
void require_input_error(F&& load, const std::string& needle) {
    try {
        load();
        FAIL("expected facet::Error mentioning '" << needle << "'");
    } catch (const facet::Error& e) {
        CHECK(e.code() == facet::ExitCode::invalid_input);
        CHECK_THAT(e.what(), Catch::Contains(needle));
    }
}

void require_bounds(const facet::Mesh& mesh, glm::vec3 lo, glm::vec3 hi, float eps = 1e-5f) {
    facet::Bounds b = mesh.bounds();
    for (int k = 0; k < 3; ++k) {
        CHECK(b.min[k] == Approx(lo[k]).margin(eps));
        CHECK(b.max[k] == Approx(hi[k]).margin(eps));
    }
}

void require_vec3(glm::vec3 got, glm::vec3 want, float eps = 1e-5f) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ") want (" << want.x << ", "
                 << want.y << ", " << want.z << ")");
    CHECK(glm::length(got - want) <= eps);
}

// Every vertex normal points to the same side as the triangle's own winding.
void require_normals_agree_with_winding(const facet::Mesh& mesh, float min_dot = 0.0f) {
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            glm::vec3 c = face_cross(part, t);
            if (glm::length(c) == 0) continue;
            glm::vec3 f = glm::normalize(c);
            for (int k = 0; k < 3; ++k)
                CHECK(glm::dot(part.normals[part.indices[3 * t + k]], f) > min_dot);
        }
}

void require_closed_and_oriented(const facet::Mesh& mesh, float eps = 1e-5f) {
    std::vector<glm::vec3> welded;
    auto weld = [&](glm::vec3 p) {
        for (size_t i = 0; i < welded.size(); ++i)
            if (glm::length(welded[i] - p) <= eps) return i;
        welded.push_back(p);
        return welded.size() - 1;
    };
    std::map<std::pair<size_t, size_t>, int> directed;
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            size_t v[3];
            for (int k = 0; k < 3; ++k) v[k] = weld(corner(part, t, k));
            for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
        }
    for (const auto& [edge, count] : directed) {
        REQUIRE(count == 1);
        auto back = directed.find({edge.second, edge.first});
        REQUIRE(back != directed.end());
        REQUIRE(back->second == 1);
    }
}

// The size in a PNG's IHDR, read directly from its bytes.
std::pair<int, int> png_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char h[24] = {};
    in.read(reinterpret_cast<char*>(h), 24);
    auto be = [&](int at) {
        return (h[at] << 24) | (h[at + 1] << 16) | (h[at + 2] << 8) | h[at + 3];
    };
    return {be(16), be(20)};
}

std::vector<uint8_t> png_bytes(const facet::ColorImage& image) {
    return facet::encode_png_color(image, 6);
}

// Cube [-1,1]^3 as 8 shared corners and 12 outward counter-clockwise triangles.
const std::vector<float> kCubeCorners = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                         -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
const std::vector<uint16_t> kCubeIndices = {4, 5, 6, 4, 6, 7, 1, 0, 3, 1, 3, 2, 5, 1, 2, 5, 2, 6,
                                            0, 4, 7, 0, 7, 3, 7, 6, 2, 7, 2, 3, 0, 1, 5, 0, 5, 4};

std::string cube_file(const std::string& path, json node_extra) {
    Gltf g;
    json prim = {{"attributes", {{"POSITION", g.floats(kCubeCorners, "VEC3")}}},
                 {"indices", g.indices(kCubeIndices, kUShort)}};
    json n = {{"mesh", g.mesh(prim)}};
    n.update(node_extra);
    g.scene({g.node(n)});
    return g.write(path);
}

}  // namespace

// --- Indices and accessors -------------------------------------------------

TEST_CASE("glTF indices of every unsigned type", "[assets][gltf]") {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<glm::vec3> want = {p[0], p[1], p[2], p[0], p[2], p[3]};
    TempDir dir("gltf");
    for (int type : {kUByte, kUShort, kUInt}) {
        DYNAMIC_SECTION("component type " << type) {
            Gltf g;
            int idx = type == kUByte    ? g.indices(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}, type)
                      : type == kUShort ? g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, type)
                                        : g.indices(std::vector<uint32_t>{0, 1, 2, 0, 2, 3}, type);
            g.scene(
                {g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(kQuad, "VEC3")}}},
                                          {"indices", idx}})}})});
            facet::Mesh mesh = facet::load_gltf(g.write(dir.file("indices.gltf")));
            check_sane(mesh);
            REQUIRE(mesh.triangle_count() == 2);
            auto corners = all_corners(mesh);
            REQUIRE(corners.size() == want.size());
            for (size_t i = 0; i < want.size(); ++i) require_vec3(corners[i], want[i]);
            for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
        }
    }
}

TEST_CASE("glTF index accessor with a byte offset", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    // Two padding indices (99) before the real ones.
    int view = g.view(bytes_of(std::vector<uint16_t>{99, 99, 2, 1, 0}));
    int idx = g.accessor(view, kUShort, 3, "SCALAR", 4);
    g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}},
                                      {"indices", idx}})}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("offset.gltf")));
    check_sane(mesh);
    auto corners = all_corners(mesh);
    REQUIRE(corners.size() == 3);
    require_vec3(corners[0], {0, 1, 0});
    require_vec3(corners[1], {1, 0, 0});
    require_vec3(corners[2], {0, 0, 0});
    require_vec3(mesh.parts[0].normals[0], {0, 0, -1});  // reversed order faces -Z
}

TEST_CASE("glTF signed or float index accessors are errors", "[assets][gltf]") {
    TempDir dir("gltf");
    for (int type : {kShort, kByte, kFloat}) {
        DYNAMIC_SECTION("component type " << type) {
            Gltf g;
            int idx = type == kShort  ? g.indices(std::vector<int16_t>{0, 1, 2}, type)
                      : type == kByte ? g.indices(std::vector<int8_t>{0, 1, 2, 0}, type)
                                      : g.indices(std::vector<float>{0, 1, 2}, type);
            if (type == kByte) g.doc["accessors"][idx]["count"] = 3;
            g.scene({g.node(
                {{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}},
                                  {"indices", idx}})}})});
            std::string path = g.write(dir.file("badindex.gltf"));
            require_input_error([&] { facet::load_gltf(path); }, "badindex.gltf");
        }
    }
}

TEST_CASE("glTF interleaved attributes with byteStride", "[assets][gltf]") {
    TempDir dir("gltf");
    // position(3) normal(3) uv(2) per vertex: a stride of 32 bytes.
    const std::vector<float> data = {
        0, 0, 0, 0, 0, 1, 0.1f, 0.2f,  //
        2, 0, 0, 0, 0, 1, 0.3f, 0.4f,  //
        0, 2, 0, 0, 0, 1, 0.5f, 0.6f,
    };
    Gltf g;
    int view = g.view(bytes_of(data), 32);
    int pos = g.accessor(view, kFloat, 3, "VEC3", 0);
    int nrm = g.accessor(view, kFloat, 3, "VEC3", 12);
    int uv = g.accessor(view, kFloat, 3, "VEC2", 24);
    g.scene({g.node(
        {{"mesh",
          g.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}})}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("interleaved.gltf")));
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 1);
    const auto& part = mesh.parts[0];
    REQUIRE(part.positions.size() == 3);
    REQUIRE(part.uvs.size() == 3);
    for (int i = 0; i < 3; ++i) {
        require_vec3(part.positions[i], {data[8 * i], data[8 * i + 1], data[8 * i + 2]});
        require_vec3(part.normals[i], {0, 0, 1});
        CHECK(part.uvs[i].x == Approx(data[8 * i + 6]));
        CHECK(part.uvs[i].y == Approx(data[8 * i + 7]));
    }
}

TEST_CASE("glTF byteStride skips padding it must not read", "[assets][gltf]") {
    TempDir dir("gltf");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // 16-byte stride: each position is followed by a NaN that is not part of it.
    const std::vector<float> data = {0, 0, 0, nan, 1, 0, 0, nan, 0, 1, 0, nan};
    Gltf g;
    int pos = g.accessor(g.view(bytes_of(data), 16), kFloat, 3, "VEC3");
    g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}})}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("stride.gltf")));
    check_sane(mesh);
    auto corners = all_corners(mesh);
    REQUIRE(corners.size() == 3);
    require_vec3(corners[1], {1, 0, 0});
    require_vec3(corners[2], {0, 1, 0});
}

TEST_CASE("glTF normalized integer accessors", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("unsigned byte texture coordinates") {
        // VEC2 of bytes, padded to a 4-byte stride as the spec asks.
        const std::vector<uint8_t> uv = {0, 0, 0, 0, 255, 128, 0, 0, 51, 255, 0, 0};
        Gltf g;
        int uva = g.accessor(g.view(uv, 4), kUByte, 3, "VEC2", 0, true);
        g.scene({g.node({{"mesh", g.mesh({{"attributes",
                                           {{"POSITION", g.floats(kTriangle, "VEC3")},
                                            {"TEXCOORD_0", uva}}}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("uv8.gltf")));
        check_sane(mesh);
        const auto& part = mesh.parts[0];
        REQUIRE(part.uvs.size() == 3);
        CHECK(part.uvs[0] == glm::vec2(0, 0));
        CHECK(part.uvs[1].x == Approx(1.0f));
        CHECK(part.uvs[1].y == Approx(128.0f / 255.0f));
        CHECK(part.uvs[2].x == Approx(0.2f));
        CHECK(part.uvs[2].y == Approx(1.0f));
    }
    SECTION("unsigned short texture coordinates") {
        const std::vector<uint16_t> uv = {0, 65535, 65535, 0, 32768, 16384};
        Gltf g;
        int uva = g.accessor(g.view(bytes_of(uv)), kUShort, 3, "VEC2", 0, true);
        g.scene({g.node({{"mesh", g.mesh({{"attributes",
                                           {{"POSITION", g.floats(kTriangle, "VEC3")},
                                            {"TEXCOORD_0", uva}}}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("uv16.gltf")));
        const auto& part = mesh.parts[0];
        REQUIRE(part.uvs.size() == 3);
        CHECK(part.uvs[0].y == Approx(1.0f));
        CHECK(part.uvs[1].x == Approx(1.0f));
        CHECK(part.uvs[2].x == Approx(32768.0f / 65535.0f));
        CHECK(part.uvs[2].y == Approx(16384.0f / 65535.0f));
    }
    SECTION("signed short and byte positions (KHR_mesh_quantization)") {
        // short: 32767 -> 1, -32768 -> -1 (clamped), 16384 -> ~0.5
        const std::vector<int16_t> pos = {0, 0, 0, 0, 32767, 0, 0, 0, -32768, 16384, 0, 0};
        Gltf g;
        g.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
        g.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
        int pa = g.accessor(g.view(bytes_of(pos), 8), kShort, 3, "VEC3", 0, true);
        int m = g.mesh({{"attributes", {{"POSITION", pa}}}});
        // byte: 127 -> 1, -128 -> -1 (clamped)
        const std::vector<int8_t> pos8 = {0, 0, 0, 0, 127, 0, 0, 0, 0, -128, 0, 0};
        int pb = g.accessor(g.view(bytes_of(pos8), 4), kByte, 3, "VEC3", 0, true);
        int m8 = g.mesh({{"attributes", {{"POSITION", pb}}}});
        g.scene({g.node({{"mesh", m}}), g.node({{"mesh", m8}, {"translation", {0, 0, 10}}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("quantized.gltf")));
        check_sane(mesh);
        auto c = all_corners(mesh);
        REQUIRE(c.size() == 6);
        require_vec3(c[0], {0, 0, 0});
        require_vec3(c[1], {1, 0, 0});
        require_vec3(c[2], {-1, 16384.0f / 32767.0f, 0});
        require_vec3(c[3], {0, 0, 10});
        require_vec3(c[4], {1, 0, 10});
        require_vec3(c[5], {0, -1, 10});
    }
    SECTION("unnormalized unsigned byte positions keep their integer values") {
        const std::vector<uint8_t> pos = {0, 0, 0, 0, 4, 0, 0, 0, 0, 3, 0, 0};
        Gltf g;
        int pa = g.accessor(g.view(pos, 4), kUByte, 3, "VEC3");
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pa}}}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("ints.gltf")));
        require_bounds(mesh, {0, 0, 0}, {4, 3, 0});
        CHECK(total_area(mesh) == Approx(6.0f));
    }
}

TEST_CASE("glTF triangle strips keep one winding", "[assets][gltf]") {
    // Zig-zag along +X: 5 vertices, 3 triangles, every one facing +Z.
    const std::vector<float> strip = {0, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 2, 1, 0};
    TempDir dir("gltf");
    SECTION("without indices") {
        facet::Mesh mesh =
            facet::load_gltf(single_mesh_file(dir.file("strip.gltf"), strip, json::object(), 5));
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 3);
        CHECK(total_area(mesh) == Approx(1.5f));
        for (const auto& part : mesh.parts)
            for (size_t t = 0; t < part.triangle_count(); ++t) CHECK(face_cross(part, t).z > 0);
        require_normals_agree_with_winding(mesh, 0.99f);
    }
    SECTION("with indices, reversed order faces the other way") {
        Gltf g;
        int idx = g.indices(std::vector<uint8_t>{4, 3, 2, 1, 0}, kUByte);
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(strip, "VEC3")}}},
                                          {"indices", idx},
                                          {"mode", 5}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("strip_idx.gltf")));
        CHECK(mesh.triangle_count() == 3);
        for (const auto& part : mesh.parts)
            for (size_t t = 0; t < part.triangle_count(); ++t) CHECK(face_cross(part, t).z < 0);
    }
}

TEST_CASE("glTF triangle fans", "[assets][gltf]") {
    // Centre at the origin and six points on the upper half circle, counter-clockwise.
    std::vector<float> fan = {0, 0, 0};
    for (int i = 0; i <= 5; ++i) {
        double a = 3.14159265358979 * i / 5;
        fan.insert(fan.end(),
                   {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0});
    }
    TempDir dir("gltf");
    facet::Mesh mesh =
        facet::load_gltf(single_mesh_file(dir.file("fan.gltf"), fan, json::object(), 6));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 5);
    // Five slices of angle pi/5 of the unit disc.
    CHECK(total_area(mesh) == Approx(5 * 0.5 * std::sin(3.14159265358979 / 5)).epsilon(1e-5));
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            CHECK(corner(part, t, 0) == glm::vec3(0));  // every triangle starts at the centre
            CHECK(face_cross(part, t).z > 0);
        }
}

TEST_CASE("glTF strips and fans too short for a triangle give none", "[assets][gltf]") {
    TempDir dir("gltf");
    for (int mode : {5, 6}) {
        DYNAMIC_SECTION("mode " << mode) {
            std::string path =
                single_mesh_file(dir.file("short.gltf"), {0, 0, 0, 1, 0, 0}, json::object(), mode);
            require_input_error([&] { facet::load_gltf(path); }, "short.gltf");
        }
    }
}

// --- Node transforms --------------------------------------------------------

TEST_CASE("glTF node transforms are applied to positions", "[assets][gltf]") {
    TempDir dir("gltf");
    struct Case {
        const char* name;
        json node;
        std::vector<glm::vec3> want;  // images of (0,0,0), (1,0,0), (0,1,0)
    };
    const float h = std::sqrt(0.5f);
    const std::vector<Case> cases = {
        {"translation", {{"translation", {1, 2, 3}}}, {{1, 2, 3}, {2, 2, 3}, {1, 3, 3}}},
        {"rotation 90 degrees about Y",
         {{"rotation", {0, h, 0, h}}},
         {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}},
        {"scale", {{"scale", {2, 3, 4}}}, {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}},
        // T * R * S: scale x by 2, turn 90 degrees about Z, then move by +X.
        {"translation, rotation and scale together",
         {{"translation", {1, 0, 0}}, {"rotation", {0, 0, h, h}}, {"scale", {2, 1, 1}}},
         {{1, 0, 0}, {1, 2, 0}, {0, 0, 0}}},
        {"unnormalised rotation quaternion",
         {{"rotation", {0, 0, 2, 2}}},
         {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}}},
        {"matrix, column-major translation",
         {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}},
         {{5, 6, 7}, {6, 6, 7}, {5, 7, 7}}},
        // Columns are the images of the axes: x -> (0,2,0), y -> (-3,0,0).
        {"matrix, rotation and scale",
         {{"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
         {{0, 0, 0}, {0, 2, 0}, {-3, 0, 0}}},
    };
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            facet::Mesh mesh =
                facet::load_gltf(single_mesh_file(dir.file("node.gltf"), kTriangle, c.node));
            check_sane(mesh);
            auto corners = all_corners(mesh);
            REQUIRE(corners.size() == 3);
            for (int k = 0; k < 3; ++k) require_vec3(corners[k], c.want[k], 1e-5f);
        }
    }
}

TEST_CASE("glTF node hierarchy composes parent and child transforms", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    int child = g.node({{"mesh", m}, {"translation", {0, 1, 0}}});
    int parent = g.node({{"children", {child}}, {"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}});
    int other =
        g.node({{"mesh", m}, {"translation", {0, 0, -5}}});  // a second instance of the same mesh
    g.scene({parent, other});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("tree.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 2);
    auto c = all_corners(mesh);
    REQUIRE(c.size() == 6);
    // 10 + 2 * (p + (0,1,0))
    require_vec3(c[0], {10, 2, 0});
    require_vec3(c[1], {12, 2, 0});
    require_vec3(c[2], {10, 4, 0});
    require_vec3(c[3], {0, 0, -5});
    require_vec3(c[4], {1, 0, -5});
    require_vec3(c[5], {0, 1, -5});
}

TEST_CASE("glTF normals follow the inverse transpose of the node transform", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    const float s = std::sqrt(0.5f);
    // A triangle in the plane x + y = 1, with its normal (1,1,0)/sqrt2.
    int pos = g.floats({1, 0, 0, 0, 1, 0, 1, 0, 1}, "VEC3");
    int nrm = g.floats({s, s, 0, s, s, 0, s, s, 0}, "VEC3");
    g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}})},
                     {"scale", {1, 2, 1}}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("normals.gltf")));
    check_sane(mesh);
    // Stretching y by 2 makes the plane 2x + y = 2: normal (2,1,0)/sqrt5.
    glm::vec3 want = glm::normalize(glm::vec3(2, 1, 0));
    for (const auto& n : mesh.parts[0].normals) require_vec3(n, want, 1e-5f);
    // and that is indeed perpendicular to the transformed triangle.
    glm::vec3 f = glm::normalize(face_cross(mesh.parts[0], 0));
    CHECK(std::abs(glm::dot(f, want)) == Approx(1.0f).margin(1e-5));
}

TEST_CASE("glTF mirrored nodes flip the winding back to front-facing", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("triangle with normals, negative scale") {
        Gltf g;
        int nrm = g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
        g.scene({g.node(
            {{"mesh", g.mesh({{"attributes",
                               {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}})},
             {"scale", {-1, 1, 1}}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("mirror.gltf")));
        check_sane(mesh);
        require_bounds(mesh, {-1, 0, 0}, {0, 1, 0});
        CHECK(face_cross(mesh.parts[0], 0).z > 0);  // still faces +Z, like its normal
        for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
        require_normals_agree_with_winding(mesh, 0.99f);
    }
    for (const auto& [name, node] : std::vector<std::pair<std::string, json>>{
             {"scale -1 in x", {{"scale", {-1, 1, 1}}}},
             {"scale -1 in all axes", {{"scale", {-1, -1, -1}}}},
             {"mirror matrix", {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 3, 0, 0, 1}}}},
             {"mirror in the parent", {{"scale", {1, 1, 1}}}}}) {
        DYNAMIC_SECTION("cube, " << name) {
            std::string path;
            glm::vec3 centre(0);
            if (name == "mirror in the parent") {
                Gltf g;
                json prim = {{"attributes", {{"POSITION", g.floats(kCubeCorners, "VEC3")}}},
                             {"indices", g.indices(kCubeIndices, kUShort)}};
                int child = g.node({{"mesh", g.mesh(prim)}, {"translation", {2, 0, 0}}});
                g.scene({g.node({{"children", {child}}, {"scale", {1, -1, 1}}})});
                path = g.write(dir.file("mirror_parent.gltf"));
                centre = {2, 0, 0};
            } else {
                path = cube_file(dir.file("mirror_cube.gltf"), node);
                if (node.contains("matrix")) centre = {3, 0, 0};
            }
            facet::Mesh mesh = facet::load_gltf(path);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 12);
            require_closed_and_oriented(mesh);
            for (const auto& part : mesh.parts)
                for (size_t t = 0; t < part.triangle_count(); ++t) {
                    glm::vec3 centroid =
                        (corner(part, t, 0) + corner(part, t, 1) + corner(part, t, 2)) / 3.0f;
                    CHECK(glm::dot(face_cross(part, t), centroid - centre) > 0);  // outward
                }
            require_normals_agree_with_winding(mesh, 0.99f);
        }
    }
}

// --- Sparse accessors, normals, materials ----------------------------------

TEST_CASE("glTF sparse accessors substitute values", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("on top of a buffer view") {
        Gltf g;
        int pos = g.floats(kTriangle, "VEC3");
        int si = g.view(bytes_of(std::vector<uint16_t>{2, 0}));
        int sv = g.view(bytes_of(std::vector<float>{0, 5, 0}));
        g.doc["accessors"][pos]["sparse"] = {
            {"count", 1},
            {"indices", {{"bufferView", si}, {"componentType", kUShort}}},
            {"values", {{"bufferView", sv}}}};
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("sparse.gltf")));
        check_sane(mesh);
        auto c = all_corners(mesh);
        require_vec3(c[0], {0, 0, 0});
        require_vec3(c[1], {1, 0, 0});
        require_vec3(c[2], {0, 5, 0});
    }
    SECTION("without a buffer view: zeros plus substitutions") {
        Gltf g;
        int pos = g.accessor(-1, kFloat, 3, "VEC3");
        int si = g.view(std::vector<uint8_t>{1, 2, 0, 0});
        int sv = g.view(bytes_of(std::vector<float>{3, 0, 0, 0, 4, 0}));
        g.doc["accessors"][pos]["sparse"] = {
            {"count", 2},
            {"indices", {{"bufferView", si}, {"componentType", kUByte}}},
            {"values", {{"bufferView", sv}}}};
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}})}})});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("sparse_only.gltf")));
        auto c = all_corners(mesh);
        require_vec3(c[0], {0, 0, 0});
        require_vec3(c[1], {3, 0, 0});
        require_vec3(c[2], {0, 4, 0});
        CHECK(total_area(mesh) == Approx(6.0f));
    }
    SECTION("sparse index past the end is an error") {
        Gltf g;
        int pos = g.floats(kTriangle, "VEC3");
        int si = g.view(bytes_of(std::vector<uint16_t>{3, 0}));
        int sv = g.view(bytes_of(std::vector<float>{0, 5, 0}));
        g.doc["accessors"][pos]["sparse"] = {
            {"count", 1},
            {"indices", {{"bufferView", si}, {"componentType", kUShort}}},
            {"values", {{"bufferView", sv}}}};
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}})}})});
        std::string path = g.write(dir.file("sparse_bad.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "sparse_bad.gltf");
    }
    SECTION("sparse count larger than its data is an error") {
        Gltf g;
        int pos = g.floats(kTriangle, "VEC3");
        int si = g.view(bytes_of(std::vector<uint16_t>{1, 2}));
        int sv = g.view(bytes_of(std::vector<float>{0, 5, 0}));
        g.doc["accessors"][pos]["sparse"] = {
            {"count", 1000},
            {"indices", {{"bufferView", si}, {"componentType", kUShort}}},
            {"values", {{"bufferView", sv}}}};
        g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}})}})});
        std::string path = g.write(dir.file("sparse_long.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "sparse_long.gltf");
    }
}

TEST_CASE("glTF without normals gets flat normals perpendicular to faces", "[assets][gltf]") {
    // Two triangles sharing the edge (0,0,0)-(1,0,0), folded by about 11 degrees:
    // flat shading must not average them even at that small angle.
    TempDir dir("gltf");
    Gltf g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0.5f, 1, 0.1f, 0.5f, -1, 0.1f}, "VEC3");
    int idx = g.indices(std::vector<uint16_t>{0, 1, 2, 1, 0, 3}, kUShort);
    g.scene({g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}})}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("flat.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 2);
    CHECK(mesh.vertex_count() == 6);  // the shared edge is split
    const glm::vec3 want[2] = {glm::normalize(glm::vec3(0, -0.1f, 1)),
                               glm::normalize(glm::vec3(0, 0.1f, 1))};
    const auto& part = mesh.parts[0];
    for (size_t t = 0; t < 2; ++t) {
        glm::vec3 f = glm::normalize(face_cross(part, t));
        require_vec3(f, want[t], 1e-5f);
        for (int k = 0; k < 3; ++k) {
            glm::vec3 n = part.normals[part.indices[3 * t + k]];
            require_vec3(n, f, 1e-5f);
            // perpendicular to both edges of the face
            CHECK(glm::dot(n, corner(part, t, 1) - corner(part, t, 0)) ==
                  Approx(0.0f).margin(1e-5));
            CHECK(glm::dot(n, corner(part, t, 2) - corner(part, t, 0)) ==
                  Approx(0.0f).margin(1e-5));
        }
    }
}

TEST_CASE("glTF zero-length normals are replaced by face normals", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    int nrm = g.floats({0, 0, 0, 0, 0, 1, 0, 0, 1}, "VEC3");
    g.scene({g.node(
        {{"mesh", g.mesh({{"attributes",
                           {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}})}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("zeronormal.gltf")));
    check_sane(mesh);
    for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
}

TEST_CASE("glTF materials: baseColorFactor, double sided, default", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    g.doc["materials"] =
        json::array({{{"name", "paint"},
                      {"doubleSided", true},
                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}}}});
    int pos = g.floats(kTriangle, "VEC3");
    int with = g.mesh({{"attributes", {{"POSITION", pos}}}, {"material", 0}});
    int without = g.mesh({{"attributes", {{"POSITION", pos}}}});
    g.scene({g.node({{"mesh", with}}), g.node({{"mesh", without}, {"translation", {0, 0, 1}}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("materials.gltf")));
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    const auto& paint = mesh.materials.at(mesh.parts[0].material);
    CHECK(paint.name == "paint");
    CHECK(paint.color.r == Approx(0.2f));
    CHECK(paint.color.g == Approx(0.4f));
    CHECK(paint.color.b == Approx(0.6f));
    CHECK(paint.double_sided);
    CHECK(paint.texture == nullptr);
    const auto& fallback = mesh.materials.at(mesh.parts[1].material);
    CHECK(fallback.name != "paint");
    CHECK(fallback.color == glm::vec3(1));  // glTF's default base colour is white
    CHECK_FALSE(fallback.double_sided);
}

TEST_CASE("glTF base colour texture from a data URI, with sampler wrap", "[assets][gltf]") {
    TempDir dir("gltf");
    facet::ColorImage img(3, 2, {0, 0, 0, 1});
    img.at(2, 0) = {1, 1, 1, 1};  // top-right white
    img.at(0, 1) = {1, 0, 0, 1};  // bottom-left red
    Gltf g;
    g.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(png_bytes(img))}}});
    g.doc["samplers"] = json::array({{{"wrapS", 33071}, {"wrapT", 33071}}, json::object()});
    g.doc["textures"] =
        json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}});
    json tex0 = {{"index", 0}};
    json tex1 = {{"index", 1}, {"texCoord", 1}};
    json mat0 = {{"pbrMetallicRoughness", {{"baseColorTexture", tex0}}}};
    json mat1 = {{"pbrMetallicRoughness", {{"baseColorTexture", tex1}}}};
    g.doc["materials"] = json::array({mat0, mat1});
    int pos = g.floats(kTriangle, "VEC3");
    int uv0 = g.floats({0, 0, 1, 0, 0, 1}, "VEC2");
    int uv1 = g.floats({0.5f, 0.5f, 0.25f, 0.25f, 0.75f, 0.75f}, "VEC2");
    int a = g.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}},
                    {"material", 0}});
    int b = g.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}},
                    {"material", 1}});
    g.scene({g.node({{"mesh", a}}), g.node({{"mesh", b}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("textured.gltf")));
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    const auto& ma = mesh.materials.at(mesh.parts[0].material);
    const auto& mb = mesh.materials.at(mesh.parts[1].material);
    REQUIRE(ma.texture != nullptr);
    REQUIRE(mb.texture != nullptr);
    CHECK(ma.texture->width == 3);
    CHECK(ma.texture->height == 2);
    CHECK(ma.texture->texels[2] == glm::vec4(1, 1, 1, 1));
    CHECK(ma.texture->texels[3] == glm::vec4(1, 0, 0, 1));
    CHECK(ma.texture->wrap == facet::Wrap::clamp);
    CHECK(mb.texture->wrap == facet::Wrap::repeat);  // the glTF default
    // Material 0 reads TEXCOORD_0; material 1 asks for TEXCOORD_1. No v flip in glTF.
    CHECK(mesh.parts[0].uvs[1] == glm::vec2(1, 0));
    CHECK(mesh.parts[1].uvs[1] == glm::vec2(0.25f, 0.25f));
}

// --- Broken files of our own ------------------------------------------------

TEST_CASE("glTF broken references and data are errors naming the file", "[assets][gltf]") {
    TempDir dir("gltf");
    auto triangle_doc = [] {
        Gltf g;
        g.scene({g.node(
            {{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}})}})});
        return g;
    };
    SECTION("index past the vertex count") {
        Gltf g;
        int idx = g.indices(std::vector<uint16_t>{0, 1, 3}, kUShort);
        g.scene(
            {g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}},
                                      {"indices", idx}})}})});
        std::string path = g.write(dir.file("index_oob.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "index_oob.gltf");
    }
    SECTION("accessor longer than its buffer view") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0]["count"] = 4;
        std::string path = g.write(dir.file("acc_long.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_long.gltf");
    }
    SECTION("accessor with an absurd count") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0]["count"] = 1000000000;
        std::string path = g.write(dir.file("acc_huge.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_huge.gltf");
    }
    SECTION("accessor count that overflows byte arithmetic") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0]["count"] = 1537228672809129302ull;  // 12 * count wraps around 2^64
        std::string path = g.write(dir.file("acc_wrap.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_wrap.gltf");
    }
    SECTION("accessor without data with an absurd count") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0].erase("bufferView");
        g.doc["accessors"][0]["count"] = 2000000000;
        std::string path = g.write(dir.file("acc_nodata.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_nodata.gltf");
    }
    SECTION("accessor offset past its buffer view") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0]["byteOffset"] = 4;
        std::string path = g.write(dir.file("acc_offset.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_offset.gltf");
    }
    SECTION("accessor refers to a missing buffer view") {
        Gltf g = triangle_doc();
        g.doc["accessors"][0]["bufferView"] = 7;
        std::string path = g.write(dir.file("acc_view.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "acc_view.gltf");
    }
    SECTION("buffer view past the end of its buffer") {
        Gltf g = triangle_doc();
        g.doc["bufferViews"][0]["byteLength"] = 4000;
        std::string path = g.write(dir.file("view_long.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "view_long.gltf");
    }
    SECTION("POSITION with two components") {
        Gltf g;
        g.scene({g.node(
            {{"mesh",
              g.mesh({{"attributes", {{"POSITION", g.floats({0, 0, 1, 0, 0, 1}, "VEC2")}}}})}})});
        std::string path = g.write(dir.file("pos_vec2.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "pos_vec2.gltf");
    }
    SECTION("NaN position") {
        Gltf g;
        float nan = std::numeric_limits<float>::quiet_NaN();
        g.scene({g.node(
            {{"mesh",
              g.mesh({{"attributes",
                       {{"POSITION", g.floats({0, 0, 0, 1, nan, 0, 0, 1, 0}, "VEC3")}}}})}})});
        std::string path = g.write(dir.file("nan.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "nan.gltf");
    }
    SECTION("infinite normal") {
        Gltf g;
        float inf = std::numeric_limits<float>::infinity();
        int nrm = g.floats({0, 0, 1, 0, 0, inf, 0, 0, 1}, "VEC3");
        g.scene({g.node(
            {{"mesh", g.mesh({{"attributes",
                               {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}})}})});
        std::string path = g.write(dir.file("infnormal.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "infnormal.gltf");
    }
    SECTION("NORMAL count differs from POSITION count") {
        Gltf g;
        int nrm = g.floats({0, 0, 1, 0, 0, 1}, "VEC3");
        g.scene({g.node(
            {{"mesh", g.mesh({{"attributes",
                               {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}})}})});
        std::string path = g.write(dir.file("normal_count.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "normal_count.gltf");
    }
    SECTION("node refers to a missing mesh") {
        Gltf g = triangle_doc();
        g.doc["nodes"][0]["mesh"] = 5;
        std::string path = g.write(dir.file("node_mesh.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "node_mesh.gltf");
    }
    SECTION("scene refers to a missing node") {
        Gltf g = triangle_doc();
        g.doc["scenes"][0]["nodes"] = {0, 9};
        std::string path = g.write(dir.file("scene_node.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "scene_node.gltf");
    }
    SECTION("primitive refers to a missing material") {
        Gltf g = triangle_doc();
        g.doc["meshes"][0]["primitives"][0]["material"] = 3;
        std::string path = g.write(dir.file("prim_mat.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "prim_mat.gltf");
    }
    SECTION("material refers to a missing texture") {
        Gltf g = triangle_doc();
        g.doc["materials"] =
            json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 4}}}}}}});
        g.doc["meshes"][0]["primitives"][0]["material"] = 0;
        std::string path = g.write(dir.file("mat_tex.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "mat_tex.gltf");
    }
    SECTION("texture without an image") {
        Gltf g = triangle_doc();
        g.doc["textures"] = json::array({{{"source", 2}}});
        g.doc["materials"] =
            json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
        g.doc["meshes"][0]["primitives"][0]["material"] = 0;
        std::string path = g.write(dir.file("tex_img.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "tex_img.gltf");
    }
    SECTION("image that is not an image") {
        Gltf g = triangle_doc();
        g.doc["images"] =
            json::array({{{"uri", "data:image/png;base64," + base64({1, 2, 3, 4, 5, 6, 7, 8})}}});
        g.doc["textures"] = json::array({{{"source", 0}}});
        g.doc["materials"] =
            json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
        g.doc["meshes"][0]["primitives"][0]["material"] = 0;
        std::string path = g.write(dir.file("bad_image.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "bad_image.gltf");
    }
    SECTION("only points and lines") {
        Gltf g = triangle_doc();
        g.doc["meshes"][0]["primitives"][0]["mode"] = 0;
        g.doc["meshes"][0]["primitives"].push_back(
            {{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
        std::string path = g.write(dir.file("points.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "points.gltf");
    }
    SECTION("primitive without POSITION") {
        Gltf g = triangle_doc();
        g.doc["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
        std::string path = g.write(dir.file("nopos.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "nopos.gltf");
    }
    SECTION("buffer file that does not exist") {
        Gltf g = triangle_doc();
        g.write(dir.file("nobin.gltf"));
        g.doc["buffers"][0]["uri"] = "missing.bin";
        std::string path = write_text(dir.file("nobin.gltf"), g.doc.dump());
        require_input_error([&] { facet::load_gltf(path); }, "nobin.gltf");
    }
    SECTION("buffer data URI that is not base64") {
        Gltf g = triangle_doc();
        g.write(dir.file("b64.gltf"));
        g.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64,@@@@!!!!";
        std::string path = write_text(dir.file("b64.gltf"), g.doc.dump());
        require_input_error([&] { facet::load_gltf(path); }, "b64.gltf");
    }
    SECTION("geometry compressed with an unsupported required extension") {
        Gltf g = triangle_doc();
        g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        g.doc["meshes"][0]["primitives"][0]["extensions"] = {
            {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
        std::string path = g.write(dir.file("draco.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "draco.gltf");
    }
}

TEST_CASE("glTF malformed containers are errors naming the file", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("empty .gltf") {
        std::string path = write_text(dir.file("empty.gltf"), "");
        require_input_error([&] { facet::load_gltf(path); }, "empty.gltf");
    }
    SECTION("invalid JSON") {
        std::string path =
            write_text(dir.file("broken.gltf"), "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
        require_input_error([&] { facet::load_gltf(path); }, "broken.gltf");
    }
    SECTION("JSON that is not an object") {
        std::string path = write_text(dir.file("array.gltf"), "[1, 2, 3]");
        require_input_error([&] { facet::load_gltf(path); }, "array.gltf");
    }
    SECTION("valid but empty document") {
        std::string path =
            write_text(dir.file("nothing.gltf"), "{\"asset\": {\"version\": \"2.0\"}}");
        require_input_error([&] { facet::load_gltf(path); }, "nothing.gltf");
    }
    SECTION("missing file") {
        require_input_error([&] { facet::load_gltf(dir.file("absent.gltf")); }, "absent.gltf");
        require_input_error([&] { facet::load_mesh(dir.file("absent.glb")); }, "absent.glb");
    }
    SECTION("empty .glb") {
        std::string path = write_text(dir.file("empty.glb"), "");
        require_input_error([&] { facet::load_gltf(path); }, "empty.glb");
    }
    SECTION(".glb with a wrong magic number") {
        std::string bytes = "glTX\x02\0\0\0\x20\0\0\0" + std::string(20, '\0');
        std::string path = write_text(dir.file("magic.glb"), bytes);
        require_input_error([&] { facet::load_gltf(path); }, "magic.glb");
    }
    SECTION("truncated and corrupted real .glb") {
        std::ifstream in(kGltfDir + "BoxTextured-glTF-Binary/BoxTextured.glb", std::ios::binary);
        std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        REQUIRE(whole.size() > 1000);
        for (size_t keep :
             {size_t(12), size_t(20), whole.size() / 3, whole.size() / 2, whole.size() - 1}) {
            std::string path = write_text(dir.file("cut.glb"), whole.substr(0, keep));
            INFO("kept " << keep << " bytes");
            require_input_error([&] { facet::load_gltf(path); }, "cut.glb");
        }
        std::string lying = whole;
        lying[12] = '\xff';  // JSON chunk length far past the file
        lying[13] = '\xff';
        std::string path = write_text(dir.file("lying.glb"), lying);
        require_input_error([&] { facet::load_gltf(path); }, "lying.glb");
    }
}

TEST_CASE("glTF node cycles and shared subtrees end quickly", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("a node that is its own child") {
        Gltf g;
        int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
        g.node({{"mesh", m}, {"children", {0}}});
        g.scene({0});
        std::string path = g.write(dir.file("self.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "self.gltf");
    }
    SECTION("a cycle below the root") {
        Gltf g;
        int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
        g.node({{"children", {1}}});
        g.node({{"mesh", m}, {"children", {2}}});
        g.node({{"children", {1}}});
        g.scene({0});
        std::string path = g.write(dir.file("cycle.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "cycle.gltf");
    }
    SECTION("nodes shared by many parents, doubling at every level") {
        // Node i has node i+1 as its child twice: 2^60 paths if walked naively.
        Gltf g;
        int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
        for (int i = 0; i < 60; ++i) g.node({{"children", {i + 1, i + 1}}});
        g.node({{"mesh", m}});
        g.scene({0});
        std::string path = g.write(dir.file("diamond.gltf"));
        auto start = std::chrono::steady_clock::now();
        try {
            facet::Mesh mesh = facet::load_gltf(path);
            CHECK(mesh.triangle_count() <= 2);
        } catch (const facet::Error& e) {
            CHECK(e.code() == facet::ExitCode::invalid_input);
            CHECK_THAT(e.what(), Catch::Contains("diamond.gltf"));
        }
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
    }
    SECTION("a very deep but valid chain") {
        Gltf g;
        int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
        const int depth = 5000;
        for (int i = 0; i < depth; ++i)
            g.node({{"children", {i + 1}}, {"translation", {0.001, 0, 0}}});
        g.node({{"mesh", m}});
        g.scene({0});
        std::string path = g.write(dir.file("deep.gltf"));
        try {
            facet::Mesh mesh = facet::load_gltf(path);
            check_sane(mesh);
            require_bounds(mesh, {5, 0, 0}, {6, 1, 0}, 1e-3f);
        } catch (const facet::Error& e) {
            CHECK(e.code() == facet::ExitCode::invalid_input);
            CHECK_THAT(e.what(), Catch::Contains("deep.gltf"));
        }
    }
}

TEST_CASE("glTF without scenes uses every root node", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    int m = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    int child = g.node({{"mesh", m}, {"translation", {0, 0, 1}}});
    g.node({{"mesh", m}, {"children", {child}}});
    g.node({{"mesh", m}, {"translation", {0, 0, 2}}});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("noscene.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 3);  // child once (through its parent), two roots
    require_bounds(mesh, {0, 0, 0}, {1, 1, 2});
}

// --- Real files -------------------------------------------------------------

TEST_CASE("glTF real BoxTextured in all three containers", "[assets][gltf][real]") {
    auto [tw, th] = png_size(kGltfDir + "BoxTextured-glTF/CesiumLogoFlat.png");
    REQUIRE(tw == 211);
    // The texture coordinates' range, as the file's own accessor states it
    // (they run past 1 to repeat the logo).
    std::ifstream in(kGltfDir + "BoxTextured-glTF/BoxTextured.gltf");
    json doc = json::parse(in);
    const json& uv_accessor =
        doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"].get<int>()];
    const glm::vec2 uv_min(uv_accessor["min"][0].get<float>(), uv_accessor["min"][1].get<float>());
    const glm::vec2 uv_max(uv_accessor["max"][0].get<float>(), uv_accessor["max"][1].get<float>());
    REQUIRE(uv_max.x > uv_min.x);
    for (const std::string rel :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
          "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        DYNAMIC_SECTION(rel) {
            facet::Mesh mesh = facet::load_mesh(kGltfDir + rel);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 12);
            require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
            require_closed_and_oriented(mesh);
            CHECK(total_area(mesh) == Approx(6.0f));
            require_normals_agree_with_winding(mesh, 0.99f);
            for (const auto& part : mesh.parts) {
                const auto& m = mesh.materials.at(part.material);
                CHECK(m.name == "Texture");
                REQUIRE(m.texture != nullptr);
                CHECK(m.texture->width == tw);
                CHECK(m.texture->height == th);
                CHECK(part.uvs.size() == part.positions.size());
                glm::vec2 lo(1e30f), hi(-1e30f);
                for (const auto& uv : part.uvs) {
                    lo = glm::min(lo, uv);
                    hi = glm::max(hi, uv);
                }
                CHECK(lo.x == Approx(uv_min.x));
                CHECK(lo.y == Approx(uv_min.y));
                CHECK(hi.x == Approx(uv_max.x));
                CHECK(hi.y == Approx(uv_max.y));
            }
        }
    }
}

TEST_CASE("glTF real 2CylinderEngine flattens its node hierarchy", "[assets][gltf][real]") {
    // Expected values computed independently from the file with a small
    // Python reader (sum of index counts / 3 over every mesh instance reached
    // from the scene; world-space bounds of the transformed vertices).
    facet::Mesh mesh =
        facet::load_gltf(kGltfDir + "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 121496);
    require_bounds(mesh, {-371.69226f, -180.97156f, -139.99999f}, {371.69217f, 92.04156f, 128.0f},
                   0.01f);
    CHECK(mesh.materials.size() >= 34);
}

TEST_CASE("glTF real broken files are errors, not crashes", "[assets][gltf][real]") {
    for (const std::string rel :
         {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
          "IndexOutOfRange/IndexOutOfRange.gltf", "IndexOutOfRange/AllIndicesOutOfRange.gltf",
          "MissingBin/BoxTextured.gltf", "RecursiveNodes/RecursiveNodes.gltf",
          "TestNoRootNode/NoScene.gltf", "TestNoRootNode/SceneWithoutNodes.gltf",
          "draco/2CylinderEngine.gltf"}) {
        DYNAMIC_SECTION(rel) {
            require_input_error([&] { facet::load_mesh(kGltfDir + rel); },
                                fs::path(rel).filename().string());
        }
    }
}

TEST_CASE("glTF real BoxBadNormals: bad normals become usable ones", "[assets][gltf][real]") {
    // Four normals are (0,0,0) and four are (0,-0.1,0): neither is unit length.
    facet::Mesh mesh = facet::load_gltf(kGltfDir + "BoxBadNormals-glTF-Binary/BoxBadNormals.glb");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 12);
    require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
    require_normals_agree_with_winding(mesh, 0.99f);
}

TEST_CASE("glTF real IncorrectVertexArrays drops incomplete triangles", "[assets][gltf][real]") {
    // Cube (36 vertices) 12, TruncatedCube (35) 11, IndexedCube 12,
    // TruncatedIndexedCube (35 indices) 11; the four line meshes give none.
    facet::Mesh mesh = facet::load_gltf(kGltfDir + "IncorrectVertexArrays/Cube.gltf");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 46);
    require_bounds(mesh, {-3.5f, -1, -1}, {3.5f, 1, 3.5f}, 1e-4f);
}

TEST_CASE("glTF real small scenes", "[assets][gltf][real]") {
    SECTION("simple_skin: the bind pose, animation listed") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "simple_skin/simple_skin.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 8);
        require_bounds(mesh, {0, 0, 0}, {1, 2, 0});
        CHECK(mesh.animations.size() == 1);
    }
    SECTION("cameras: rotated square, cameras ignored") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "cameras/Cameras.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 2);
        require_bounds(mesh, {0, 0, -0.70759f}, {1, 0.70662f, 0}, 1e-4f);
    }
    SECTION("textureTransform: nine textured squares") {
        facet::Mesh mesh =
            facet::load_gltf(kGltfDir + "textureTransform/TextureTransformTest.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 24);
        require_bounds(mesh, {-1.6f, -1.14127f, 0}, {1.6f, 1.05f, 0.01f}, 1e-4f);
        for (const auto& part : mesh.parts)
            CHECK(mesh.materials.at(part.material).texture != nullptr);
    }
    SECTION("BoxTexcoords: two texture coordinate sets") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "BoxTexcoords-glTF/boxTexcoords.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 12);
        require_bounds(mesh, glm::vec3(-1), glm::vec3(1));
    }
    SECTION("AnimatedMorphCube: base shape and its animation name") {
        facet::Mesh mesh = facet::load_gltf(
            kGltfDir + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 12);
        REQUIRE(mesh.animations.size() == 1);
        CHECK(mesh.animations[0] == "Square");
    }
}

TEST_CASE("glTF real wrongTypes files load sanely or are errors", "[assets][gltf][real]") {
    for (const std::string name : {"badArray.gltf", "badExtension.gltf", "badNumber.gltf",
                                   "badObject.gltf", "badString.gltf", "badUint.gltf"}) {
        DYNAMIC_SECTION(name) {
            try {
                facet::Mesh mesh = facet::load_gltf(kGltfDir + "wrongTypes/" + name);
                check_sane(mesh);
                CHECK(mesh.triangle_count() == 12);  // it is BoxTextured underneath
            } catch (const facet::Error& e) {
                CHECK(e.code() == facet::ExitCode::invalid_input);
                CHECK_THAT(e.what(), Catch::Contains(name));
            }
        }
    }
}

TEST_CASE("glTF real Asset-Generator primitive modes", "[assets][gltf][real]") {
    // Mesh_PrimitiveMode_NN: a unit square at z = 0 drawn with mode N.
    // 00-03 and 07-10 are points, lines, line loops and line strips: nothing to
    // render. The others are two counter-clockwise triangles facing +Z.
    const std::string dir = kGltfDir + "glTF-Asset-Generator/Mesh_PrimitiveMode/";
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".gltf") continue;
        ++files;
        const std::string name = entry.path().filename().string();
        const int number = std::stoi(name.substr(name.size() - 7, 2));
        DYNAMIC_SECTION(name) {
            const bool lines_or_points = number <= 3 || (number >= 7 && number <= 10);
            if (lines_or_points) {
                require_input_error([&] { facet::load_gltf(entry.path().string()); }, name);
            } else {
                facet::Mesh mesh = facet::load_gltf(entry.path().string());
                check_sane(mesh);
                CHECK(mesh.triangle_count() == 2);
                CHECK(total_area(mesh) == Approx(1.0f));
                require_bounds(mesh, {-0.5f, -0.5f, 0}, {0.5f, 0.5f, 0});
                for (const auto& part : mesh.parts)
                    for (size_t t = 0; t < part.triangle_count(); ++t)
                        CHECK(face_cross(part, t).z > 0);
                require_normals_agree_with_winding(mesh, 0.99f);
            }
        }
    }
    CHECK(files == 16);
}

TEST_CASE("glTF every real file loads sanely or is a facet::Error", "[assets][gltf][real]") {
    std::vector<fs::path> paths;
    for (const std::string root :
         {"/usr/share/assimp/models/glTF2", "/usr/share/assimp/models/glTF"})
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            auto ext = entry.path().extension();
            if (ext == ".gltf" || ext == ".glb") paths.push_back(entry.path());
        }
    std::sort(paths.begin(), paths.end());
    REQUIRE(paths.size() > 40);
    for (const auto& p : paths) {
        DYNAMIC_SECTION(p.string()) {
            try {
                facet::Mesh mesh = facet::load_mesh(p.string());
                check_sane(mesh);
            } catch (const facet::Error& e) {
                CHECK(e.code() == facet::ExitCode::invalid_input);
                CHECK_THAT(e.what(), Catch::Contains(p.filename().string()));
            }
        }
    }
}
