// Raster core: fill rule, clipping, perspective-correct interpolation and
// depth, checked against independent computations (ray casting).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <mutex>
#include <random>

#include <glm/geometric.hpp>

#include "core/thread_pool.hpp"
#include "raster/rasterizer.hpp"
#include "render/camera.hpp"

using namespace facet;

namespace {

// Coverage of each pixel by one triangle given directly in NDC (w = 1).
std::vector<int> coverage_of(const std::vector<glm::vec4>& clip, const std::vector<uint32_t>& tri,
                             int width, int height, ThreadPool& pool, bool cull_back = false) {
    Rasterizer r(width, height);
    uint8_t cull = cull_back ? 1 : 0;
    RasterInput in{clip.data(), clip.size(), tri.data(), 1, &cull};
    r.set_geometry(in, pool);
    std::vector<int> covered(static_cast<size_t>(width) * height, 0);
    r.draw_tiles(pool, [&](const TileVisibility& t) {
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x < t.width; ++x)
                if (t.id[y * kTileSize + x] != kNoTriangle)
                    covered[(t.y0 + y) * width + t.x0 + x] = 1;
    });
    return covered;
}

// Pixel coordinates (x right, y down) -> NDC at w = 1.
glm::vec4 ndc(double px, double py, int width, int height) {
    return {static_cast<float>(px / width * 2 - 1), static_cast<float>(1 - py / height * 2), 0.5f,
            1.0f};
}

// Möller & Trumbore 1997: ray/triangle hit, returning distance and barycentrics.
bool ray_hit(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, double& t,
             double& u, double& v) {
    glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-15) return false;
    glm::dvec3 s = origin - a;
    u = glm::dot(s, p) / det;
    glm::dvec3 q = glm::cross(s, e1);
    v = glm::dot(dir, q) / det;
    t = glm::dot(e2, q) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && t > 0;
}

struct View {
    int width = 160, height = 120;
    CameraMatrices camera;
    glm::dvec3 ray(int px, int py) const {
        // Through the pixel centre, built from the inverse view-projection.
        glm::dmat4 inv = glm::inverse(glm::dmat4(camera.view_projection));
        double nx = (px + 0.5) / width * 2 - 1, ny = 1 - (py + 0.5) / height * 2;
        glm::dvec4 far = inv * glm::dvec4(nx, ny, 0.0, 1.0);  // reversed-Z: 0 is the far plane
        return glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(camera.position));
    }
};

View make_view(glm::vec3 eye, glm::vec3 target, float fov = 60, float near = 0.1f,
               float far = 100) {
    View v;
    v.camera =
        make_camera({eye, target, {0, 1, 0}, fov, near, far}, float(v.width) / float(v.height));
    return v;
}

}  // namespace

TEST_CASE("shared edges are covered exactly once (top-left rule)", "[raster][fill]") {
    // A square split into many triangles that share every interior edge.
    // Vertices sit on a mix of random sub-pixel positions and exact pixel
    // centres, so edges run exactly through sample points.
    const int W = 96, H = 80;
    ThreadPool pool(2);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.45, 0.45);
    const int N = 6;
    std::vector<glm::dvec2> grid;
    for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i) {
            double x = 8.2 + i * 12.0, y = 6.3 + j * 11.0;
            bool border = i == 0 || j == 0 || i == N || j == N;
            if (!border) {
                if ((i + j) % 3 == 0) {
                    x = std::floor(x) + 0.5;
                    y = std::floor(y) + 0.5;
                } else {
                    x += jitter(rng);
                    y += jitter(rng);
                }
            }
            grid.push_back({x, y});
        }
    std::vector<glm::vec4> clip;
    for (auto p : grid) clip.push_back(ndc(p.x, p.y, W, H));
    std::vector<int> total(W * H, 0);
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            uint32_t a = j * (N + 1) + i, b = a + 1, c = a + N + 1, d = c + 1;
            // Alternate the diagonal, and give some triangles the other winding.
            std::vector<std::vector<uint32_t>> tris =
                (i + j) % 2 ? std::vector<std::vector<uint32_t>>{{a, c, b}, {b, c, d}}
                            : std::vector<std::vector<uint32_t>>{{a, d, b}, {a, c, d}};
            for (auto& t : tris) {
                auto cov = coverage_of(clip, t, W, H, pool);
                for (int k = 0; k < W * H; ++k) total[k] += cov[k];
            }
        }
    int inside = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double cx = x + 0.5, cy = y + 0.5;
            bool in_square = cx > 8.2 && cx < 8.2 + N * 12.0 && cy > 6.3 && cy < 6.3 + N * 11.0;
            INFO("pixel " << x << "," << y);
            REQUIRE(total[y * W + x] == (in_square ? 1 : 0));
            inside += in_square;
        }
    CHECK(inside > 3000);
}

