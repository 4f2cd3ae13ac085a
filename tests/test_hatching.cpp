// Hatching (style `hatching`): strokes darken monotonically with the
// tone, keep their size in pixels whatever the UV scale or distance, run
// at the angle asked for, follow a cylinder's axis, and stick to a moving
// object in object space while screen-space strokes stay put.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/half.hpp"
#include "render/principal_directions.hpp"
#include "render_check.hpp"
#include "shade/hatch_mapping.hpp"
#include "shapes/primitives.hpp"
#include "support.hpp"

namespace {

// A white square facing the camera, 4 m away, filling a 256x256 view
// (fov 90: 32 pixels per metre at that depth), lit head-on. Black ink on
// white paper, no wash of colour, so a pixel's darkness is its coverage.
std::string plane_scene(float intensity, const std::string& hatching, float distance = 4,
                        float shift = 0) {
    return "output: { size: [256, 256], samples: 4, background: [1, 1, 1, 1] }\n"
           "camera: { position: [0, 0, " +
           std::to_string(distance) +
           "], target: [0, 0, 0], fov: 90 }\n"
           "style: { shading: blinn_phong, outlines: false, hatching: { wash: 0, paper: [1, 1, 1],"
           " ink: [0, 0, 0], white: 1, " +
           hatching +
           " } }\n"
           "lights: [{ type: directional, direction: [0, 0, -1], intensity: " +
           std::to_string(intensity) +
           " }]\n"
           "objects:\n"
           "  - name: card\n"
           "    primitive: { type: plane, size: 40 }\n"
           "    rotate: [90, 0, 0]\n"
           "    translate: [" +
           std::to_string(shift) +
           ", 0, 0]\n"
           "    material: { color: [1, 1, 1], ambient: 0, specular: 0 }\n";
}

// Darkness (1 − red) per pixel.
std::vector<float> darkness(const facet::FrameImages& images) {
    std::vector<float> out;
    out.reserve(images.color.pixels.size());
    for (const auto& p : images.color.pixels) out.push_back(1.0f - facet::to_float(p).r);
    return out;
}

std::vector<float> render_darkness(const std::string& yaml) {
    facet::test::TempDir dir("hatching");
    return darkness(facet::test::render_yaml(dir.path(), yaml, 1, 2));
}

double mean(const std::vector<float>& v) {
    double sum = 0;
    for (float x : v) sum += x;
    return sum / static_cast<double>(v.size());
}

// Strokes crossed per pixel: how often the darkness crosses 0.5 along
// rows and along columns, whichever is more (the strokes' spacing across
// them, which grows with their width and length).
double crossings_per_pixel(const std::vector<float>& d, int size) {
    long rows = 0, cols = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 1; x < size; ++x) {
            rows += (d[y * size + x] > 0.5f) != (d[y * size + x - 1] > 0.5f);
            cols += (d[x * size + y] > 0.5f) != (d[(x - 1) * size + y] > 0.5f);
        }
    return static_cast<double>(std::max(rows, cols)) / (static_cast<double>(size) * size);
}

}  // namespace

TEST_CASE("hatching density rises monotonically with darkness", "[render][hatching]") {
    // From more than full light (no strokes) down to none. Ink covers as
    // much of the paper as the tone (the lightness L* of the light) is
    // dark, up to the darkest level's coverage (0.8).
    const float intensities[] = {1.6f, 1.0f, 0.8f, 0.6f, 0.45f, 0.3f, 0.0f};
    double previous = -1;
    for (float intensity : intensities) {
        const double coverage = mean(render_darkness(plane_scene(intensity, "levels: 24")));
        INFO("light " << intensity << ": mean ink " << coverage);
        if (previous >= 0 && intensity > 0.0f) CHECK(coverage > previous + 0.05);
        if (intensity == 0.0f) CHECK(coverage >= previous);
        if (intensity > 1.5f) CHECK(coverage == 0.0);
        if (intensity == 0.0f) CHECK(coverage > 0.7);
        previous = coverage;
    }
}

TEST_CASE("hatching exposure: one stop up draws as twice the light, one down as half",
          "[render][hatching]") {
    // Below full light the tone follows the light, so +1 stop at 0.3 is
    // the light of 0.6, and -1 stop at 0.6 that of 0.3; the strokes match.
    const double at_03 = mean(render_darkness(plane_scene(0.3f, "levels: 24")));
    const double at_06 = mean(render_darkness(plane_scene(0.6f, "levels: 24")));
    const double up = mean(render_darkness(plane_scene(0.3f, "levels: 24, exposure: 1")));
    const double down = mean(render_darkness(plane_scene(0.6f, "levels: 24, exposure: -1")));
    INFO("ink at 0.3 " << at_03 << ", 0.6 " << at_06 << ", 0.3 +1 " << up << ", 0.6 -1 " << down);
    REQUIRE(at_03 > at_06 + 0.05);  // the two lights differ in strokes
    CHECK(up == Approx(at_06).margin(0.005));
    CHECK(down == Approx(at_03).margin(0.005));
}

TEST_CASE("hatching strokes keep their size in pixels at any UV scale and distance",
          "[render][hatching]") {
    const double base = crossings_per_pixel(
        render_darkness(plane_scene(0.55f, "space: uv, direction: fixed, scale: 1")), 256);
    const double fine = crossings_per_pixel(
        render_darkness(plane_scene(0.55f, "space: uv, direction: fixed, scale: 20")), 256);
    const double far = crossings_per_pixel(
        render_darkness(plane_scene(0.55f, "space: uv, direction: fixed, scale: 1", 12)), 256);
    INFO("crossings per pixel: scale 1 " << base << ", scale 20 " << fine << ", 3x farther "
                                         << far);
    REQUIRE(base > 0.02);  // there are strokes to count
    // Tiles per unit 20 times over would give 20 times the strokes per
    // pixel without the octaves; a factor within 1.5 is the octave blend.
    CHECK(fine / base == Approx(1.0).margin(0.5));
    CHECK(far / base == Approx(1.0).margin(0.5));
}

