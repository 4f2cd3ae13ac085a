// The frame's stage records where no render test reaches them directly:
// surface reconstruction from the visibility buffer, the texture level of
// detail, the frame inputs and the shading-model switch.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "core/thread_pool.hpp"
#include "raster/rasterizer.hpp"
#include "raster/surface_sample.hpp"
#include "render/frame_inputs.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "shade/shading_models.hpp"
#include "shade/texture_lod.hpp"
#include "support.hpp"

using namespace facet;

namespace {

constexpr int kWidth = 96, kHeight = 64;

// Screen position of a clip-space vertex, in pixels (x right, y down).
glm::dvec2 screen_of(const glm::vec4& v) {
    return {(v.x / v.w + 1.0) * 0.5 * kWidth, (1.0 - v.y / v.w) * 0.5 * kHeight};
}

// Perspective-correct barycentrics at a screen point, computed without the
// rasterizer's planes: screen-space weights from areas, then each divided
// by its vertex's w and renormalised (Heckbert & Moreton 1991).
glm::dvec3 expected_bary(const glm::vec4 v[3], glm::dvec2 p, double& w) {
    const glm::dvec2 a = screen_of(v[0]), b = screen_of(v[1]), c = screen_of(v[2]);
    auto area = [](glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2) {
        return (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    };
    const double total = area(a, b, c);
    const glm::dvec3 screen(area(p, b, c) / total, area(a, p, c) / total, area(a, b, p) / total);
    const glm::dvec3 over_w(screen.x / v[0].w, screen.y / v[1].w, screen.z / v[2].w);
    const double sum = over_w.x + over_w.y + over_w.z;
    w = 1.0 / sum;
    return over_w / sum;
}

// Rasterizes one triangle and reconstructs every covered pixel.
std::vector<std::pair<glm::ivec2, SurfaceSample>> reconstruct_all(const glm::vec4 v[3]) {
    ThreadPool pool(1);
    Rasterizer raster(kWidth, kHeight);
    const uint32_t indices[3] = {0, 1, 2};
    const uint8_t cull = 0;
    raster.set_geometry({v, 3, indices, 1, &cull}, pool);
    std::vector<std::pair<glm::ivec2, SurfaceSample>> out;
    raster.draw_tiles(pool, [&](const TileVisibility& t) {
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x < t.width; ++x) {
                const uint32_t id = t.id[y * kTileSize + x];
                if (id == kNoTriangle) continue;
                const int px = t.x0 + x, py = t.y0 + y;
                out.push_back({{px, py}, reconstruct_surface(raster.shade_setup(id), px, py)});
            }
    });
    return out;
}

}  // namespace

