// Screen-space outlines on synthetic depth/normal/id buffers: even line
// widths, relative depth jumps, creases by angle, object boundaries,
// intersection lines, colours and compositing, and thread-count independence.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "core/error.hpp"
#include "post/outlines.hpp"

using namespace facet;

namespace {

constexpr int kSize = 64;

// Background everywhere, then `inside(x, y)` pixels get depth, id, normal.
void paint(OutlineBuffers& b, const std::function<bool(int, int)>& inside, float depth, uint32_t id,
           glm::vec3 normal = {0, 0, 1}) {
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            if (inside(x, y)) {
                b.depth[b.index(x, y)] = depth;
                b.object_id[b.index(x, y)] = id;
                b.normal[b.index(x, y)] = normal;
            }
}

OutlineBuffers square_scene(float depth = 5.0f) {
    OutlineBuffers b;
    b.reset(kSize, kSize);
    paint(
        b, [](int x, int y) { return x >= 16 && x < 48 && y >= 16 && y < 48; }, depth, 1);
    return b;
}

OutlineStyle only(LineKind kind, float width) {
    OutlineStyle s;
    s.silhouette.enabled = s.crease.enabled = s.boundary.enabled = s.intersection.enabled = false;
    LineStyle& line = kind == LineKind::silhouette ? s.silhouette
                      : kind == LineKind::crease   ? s.crease
                      : kind == LineKind::boundary ? s.boundary
                                                   : s.intersection;
    line.enabled = true;
    line.width = width;
    line.color = {1, 0, 0};
    return s;
}

ColorImage draw(const OutlineBuffers& b, const OutlineStyle& s, unsigned threads = 1) {
    ThreadPool pool(threads);
    OutlineScratch scratch;
    ColorImage lines;
    draw_outlines(b, s, lines, pool, scratch);
    return lines;
}

// Sum of coverage and count of pixels with coverage >= 1/2 along a path.
struct Profile {
    double sum = 0;
    int count = 0;
};
Profile profile(const ColorImage& lines, int x0, int y0, int dx, int dy, int steps) {
    Profile p;
    for (int i = 0; i < steps; ++i) {
        const float a = lines.at(x0 + i * dx, y0 + i * dy).a;
        p.sum += a;
        p.count += a >= 0.5f;
    }
    return p;
}

bool any_edge(const std::vector<uint8_t>& edges, LineKind kind) {
    for (uint8_t e : edges)
        if (e & (edge_bit(kind, false) | edge_bit(kind, true))) return true;
    return false;
}

std::vector<uint8_t> edges_of(const OutlineBuffers& b, const OutlineStyle& s) {
    ThreadPool pool(1);
    OutlineScratch scratch;
    find_edges(b, s, scratch, pool);
    return scratch.edges;
}

OutlineStyle all_kinds() {
    OutlineStyle s;
    s.silhouette.enabled = s.crease.enabled = s.boundary.enabled = s.intersection.enabled = true;
    return s;
}

}  // namespace

TEST_CASE("silhouettes of a square are as wide as asked on rows, columns, diagonals", "[outline]") {
    const OutlineBuffers b = square_scene();
    for (float width : {1.0f, 2.0f, 3.0f, 5.0f}) {
        const ColorImage lines = draw(b, only(LineKind::silhouette, width));
        INFO("width " << width);
        // Across the left edge on row 32, the top edge on column 32, and
        // diagonally across the left edge (each step one pixel in x).
        for (const Profile& p : {profile(lines, 8, 32, 1, 0, 16), profile(lines, 32, 8, 0, 1, 16),
                                 profile(lines, 8, 24, 1, 1, 16)}) {
            CHECK(p.sum == Approx(width).margin(0.01));
            CHECK(std::abs(p.count - width) <= 1.0f);
        }
        // Away from any edge: nothing.
        CHECK(lines.at(32, 32).a == 0.0f);
        CHECK(lines.at(2, 2).a == 0.0f);
        CHECK(glm::vec3(lines.at(16, 32)) == glm::vec3(1, 0, 0));
    }
}

TEST_CASE("silhouettes of a disc are as wide as asked along a row and a diagonal", "[outline]") {
    OutlineBuffers b;
    b.reset(kSize, kSize);
    // Disc of radius 20 about (32, 32) (pixel centres at +0.5).
    paint(
        b, [](int x, int y) { return std::hypot(x + 0.5 - 32, y + 0.5 - 32) < 20; }, 5.0f, 1);
    for (float width : {1.0f, 2.0f, 3.0f, 5.0f}) {
        const ColorImage lines = draw(b, only(LineKind::silhouette, width));
        INFO("width " << width);
        // Through the centre along row 32, and along the diagonal, where a
        // step is sqrt(2) pixels: both cross the circle at right angles.
        const Profile row = profile(lines, 2, 32, 1, 0, 20);
        const Profile diagonal = profile(lines, 32 - 28, 32 - 28, 1, 1, 24);
        CHECK(row.sum == Approx(width).margin(1.0));
        CHECK(diagonal.sum * std::sqrt(2.0) == Approx(width).margin(1.0));
        CHECK(std::abs(row.count - width) <= 1.0f);
    }
}

