// Outlines measured on rendered frames of known scenes (docs/styles.md,
// "Outlines"): the width in output pixels across silhouette edges, at one
// sample per pixel and supersampled, and intersection lines lying on the
// projected line where two boxes cut through each other.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "anim/frame_state.hpp"
#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/camera.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

struct Rendered {
    SceneDesc scene;
    ColorImage color;
    CameraMatrices camera;
};

Rendered render_text(const std::string& text) {
    TempDir dir("outline-width");
    const std::string path = write_text(dir.file("s.yaml"), text);
    Rendered r{load(path), {}, {}};
    const World world = build_world(r.scene);
    ThreadPool pool(2);
    FrameRenderer renderer(r.scene, world, pool);
    FrameImages images;
    renderer.render(1, 0, images);
    r.color = to_float_image(images.color);
    const FrameState state = evaluate_frame(r.scene, world.object_bounds, 1, 0);
    r.camera = make_camera(state.camera, static_cast<float>(r.scene.output.width) /
                                             static_cast<float>(r.scene.output.height));
    return r;
}

// Where a world point lands in the image, in pixels (pixel centres at +0.5).
glm::vec2 project(const Rendered& r, const glm::vec3& p) {
    const glm::vec4 clip = r.camera.view_projection * glm::vec4(p, 1.0f);
    const float x = clip.x / clip.w, y = clip.y / clip.w;
    return {(x + 1.0f) * 0.5f * static_cast<float>(r.scene.output.width),
            (1.0f - y) * 0.5f * static_cast<float>(r.scene.output.height)};
}

// A white cube (unlit, edge 2) seen face-on from 10 units on a white
// background: only its front face shows, a square whose border is all
// silhouette. Black lines, so a pixel's line coverage is 1 - its value.
std::string square_scene(const std::string& style, int samples) {
    return "output: { size: [160, 120], background: [1, 1, 1, 1], samples: " +
           std::to_string(samples) + " }\nstyle: " + style +
           "\ncamera: { position: [0, 0, 10], target: [0, 0, 0], fov: 20 }\n"
           "objects:\n  - primitive: { type: cube, size: 2 }\n"
           "    material: { color: [1, 1, 1] }\n";
}

std::string silhouettes_only(float width) {
    return "{ shading: unlit, base_color: [1, 1, 1], outlines: { silhouette: { width: " +
           std::to_string(width) + ", color: [0, 0, 0] } } }";
}

float coverage(const ColorImage& image, int x, int y) {
    const glm::vec4 c = image.at(x, y);
    return 1.0f - (c.r + c.g + c.b) / 3.0f;
}

struct Crossing {
    double sum = 0;     // total coverage: the width
    int count = 0;      // pixels at least half covered
    double centre = 0;  // coverage-weighted position along the path
};

// Coverage along a row (horizontal) or a column, over [from, to).
Crossing cross(const ColorImage& image, bool horizontal, int fixed, int from, int to) {
    Crossing c;
    for (int i = from; i < to; ++i) {
        const float a = horizontal ? coverage(image, i, fixed) : coverage(image, fixed, i);
        c.sum += a;
        c.count += a >= 0.5f;
        c.centre += a * (i + 0.5);
    }
    if (c.sum > 0) c.centre /= c.sum;
    return c;
}

// Measures all four silhouettes of the square on several rows and columns
// against `width`; checks the lines sit on the projected cube edges.
void check_square_outline(const Rendered& r, float width) {
    const ColorImage& image = r.color;
    const glm::vec2 top_left = project(r, {-1, 1, 1}), bottom_right = project(r, {1, -1, 1});
    const int w = image.width, h = image.height;
    const int mid_x = w / 2, mid_y = h / 2;
    // Nothing inside the square or far outside it.
    CHECK(coverage(image, mid_x, mid_y) < 0.01f);
    CHECK(coverage(image, 2, 2) < 0.01f);
    for (int k = -3; k <= 3; ++k) {
        const int y = mid_y + k * 8, x = mid_x + k * 8;
        INFO("width " << width << ", row " << y << " / column " << x);
        const Crossing left = cross(image, true, y, 0, mid_x);
        const Crossing right = cross(image, true, y, mid_x, w);
        const Crossing top = cross(image, false, x, 0, mid_y);
        const Crossing bottom = cross(image, false, x, mid_y, h);
        for (const Crossing& c : {left, right, top, bottom}) {
            CHECK(c.sum == Approx(width).margin(0.05));
            CHECK(std::abs(c.count - width) <= 1.0f);
        }
        CHECK(std::abs(left.centre - top_left.x) <= 1.0);
        CHECK(std::abs(right.centre - bottom_right.x) <= 1.0);
        CHECK(std::abs(top.centre - top_left.y) <= 1.0);
        CHECK(std::abs(bottom.centre - bottom_right.y) <= 1.0);
    }
}

}  // namespace

