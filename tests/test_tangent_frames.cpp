// Tangent frames for normal maps (src/assets/tangent_frames.cpp), the glTF
// TANGENT attribute (src/assets/gltf_primitives.cpp), and their way through
// a glTF rig, the pose stage and the vertex stage. Expected frames are
// worked out by hand from the surfaces' parametrisations.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/gltf_pose.hpp"
#include "assets/normal_map_tangents.hpp"
#include "assets/tangent_frames.hpp"
#include "core/exact_trig.hpp"
#include "core/thread_pool.hpp"
#include "gltf_anim_support.hpp"
#include "render/pose_stage.hpp"
#include "render/vertex_stage.hpp"

using namespace facet;
using namespace facet::test;
using nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

void require_frame(const glm::vec4& got, const glm::vec3& direction, float w, float eps = 1e-5f) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ", " << got.w << ") want ("
                 << direction.x << ", " << direction.y << ", " << direction.z << ", " << w << ")");
    CHECK(glm::length(glm::vec3(got) - direction) <= eps);
    CHECK(got.w == w);
}

// Every tangent finite, unit, across its vertex normal, w exactly +1 or -1.
void require_valid_frames(const MeshPart& part) {
    REQUIRE(part.tangents.size() == part.positions.size());
    for (size_t v = 0; v < part.tangents.size(); ++v) {
        INFO("vertex " << v);
        const glm::vec4& t = part.tangents[v];
        REQUIRE((std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)));
        CHECK(glm::length(glm::vec3(t)) == Approx(1.0f).margin(1e-5));
        CHECK(std::fabs(glm::dot(glm::vec3(t), part.normals[v])) <= 1e-5f);
        CHECK((t.w == 1.0f || t.w == -1.0f));
    }
}

// A (cells + 1)² grid over [0, 1]² in the xy plane facing +z, with the
// coordinates `uv_of` gives each point.
template <typename F>
MeshPart grid(int cells, F uv_of) {
    MeshPart part;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const glm::vec3 p(float(i) / cells, float(j) / cells, 0);
            part.positions.push_back(p);
            part.normals.push_back({0, 0, 1});
            part.uvs.push_back(uv_of(p));
        }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i)
            part.indices.insert(part.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                                     at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    return part;
}

// The image upright on the xy plane: u right along +x, up along +y, so
// v (which grows down the image) is 1 - y.
glm::vec2 upright(const glm::vec3& p) {
    return {p.x, 1 - p.y};
}

// Two triangles meeting along x = 0, their coordinates mirrored across it
// (u = |x|), as a symmetric model's two halves share one half of a texture.
// Vertices 0 (0,0) and 1 (0,1) are on the shared edge; 2 is at (1,0) and
// 3 at (-1,0). Each vertex has its own colour and second coordinates.
MeshPart mirrored_pair() {
    MeshPart part;
    part.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {-1, 0, 0}};
    part.normals.assign(4, {0, 0, 1});
    for (const glm::vec3& p : part.positions) {
        part.uvs.push_back({std::fabs(p.x), 1 - p.y});
        part.uvs1.push_back({p.x + 5, p.y + 7});
        part.colors.push_back({p.x + 2, p.y + 3, 0.5f});
    }
    part.indices = {0, 2, 1, 0, 1, 3};  // right then left, both counter-clockwise from +z
    return part;
}

}  // namespace