TEST_CASE("surface reconstruction: perspective-correct barycentrics, depth and derivatives",
          "[stages][raster]") {
    // Vertices at different depths (w), so screen-linear weights would be wrong.
    const glm::vec4 v[3] = {
        {-0.8f, -0.7f, 0.5f, 1.0f}, {2.4f, -1.5f, 1.0f, 3.0f}, {0.0f, 4.5f, 2.0f, 5.0f}};
    const auto samples = reconstruct_all(v);
    REQUIRE(samples.size() > 500);
    double worst_bary = 0, worst_w = 0, worst_ddx = 0;
    for (const auto& [p, s] : samples) {
        CHECK(s.triangle == 0);
        double w = 0;
        const glm::dvec3 b = expected_bary(v, {p.x + 0.5, p.y + 0.5}, w);
        for (int i = 0; i < 3; ++i) worst_bary = std::max(worst_bary, std::abs(s.bary[i] - b[i]));
        worst_w = std::max(worst_w, std::abs(s.w - w) / w);
        // The derivative along x against the change to the next pixel; b is
        // a ratio of affine functions, so the two agree to second order.
        double w_next = 0;
        const glm::dvec3 next = expected_bary(v, {p.x + 1.5, p.y + 0.5}, w_next);
        double w_prev = 0;
        const glm::dvec3 prev = expected_bary(v, {p.x - 0.5, p.y + 0.5}, w_prev);
        for (int i = 0; i < 3; ++i)
            worst_ddx = std::max(worst_ddx, std::abs(s.ddx[i] - (next[i] - prev[i]) / 2));
    }
    // Vertices snap to 1/256 pixel before setup, which moves the planes by
    // a few 1e-5; interpolating in screen space instead would be off by
    // more than 0.1 on this triangle (checked below).
    CHECK(worst_bary < 1e-4);
    CHECK(worst_w < 1e-4);
    CHECK(worst_ddx < 2e-4);
    double screen_linear_error = 0;
    for (const auto& [p, s] : samples) {
        double w = 0;
        const glm::dvec3 b = expected_bary(v, {p.x + 0.5, p.y + 0.5}, w);
        const glm::vec4 flat[3] = {{v[0].x / v[0].w, v[0].y / v[0].w, 0, 1},
                                   {v[1].x / v[1].w, v[1].y / v[1].w, 0, 1},
                                   {v[2].x / v[2].w, v[2].y / v[2].w, 0, 1}};
        double unused = 0;
        const glm::dvec3 linear = expected_bary(flat, {p.x + 0.5, p.y + 0.5}, unused);
        screen_linear_error = std::max(screen_linear_error, std::abs(linear.x - b.x));
    }
    CHECK(screen_linear_error > 0.1);
    // Barycentrics sum to one and stay inside the triangle (up to rounding).
    for (const auto& [p, s] : samples) {
        CHECK(std::abs(s.bary.x + s.bary.y + s.bary.z - 1.0f) < 1e-5f);
        CHECK(s.bary.x > -1e-4f);
        CHECK(s.bary.y > -1e-4f);
        CHECK(s.bary.z > -1e-4f);
    }
}

TEST_CASE("surface reconstruction: back faces are marked", "[stages][raster]") {
    const glm::vec4 front[3] = {
        {-0.5f, -0.5f, 0.5f, 1}, {0.5f, -0.5f, 0.5f, 1}, {0, 0.5f, 0.5f, 1}};
    const glm::vec4 back[3] = {front[0], front[2], front[1]};
    const auto f = reconstruct_all(front);
    const auto b = reconstruct_all(back);
    REQUIRE(!f.empty());
    REQUIRE(f.size() == b.size());
    for (const auto& [p, s] : f) CHECK_FALSE(s.back_facing);
    for (const auto& [p, s] : b) CHECK(s.back_facing);
}

TEST_CASE("texture footprint: texels per pixel step along the longer and shorter axes",
          "[stages][texture]") {
    SurfaceSample s{};
    s.bary = {0.5f, 0.25f, 0.25f};
    const glm::vec2 uv0(0, 0), uv1(1, 0), uv2(0, 1);
    // u = b1, v = b2: one pixel step in x moves u by 1/64 of the texture.
    s.ddx = {-1.0f / 64, 1.0f / 64, 0};
    s.ddy = {-1.0f / 128, 0, 1.0f / 128};
    TextureFootprint t = texture_lookup(uv0, uv1, uv2, s, glm::vec2(256));
    CHECK(t.uv.x == Approx(0.25f));
    CHECK(t.uv.y == Approx(0.25f));
    CHECK(t.major == Approx(4.0f));  // 256 / 64 texels per step along x, the longer axis
    CHECK(t.minor == Approx(2.0f));  // 256 / 128 along y
    CHECK(t.major_axis.x == Approx(1.0f / 64));
    CHECK(t.major_axis.y == 0.0f);
    // Scaled coordinates (a texture repeated 4 times) cover 4x as many texels.
    t = texture_lookup(uv0 * 4.0f, uv1 * 4.0f, uv2 * 4.0f, s, glm::vec2(256));
    CHECK(t.major == Approx(16.0f));
    CHECK(t.uv.x == Approx(1.0f));
    // A footprint along y alone: y is the longer axis.
    s.ddx = {0, 0, 0};
    s.ddy = {-1.0f / 8, 0, 1.0f / 8};
    t = texture_lookup(uv0, uv1, uv2, s, glm::vec2(256));
    CHECK(t.major == Approx(32.0f));  // 256 / 8 texels
    CHECK(t.minor == 0.0f);
    CHECK(t.major_axis.y == Approx(1.0f / 8));
}

