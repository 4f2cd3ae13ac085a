// A metallic-roughness material under the Phong family (docs/styles.md,
// "PBR materials under every preset"; shade/metal_rough_phong.hpp): the
// albedo is base * (1 - metallic), the highlight's colour mix(0.04, base,
// metallic), its exponent n = 2 / roughness^4 - 2 and its strength
// (n + 8) / 8, and the ambient light reflects off both. Each case renders a
// sphere and compares every pixel with those formulas worked out here in
// double precision from the ray through the pixel.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

namespace {

using dvec3 = glm::dvec3;

constexpr int kSize = 101;  // odd: the middle pixel's ray is the axis
constexpr double kFovDegrees = 40, kEyeZ = 4;
constexpr double kLight = 0.3, kAmbientLight = 0.2;  // intensities
constexpr double kAmbient = 0.1, kDiffuse = 0.8;     // the materials' default ka, kd

struct Sphere {
    std::string style;   // a shipped preset
    std::string colour;  // YAML list
    dvec3 base;
    double metallic, roughness;
    std::string extra;  // more material keys
};

facet::FrameImages render(const Sphere& s) {
    facet::test::TempDir dir("metal-rough-phong");
    const std::string text = "output: { size: [" + std::to_string(kSize) + ", " +
                             std::to_string(kSize) +
                             "], background: [0, 0, 0] }\n"
                             "camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 40 }\n"
                             "style: " +
                             s.style +
                             "\n"
                             "lights:\n"
                             "  - { type: directional, direction: [0, 0, -1], intensity: 0.3 }\n"
                             "  - { type: ambient, intensity: 0.2 }\n"
                             "objects:\n"
                             "  - primitive: { type: sphere, radius: 1, segments: 256 }\n"
                             "    material: { color: " +
                             s.colour + ", metallic: " + std::to_string(s.metallic) +
                             ", roughness: " + std::to_string(s.roughness) + s.extra + " }\n";
    return facet::test::render_yaml(dir.path(), text, 1, 2);
}

// Where the ray through pixel (x, y) meets the unit sphere: the unit normal
// and the unit vector to the eye; false when it misses or grazes (|n.v| <
// `least`, where the tessellation's normals part from the sphere's).
bool hit(int x, int y, double least, dvec3& n, dvec3& v) {
    const double t = std::tan(kFovDegrees * 0.5 * 3.14159265358979323846 / 180.0);
    const double u = ((x + 0.5) / kSize * 2 - 1) * t, w = (1 - (y + 0.5) / kSize * 2) * t;
    const dvec3 eye(0, 0, kEyeZ), d = glm::normalize(dvec3(u, w, -1));
    const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1, disc = b * b - c;
    if (disc <= 0) return false;
    n = eye + d * (-b - std::sqrt(disc));
    v = -d;
    return glm::dot(n, v) >= least;
}

// The documented conversion's colour at a point (light along +z).
dvec3 expected(const Sphere& s, const dvec3& n, const dvec3& v, bool blinn) {
    const dvec3 l(0, 0, 1);
    const double n_dot_l = glm::dot(n, l);
    const double r4 = std::pow(std::max(s.roughness, 0.05), 4);
    const double exponent = std::clamp(2 / r4 - 2, 1.0, 2048.0);
    const double strength = (exponent + 8) / 8;
    const dvec3 albedo = s.base * (1 - s.metallic);
    const dvec3 specular = glm::mix(dvec3(0.04), s.base, s.metallic);
    const double cosine =
        blinn ? glm::dot(n, glm::normalize(l + v)) : glm::dot(2 * n_dot_l * n - l, v);
    const double highlight =
        n_dot_l > 0 && cosine > 0 ? strength * std::pow(std::min(cosine, 1.0), exponent) : 0;
    return albedo * (kAmbient * kAmbientLight + kDiffuse * std::max(n_dot_l, 0.0) * kLight) +
           specular * (kAmbient * kAmbientLight + highlight * kLight);
}

// Every pixel of the sphere facing the eye (n.v >= 0.3) against the
// formulas, each channel within 2% + 0.004 (half floats, and the
// tessellation's normals).
void check_against_formulas(const Sphere& s, bool blinn) {
    const facet::FrameImages image = render(s);
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            dvec3 n, v;
            if (!hit(x, y, 0.3, n, v)) continue;
            const glm::vec4 got = facet::to_float(image.color.at(x, y));
            const dvec3 want = expected(s, n, v, blinn);
            for (int a = 0; a < 3; ++a) {
                INFO("pixel " << x << ", " << y << " channel " << a);
                REQUIRE(got[a] == Approx(want[a]).epsilon(0.02).margin(0.004));
            }
            ++checked;
        }
    CHECK(checked > 3000);
}