TEST_CASE("A UV-mapped plane gets the analytic tangent", "[tangents]") {
    SECTION("upright: +u along +x and w = +1") {
        MeshPart part = grid(2, upright);
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        CHECK(part.positions.size() == 9);
        for (const glm::vec4& t : part.tangents) require_frame(t, {1, 0, 0}, 1);
    }
    SECTION("upside down (v growing up the plane): the bitangent turns, w = -1") {
        MeshPart part = grid(2, [](const glm::vec3& p) { return glm::vec2(p.x, p.y); });
        add_tangent_frames(part, 0);
        for (const glm::vec4& t : part.tangents) require_frame(t, {1, 0, 0}, -1);
    }
    SECTION("a sheared mapping: the derivative of position along u") {
        // (u, up) = J (x, y) with J = [[2, 0.5], [-0.3, 1]]; dp/du is J's
        // inverse's first column, (1, 0.3) / det J, and det J > 0.
        MeshPart part = grid(3, [](const glm::vec3& p) {
            return glm::vec2(2 * p.x + 0.5f * p.y, -(-0.3f * p.x + p.y));
        });
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        for (const glm::vec4& t : part.tangents)
            require_frame(t, glm::normalize(glm::vec3(1, 0.3f, 0)), 1);
    }
    SECTION("tilted vertex normals: the tangent is made perpendicular to them") {
        MeshPart part = grid(1, upright);
        part.normals.assign(4, {0.6f, 0, 0.8f});
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        // x less its part along n, (1, 0, 0) - 0.6 n, made unit.
        for (const glm::vec4& t : part.tangents) require_frame(t, {0.8f, 0, -0.6f}, 1);
    }
    SECTION("set 1 when the map reads it, set 0 when the part has no set 1") {
        MeshPart part = grid(1, upright);
        for (const glm::vec3& p : part.positions) part.uvs1.push_back({p.y, p.x});  // u along +y
        MeshPart without = part;
        without.uvs1.clear();
        add_tangent_frames(part, 1);
        add_tangent_frames(without, 1);
        for (const glm::vec4& t : part.tangents) require_frame(t, {0, 1, 0}, 1);
        for (const glm::vec4& t : without.tangents) require_frame(t, {1, 0, 0}, 1);
    }
}

TEST_CASE("Both sides of a cylinder's UV seam get the circle's tangent, without a split",
          "[tangents]") {
    // Around the y axis, the texture wrapped once and upright seen from
    // outside: u = j / N at angle -2 pi j / N, so seam vertices j = 0 and
    // j = N share position and normal but not u.
    constexpr int kSegments = 12;
    MeshPart part;
    auto angle = [](int j) { return -2 * kPi * j / kSegments; };
    for (int ring = 0; ring < 2; ++ring)
        for (int j = 0; j <= kSegments; ++j) {
            const double a = angle(j % kSegments);
            const glm::vec3 radial(static_cast<float>(std::cos(a)), 0,
                                   static_cast<float>(std::sin(a)));
            part.positions.push_back(radial + glm::vec3(0, ring, 0));
            part.normals.push_back(radial);
            part.uvs.push_back({float(j) / kSegments, 1.0f - ring});
        }
    const auto at = [](int j, int ring) {
        return static_cast<uint32_t>(ring * (kSegments + 1) + j);
    };
    for (int j = 0; j < kSegments; ++j)
        for (std::array<uint32_t, 3> tri : {std::array{at(j, 0), at(j + 1, 0), at(j + 1, 1)},
                                            std::array{at(j, 0), at(j + 1, 1), at(j, 1)}}) {
            // Wound counter-clockwise seen from outside.
            const glm::vec3 a = part.positions[tri[0]], b = part.positions[tri[1]],
                            c = part.positions[tri[2]];
            if (glm::dot(glm::cross(b - a, c - a), a + b + c - glm::vec3(0, 1.5f, 0)) < 0)
                std::swap(tri[1], tri[2]);
            part.indices.insert(part.indices.end(), tri.begin(), tri.end());
        }
    add_tangent_frames(part, 0);
    require_valid_frames(part);
    REQUIRE(part.positions.size() == 2 * (kSegments + 1));
    for (int ring = 0; ring < 2; ++ring)
        for (int j = 0; j <= kSegments; ++j) {
            INFO("ring " << ring << " segment " << j);
            // d/du of (cos a, y, sin a) with a = -2 pi u, made unit.
            const double a = angle(j % kSegments);
            require_frame(part.tangents[at(j, ring)],
                          {static_cast<float>(std::sin(a)), 0, static_cast<float>(-std::cos(a))},
                          1);
        }
}

