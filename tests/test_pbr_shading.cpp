// The `pbr` shading model end to end (docs/pbr.md): the white furnace,
// the calibration of lights against the Phong models, the material keys,
// environments, determinism and the passes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include "core/half.hpp"
#include "render_check.hpp"
#include "shade/environment_map.hpp"
#include "support.hpp"

using facet::test::pixel_at;

namespace {

std::string number(float v) {
    std::string s = std::to_string(v);
    return s;
}

// A unit sphere at the origin seen from +Z, in linear colour.
facet::FrameImages render_sphere(const std::string& material, const std::string& environment,
                                 const std::string& lights = "[]", unsigned threads = 2,
                                 const std::string& extra = "") {
    facet::test::TempDir dir("pbr");
    const std::string text = R"(output: { size: [96, 96], tonemap: none, passes: [color, normal] }
camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 35 }
style: pbr
)" + environment +
                             "\nlights: " + lights +
                             R"(
objects:
  - name: ball
    primitive: { type: sphere, radius: 1, segments: 96, rings: 48 }
    material: )" + material + "\n" +
                             extra;
    return facet::test::render_yaml(dir.path(), text, 1, threads);
}

// The sphere's point whose normal makes angle `degrees` with the view, in
// the horizontal plane (the camera is far enough for n.v to be close).
glm::vec3 sphere_point(float degrees) {
    const float a = glm::radians(degrees);
    return {std::sin(a), 0.0f, std::cos(a)};
}

}  // namespace

TEST_CASE("pbr: a white sphere in a white environment reflects 1 (the white furnace)",
          "[render][pbr]") {
    for (const float metallic : {0.0f, 1.0f})
        for (const float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            const facet::FrameImages images =
                render_sphere("{ color: [1, 1, 1], metallic: " + number(metallic) +
                                  ", roughness: " + number(roughness) + " }",
                              "environment: { color: [1, 1, 1] }");
            for (const float angle : {0.0f, 30.0f, 60.0f}) {
                INFO("metallic " << metallic << ", roughness " << roughness << ", angle " << angle);
                const glm::vec4 c = pixel_at(images, images.color, sphere_point(angle));
                for (int a = 0; a < 3; ++a) CHECK(c[a] == Approx(1.0).margin(0.03));
            }
        }
}

TEST_CASE(
    "pbr: a light of intensity 1 gives a white matte surface facing it radiance 1, as "
    "Phong does",
    "[render][pbr]") {
    // A rough dielectric with its reflectance taken away (specular weight
    // 0 through ior 1) is Lambertian: albedo * pi * E / pi.
    const facet::FrameImages images = render_sphere(
        "{ color: [1, 1, 1], metallic: 0, roughness: 1, ior: 1 }", "environment: none",
        "[{ type: directional, direction: [0, 0, -1], intensity: 1 }]");
    const glm::vec4 facing = pixel_at(images, images.color, sphere_point(0));
    for (int a = 0; a < 3; ++a) CHECK(facing[a] == Approx(1.0).margin(0.01));
    // Lambert's cosine at 60 degrees.
    const glm::vec4 side = pixel_at(images, images.color, sphere_point(60));
    CHECK(side.r == Approx(0.5).margin(0.03));
}

TEST_CASE("pbr: a metal takes its base colour as its reflection's tint, a dielectric does not",
          "[render][pbr]") {
    const std::string env = "environment: { color: [1, 1, 1] }";
    const facet::FrameImages gold =
        render_sphere("{ color: [1.0, 0.78, 0.34], metallic: 1, roughness: 0.3 }", env);
    const facet::FrameImages plastic =
        render_sphere("{ color: [1.0, 0.78, 0.34], metallic: 0, roughness: 0.3 }", env);
    const glm::vec4 g = pixel_at(gold, gold.color, sphere_point(0));
    const glm::vec4 p = pixel_at(plastic, plastic.color, sphere_point(0));
    // At normal incidence a metal reflects its f0, the base colour.
    CHECK(g.b == Approx(0.34).margin(0.05));
    // The dielectric's white 4 % reflection lifts blue above its albedo.
    CHECK(p.b > 0.34f + 0.02f);
}

TEST_CASE("pbr: the built-in studio lights a scene without an environment", "[render][pbr]") {
    const facet::FrameImages images =
        render_sphere("{ color: [0.8, 0.8, 0.8], metallic: 0, roughness: 0.5 }", "");
    const glm::vec4 c = pixel_at(images, images.color, sphere_point(0));
    // Exactly the scene with `environment: studio` written out.
    const facet::FrameImages studio = render_sphere(
        "{ color: [0.8, 0.8, 0.8], metallic: 0, roughness: 0.5 }", "environment: studio");
    REQUIRE(images.color.pixels.size() == studio.color.pixels.size());
    CHECK(std::memcmp(images.color.pixels.data(), studio.color.pixels.data(),
                      images.color.pixels.size() * sizeof(images.color.pixels[0])) == 0);
    CHECK(c.r > 0.2f);  // lit: the studio's key faces the camera
    // Neutral grey stays grey.
    CHECK(c.g == Approx(c.r).margin(0.02));
    // `environment: none` with no lights leaves the sphere black.
    const facet::FrameImages dark =
        render_sphere("{ color: [0.8, 0.8, 0.8] }", "environment: none");
    CHECK(glm::vec3(pixel_at(dark, dark.color, sphere_point(0))) == glm::vec3(0.0f));
}

