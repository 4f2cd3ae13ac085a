// Normal maps end to end (docs/pbr.md, "Material keys" and "Tangent
// frames"): a flat quad whose map holds a hemispherical bump shows, in the
// normal pass, the normals of the real hemisphere; the green channel's
// convention (OpenGL: green up the image) is pinned by its flipped twin.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "asset_support.hpp"
#include "render_check.hpp"
#include "shade/normal_map.hpp"
#include "support.hpp"

namespace {

constexpr int kMapSize = 256;
constexpr float kBumpRadius = 0.3f;  // in texture units, centred at (0.5, 0.5)

// The bump's tangent-space normal at (u, v): x along +u, y up the image
// (towards -v), z out of the surface; flat outside the bump.
glm::vec3 bump_normal(float u, float v) {
    const glm::vec2 d = (glm::vec2(u, v) - 0.5f) / kBumpRadius;
    const float r2 = glm::dot(d, d);
    if (r2 >= 1.0f) return {0, 0, 1};
    return {d.x, -d.y, std::sqrt(1.0f - r2)};
}

// The map as 8-bit RGB bytes, (n + 1) / 2; `flip_green` negates y.
void write_bump_map(const std::string& path, bool flip_green) {
    std::vector<uint8_t> samples;
    for (int y = 0; y < kMapSize; ++y)
        for (int x = 0; x < kMapSize; ++x) {
            glm::vec3 n = bump_normal((static_cast<float>(x) + 0.5f) / kMapSize,
                                      (static_cast<float>(y) + 0.5f) / kMapSize);
            if (flip_green) n.y = -n.y;
            for (int a = 0; a < 3; ++a)
                samples.push_back(static_cast<uint8_t>(std::lround((n[a] + 1.0f) * 127.5f)));
        }
    facet::test::write_bytes(path, facet::test::png_of(kMapSize, kMapSize, 3, samples));
}

// A 2 x 2 plane (u along +X, v along +Z) seen from above, its normal pass.
facet::FrameImages render_bump(bool flip_green, const std::string& style = "pbr",
                               const std::string& extra_material = "") {
    facet::test::TempDir dir("normal-map");
    write_bump_map(dir.file("bump.png"), flip_green);
    const std::string text = R"(output: { size: [200, 200], passes: [color, normal] }
camera: { position: [0, 4, 0.001], target: [0, 0, 0], fov: 32 }
style: )" + style + R"(
objects:
  - name: quad
    primitive: { type: plane, size: 2 }
    material: { color: [0.8, 0.8, 0.8], normal_map: bump.png, roughness: 0.5)" +
                             extra_material + R"( }
)";
    return facet::test::render_yaml(dir.path(), text, 1, 2);
}

glm::vec3 normal_at(const facet::FrameImages& images, glm::vec3 p) {
    const glm::vec4 clip = images.projection * images.view * glm::vec4(p, 1.0f);
    const auto& normal = images.surface.normal;
    const float x = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(normal.width);
    const float y = (0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(normal.height);
    return normal.at(static_cast<int>(x), static_cast<int>(y));
}

// The real hemisphere's normal at the world point (x, 0, z) of the plane:
// the bump's (u, v) is ((x + 1) / 2, (z + 1) / 2), and with +u along +X
// and up the image along -Z the tangent-space normal (a, b, c) is the world
// normal (a, c, -b).
glm::vec3 hemisphere_normal(float x, float z) {
    const glm::vec3 t = bump_normal((x + 1.0f) / 2.0f, (z + 1.0f) / 2.0f);
    return glm::normalize(glm::vec3(t.x, t.z, -t.y));
}

float degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::fmin(1.0f, glm::dot(glm::normalize(a), glm::normalize(b)))));
}

// World points on the bump, up to 80 % of its radius (the rim, where the
// map's slope jumps, is filtered by any texture lookup), and off it.
std::vector<glm::vec3> bump_points() {
    std::vector<glm::vec3> points;
    const float world_radius = 2.0f * kBumpRadius;
    for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j) {
            const glm::vec2 d = glm::vec2(i, j) * (0.8f * world_radius / 4.0f);
            if (glm::length(d) <= 0.8f * world_radius) points.push_back({d.x, 0.0f, d.y});
        }
    return points;
}

}  // namespace

TEST_CASE(
    "normal map: a bump map on a flat quad gives the real hemisphere's normals within 2 "
    "degrees",
    "[render][pbr][normal_map]") {
    const facet::FrameImages images = render_bump(false);
    for (const glm::vec3& p : bump_points()) {
        INFO("point " << p.x << ", " << p.z);
        CHECK(degrees_between(normal_at(images, p), hemisphere_normal(p.x, p.z)) < 2.0f);
    }
    // Off the bump the quad is flat.
    CHECK(degrees_between(normal_at(images, {0.9f, 0, 0.9f}), {0, 1, 0}) < 1.0f);
}

TEST_CASE("normal map: a flipped green channel tilts the bump the wrong way along v",
          "[render][pbr][normal_map]") {
    const facet::FrameImages images = render_bump(true);
    // Along the v axis (world Z) the flipped map's normals lean the other way.
    const float z = 0.4f;
    const glm::vec3 seen = normal_at(images, {0.0f, 0.0f, z});
    CHECK(degrees_between(seen, hemisphere_normal(0.0f, z)) > 30.0f);
    CHECK(seen.z < 0.0f);
    // Along u (world X) nothing changes.
    CHECK(degrees_between(normal_at(images, {0.4f, 0.0f, 0.0f}), hemisphere_normal(0.4f, 0.0f)) <
          2.0f);
}

TEST_CASE("normal map: styles other than pbr leave the normals as the mesh has them",
          "[render][pbr][normal_map]") {
    const facet::FrameImages images = render_bump(false, "blinn-phong");
    CHECK(degrees_between(normal_at(images, {0.3f, 0.0f, 0.3f}), {0, 1, 0}) < 0.5f);
}

TEST_CASE("mapped_normal: seen from the back, the whole frame turns over", "[pbr][normal_map]") {
    const glm::vec3 n(0, 1, 0);
    const glm::vec4 t(1, 0, 0, 1);
    const glm::vec3 texel(0.75f, 0.5f, 0.5f + 0.5f * std::sqrt(0.75f));  // tilted towards +u
    const glm::vec3 front = facet::mapped_normal(n, t, false, texel, 1.0f);
    const glm::vec3 back = facet::mapped_normal(n, t, true, texel, 1.0f);
    CHECK(front.x == Approx(0.5f).margin(1e-3));
    CHECK(back.x == Approx(-front.x).margin(1e-6));
    CHECK(back.y == Approx(-front.y).margin(1e-6));
    // normal_scale 0 leaves the normal.
    CHECK(degrees_between(facet::mapped_normal(n, t, false, texel, 0.0f), n) < 1e-3f);
    // A tangent along the normal cannot make a frame: the normal stays.
    CHECK(facet::mapped_normal(n, glm::vec4(0, 1, 0, 1), false, texel, 1.0f) == n);
}

TEST_CASE("normal map: a mirrored mapping (uv_scale -1) still gives the hemisphere's normals",
          "[render][pbr][normal_map]") {
    // u' = -u, v' = -v: the map is read turned half round, and its stored
    // directions must turn with it, or the bump lights as a dent.
    const facet::FrameImages images = render_bump(false, "pbr", ", uv_scale: -1");
    for (const glm::vec3& p : bump_points()) {
        INFO("point " << p.x << ", " << p.z);
        CHECK(degrees_between(normal_at(images, p), hemisphere_normal(p.x, p.z)) < 2.0f);
    }
}