TEST_CASE("Mirrored UV charts keep opposite w and split the vertices they share", "[tangents]") {
    const MeshPart before = mirrored_pair();
    MeshPart part = before;
    std::vector<uint32_t> source;
    add_tangent_frames(part, 0, &source);
    require_valid_frames(part);
    // Vertices 0 and 1 need two frames each: 4 + 2.
    REQUIRE(part.positions.size() == 6);
    REQUIRE(source.size() == 6);
    for (uint32_t v = 0; v < 4; ++v) CHECK(source[v] == v);
    CHECK(std::set<uint32_t>{source[4], source[5]} == std::set<uint32_t>{0, 1});
    for (size_t v = 0; v < 6; ++v) {
        INFO("vertex " << v);
        CHECK(part.positions[v] == before.positions[source[v]]);
        CHECK(part.normals[v] == before.normals[source[v]]);
        CHECK(part.uvs[v] == before.uvs[source[v]]);
        CHECK(part.uvs1[v] == before.uvs1[source[v]]);
        CHECK(part.colors[v] == before.colors[source[v]]);
    }
    for (size_t c = 0; c < 6; ++c) {
        INFO("corner " << c);
        CHECK(source[part.indices[c]] == before.indices[c]);
        // The right triangle: +u along +x, upright. The left: +u along -x,
        // mirrored, so w = -1 keeps the bitangent w (n x t) = +y up the image.
        if (c < 3)
            require_frame(part.tangents[part.indices[c]], {1, 0, 0}, 1);
        else
            require_frame(part.tangents[part.indices[c]], {-1, 0, 0}, -1);
        const glm::vec4 t = part.tangents[part.indices[c]];
        require_vec3(t.w * glm::cross(part.normals[part.indices[c]], glm::vec3(t)), {0, 1, 0});
    }
}

TEST_CASE("Turning the texture coordinates turns the tangent", "[tangents]") {
    for (double degrees : {0.0, 30.0, 90.0, 180.0, 270.0}) {
        INFO(degrees << " degrees");
        const double a = degrees * kPi / 180;
        const float c = static_cast<float>(std::cos(a)), s = static_cast<float>(std::sin(a));
        // (u, up) = R(a) (x, y), so p = R(-a) (u, up) and dp/du = (cos a, -sin a).
        MeshPart part = grid(2, [&](const glm::vec3& p) {
            return glm::vec2(c * p.x - s * p.y, -(s * p.x + c * p.y));
        });
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        for (const glm::vec4& t : part.tangents) require_frame(t, {c, -s, 0}, 1);
    }
}

TEST_CASE("Degenerate texture coordinates give finite unit tangents across the normal",
          "[tangents]") {
    SECTION("every coordinate the same, normals all ways") {
        MeshPart part = grid(2, [](const glm::vec3&) { return glm::vec2(0.25f, 0.5f); });
        part.normals[1] = glm::normalize(glm::vec3(1, 1, 1));
        part.normals[4] = {1, 0, 0};
        part.normals[7] = {0, -1, 0};
        MeshPart again = part;
        add_tangent_frames(part, 0);
        add_tangent_frames(again, 0);
        require_valid_frames(part);
        CHECK(std::memcmp(part.tangents.data(), again.tangents.data(),
                          part.tangents.size() * sizeof(glm::vec4)) == 0);
        for (const glm::vec4& t : part.tangents) CHECK(t.w == 1);
    }
    SECTION("coordinates that are not numbers, and a triangle of no area") {
        MeshPart part = grid(2, upright);
        part.normals.assign(9, {0.6f, 0, 0.8f});
        part.uvs[4] = {std::nanf(""), 0.5f};
        part.positions[8] = part.positions[7];  // triangle (4, 8, 7) has no area
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        // Vertex 2 is in one triangle, (1, 2, 5), which is sound.
        require_frame(part.tangents[2], {0.8f, 0, -0.6f}, 1);
    }
    SECTION("a triangle with collinear coordinates takes its neighbour's frame") {
        MeshPart part = grid(1, upright);
        // Vertices 0, 1, 2, 3 at (0,0), (1,0), (0,1), (1,1); triangle (0, 3, 2)
        // loses its texture area when vertex 2 has vertex 0's coordinates.
        part.uvs[2] = part.uvs[0];
        part.normals.assign(4, {0.6f, 0, 0.8f});
        add_tangent_frames(part, 0);
        require_valid_frames(part);
        CHECK(part.positions.size() == 4);
        for (uint32_t v : {0u, 3u}) require_frame(part.tangents[v], {0.8f, 0, -0.6f}, 1);
        // Vertex 2 touches no usable triangle: the fixed perpendicular, the
        // axis least along the normal.
        require_frame(part.tangents[2], {0, 1, 0}, 1);
    }
    SECTION("a part without texture coordinates") {
        MeshPart part = grid(1, upright);
        part.uvs.clear();
        add_tangent_frames(part, 0);
        require_valid_frames(part);
    }
}