TEST_CASE("object-space strokes move with the object, screen-space ones stay put",
          "[render][hatching]") {
    // The card moves 0.25 m, which is 8 pixels at 4 m with fov 90 over 256.
    auto shifted_difference = [](const std::string& hatching) {
        const std::vector<float> a = render_darkness(plane_scene(0.5f, hatching));
        const std::vector<float> b = render_darkness(plane_scene(0.5f, hatching, 4, 0.25f));
        double moved = 0, still = 0;
        int n = 0;
        for (int y = 16; y < 240; ++y)
            for (int x = 16; x < 232; ++x, ++n) {
                moved += std::fabs(a[y * 256 + x] - b[y * 256 + x + 8]);
                still += std::fabs(a[y * 256 + x] - b[y * 256 + x]);
            }
        return std::pair<double, double>(moved / n, still / n);
    };
    const auto [object_moved, object_still] = shifted_difference("space: object");
    const auto [screen_moved, screen_still] = shifted_difference("space: screen");
    INFO("object: " << object_moved << " moved, " << object_still << " still; screen: "
                    << screen_moved << " moved, " << screen_still << " still");
    CHECK(object_moved < 0.01);
    CHECK(object_still > 0.1);
    CHECK(screen_still < 0.01);
    CHECK(screen_moved > 0.1);
}

TEST_CASE("hatch mapping turns the strokes to the angle asked for", "[style][hatching]") {
    facet::TamParams p;
    p.size = 128;
    p.levels = 8;
    p.hatch_angle = 0;
    p.cross_from_level = 8;  // no cross strokes
    const facet::TonalArtMap tam = facet::generate_tonal_art_map(p);
    for (float degrees : {0.0f, 30.0f, 75.0f, 120.0f, 165.0f}) {
        // A 256-pixel image of one chart at that angle, in pixels (y down),
        // magnified 4 times: strokes 6 pixels wide, whose gradients central
        // differences measure without favouring the pixel grid's axes.
        const int size = 256;
        std::vector<float> img(size * size);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                facet::HatchFootprint f;
                f.count = 0;
                const facet::HatchChart chart{glm::vec2(x + 0.5f, y + 0.5f) / 512.0f,
                                              glm::vec2(1.0f / 512, 0), glm::vec2(0, 1.0f / 512),
                                              glm::radians(degrees), 1.0f};
                facet::add_hatch_chart(chart, p.size, 0.0f, false, f);
                img[y * size + x] = facet::hatch_coverage(tam, 0.5f, f);
            }
        // The structure tensor's main axis is the gradient's: across the strokes.
        double jxx = 0, jyy = 0, jxy = 0;
        for (int y = 1; y + 1 < size; ++y)
            for (int x = 1; x + 1 < size; ++x) {
                const double gx = img[y * size + x + 1] - img[y * size + x - 1];
                const double gy = img[(y + 1) * size + x] - img[(y - 1) * size + x];
                jxx += gx * gx, jyy += gy * gy, jxy += gx * gy;
            }
        const double across = 0.5 * std::atan2(2 * jxy, jxx - jyy);
        double along = glm::degrees(across) + 90.0;
        along = std::fmod(along + 360.0, 180.0);
        double error = std::fabs(along - degrees);
        error = std::min(error, 180.0 - error);
        INFO("asked " << degrees << "°, strokes at " << along << "°");
        CHECK(error < 5.0);  // orientations 11.25° apart, blended
    }
}

TEST_CASE("principal directions run along a cylinder, and trust no direction on a sphere",
          "[style][hatching]") {
    facet::PrimitiveSpec cylinder;
    cylinder.type = "cylinder";
    cylinder.radius = 0.3f;
    cylinder.height = 2.0f;
    cylinder.segments = 32;
    const facet::Mesh c = facet::make_primitive(cylinder);
    int side = 0, along = 0;
    for (const facet::MeshPart& part : c.parts) {
        const std::vector<glm::vec3> d = facet::principal_directions(part);
        REQUIRE(d.size() == part.positions.size());
        for (size_t i = 0; i < d.size(); ++i) {
            if (std::fabs(part.normals[i].y) > 0.01f) continue;  // the caps
            ++side;
            const float length = glm::length(d[i]);
            if (length > 0.9f && std::fabs(d[i].y) / length > 0.98f) ++along;
        }
    }
    INFO(along << " of " << side << " side vertices point along the axis");
    REQUIRE(side > 0);
    CHECK(along == side);

    facet::PrimitiveSpec sphere;
    sphere.type = "sphere";
    sphere.segments = 48;
    sphere.rings = 24;
    const facet::Mesh s = facet::make_primitive(sphere);
    double confidence = 0;
    size_t count = 0;
    for (const facet::MeshPart& part : s.parts)
        for (const glm::vec3& d : facet::principal_directions(part))
            confidence += glm::length(d), ++count;
    INFO("mean confidence on the sphere " << confidence / count);
    CHECK(confidence / count < 0.15);

    facet::PrimitiveSpec plane;
    plane.type = "plane";
    for (const facet::MeshPart& part : facet::make_primitive(plane).parts)
        for (const glm::vec3& d : facet::principal_directions(part)) CHECK(glm::length(d) == 0.0f);
}