TEST_CASE("a pixel centre on an edge goes to the left or top triangle only", "[raster][fill]") {
    ThreadPool pool(1);
    const int W = 16, H = 16;
    // Vertical edge exactly through centres x = 8.5: a left edge of the right
    // triangle (owned by it), a right edge of the left one.
    std::vector<glm::vec4> clip = {ndc(8.5, 2, W, H), ndc(8.5, 14, W, H), ndc(2, 8, W, H),
                                   ndc(14, 8, W, H)};
    auto left = coverage_of(clip, {0, 2, 1}, W, H, pool);
    auto right = coverage_of(clip, {0, 1, 3}, W, H, pool);
    CHECK(left[8 * W + 8] == 0);
    CHECK(right[8 * W + 8] == 1);
    // Horizontal edge through centres y = 8.5: the lower triangle has it as its top edge.
    std::vector<glm::vec4> clip2 = {ndc(2, 8.5, W, H), ndc(14, 8.5, W, H), ndc(8, 2, W, H),
                                    ndc(8, 14, W, H)};
    auto upper = coverage_of(clip2, {0, 1, 2}, W, H, pool);
    auto lower = coverage_of(clip2, {0, 3, 1}, W, H, pool);
    CHECK(upper[8 * W + 8] == 0);
    CHECK(lower[8 * W + 8] == 1);
}

TEST_CASE("back faces are culled only when asked", "[raster][cull]") {
    ThreadPool pool(1);
    const int W = 32, H = 32;
    // Counter-clockwise in NDC (y up) is the front.
    std::vector<glm::vec4> clip = {ndc(4, 28, W, H), ndc(28, 28, W, H), ndc(16, 4, W, H)};
    auto count = [](const std::vector<int>& c) {
        int n = 0;
        for (int v : c) n += v;
        return n;
    };
    CHECK(count(coverage_of(clip, {0, 1, 2}, W, H, pool, true)) > 100);
    CHECK(count(coverage_of(clip, {0, 2, 1}, W, H, pool, true)) == 0);
    CHECK(count(coverage_of(clip, {0, 2, 1}, W, H, pool, false)) ==
          count(coverage_of(clip, {0, 1, 2}, W, H, pool, false)));
}

namespace {

// Renders world-space triangles through the camera and checks every pixel
// against a ray cast: coverage, perspective-correct barycentrics and depth.
void check_against_rays(const View& view, const std::vector<glm::vec3>& world,
                        const std::vector<uint32_t>& indices, int expect_min_covered) {
    ThreadPool pool(2);
    std::vector<glm::vec4> clip;
    for (auto& p : world) clip.push_back(view.camera.view_projection * glm::vec4(p, 1));
    std::vector<uint8_t> cull(indices.size() / 3, 0);
    Rasterizer r(view.width, view.height);
    r.set_geometry({clip.data(), clip.size(), indices.data(), indices.size() / 3, cull.data()},
                   pool);
    struct Sample {
        uint32_t tri = kNoTriangle;
        float b1 = 0, b2 = 0, depth = 0;
    };
    std::vector<Sample> samples(view.width * view.height);
    r.draw_tiles(pool, [&](const TileVisibility& t) {
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x < t.width; ++x) {
                uint32_t id = t.id[y * kTileSize + x];
                if (id == kNoTriangle) continue;
                const ShadeSetup& s = r.shade_setup(id);
                float fx = (t.x0 + x + 0.5f) - s.x0, fy = (t.y0 + y + 0.5f) - s.y0;
                float inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
                Sample& out = samples[(t.y0 + y) * view.width + t.x0 + x];
                out.tri = s.source_triangle;
                out.b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) / inv_w;
                out.b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) / inv_w;
                out.depth = 1 / inv_w;
            }
    });
    int covered = 0, mismatched = 0;
    const glm::dvec3 eye = view.camera.position;
    const glm::dvec3 forward = view.camera.forward;
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            glm::dvec3 dir = view.ray(x, y);
            double best = 1e30, bu = 0, bv = 0;
            uint32_t best_tri = kNoTriangle;
            for (size_t t = 0; t < indices.size() / 3; ++t) {
                double d, u, v;
                if (ray_hit(eye, dir, world[indices[3 * t]], world[indices[3 * t + 1]],
                            world[indices[3 * t + 2]], d, u, v)) {
                    double along = d * glm::dot(dir, forward);
                    if (along >= view.camera.near && along <= view.camera.far && d < best) {
                        best = d;
                        bu = u;
                        bv = v;
                        best_tri = static_cast<uint32_t>(t);
                    }
                }
            }
            const Sample& s = samples[y * view.width + x];
            if ((best_tri == kNoTriangle) != (s.tri == kNoTriangle)) {
                // Only pixels whose centre is within a hair of an edge may disagree.
                double margin = best_tri == kNoTriangle ? 0 : std::min({bu, bv, 1 - bu - bv});
                if (best_tri != kNoTriangle && margin > 1e-3) ++mismatched;
                if (best_tri == kNoTriangle) ++mismatched;
                continue;
            }
            if (s.tri == kNoTriangle) continue;
            ++covered;
            INFO("pixel " << x << "," << y);
            REQUIRE(s.tri == best_tri);
            CHECK(s.b1 == Approx(bu).margin(2e-3));
            CHECK(s.b2 == Approx(bv).margin(2e-3));
            CHECK(s.depth == Approx(best * glm::dot(dir, forward)).epsilon(1e-3));
        }
    CHECK(mismatched <= view.width / 10);
    CHECK(covered >= expect_min_covered);
}

}  // namespace

