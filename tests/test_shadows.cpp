// Shadow maps on small scenes with known answers, rendered through the
// library: a white floor (ambient 0.2, diffuse 0.8, no highlight) and red
// casters, so floor pixels are told apart by their green channel and a
// shadowed floor pixel is 0.2 where a lit one is 0.2 + 0.8 n·l.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "anim/frame_state.hpp"
#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/camera.hpp"
#include "render/frame_renderer.hpp"
#include "render/pose_stage.hpp"
#include "render/shadow_stage.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "shade/shadow_map.hpp"
#include "support.hpp"

using namespace facet;

namespace {

const char* kFloorMaterial = "{ color: [1, 1, 1], ambient: 0.2, diffuse: 0.8, specular: 0 }";
const char* kRedMaterial = "{ color: [1, 0, 0], ambient: 0.2, diffuse: 0.8, specular: 0 }";

struct Rendered {
    FrameImages frame;
    ColorImage color;  // the frame's colour as floats
    CameraMatrices camera;
};

Rendered render_yaml(const std::string& yaml, unsigned threads = 2) {
    test::TempDir dir("shadows");
    const std::string path = test::write_text(dir.file("scene.yaml"), yaml);
    const SceneDesc scene = test::load(path);
    const World world = build_world(scene);
    ThreadPool pool(threads);
    FrameRenderer renderer(scene, world, pool);
    Rendered out;
    renderer.render(1, 0, out.frame);
    out.color = to_float_image(out.frame.color);
    const FrameState state = evaluate_frame(scene, world.object_bounds, 1);
    out.camera = make_camera(state.camera, static_cast<float>(scene.output.width) /
                                               static_cast<float>(scene.output.height));
    return out;
}

bool is_floor(const glm::vec4& c) {
    return c.g > 0.1f && std::abs(c.r - c.g) < 1e-4f;
}

// The pixel that shows world point p; the test fails if p is off screen.
glm::vec4 pixel_at(const Rendered& r, const glm::vec3& p) {
    const glm::vec4 clip = r.camera.view_projection * glm::vec4(p, 1.0f);
    const float x = (clip.x / clip.w + 1.0f) * 0.5f * static_cast<float>(r.color.width);
    const float y = (1.0f - clip.y / clip.w) * 0.5f * static_cast<float>(r.color.height);
    INFO("world point (" << p.x << ", " << p.y << ", " << p.z << ") at pixel " << x << ", " << y);
    REQUIRE(clip.w > 0);
    REQUIRE(x >= 0);
    REQUIRE(y >= 0);
    REQUIRE(x < static_cast<float>(r.color.width));
    REQUIRE(y < static_cast<float>(r.color.height));
    return r.color.at(static_cast<int>(x), static_cast<int>(y));
}

// Floor brightness halfway between shadowed (0.2) and lit (0.2 + 0.8 n·l).
float threshold(float n_dot_l) {
    return 0.2f + 0.4f * n_dot_l;
}

// A cube of edge 1 standing on the floor, seen from straight above by a
// camera 20 units up whose view is 4 x 4 units at the floor.
std::string standing_cube_scene(const std::string& cube_extra, const std::string& floor_extra) {
    return std::string(R"(
output: { size: [256, 256], background: [0, 0, 0, 1] }
style: blinn-phong
camera: { position: [0, 20, 0], target: [0, 0, 0], up: [0, 0, -1], fov: 11.421186 }
lights: [ { type: directional, direction: [1, -2, 0], shadows: true } ]
objects:
  - { name: cube, primitive: cube, translate: [0, 0.5, 0], material: )") +
           kRedMaterial + cube_extra + R"( }
  - { name: floor, primitive: { type: plane, size: 6 }, material: )" +
           kFloorMaterial + floor_extra + " }\n";
}

struct ShadowPixels {
    size_t count = 0;
    double sum_x = 0, sum_z = 0;  // world coordinates of the shadowed floor pixels
};

// Shadowed floor pixels of the top view (image x -> world x, image y -> world z).
ShadowPixels count_shadow(const Rendered& r, float n_dot_l) {
    ShadowPixels s;
    const ColorImage& img = r.color;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::vec4& c = img.at(x, y);
            if (!is_floor(c) || c.g >= threshold(n_dot_l)) continue;
            ++s.count;
            s.sum_x += ((x + 0.5) / img.width * 2 - 1) * 2;
            s.sum_z += ((y + 0.5) / img.height * 2 - 1) * 2;
        }
    return s;
}

}  // namespace