TEST_CASE("depth jumps are judged relative to depth, at any distance", "[outline]") {
    for (float far : {1.0f, 1000.0f}) {
        INFO("distance " << far);
        OutlineBuffers b;
        b.reset(kSize, kSize);
        paint(
            b, [](int, int) { return true; }, far * 1.05f, 2);  // a wall 5% behind
        paint(
            b, [](int x, int) { return x < 32; }, far, 2);  // same object id
        CHECK(any_edge(edges_of(b, only(LineKind::silhouette, 1)), LineKind::silhouette));
        paint(
            b, [](int x, int) { return x >= 32; }, far * 1.01f, 2);  // 1%: below 2%
        CHECK_FALSE(any_edge(edges_of(b, only(LineKind::silhouette, 1)), LineKind::silhouette));
    }
}

TEST_CASE("a plane seen at a grazing angle has no false silhouettes", "[outline]") {
    OutlineBuffers b;
    b.reset(kSize, kSize);
    // 1/z affine in x, as on any plane: depth from 10 to about 80, up to
    // 12% from one pixel to the next, far beyond the 2% threshold.
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            b.depth[b.index(x, y)] = 1.0f / (0.1f - 0.00155f * (x + 0.5f));
            b.object_id[b.index(x, y)] = 1;
            b.normal[b.index(x, y)] = {0.99f, 0, 0.14f};
        }
    CHECK_FALSE(any_edge(edges_of(b, only(LineKind::silhouette, 1)), LineKind::silhouette));
}

TEST_CASE("creases appear at 90 degrees and not at 10 with a 30 degree threshold", "[outline]") {
    const float radians = 10.0f * static_cast<float>(M_PI) / 180.0f;
    for (auto [right_normal, expect] :
         {std::pair{glm::vec3(1, 0, 0), true},
          std::pair{glm::vec3(std::sin(radians), 0, std::cos(radians)), false},
          std::pair{glm::vec3(0, 0, -2), true}}) {
        OutlineBuffers b;
        b.reset(kSize, kSize);
        paint(b, [](int, int) { return true; }, 5.0f, 1, {0, 0, 1});
        paint(
            b, [](int x, int) { return x >= 32; }, 5.0f, 1, right_normal);
        OutlineStyle s = all_kinds();
        s.crease_angle = 30;
        const std::vector<uint8_t> edges = edges_of(b, s);
        INFO("right normal " << right_normal.x << " " << right_normal.y << " " << right_normal.z);
        CHECK(((edges[b.index(31, 10)] & edge_bit(LineKind::crease, false)) != 0) == expect);
        CHECK(any_edge(edges, LineKind::crease) == expect);
        CHECK_FALSE(any_edge(edges, LineKind::silhouette));
        CHECK_FALSE(any_edge(edges, LineKind::boundary));
        // The crease line is drawn in the crease colour.
        s.crease.color = {0, 0, 1};
        s.crease.width = 2;
        const ColorImage lines = draw(b, s);
        CHECK((lines.at(31, 10).a == 1.0f) == expect);
        if (expect) CHECK(glm::vec3(lines.at(32, 10)) == glm::vec3(0, 0, 1));
    }
}

TEST_CASE("intersection lines where two objects meet at the same depth", "[outline]") {
    OutlineBuffers b;
    b.reset(kSize, kSize);
    // Two objects side by side on one continuous depth ramp: they pass
    // through each other along x = 32.
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            b.depth[b.index(x, y)] = 5.0f + 0.01f * y;
            b.object_id[b.index(x, y)] = x < 32 ? 1 : 2;
            b.normal[b.index(x, y)] = x < 32 ? glm::vec3(0.6f, 0, 0.8f) : glm::vec3(-0.6f, 0, 0.8f);
        }
    const OutlineStyle s = all_kinds();
    std::vector<uint8_t> edges = edges_of(b, s);
    CHECK((edges[b.index(31, 20)] & edge_bit(LineKind::intersection, false)) != 0);
    CHECK((edges[b.index(31, 20)] & edge_bit(LineKind::boundary, false)) != 0);
    CHECK_FALSE(any_edge(edges, LineKind::silhouette));
    // Only along the meeting line.
    int intersection_pairs = 0;
    for (uint8_t e : edges)
        intersection_pairs += (e & edge_bit(LineKind::intersection, false)) != 0;
    CHECK(intersection_pairs == kSize);
    // Intersection lines have their own colour and take precedence over the
    // boundary and crease on the same edge (the normals differ by 74 degrees).
    CHECK(any_edge(edges, LineKind::crease));
    const ColorImage lines = draw(b, s);
    CHECK(glm::vec3(lines.at(31, 20)) == s.intersection.color);
    CHECK(lines.at(31, 20).a == 0.5f);

    // One object well in front: a silhouette and a boundary, no intersection.
    for (int y = 0; y < kSize; ++y)
        for (int x = 32; x < kSize; ++x) b.depth[b.index(x, y)] = 9.0f;
    edges = edges_of(b, s);
    CHECK((edges[b.index(31, 20)] & edge_bit(LineKind::silhouette, false)) != 0);
    CHECK((edges[b.index(31, 20)] & edge_bit(LineKind::boundary, false)) != 0);
    CHECK_FALSE(any_edge(edges, LineKind::intersection));
}