TEST_CASE("perspective-correct barycentrics and linear depth match ray casting",
          "[raster][interp]") {
    View view = make_view({0.3f, 1.2f, 3}, {0, 0, 0});
    // A steeply slanted triangle: affine (screen-space) interpolation would be far off.
    check_against_rays(view, {{-2, -0.5f, 1.5f}, {2, -0.5f, 1}, {0, 0.8f, -8}}, {0, 1, 2}, 2000);
}

TEST_CASE("triangles crossing the near plane are clipped correctly", "[raster][clip]") {
    // A floor running under and behind the camera: two of its corners are
    // behind the eye (w < 0), which only homogeneous clipping gets right.
    View view = make_view({0, 1, 0}, {0, 0.6f, -5}, 70, 0.5f, 60);
    check_against_rays(view, {{-6, 0, 4}, {6, 0, 4}, {6, 0, -20}, {-6, 0, -20}}, {0, 1, 2, 0, 2, 3},
                       3000);
}

TEST_CASE("triangles far outside the screen are clipped to the guard band", "[raster][clip]") {
    // Vertices thousands of screen widths away from the view.
    View view = make_view({0, 0, 5}, {0, 0, 0}, 50);
    check_against_rays(view, {{-4000, -1, 0}, {3000, -2, -1}, {0, 2500, -2}}, {0, 1, 2}, 3000);
}

TEST_CASE("the far plane cuts geometry beyond it", "[raster][clip]") {
    View view = make_view({0, 2, 0}, {0, 1.5f, -10}, 60, 0.1f, 12);
    check_against_rays(view, {{-30, 0, 2}, {30, 0, 2}, {0, 0, -60}}, {0, 1, 2}, 1000);
}

TEST_CASE("nearer triangles win the depth test regardless of order", "[raster][depth]") {
    View view = make_view({0, 0, 4}, {0, 0, 0});
    // Two interpenetrating triangles: each is in front over part of the screen.
    check_against_rays(
        view, {{-2, -1, -1}, {2, -1, 1}, {0, 1.5f, 0}, {-2, -1, 1}, {2, -1, -1}, {0, 1.4f, 0.2f}},
        {0, 1, 2, 3, 4, 5}, 2000);
}

TEST_CASE("triangles with infinite or NaN coordinates are dropped", "[raster][clip]") {
    ThreadPool pool(1);
    const int W = 32, H = 32;
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (glm::vec4 bad :
         {glm::vec4(inf, 0, 0.5f, 1), glm::vec4(0, nan, 0.5f, 1), glm::vec4(0, 0, 0.5f, inf)}) {
        std::vector<glm::vec4> clip = {ndc(4, 28, W, H), ndc(28, 28, W, H), bad};
        auto covered = coverage_of(clip, {0, 1, 2}, W, H, pool);
        int n = 0;
        for (int c : covered) n += c;
        CHECK(n == 0);
    }
}

// The frame's rasterizer uses tiles of whole pixels of k x k samples: 63
// samples a side at 9 samples a pixel, 60 at 25. Tiles are binned and
// drawn on that grid, so a triangle covering the screen covers every
// sample once, whatever the tile size.
TEST_CASE("tiles smaller than the largest cover every sample once", "[raster][fill]") {
    ThreadPool pool(2);
    for (const int tile_size : {64, 63, 60, 17}) {
        INFO("tile size " << tile_size);
        const int width = 301, height = 197;
        Rasterizer r(width, height, tile_size);
        // Two triangles past the screen's corners: every sample is inside one.
        const std::vector<glm::vec4> clip = {{-1.5f, -1.5f, 0.5f, 1},
                                             {1.5f, -1.5f, 0.5f, 1},
                                             {1.5f, 1.5f, 0.5f, 1},
                                             {-1.5f, 1.5f, 0.5f, 1}};
        const std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
        const uint8_t cull[2] = {0, 0};
        r.set_geometry({clip.data(), clip.size(), triangles.data(), 2, cull}, pool);
        std::vector<int> seen(static_cast<size_t>(width) * height, 0);
        std::mutex mutex;
        r.draw_tiles(pool, [&](const TileVisibility& t) {
            CHECK(t.x0 % tile_size == 0);
            CHECK(t.y0 % tile_size == 0);
            CHECK(t.width <= tile_size);
            CHECK(t.height <= tile_size);
            std::lock_guard lock(mutex);
            for (int y = 0; y < t.height; ++y)
                for (int x = 0; x < t.width; ++x)
                    seen[(t.y0 + y) * width + t.x0 + x] +=
                        t.id[y * kTileSize + x] != kNoTriangle ? 1 : 100;
        });
        size_t once = 0;
        for (int s : seen) once += s == 1 ? 1 : 0;
        CHECK(once == seen.size());
    }
}