TEST_CASE("a cube's shadow under a directional light has the expected area and place",
          "[shadow][render]") {
    const Rendered r = render_yaml(standing_cube_scene("", ""));
    const float n_dot_l = 2.0f / std::sqrt(5.0f);
    const ShadowPixels s = count_shadow(r, n_dot_l);
    // Light travelling (1, -2, 0) throws the cube's top edge at x = 0.5 to
    // x = 1 on the floor: the shadow is x in [0.5, 1], z in [-0.5, 0.5].
    // From 20 units up the cube's top hides the floor to x = 0.5 * 20/19.
    const double hidden_edge = 0.5 * 20.0 / 19.0;
    const double expected_area = (1.0 - hidden_edge) * 1.0;
    const double pixel_area = (4.0 / 256) * (4.0 / 256);
    const double area = static_cast<double>(s.count) * pixel_area;
    INFO("shadow area " << area << ", expected " << expected_area);
    // Within 4%: the edge pixels (about 190 of 1940) may fall either way.
    CHECK(area == Approx(expected_area).epsilon(0.04));
    REQUIRE(s.count > 0);
    // Centroid within a pixel and a half (0.023 units).
    CHECK(s.sum_x / s.count == Approx((1.0 + hidden_edge) / 2).margin(0.023));
    CHECK(s.sum_z / s.count == Approx(0.0).margin(0.023));
}

TEST_CASE("cast_shadows and receive_shadows false leave the floor lit", "[shadow][render]") {
    const float n_dot_l = 2.0f / std::sqrt(5.0f);
    CHECK(count_shadow(render_yaml(standing_cube_scene(", cast_shadows: false", "")), n_dot_l)
              .count == 0);
    CHECK(count_shadow(render_yaml(standing_cube_scene("", ", receive_shadows: false")), n_dot_l)
              .count == 0);
    // Shadows off on the light: the same.
    std::string off = standing_cube_scene("", "");
    off.replace(off.find("shadows: true"), 13, "shadows: false");
    CHECK(count_shadow(render_yaml(off), n_dot_l).count == 0);
}

