// glTF 2.0 loading (src/assets/gltf_loader.cpp), reading geometry: index and
// attribute accessors of every component type, strides, normalized integers,
// sparse accessors and the triangle strip and fan modes. The files are tiny
// ones with known answers, built here.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

using namespace facet::test;
using nlohmann::json;

namespace {

const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

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
            g.one_node_scene(
                {{"attributes", {{"POSITION", g.floats(kQuad, "VEC3")}}}, {"indices", idx}});
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
    g.one_node_scene(
        {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}, {"indices", idx}});
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
            g.one_node_scene(
                {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}, {"indices", idx}});
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
    g.one_node_scene({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}});
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
    g.one_node_scene({{"attributes", {{"POSITION", pos}}}});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("stride.gltf")));
    check_sane(mesh);
    auto corners = all_corners(mesh);
    REQUIRE(corners.size() == 3);
    require_vec3(corners[1], {1, 0, 0});
    require_vec3(corners[2], {0, 1, 0});
}

TEST_CASE("glTF normalized integer accessors", "[assets][gltf]") {
    TempDir dir("gltf");
    // The triangle, with texture coordinates from accessor `uv`.
    auto textured_triangle = [](Gltf& g, int uv) {
        g.one_node_scene(
            {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}, {"TEXCOORD_0", uv}}}});
    };
    SECTION("unsigned byte texture coordinates") {
        // VEC2 of bytes, padded to a 4-byte stride as the spec asks.
        const std::vector<uint8_t> uv = {0, 0, 0, 0, 255, 128, 0, 0, 51, 255, 0, 0};
        Gltf g;
        textured_triangle(g, g.accessor(g.view(uv, 4), kUByte, 3, "VEC2", 0, true));
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
        textured_triangle(g, g.accessor(g.view(bytes_of(uv)), kUShort, 3, "VEC2", 0, true));
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
        g.one_node_scene(
            {{"attributes", {{"POSITION", g.accessor(g.view(pos, 4), kUByte, 3, "VEC3")}}}});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("ints.gltf")));
        require_bounds(mesh, {0, 0, 0}, {4, 3, 0});
        CHECK(total_area(mesh) == Approx(6.0f));
    }
}

// --- Strips and fans --------------------------------------------------------

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
        g.one_node_scene({{"attributes", {{"POSITION", g.floats(strip, "VEC3")}}},
                          {"indices", idx},
                          {"mode", 5}});
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

// --- Sparse accessors -------------------------------------------------------

TEST_CASE("glTF sparse accessors substitute values", "[assets][gltf]") {
    TempDir dir("gltf");
    // The triangle with `count` of its positions replaced: the ones at
    // `indices` (unsigned shorts), by (0, 5, 0).
    auto sparse_triangle = [](const std::vector<uint16_t>& indices, size_t count) {
        Gltf g;
        int pos = g.floats(kTriangle, "VEC3");
        int si = g.view(bytes_of(indices));
        int sv = g.view(bytes_of(std::vector<float>{0, 5, 0}));
        g.sparse(pos, count, si, kUShort, sv);
        g.one_node_scene({{"attributes", {{"POSITION", pos}}}});
        return g;
    };
    SECTION("on top of a buffer view") {
        Gltf g = sparse_triangle({2, 0}, 1);
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
        g.sparse(pos, 2, si, kUByte, sv);
        g.one_node_scene({{"attributes", {{"POSITION", pos}}}});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("sparse_only.gltf")));
        auto c = all_corners(mesh);
        require_vec3(c[0], {0, 0, 0});
        require_vec3(c[1], {3, 0, 0});
        require_vec3(c[2], {0, 4, 0});
        CHECK(total_area(mesh) == Approx(6.0f));
    }
    SECTION("sparse index past the end is an error") {
        std::string path = sparse_triangle({3, 0}, 1).write(dir.file("sparse_bad.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "sparse_bad.gltf");
    }
    SECTION("sparse count larger than its data is an error") {
        std::string path = sparse_triangle({1, 2}, 1000).write(dir.file("sparse_long.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "sparse_long.gltf");
    }
}