TEST_CASE("A cloth's tangents are made in place and follow its moved triangles", "[tangents]") {
    MeshPart part = grid(2, upright);
    add_tangent_frames_in_place(part, 0);
    CHECK(part.positions.size() == 9);
    for (const glm::vec4& t : part.tangents) require_frame(t, {1, 0, 0}, 1);
    // Turned a quarter about +z: +u now runs along +y.
    std::vector<glm::vec3> positions, normals = part.normals;
    for (const glm::vec3& p : part.positions) positions.push_back({-p.y, p.x, 0});
    refresh_tangent_directions(positions, normals, part.uvs, part.indices, 0, part.tangents);
    for (const glm::vec4& t : part.tangents) require_frame(t, {0, 1, 0}, 1);
}

namespace {

// A quad in the xy plane facing +z, upright in its texture, with
// `tangents` (four values per vertex) as its TANGENT attribute when given.
Gltf quad_with_tangents(const std::vector<float>& tangents, json node_extra = json::object()) {
    Gltf g;
    json attributes = {{"POSITION", g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3")},
                       {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                       {"TEXCOORD_0", g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2")}};
    if (!tangents.empty()) attributes["TANGENT"] = g.floats(tangents, "VEC4");
    g.one_node_scene({{"attributes", attributes},
                      {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort)}},
                     std::move(node_extra));
    return g;
}

// Not MikkTSpace's frames for the quad: a file's own, kept as given.
const std::vector<float> kFileTangents = {0, 1, 0, -1, 0, 1, 0, -1, 0, 2, 0, -1, 0.6f, 0.8f, 0, 1};

Material normal_mapped(const Material& base) {
    Material m = base;
    const uint8_t pixel[3] = {128, 128, 255};
    m.normal_map.texture = std::make_shared<Texture>(texture_from_pixels(1, 1, 3, 8, pixel));
    return m;
}

}  // namespace

TEST_CASE("A normal map the materials add gets tangents on a copy of the mesh", "[tangents]") {
    auto mesh = std::make_shared<Mesh>();
    mesh->source = "pair.obj";
    mesh->parts = {grid(1, upright), grid(1, upright)};
    mesh->parts[1].uvs.clear();
    mesh->parts[1].material = 1;
    mesh->materials.resize(2);
    mesh->materials[0].name = "painted";
    mesh->materials[1].name = "bare";
    Warnings warnings;
    CHECK(with_normal_map_tangents(mesh, mesh->materials, warnings) == mesh);
    CHECK(warnings.empty());

    // As a scene's `material:` does to every material of its object.
    const std::vector<Material> mapped = {normal_mapped(mesh->materials[0]),
                                          normal_mapped(mesh->materials[1])};
    const std::shared_ptr<const Mesh> with = with_normal_map_tangents(mesh, mapped, warnings);
    REQUIRE(with != mesh);
    CHECK(mesh->parts[0].tangents.empty());
    require_valid_frames(with->parts[0]);
    CHECK(with->parts[1].tangents.empty());
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].where.file == "pair.obj");
    CHECK(warnings[0].message.find("part 1 (material 'bare')") != std::string::npos);
    CHECK(warnings[0].message.find("drawn without its normal maps and anisotropy") !=
          std::string::npos);

    Warnings again;
    CHECK(with_normal_map_tangents(with, mapped, again) == with);
    CHECK(again.size() == 1);
}

TEST_CASE("A glTF file's TANGENT is read as given", "[tangents]") {
    TempDir dir("tangents");
    SECTION("untransformed, made unit, and not replaced for a normal map") {
        Mesh mesh = load_gltf(quad_with_tangents(kFileTangents).write(dir.file("given.gltf")));
        REQUIRE(mesh.parts.size() == 1);
        const MeshPart& part = mesh.parts[0];
        REQUIRE(part.tangents.size() == 4);
        require_frame(part.tangents[0], {0, 1, 0}, -1, 0);
        require_frame(part.tangents[2], {0, 1, 0}, -1, 1e-7f);
        require_frame(part.tangents[3], {0.6f, 0.8f, 0}, 1, 1e-6f);
        std::vector<Material> materials;
        for (const Material& m : mesh.materials) materials.push_back(normal_mapped(m));
        Warnings warnings;
        const std::vector<glm::vec4> before = part.tangents;
        add_normal_map_tangents(mesh, materials, warnings);
        CHECK(mesh.parts[0].tangents == before);
        CHECK(warnings.empty());
    }
    SECTION("through a node that mirrors: turned by the node, w flipped") {
        Mesh mesh = load_gltf(quad_with_tangents(kFileTangents, {{"scale", {-2, 1, 1}}})
                                  .write(dir.file("mirrored.gltf")));
        const MeshPart& part = mesh.parts[0];
        require_frame(part.tangents[0], {0, 1, 0}, 1);
        require_frame(part.tangents[3], glm::normalize(glm::vec3(-1.2f, 0.8f, 0)), -1);
    }
    SECTION("a sign near +1 or -1 is taken as it") {
        std::vector<float> t = kFileTangents;
        t[3] = -0.9995f, t[7] = 1.004f;
        const Mesh mesh = load_gltf(quad_with_tangents(t).write(dir.file("near.gltf")));
        CHECK(mesh.parts[0].tangents[0].w == -1.0f);
        CHECK(mesh.parts[0].tangents[1].w == 1.0f);
    }
}

TEST_CASE("A glTF file's TANGENT is checked", "[tangents]") {
    TempDir dir("tangents");
    SECTION("a w that is no sign") {
        std::vector<float> t = kFileTangents;
        t[11] = 0.5f;
        const std::string file = quad_with_tangents(t).write(dir.file("half.gltf"));
        require_input_error([&] { load_gltf(file); }, "half.gltf: mesh '' primitive 0 TANGENT");
        require_input_error([&] { load_gltf(file); }, "vertex 2 has w = 0.5");
    }
    SECTION("a value that is not a number") {
        std::vector<float> t = kFileTangents;
        t[4] = std::nanf("");
        const std::string file = quad_with_tangents(t).write(dir.file("nan.gltf"));
        require_input_error([&] { load_gltf(file); }, "nan.gltf: mesh '' primitive 0 TANGENT");
        require_input_error([&] { load_gltf(file); }, "not finite");
    }
    SECTION("three components") {
        Gltf g = quad_with_tangents(kFileTangents);
        g.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
            g.floats({1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0}, "VEC3");
        const std::string file = g.write(dir.file("vec3.gltf"));
        require_input_error([&] { load_gltf(file); }, "TANGENT must be VEC4");
    }
    SECTION("ignored without NORMAL, with a warning") {
        Gltf g = quad_with_tangents(kFileTangents);
        g.doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
        const Mesh mesh = load_gltf(g.write(dir.file("flat.gltf")));
        CHECK(mesh.parts[0].tangents.empty());
        bool warned = false;
        for (const Warning& w : mesh.warnings)
            warned = warned || w.message.find("TANGENT is ignored") != std::string::npos;
        CHECK(warned);
    }
}

TEST_CASE("A glTF morph target's TANGENT deltas move the tangents", "[tangents]") {
    TempDir dir("tangents");
    Gltf g = quad_with_tangents({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1});
    // Weight 1 by default: each tangent (1, 0, 0) becomes (0, 1, 0), and vertex 3's (0, 2, 0).
    const std::vector<float> deltas = {-1, 1, 0, -1, 1, 0, -1, 1, 0, -1, 2, 0};
    g.doc["meshes"][0]["primitives"][0]["targets"] =
        json::array({{{"TANGENT", g.floats(deltas, "VEC3")}}});
    g.doc["meshes"][0]["weights"] = {1.0};
    const Mesh mesh = load_gltf(g.write(dir.file("morph.gltf")));
    REQUIRE(mesh.rig);
    for (const glm::vec4& t : mesh.parts[0].tangents) require_frame(t, {0, 1, 0}, 1);
    REQUIRE(mesh.rig->parts[0].morph_targets.size() == 1);
    CHECK(mesh.rig->parts[0].morph_targets[0].tangent_deltas.size() == 4);
}

namespace {

// The mirrored pair of triangles as a glTF file whose node's scale runs
// from (1, 1, 1) at 0 s to (-1, 1, 1) at 1 s: its generated tangents must
// split with the rig and be posed through the mirror.
Mesh mirrored_pair_file(const TempDir& dir) {
    const MeshPart pair = mirrored_pair();
    std::vector<float> positions, normals, uvs;
    for (size_t v = 0; v < pair.positions.size(); ++v) {
        positions.insert(positions.end(), {pair.positions[v].x, pair.positions[v].y, 0});
        normals.insert(normals.end(), {0, 0, 1});
        uvs.insert(uvs.end(), {pair.uvs[v].x, pair.uvs[v].y});
    }
    Gltf g;
    std::vector<uint16_t> indices(pair.indices.begin(), pair.indices.end());
    g.one_node_scene({{"attributes",
                       {{"POSITION", g.floats(positions, "VEC3")},
                        {"NORMAL", g.floats(normals, "VEC3")},
                        {"TEXCOORD_0", g.floats(uvs, "VEC2")}}},
                      {"indices", g.indices(indices, kUShort)}});
    add_channel(g, add_animation(g, "mirror"), 0, "scale", {0, 1}, {1, 1, 1, -1, 1, 1});
    Mesh mesh = load_gltf(g.write(dir.file("pair.gltf")));
    std::vector<Material> materials;
    for (const Material& m : mesh.materials) materials.push_back(normal_mapped(m));
    Warnings warnings;
    add_normal_map_tangents(mesh, materials, warnings);
    CHECK(warnings.empty());
    return mesh;
}

// The tangent a mirror in x makes of `t`.
glm::vec4 mirrored_x(const glm::vec4& t) {
    return {-t.x, t.y, t.z, -t.w};
}

}  // namespace

TEST_CASE("Generated tangents split a glTF rig with the part and pose through a mirror",
          "[tangents]") {
    TempDir dir("tangents");
    const Mesh mesh = mirrored_pair_file(dir);
    const MeshPart& part = mesh.parts[0];
    REQUIRE(part.positions.size() == 6);
    require_valid_frames(part);
    const RigPart& rig_part = mesh.rig->parts[0];
    REQUIRE(rig_part.positions.size() == 6);
    REQUIRE(rig_part.tangents.size() == 6);
    for (size_t v = 0; v < 6; ++v) CHECK(rig_part.positions[v] == part.positions[v]);

    std::vector<PosedPart> rest, mirrored;
    pose_mesh(mesh, 0, 0.0, rest);
    pose_mesh(mesh, 0, 1.0, mirrored);
    REQUIRE(rest[0].tangents.size() == 6);
    REQUIRE(mirrored[0].tangents.size() == 6);
    CHECK(mirrored[0].winding_flipped);
    for (size_t v = 0; v < 6; ++v) {
        INFO("vertex " << v);
        require_frame(rest[0].tangents[v], glm::vec3(part.tangents[v]), part.tangents[v].w, 1e-6f);
        const glm::vec4 want = mirrored_x(part.tangents[v]);
        require_frame(mirrored[0].tangents[v], glm::vec3(want), want.w, 1e-6f);
    }
}

TEST_CASE("The pose and vertex stages carry tangents through mirroring transforms", "[tangents]") {
    TempDir dir("tangents");
    const auto mesh = std::make_shared<const Mesh>(mirrored_pair_file(dir));
    const MeshPart& part = mesh->parts[0];
    // A world of the one animated part, as build_world makes it.
    World world;
    world.materials = {normal_mapped(mesh->materials[0])};
    world.material_object = {0};
    const uint32_t vertices = static_cast<uint32_t>(part.positions.size());
    const uint32_t triangles = static_cast<uint32_t>(part.triangle_count());
    world.draws.push_back({0, 0, vertices, 0, triangles, 0, true, false, true});
    world.animated_meshes.push_back({0, mesh, {0}, 1.0, false, 0});
    world.object_bounds = {mesh->bounds()};
    world.positions = part.positions;
    world.normals = part.normals;
    world.uvs = part.uvs;
    world.tangents = part.tangents;
    world.vertex_draw.assign(vertices, 0);
    world.indices = part.indices;
    world.triangle_draw.assign(triangles, 0);
    world.cull_back.assign(triangles, 1);

    SceneDesc scene;
    PoseStage pose(scene, world);
    FrameInputs frame;
    frame.state.objects.resize(1);
    frame.state.objects[0].animation_seconds = 1.0;  // the node's scale is (-1, 1, 1)
    frame.camera.view_projection = glm::mat4(1.0f);
    frame.materials = world.materials;
    const PosedVertices posed = pose.pose(frame.state);
    REQUIRE(posed.tangents.size() == vertices);
    for (size_t v = 0; v < vertices; ++v) {
        const glm::vec4 want = mirrored_x(part.tangents[v]);
        require_frame(posed.tangents[v], glm::vec3(want), want.w, 1e-6f);
    }

    ThreadPool pool(2);
    VertexStage stage(world);
    SECTION("a model matrix that turns without mirroring keeps w") {
        frame.state.objects[0].transform =
            glm::rotate(glm::mat4(1.0f), float(kPi / 2), glm::vec3(0, 0, 1));
        const TransformedVertices& out = stage.transform(frame, posed, {}, nullptr, pool);
        REQUIRE(out.world_tangent.size() == vertices);
        for (size_t v = 0; v < vertices; ++v) {
            const glm::vec4 t = posed.tangents[v];
            require_frame(out.world_tangent[v], {-t.y, t.x, t.z}, t.w, 1e-6f);
            // Up the texture was +y after the pose's mirror in x; turned, it is -x.
            const glm::vec4 w = out.world_tangent[v];
            require_vec3(w.w * glm::cross(out.world_normal[v], glm::vec3(w)), {-1, 0, 0}, 1e-6f);
        }
    }
    SECTION("a model matrix that mirrors (negative scale) flips w again") {
        frame.state.objects[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(1, -3, 1));
        const TransformedVertices& out = stage.transform(frame, posed, {}, nullptr, pool);
        REQUIRE(out.world_tangent.size() == vertices);
        for (size_t v = 0; v < vertices; ++v) {
            const glm::vec4 t = posed.tangents[v];
            require_frame(out.world_tangent[v], glm::normalize(glm::vec3(t.x, -3 * t.y, t.z)), -t.w,
                          1e-6f);
            // Up the texture, +y before, is -y in the mirror.
            const glm::vec4 w = out.world_tangent[v];
            require_vec3(w.w * glm::cross(out.world_normal[v], glm::vec3(w)), {0, -1, 0}, 1e-6f);
        }
    }
    SECTION("a world without tangents spends nothing on them") {
        PosedVertices bare = posed;
        bare.tangents = {};
        const TransformedVertices& out = stage.transform(frame, bare, {}, nullptr, pool);
        CHECK(out.world_tangent.empty());
        CHECK(out.world_normal.size() == vertices);
    }
}