const Sphere kGold{"phong", "[0.9, 0.6, 0.2]", {0.9, 0.6, 0.2}, 1.0, 0.6, ""};

}  // namespace

TEST_CASE("a metal sphere under phong: no diffuse light, a highlight of its own colour",
          "[render][metal_rough_phong]") {
    check_against_formulas(kGold, false);
    // Spelled out: where the highlight has faded the metal shows only the
    // ambient light in its colour, far darker than the same dielectric.
    const facet::FrameImages metal = render(kGold);
    Sphere dielectric = kGold;
    dielectric.metallic = 0;
    const facet::FrameImages plastic = render(dielectric);
    dvec3 n, v;
    int x = 50, y = 50;
    for (; x < kSize; ++x)
        if (hit(x, y, 0, n, v) && glm::dot(n, v) < 0.5) break;
    const glm::vec4 dark = facet::to_float(metal.color.at(x, y));
    const glm::vec4 light = facet::to_float(plastic.color.at(x, y));
    CHECK(dark.r < 0.25 * light.r);
    // The highlight's middle: the base colour's hue, bright.
    const glm::vec4 middle = facet::to_float(metal.color.at(kSize / 2, kSize / 2));
    CHECK(middle.r > 0.5);
    CHECK(middle.g / middle.r == Approx(0.6 / 0.9).epsilon(0.01));
    CHECK(middle.b / middle.r == Approx(0.2 / 0.9).epsilon(0.01));
}

TEST_CASE("a rough dielectric under blinn-phong: a broad, dim, white highlight",
          "[render][metal_rough_phong]") {
    const Sphere rough{"blinn-phong", "[0.2, 0.4, 0.8]", {0.2, 0.4, 0.8}, 0.0, 0.8, ""};
    check_against_formulas(rough, true);
    // Its highlight is 0.04 (n + 8) / 8 at its peak, n = 2 / 0.8^4 - 2:
    // under 6% of the light, and still above half of that where n.h = 0.8.
    const double n = 2 / std::pow(0.8, 4) - 2;
    CHECK(0.04 * (n + 8) / 8 < 0.06);
    CHECK(std::pow(0.8, n) > 0.5);
    const Sphere smooth{"blinn-phong", "[0.2, 0.4, 0.8]", {0.2, 0.4, 0.8}, 0.0, 0.2, ""};
    check_against_formulas(smooth, true);
}

TEST_CASE("the Phong family's other models read metal and roughness too",
          "[render][metal_rough_phong]") {
    Sphere flat = kGold;
    flat.style = "flat";  // the face's normal: only the dark diffuse can be checked
    const facet::FrameImages image = render(flat);
    Sphere gouraud = kGold;
    gouraud.style = "gouraud";
    const facet::FrameImages vertex_lit = render(gouraud);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            dvec3 n, v;
            if (!hit(x, y, 0.3, n, v) || glm::dot(n, v) > 0.6) continue;
            // Off the highlight: the ambient light in the metal's colour.
            const double floor = kAmbient * kAmbientLight * 0.9;
            INFO("pixel " << x << ", " << y);
            CHECK(facet::to_float(image.color.at(x, y)).r == Approx(floor).margin(0.01));
            CHECK(facet::to_float(vertex_lit.color.at(x, y)).r == Approx(floor).margin(0.01));
        }
}

TEST_CASE("a preset's own colour, and a material's Phong terms, win over metal and roughness",
          "[render][metal_rough_phong]") {
    // clay's base colour: metal or not, the same clay.
    Sphere clay = kGold;
    clay.style = "clay";
    Sphere clay_dielectric = clay;
    clay_dielectric.metallic = 0;
    const facet::FrameImages a = render(clay), b = render(clay_dielectric);
    REQUIRE(a.color.pixels.size() == b.color.pixels.size());
    CHECK(std::memcmp(a.color.pixels.data(), b.color.pixels.data(),
                      a.color.pixels.size() * sizeof(facet::Rgba16F)) == 0);
    // A material that gives `specular` is a Phong one: its colour is its
    // diffuse colour and its highlight white, metal or not.
    Sphere phong_terms = kGold;
    phong_terms.extra = ", specular: 0.5, shininess: 20";
    const facet::FrameImages image = render(phong_terms);
    const glm::vec4 middle = facet::to_float(image.color.at(kSize / 2, kSize / 2));
    const double want_red = 0.9 * (kAmbient * kAmbientLight + kDiffuse * kLight) + 0.5 * kLight;
    CHECK(middle.r == Approx(want_red).epsilon(0.02));
    const double want_blue = 0.2 * (kAmbient * kAmbientLight + kDiffuse * kLight) + 0.5 * kLight;
    CHECK(middle.b == Approx(want_blue).epsilon(0.02));
}