TEST_CASE("silhouette widths in rendered frames are as asked", "[render][style]") {
    for (float width : {1.0f, 2.0f, 4.0f}) {
        const Rendered r = render_text(square_scene(silhouettes_only(width), 1));
        // The square is where the scene puts it: about 76 pixels a side.
        const glm::vec2 a = project(r, {-1, 1, 1}), b = project(r, {1, -1, 1});
        REQUIRE(b.x - a.x > 60);
        REQUIRE(b.y - a.y > 60);
        check_square_outline(r, width);
    }
}

TEST_CASE("supersampling keeps silhouette widths in output pixels", "[render][style]") {
    for (float width : {1.0f, 2.0f, 4.0f}) {
        const Rendered r = render_text(square_scene(silhouettes_only(width), 4));
        REQUIRE(r.scene.output.samples_per_side() == 2);
        check_square_outline(r, width);
    }
}

TEST_CASE("the ink preset draws its 2-pixel outline around the square", "[render][style]") {
    for (int samples : {1, 4}) {
        INFO(samples << " samples");
        const Rendered r = render_text(square_scene("ink", samples));
        REQUIRE(r.scene.style.name == "ink");
        check_square_outline(r, 2.0f);
    }
}

// ---------------------------------------------------------------------------
// Intersection lines: a post standing through a slab.

namespace {

// The slab's top face is y = 0.1; the post's front face is z = 0.5. The
// visible line where they cut each other runs along x from -0.5 to 0.5.
const char* kCrossingBoxes = R"(output: { size: [240, 180], background: [0.1, 0.1, 0.1, 1] }
style: intersections
camera: { position: [0, 2, 6], target: [0, 0, 0], fov: 40 }
lights:
  - { type: directional, direction: [-1, -2, -1.5] }
objects:
  - name: slab
    primitive: { type: box, size: [3, 0.2, 3] }
    material: { color: [0.2, 0.4, 0.8] }
  - name: post
    primitive: { type: box, size: [1, 2, 1] }
    material: { color: [0.3, 0.8, 0.3] }
)";

bool is_red(const glm::vec4& c) {
    return c.r > 0.5f && c.g < 0.25f && c.b < 0.25f;
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

}  // namespace

TEST_CASE("intersection lines lie on the projected line where two boxes cross", "[render][style]") {
    const Rendered r = render_text(kCrossingBoxes);
    const glm::vec2 a = project(r, {-0.5f, 0.1f, 0.5f}), b = project(r, {0.5f, 0.1f, 0.5f});
    const float length = glm::length(b - a);
    REQUIRE(length > 30);  // long enough to measure along

    std::vector<glm::vec2> red;
    int far_off = 0;
    float worst = 0;
    for (int y = 0; y < r.color.height; ++y)
        for (int x = 0; x < r.color.width; ++x) {
            if (!is_red(r.color.at(x, y))) continue;
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            red.push_back(p);
            const float d = distance_to_segment(p, a, b);
            worst = std::max(worst, d);
            far_off += d > 2.0f;
        }
    INFO("segment (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << "), " << red.size()
                     << " red pixels, farthest " << worst << " px");
    CHECK(far_off == 0);
    // A 2-pixel line along the whole segment.
    CHECK(red.size() >= static_cast<size_t>(1.5f * length));
    int covered = 0, samples = 0;
    for (float s = 2; s <= length - 2; s += 1.0f, ++samples) {
        const glm::vec2 q = a + (b - a) * (s / length);
        bool near = false;
        for (const glm::vec2& p : red) near = near || glm::length(p - q) <= 1.5f;
        covered += near;
    }
    CHECK(covered >= samples * 9 / 10);
}

TEST_CASE("no intersection lines where the boxes only stand apart", "[render][style]") {
    // The same boxes, the post moved clear of the slab: no red anywhere.
    std::string text = kCrossingBoxes;
    text += "    translate: [0, 1.5, 0]\n";
    const Rendered r = render_text(text);
    int red = 0;
    for (int y = 0; y < r.color.height; ++y)
        for (int x = 0; x < r.color.width; ++x) red += is_red(r.color.at(x, y));
    CHECK(red == 0);
}

// Outlines belong to the whole image (docs/styles.md, "Layers and
// precedence", step 4): an object's own style mapping that sets them is
// refused when the scene is read, naming the key, never silently dropped.
TEST_CASE("outlines in an object's own style are refused", "[render][style]") {
    const std::string own =
        "    style: { outlines: { silhouette: { width: 3, color: [1, 0, 0] } } }\n";
    // The scene's style without outlines, and with black 1-pixel silhouettes.
    for (const std::string& scene_style :
         {std::string("{ shading: unlit, base_color: [1, 1, 1] }"), silhouettes_only(1.0f)}) {
        INFO("scene style " << scene_style);
        require_input_error([&] { render_text(square_scene(scene_style, 1) + own); },
                            "'objects.0.style.outlines': 'outlines' applies to the whole image");
    }
}