TEST_CASE("frame inputs: styles per object, animated materials, depth range", "[stages]") {
    test::TempDir dir("stages");
    const std::string path = test::write_text(dir.file("inputs.yaml"), R"(
output: { size: [64, 48], frames: "1-10" }
style: blinn-phong
camera: { position: [0, 0, 5], target: [0, 0, 0] }
objects:
  - name: a
    primitive: cube
    material: { color: { keys: { 1: [1, 0, 0], 10: [0, 0, 1] } }, shininess: 20 }
  - name: b
    primitive: sphere
    translate: [2, 0, 0]
    style: toon
)");
    const SceneDesc scene = test::load(path);
    const World world = build_world(scene);
    const StylePlan plan = plan_styles(scene);
    FrameEvaluator evaluator(scene, world, plan, 1);
    REQUIRE(plan.styles.size() == 2);
    CHECK(plan.object_style == std::vector<uint32_t>{0, 1});
    CHECK_FALSE(plan.outlines);
    const FrameInputs first = evaluator.evaluate(1, 0);
    const FrameInputs last = evaluator.evaluate(10, 0);
    REQUIRE(first.styles.size() == 2);
    CHECK(first.styles[0].model == ShadingModel::blinn_phong);
    CHECK(first.styles[1].model == ShadingModel::toon);
    // The cube's material follows its keys; the world's stays as built.
    const uint32_t cube_material = world.draws[0].material;
    CHECK(first.materials[cube_material].color == glm::vec3(1, 0, 0));
    CHECK(last.materials[cube_material].color == glm::vec3(0, 0, 1));
    CHECK(last.materials[cube_material].shininess == 20.0f);
    // The depth view range holds the objects: the camera is 5 from the origin.
    CHECK(first.depth_view_range.x < 4.5f);
    CHECK(first.depth_view_range.y > 5.5f);
    CHECK(first.style_depth_range == first.depth_view_range);
}

TEST_CASE("shading models: one switch, each model's own result", "[stages][style]") {
    SurfaceLanes in;
    in.count = 2;
    for (int i = 0; i < 2; ++i) {
        in.albedo[0][i] = 0.2f, in.albedo[1][i] = 0.4f, in.albedo[2][i] = 0.6f;
        in.surface.px[i] = 0, in.surface.py[i] = 0, in.surface.pz[i] = 0;
        in.surface.nx[i] = 0, in.surface.ny[i] = 0, in.surface.nz[i] = 2;  // any length
        in.surface.ambient[i] = 0.1f, in.surface.diffuse[i] = 0.9f;
        in.surface.specular[i] = 0, in.surface.shininess[i] = 10;
        in.depth[i] = i == 0 ? 2.0f : 6.0f;
    }
    const ShadeLight light{false, {0, 0, 1}, {}, {1, 1, 1}};
    const std::vector<ShadeLight> lights{light};
    const ShadingContext context{{0, 0, 10}, lights, {2.0f, 6.0f}};
    StyleState style;
    ShadedLanes out;

    style.model = ShadingModel::unlit;
    shade_lanes(style, context, in, out);
    CHECK(out.color_at(0) == in.albedo_at(0));
    CHECK(out.palette_tone[0] == -1.0f);

    style.model = ShadingModel::depth;  // near end white, far end black
    shade_lanes(style, context, in, out);
    CHECK(out.color_at(0) == glm::vec3(1.0f));
    CHECK(out.color_at(1) == glm::vec3(0.0f));

    style.model = ShadingModel::blinn_phong;  // n.l = 1: albedo * (ambient + diffuse)
    shade_lanes(style, context, in, out);
    CHECK(out.color_at(0).x == Approx(0.2f * (0.1f + 0.9f)));
    CHECK(out.color_at(1).z == Approx(0.6f * (0.1f + 0.9f)));

    style.model = ShadingModel::palette;  // the palette model reports its cel's tone
    shade_lanes(style, context, in, out);
    CHECK(out.palette_tone[0] >= 0.0f);
    CHECK(out.palette_tone[0] <= 1.0f);
}