TEST_CASE("pbr: the same frame from 1 and 3 threads is bit-identical", "[render][pbr]") {
    const std::string material = "{ color: [0.9, 0.4, 0.2], metallic: 0.5, roughness: 0.4 }";
    const std::string lights =
        "[{ type: point, position: [2, 2, 3], intensity: 10, shadows: true }]";
    const facet::FrameImages one = render_sphere(material, "", lights, 1);
    const facet::FrameImages three = render_sphere(material, "", lights, 3);
    REQUIRE(one.color.pixels.size() == three.color.pixels.size());
    CHECK(std::memcmp(one.color.pixels.data(), three.color.pixels.data(),
                      one.color.pixels.size() * sizeof(one.color.pixels[0])) == 0);
}

TEST_CASE("pbr: a keyed environment rotation moves reflections and nothing else", "[render][pbr]") {
    // A mirror sphere reflects the studio's key; turned by 90 degrees the
    // key moves away, and the normal pass does not change.
    const std::string mirror = "{ color: [1, 1, 1], metallic: 1, roughness: 0.05 }";
    const facet::FrameImages still = render_sphere(mirror, "environment: { rotation: 0 }");
    const facet::FrameImages turned = render_sphere(mirror, "environment: { rotation: 90 }");
    CHECK(std::memcmp(
              still.surface.normal.pixels.data(), turned.surface.normal.pixels.data(),
              still.surface.normal.pixels.size() * sizeof(still.surface.normal.pixels[0])) == 0);
    // Where the still sphere mirrors the studio's key softbox (a direction
    // 35 degrees up and 40 degrees from +Z towards -X, where its light is
    // even), the turned one mirrors what the studio holds 90 degrees round:
    // a world direction r reads the map at R(-90) r = (-r.z, r.y, r.x) (+X
    // turns towards -Z). The two pixels stand as the studio's sharp lookups.
    const float up = glm::radians(35.0f), round = glm::radians(-40.0f);
    const glm::vec3 r(std::cos(up) * std::sin(round), std::sin(up), std::cos(up) * std::cos(round));
    glm::vec3 n = glm::normalize(r + glm::vec3(0, 0, 1));  // the normal halfway to the eye
    for (int i = 0; i < 20; ++i) n = glm::normalize(r + glm::normalize(glm::vec3(0, 0, 4) - n));
    const facet::pbr::SharedEnvironment studio = facet::pbr::shared_studio_environment();
    const float key = studio->specular(r, 0.05f).g;
    const float beside = studio->specular({-r.z, r.y, r.x}, 0.05f).g;
    REQUIRE(beside < 0.5f * key);  // the key is there, and not 90 degrees round
    const glm::vec4 a = pixel_at(still, still.color, n);
    const glm::vec4 b = pixel_at(turned, turned.color, n);
    CHECK(b.g / a.g == Approx(beside / key).epsilon(0.05));
}

TEST_CASE("pbr: ior sets the dielectric's reflectance at normal incidence", "[render][pbr]") {
    // Black dielectric: only the specular lobe shows; facing the view in a
    // uniform white environment it reflects its directional albedo, which
    // at n.v = 1 is close to F0 for a smooth surface.
    for (const float ior : {1.5f, 2.0f}) {
        const float f0 = std::pow((ior - 1.0f) / (ior + 1.0f), 2.0f);
        const facet::FrameImages images = render_sphere(
            "{ color: [0, 0, 0], metallic: 0, roughness: 0.05, ior: " + number(ior) + " }",
            "environment: { color: [1, 1, 1] }");
        const glm::vec4 c = pixel_at(images, images.color, sphere_point(0));
        INFO("ior " << ior);
        CHECK(c.r == Approx(f0).epsilon(0.1));
    }
}

TEST_CASE("pbr: a clear coat keeps a white sphere in a white environment at 1", "[render][pbr]") {
    for (const float roughness : {0.1f, 0.6f}) {
        const facet::FrameImages images =
            render_sphere("{ color: [1, 1, 1], metallic: 0, roughness: " + number(roughness) +
                              ", clearcoat: 1, clearcoat_roughness: 0.2 }",
                          "environment: { color: [1, 1, 1] }");
        for (const float angle : {0.0f, 45.0f}) {
            INFO("roughness " << roughness << ", angle " << angle);
            const glm::vec4 c = pixel_at(images, images.color, sphere_point(angle));
            CHECK(c.r == Approx(1.0).margin(0.03));
        }
    }
}