namespace {

// A floating cube over a large floor, lit from above by `light`; a small
// box off to the side (only in the point-light scene) shadows the far floor
// through another face of the cube map.
std::string floating_cube_scene(const std::string& light, bool side_box = false) {
    std::string yaml = std::string(R"(
output: { size: [240, 240], background: [0, 0, 0, 1] }
style: blinn-phong
camera: { position: [2, 16, 14], target: [2, 0, 0], fov: 60 }
lights: [ )") + light + R"( ]
objects:
  - { name: cube, primitive: cube, translate: [0, 2, 0], material: )" +
                       kRedMaterial + R"( }
  - { name: floor, primitive: { type: plane, size: 24 }, material: )" +
                       kFloorMaterial + " }\n";
    if (side_box)
        yaml += std::string(
                    "  - { name: side, primitive: { type: cube, size: 0.6 }, translate: "
                    "[2.5, 3.2, 0], material: ") +
                kRedMaterial + " }\n";
    return yaml;
}

void check_dark(const Rendered& r, const glm::vec3& p) {
    const glm::vec4 c = pixel_at(r, p);
    INFO("(" << p.x << ", " << p.z << ") colour " << c.r << " " << c.g << " " << c.b);
    CHECK(is_floor(c));
    CHECK(c.g == Approx(0.2f).margin(0.01f));  // ambient only
}

void check_lit(const Rendered& r, const glm::vec3& p, float at_least) {
    const glm::vec4 c = pixel_at(r, p);
    INFO("(" << p.x << ", " << p.z << ") colour " << c.r << " " << c.g << " " << c.b);
    CHECK(is_floor(c));
    CHECK(c.g > at_least);
}

}  // namespace

TEST_CASE("points inside a shadow are dark and outside lit: directional light",
          "[shadow][render]") {
    const Rendered r = render_yaml(
        floating_cube_scene("{ type: directional, direction: [0.3, -1, 0.2], shadows: true }"));
    // The cube's centre (0, 2, 0) falls on the floor at (0.6, 0, 0.4).
    check_dark(r, {0.6f, 0, 0.4f});
    check_dark(r, {0.3f, 0, 0.2f});
    check_lit(r, {-3, 0, 2}, 0.8f);
    check_lit(r, {2.5f, 0, 0.4f}, 0.8f);
}

TEST_CASE("points inside a shadow are dark and outside lit: spot light", "[shadow][render]") {
    // From (0, 5, 0) the cube (y 1.5 to 2.5) shadows the floor to |x|, |z| <= 1.
    for (const char* outer : {"45", "70"}) {  // 70: wide enough for a cube map
        INFO("outer angle " << outer);
        const Rendered r = render_yaml(floating_cube_scene(
            std::string("{ type: spot, position: [0, 5, 0], direction: [0, -1, 0], inner_angle: "
                        "35, outer_angle: ") +
            outer + ", intensity: 25, shadows: true }"));
        check_dark(r, {0, 0, 0});
        check_dark(r, {0.7f, 0, -0.7f});
        check_lit(r, {2, 0, -1}, 0.6f);  // 24 degrees off the axis, inside the inner cone
        check_lit(r, {-1.6f, 0, 0}, 0.6f);
    }
}

TEST_CASE("points inside a shadow are dark and outside lit: point light (cube map)",
          "[shadow][render]") {
    const Rendered r = render_yaml(floating_cube_scene(
        "{ type: point, position: [0, 5, 0], intensity: 25, shadows: true }", true));
    check_dark(r, {0, 0, 0});  // below: the -Y face
    check_dark(r, {-0.8f, 0, 0.8f});
    check_lit(r, {-2, 0, 0}, 0.4f);
    check_lit(r, {3.5f, 0, -2}, 0.2f + 0.1f);
    // The side box at (2.5, 3.2, 0) is seen through the +X face and throws
    // its shadow to x from about 5.2 to 9.3.
    check_dark(r, {7, 0, 0});
    check_lit(r, {7, 0, 2.5f}, 0.2f + 0.05f);
}

namespace {

// Colour differences between a render with shadows and one without.
size_t changed_pixels(const Rendered& a, const Rendered& b, bool (*where)(const glm::vec4&)) {
    size_t changed = 0;
    for (size_t i = 0; i < a.color.pixels.size(); ++i) {
        const glm::vec4& p = a.color.pixels[i];
        const glm::vec4& q = b.color.pixels[i];
        if (where(q) && glm::vec3(p) != glm::vec3(q)) ++changed;
    }
    return changed;
}

std::string open_floor(const std::string& light, bool shadows) {
    return std::string(R"(
output: { size: [200, 200], background: [0, 0, 0, 1] }
style: blinn-phong
camera: { position: [0, 6, 8], target: [0, 0, 0], fov: 60 }
lights: [ )") +
           light + ", shadows: " + (shadows ? "true" : "false") + R"( } ]
objects:
  - { name: floor, primitive: { type: plane, size: 16 }, material: )" +
           kFloorMaterial + " }\n";
}

}  // namespace

TEST_CASE("no acne: a lit floor has no shadowed pixel", "[shadow][render]") {
    for (const char* light : {"{ type: directional, direction: [0, -1, 0]",
                              "{ type: directional, direction: [3, -1, 1]",
                              "{ type: directional, direction: [1, -3, -2]",
                              "{ type: spot, position: [1, 3, 0], direction: [-1, -2, 0], "
                              "outer_angle: 55, intensity: 9",
                              "{ type: point, position: [0, 2, 0], intensity: 4",
                              "{ type: point, position: [3, 0.5, -1], intensity: 4"}) {
        INFO(light);
        const Rendered on = render_yaml(open_floor(light, true));
        const Rendered off = render_yaml(open_floor(light, false));
        CHECK(changed_pixels(on, off, is_floor) == 0);
    }
}

namespace {

bool is_red(const glm::vec4& c) {
    return c.r > 0.0f && c.g == 0.0f;
}

}  // namespace

TEST_CASE("no acne on a smooth sphere's lit side", "[shadow][render]") {
    // Smooth normals on a sphere disagree with its flat facets in the map;
    // where n·l is at least 0.3 that must not show. On a very coarse sphere
    // the facets near the terminator turn away from the light while their
    // smooth normals still face it: a larger shadow_bias clears them.
    auto scene = [](const std::string& sphere, const std::string& light) {
        return std::string(R"(
output: { size: [200, 200], background: [0, 0, 0, 1] }
style: blinn-phong
camera: { position: [0, 2, 4], target: [0, 0.6, 0], fov: 40 }
lights: [ { type: directional, direction: [1, -1.5, -0.5])") +
               light + R"( } ]
objects:
  - { primitive: { type: sphere, radius: 0.6)" +
               sphere + R"( }, translate: [0, 0.6, 0], material: )" + kRedMaterial + R"( }
  - { name: floor, primitive: { type: plane, size: 6 }, material: )" +
               kFloorMaterial + " }\n";
    };
    struct Case {
        const char* sphere;
        const char* light;
    };
    for (const Case& c : {Case{"", ", shadows: true"},
                          Case{", segments: 16, rings: 8", ", shadows: true, shadow_bias: 2"}}) {
        INFO("sphere" << c.sphere << ", light" << c.light);
        const Rendered on = render_yaml(scene(c.sphere, c.light));
        const Rendered off = render_yaml(scene(c.sphere, ""));
        size_t compared = 0, changed = 0;
        for (size_t i = 0; i < on.color.pixels.size(); ++i) {
            const glm::vec4& q = off.color.pixels[i];
            if (!is_red(q) || q.r < 0.2f + 0.8f * 0.3f) continue;
            ++compared;
            if (on.color.pixels[i].r != q.r) ++changed;
        }
        CHECK(compared > 1000);
        CHECK(changed == 0);
    }
}

TEST_CASE("contact: the floor right next to a box's base is shadowed", "[shadow][render]") {
    // Light travelling +x shadows the floor on the box's +x side; the camera
    // looks at that side. With a 512-texel map a texel is about 0.0125
    // units: the shadow reaches to within 1.2 texels of the base.
    const Rendered r = render_yaml(std::string(R"(
output: { size: [300, 300], background: [0, 0, 0, 1] }
style: blinn-phong
camera: { position: [4, 2.5, 0.5], target: [0.5, 0, 0], fov: 40 }
lights: [ { type: directional, direction: [1, -2, 0], shadows: true, shadow_resolution: 512 } ]
objects:
  - { name: box, primitive: cube, translate: [0, 0.5, 0], material: )") +
                                   kRedMaterial + R"( }
  - { name: floor, primitive: { type: plane, size: 4 }, material: )" +
                                   kFloorMaterial + " }\n");
    for (float gap : {0.015f, 0.03f, 0.06f, 0.2f, 0.4f})
        for (float z : {-0.4f, 0.0f, 0.4f}) check_dark(r, {0.5f + gap, 0, z});
    // Past the shadow's end (x = 1) the floor is lit again.
    check_lit(r, {1.15f, 0, 0}, threshold(2.0f / std::sqrt(5.0f)));
}

TEST_CASE("shadowed frames are identical at 1, 2 and 3 threads", "[shadow][determinism]") {
    const std::string yaml = std::string(R"(
output: { size: [160, 120], background: [0, 0, 0, 1] }
style: phong
camera: { position: [2, 6, 9], target: [0, 0.5, 0], fov: 50 }
lights:
  - { type: directional, direction: [1, -2, -1], intensity: 0.5, shadows: true, shadow_softness: 2 }
  - { type: spot, position: [-2, 4, 1], direction: [1, -2, 0], outer_angle: 40, intensity: 10,
      shadows: true }
  - { type: point, position: [1, 2.5, 2], intensity: 5, color: { kelvin: 2700 }, shadows: true }
  - { type: ambient, intensity: 0.5 }
objects:
  - { primitive: { type: icosahedron, radius: 0.8 }, translate: [0, 0.8, 0], material: )") +
                             kRedMaterial + R"( }
  - { primitive: { type: torus, radius: 0.6, tube: 0.2 }, translate: [1.5, 1, -1],
      rotate: [60, 0, 20] }
  - { name: floor, primitive: { type: plane, size: 10 }, material: )" +
                             kFloorMaterial + " }\n";
    const Rendered one = render_yaml(yaml, 1);
    const Rendered two = render_yaml(yaml, 2);
    const Rendered three = render_yaml(yaml, 3);
    CHECK(one.color.pixels == two.color.pixels);
    CHECK(one.color.pixels == three.color.pixels);
}

namespace {

const char* const kEachShadowLight[] = {
    "{ type: directional, direction: [0.3, -1, 0.2], shadows: true, shadow_softness: 2 }",
    "{ type: spot, position: [0, 5, 0], direction: [0, -1, 0], outer_angle: 45, shadows: true }",
    "{ type: point, position: [0, 5, 0], intensity: 25, shadows: true }"};

// The shadow map the stage draws for the floating cube's scene, lit by
// `light`; with `floor_casts` false the floor only receives (as the demo's).
ShadowMap floating_cube_shadow_map(const std::string& light, bool floor_casts = true) {
    test::TempDir dir("shadow-map");
    std::string yaml = floating_cube_scene(light, true);
    if (!floor_casts) {
        const std::string floor = "name: floor,";
        REQUIRE(yaml.find(floor) != std::string::npos);
        yaml.replace(yaml.find(floor), floor.size(), floor + " cast_shadows: false,");
    }
    const SceneDesc scene = test::load(test::write_text(dir.file("scene.yaml"), yaml));
    const World world = build_world(scene);
    ThreadPool pool(2);
    const FrameState state = evaluate_frame(scene, world.object_bounds, 1);
    PoseStage pose(scene, world);
    const RenderPlan plan = plan_render(scene, world);
    ShadowStage stage(scene, world, plan.transmitting);
    const std::span<const ShadowMap* const> maps = stage.render(state, pose.pose(state), pool);
    REQUIRE(maps.size() == 1);
    REQUIRE(maps[0] != nullptr);
    return *maps[0];
}

// Each light with the floor casting shadows and not.
std::vector<std::pair<std::string, bool>> each_light_and_floor() {
    std::vector<std::pair<std::string, bool>> cases;
    for (const char* light : kEachShadowLight)
        for (const bool floor_casts : {true, false}) cases.emplace_back(light, floor_casts);
    return cases;
}

// Points on the floor round the shadow and on the cube's top, with the
// normals of both, tilted ones and none, handed to `look(position, normal)`.
template <typename Look>
void each_receiver(Look look) {
    for (float x = -3.0f; x <= 3.0f; x += 0.037f)
        for (float z = -3.0f; z <= 3.0f; z += 0.041f)
            for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0.3f, 1, -0.2f), glm::vec3(0)})
                for (const glm::vec3 p : {glm::vec3(x, 0, z), glm::vec3(0.2f * x, 2.5f, 0.2f * z)})
                    look(p, n);
}

}  // namespace

// A map keeps the nearest caster of each block of texels, and a lookup
// whose filter lies in blocks whose casters are all farther than the point
// skips its texels (shade/shadow_map.hpp). Skipping must change nothing:
// the same visibility, bit for bit, as reading every texel.
TEST_CASE("the shadow map's blocks change no lookup", "[shadow]") {
    for (const auto& [light, floor_casts] : each_light_and_floor()) {
        INFO(light << (floor_casts ? ", the floor casting" : ", the floor not casting"));
        const ShadowMap blocked = floating_cube_shadow_map(light, floor_casts);
        REQUIRE_FALSE(blocked.block_nearest.empty());
        ShadowMap every_texel = blocked;
        every_texel.block_nearest.clear();
        size_t dark = 0, lit = 0, partly = 0;
        each_receiver([&](const glm::vec3& p, const glm::vec3& n) {
            const float a = shadow_visibility(blocked, p, n);
            const float b = shadow_visibility(every_texel, p, n);
            if (a != b) FAIL_CHECK("at " << p.x << ", " << p.y << ", " << p.z);
            (a == 0.0f ? dark : a == 1.0f ? lit : partly) += 1;
        });
        CHECK(dark > 100);
        CHECK(lit > 1000);
        CHECK(partly > 100);
        // And the blocks are used where nothing near the point casts: with
        // every texel made a caster at the light, a lookup that reads its
        // texels finds itself in shadow, so only the skipped ones stay lit.
        // Most lit points of a floor that casts nothing are skipped (one that
        // casts is in its own blocks, so it reads its texels).
        if (floor_casts) continue;
        ShadowMap poisoned = blocked;
        std::fill(poisoned.depth.begin(), poisoned.depth.end(), 0.0f);
        size_t skipped = 0, lit_points = 0;
        each_receiver([&](const glm::vec3& p, const glm::vec3& n) {
            if (p.y != 0.0f || shadow_visibility(blocked, p, n) != 1.0f) return;
            ++lit_points;
            if (shadow_visibility(poisoned, p, n) == 1.0f) ++skipped;
        });
        INFO(skipped << " of " << lit_points << " lit floor points skipped their texels");
        CHECK(skipped * 2 > lit_points);
    }
}

// Lighting looks shadows up eight points at a time; each lane must get
// what the one-point lookup gives (the stylised models use that one).
TEST_CASE("eight shadow lookups at once give each point's own bits", "[shadow]") {
    for (const char* light : kEachShadowLight) {
        INFO(light);
        const ShadowMap map = floating_cube_shadow_map(light);
        ShadowPoints points{};
        float expected[simd::kLanes];
        int filled = 0;
        size_t compared = 0, shadowed = 0;
        const auto check_batch = [&](unsigned lanes) {
            const simd::vf got = shadow_visibility(map, points, lanes);
            for (int i = 0; i < simd::kLanes; ++i) {
                const float want = (lanes >> i) & 1 ? expected[i] : 1.0f;
                if (got[i] != want)
                    FAIL_CHECK("lane " << i << " at " << points.px[i] << ", " << points.py[i]
                                       << ", " << points.pz[i] << ": " << got[i] << " not "
                                       << want);
                ++compared;
                if (want < 1.0f) ++shadowed;
            }
        };
        each_receiver([&](const glm::vec3& p, const glm::vec3& n) {
            points.px[filled] = p.x, points.py[filled] = p.y, points.pz[filled] = p.z;
            points.nx[filled] = n.x, points.ny[filled] = n.y, points.nz[filled] = n.z;
            expected[filled] = shadow_visibility(map, p, n);
            if (++filled < simd::kLanes) return;
            check_batch(0xffu);
            check_batch(0x5au);  // some lanes left out get 1
            filled = 0;
        });
        CHECK(compared > 10000);
        CHECK(shadowed > 500);
    }
}