TEST_CASE("each kind of line can be switched off", "[outline]") {
    const OutlineBuffers b = square_scene();
    OutlineStyle s = all_kinds();
    s.silhouette.enabled = s.boundary.enabled = false;
    const ColorImage lines = draw(b, s);
    for (const glm::vec4& p : lines.pixels) CHECK(p.a == 0.0f);
    s.boundary.enabled = true;  // the square's outline is also an id boundary
    s.boundary.color = {0, 1, 0};
    const ColorImage boundary = draw(b, s);
    CHECK(boundary.at(16, 32).a > 0.0f);
    CHECK(glm::vec3(boundary.at(16, 32)) == glm::vec3(0, 1, 0));
}

TEST_CASE("fractional widths give anti-aliased coverage that adds up to the width", "[outline]") {
    const OutlineBuffers b = square_scene();
    for (float width : {0.5f, 1.5f, 2.25f}) {
        const ColorImage lines = draw(b, only(LineKind::silhouette, width));
        CHECK(profile(lines, 8, 32, 1, 0, 16).sum == Approx(width).margin(1e-4));
    }
    // 1.5 px: three quarters of each pixel beside the edge; 2.25 px: those
    // fully and an eighth of the next ones.
    ColorImage lines = draw(b, only(LineKind::silhouette, 1.5f));
    CHECK(lines.at(15, 32).a == 0.75f);
    CHECK(lines.at(16, 32).a == 0.75f);
    CHECK(lines.at(14, 32).a == 0.0f);
    lines = draw(b, only(LineKind::silhouette, 2.25f));
    CHECK(lines.at(15, 32).a == 1.0f);
    CHECK(lines.at(16, 32).a == 1.0f);
    CHECK(lines.at(14, 32).a == 0.125f);
    CHECK(lines.at(17, 32).a == 0.125f);
    CHECK(lines.at(13, 32).a == 0.0f);
}

TEST_CASE("lines composite over the colour by their coverage", "[outline]") {
    ThreadPool pool(2);
    ColorImage lines(2, 1, glm::vec4(0.0f));
    lines.at(0, 0) = {1, 0, 0, 1};
    lines.at(1, 0) = {1, 0, 0, 0.25f};
    ColorImage color(2, 1, glm::vec4(0, 0, 1, 0.5f));
    composite_lines(lines, color, pool);
    CHECK(color.at(0, 0) == glm::vec4(1, 0, 0, 1));
    CHECK(color.at(1, 0).r == Approx(0.25f));
    CHECK(color.at(1, 0).b == Approx(0.75f));
    CHECK(color.at(1, 0).a == Approx(0.25f + 0.5f * 0.75f));
}

TEST_CASE("outlines are identical with 1 and 2 threads", "[outline]") {
    OutlineBuffers b;
    b.reset(97, 61);  // not a multiple of anything
    paint(b, [](int x, int y) { return std::hypot(x - 30.0, y - 30.0) < 22; }, 4.0f, 1, {0, 0, 1});
    paint(b, [](int x, int y) { return x > 45 && x < 90 && y > 10 && y < 50; }, 4.0f, 2, {1, 0, 0});
    paint(b, [](int x, int y) { return x > 60 && y > 30; }, 9.0f, 3, {0, 1, 0});
    OutlineStyle s = all_kinds();
    s.silhouette.width = 3.5f;
    const ColorImage one = draw(b, s, 1);
    const ColorImage two = draw(b, s, 2);
    REQUIRE(one.pixels.size() == two.pixels.size());
    CHECK(std::memcmp(one.pixels.data(), two.pixels.data(),
                      one.pixels.size() * sizeof(glm::vec4)) == 0);
    int covered = 0;
    for (const glm::vec4& p : one.pixels) covered += p.a > 0;
    CHECK(covered > 200);  // the comparison is not of two empty images
}

TEST_CASE("outline buffers of the wrong size are refused", "[outline]") {
    OutlineBuffers b = square_scene();
    b.normal.pop_back();
    CHECK_THROWS_AS(draw(b, OutlineStyle{}), facet::Error);
}