TEST_CASE("pbr: a sheen keeps a white sphere in a white environment at 1", "[render][pbr]") {
    // The sheen takes from the base what it reflects (docs/pbr.md, "The sheen").
    for (const float sheen_roughness : {0.3f, 0.8f}) {
        const facet::FrameImages images = render_sphere(
            "{ color: [1, 1, 1], metallic: 0, roughness: 0.5, sheen_color: [0.8, 0.8, 0.8], "
            "sheen_roughness: " +
                number(sheen_roughness) + " }",
            "environment: { color: [1, 1, 1] }");
        for (const float angle : {0.0f, 45.0f, 60.0f}) {
            INFO("sheen roughness " << sheen_roughness << ", angle " << angle);
            const glm::vec4 c = pixel_at(images, images.color, sphere_point(angle));
            for (int a = 0; a < 3; ++a) CHECK(c[a] == Approx(1.0).margin(0.03));
        }
    }
}

TEST_CASE("pbr: a red sheen over a dark base lights the rim red, the centre little",
          "[render][pbr]") {
    // Velvet: a dark base whose fibres catch the light at grazing angles.
    const std::string light = "[{ type: directional, direction: [0, 0, -1], intensity: 2 }]";
    const std::string base = "color: [0.02, 0.02, 0.02], metallic: 0, roughness: 1";
    const facet::FrameImages velvet =
        render_sphere("{ " + base + ", sheen_color: [1, 0, 0], sheen_roughness: 0.5 }",
                      "environment: { color: [0, 0, 0] }", light);
    const facet::FrameImages bare =
        render_sphere("{ " + base + " }", "environment: { color: [0, 0, 0] }", light);
    const glm::vec4 rim = pixel_at(velvet, velvet.color, sphere_point(62.0f));
    const glm::vec4 centre = pixel_at(velvet, velvet.color, sphere_point(0.0f));
    const glm::vec4 bare_rim = pixel_at(bare, bare.color, sphere_point(62.0f));
    INFO("rim " << rim.r << " " << rim.g << " " << rim.b << ", centre " << centre.r);
    CHECK(rim.r > 4.0f * bare_rim.r);  // the sheen shows
    CHECK(rim.r > 3.0f * rim.g);       // in its colour
    CHECK(rim.g < bare_rim.g);         // and the base under it keeps less
    CHECK(rim.r > 1.5f * centre.r);    // most at grazing
}

TEST_CASE(
    "pbr: the environment as background fills what nothing covers, and a shadow "
    "catcher darkens it",
    "[render][pbr]") {
    facet::test::TempDir dir("pbr-background");
    const std::string text = R"(output: { size: [120, 90], tonemap: none, background: [0, 0, 1, 1] }
camera: { position: [0, 3, 5], target: [0, 0.5, 0], fov: 40 }
style: pbr
environment: { color: [0.5, 0.25, 0.125], background: true }
lights: [{ type: directional, direction: [0, -1, 0], intensity: 1, shadows: true }]
objects:
  - name: floor
    primitive: { type: plane, size: 6 }
    material: { shadow_catcher: true }
  - name: cube
    primitive: { type: cube, size: 1 }
    translate: [0, 1, 0]
)";
    const facet::FrameImages images = facet::test::render_yaml(dir.path(), text, 1, 2);
    // A corner above the horizon shows the environment, not the blue background.
    const glm::vec4 sky = facet::to_float(images.color.at(2, 2));
    CHECK(sky.r == Approx(0.5).margin(0.002));
    CHECK(sky.g == Approx(0.25).margin(0.002));
    CHECK(sky.b == Approx(0.125).margin(0.002));
    CHECK(sky.a == 1.0f);
    // Under the cube the catcher's shadow darkens the environment behind it.
    const glm::vec4 shadow = pixel_at(images, images.color, {0.0f, 0.0f, 0.45f});
    CHECK(shadow.r < 0.3f);
    CHECK(shadow.b == Approx(shadow.r / 4).margin(0.01));
}

TEST_CASE(
    "pbr: a frame rendered alone is the same bytes as in its sequence, with a keyed "
    "rotation",
    "[render][pbr][cli]") {
    facet::test::TempDir dir("pbr-frames");
    const std::string scene = facet::test::write_text(dir.file("scene.yaml"), R"(
output: { size: [64, 48], frames: "1-3" }
camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 35 }
style: pbr
environment: { rotation: { keys: { 1: 0, 3: 120 } } }
objects:
  - primitive: { type: sphere, radius: 1 }
    material: { color: [0.9, 0.9, 0.9], metallic: 1, roughness: 0.2 }
)");
    const auto all =
        facet::test::run_facet("render '" + scene + "' -q -o '" + dir.file("all") + "'");
    const auto one =
        facet::test::run_facet("render '" + scene + "' -q -f 3 -o '" + dir.file("one") + "'");
    REQUIRE(all.exit_code == 0);
    REQUIRE(one.exit_code == 0);
    const std::string in_sequence = facet::test::read_file(dir.file("all/scene/color.0003.png"));
    CHECK_FALSE(in_sequence.empty());
    CHECK(in_sequence == facet::test::read_file(dir.file("one/scene/color.0003.png")));
    // The rotation moved the reflections between frames 1 and 3.
    CHECK(in_sequence != facet::test::read_file(dir.file("all/scene/color.0001.png")));
}
