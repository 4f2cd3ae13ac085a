// KHR_materials_iridescence in the `pbr` model (shade/thin_film.hpp,
// docs/pbr.md, "Iridescence"): the thin film's reflectance at normal
// incidence against the Airy formula integrated over the spectrum here,
// in double, with the CIE 1931 colour matching functions; a film of no
// thickness against the bare surface; a strength of 0 keeping the bits;
// and reading the extension.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <cstring>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "pbr_lane_support.hpp"
#include "shade/brdf.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The CIE 1931 2-degree colour matching functions, by the multi-lobe fit
// of Wyman, Sloan & Shirley 2013 ("Simple Analytic Approximations to the
// CIE XYZ Color Matching Functions", JCGT 2 (2)).
double lobe(double nm, double mean, double below, double above) {
    const double t = (nm - mean) / (nm < mean ? below : above);
    return std::exp(-0.5 * t * t);
}
glm::dvec3 cie_xyz(double nm) {
    return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                0.065 * lobe(nm, 501.1, 20.4, 26.2),
            0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
            1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

glm::dvec3 xyz_to_rec709(const glm::dvec3& c) {
    return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
            -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
            0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

// The reflectance of a film of index n2 and thickness d (nm) between air
// and a dielectric of index n3, seen head-on, by Airy's formula summed
// over every reflection: |r12 + r23 e^(i delta)|^2 / |1 + r12 r23
// e^(i delta)|^2 with delta = 4 pi n2 d / lambda. As linear RGB: the
// spectrum weighted by the matching functions from 360 to 830 nm, each
// channel divided by that of a reflectance of 1, so grey stays grey.
glm::dvec3 airy_rgb(double n2, double n3, double d) {
    const double r12 = (1.0 - n2) / (1.0 + n2), r23 = (n2 - n3) / (n2 + n3);
    glm::dvec3 film(0.0), white(0.0);
    for (double nm = 360.0; nm <= 830.0; nm += 0.5) {
        const std::complex<double> phase = std::polar(1.0, 4.0 * kPi * n2 * d / nm);
        const double r = std::norm(r12 + r23 * phase) / std::norm(1.0 + r12 * r23 * phase);
        film += r * cie_xyz(nm);
        white += cie_xyz(nm);
    }
    const glm::dvec3 rgb = xyz_to_rec709(film), one = xyz_to_rec709(white);
    return rgb / one;
}

lanes::Vec3<float> film_at_normal(float film_ior, float thickness, float base_f0) {
    return pbr::thin_film_fresnel<float>(1.0f, film_ior, thickness, {base_f0, base_f0, base_f0});
}

}  // namespace

TEST_CASE("iridescence: the film's colour at normal incidence follows Airy's formula",
          "[shade][iridescence]") {
    // A soap-like film (1.33) and a denser one (1.8) over glass (1.5), from
    // thin to thick: the colours swing through the interference orders.
    double worst = 0.0;
    for (const double n2 : {1.33, 1.8})
        for (const double d : {150.0, 250.0, 350.0, 500.0, 700.0}) {
            const double n3 = 1.5;
            const float base_f0 = static_cast<float>(((n3 - 1) / (n3 + 1)) * ((n3 - 1) / (n3 + 1)));
            const lanes::Vec3<float> model =
                film_at_normal(static_cast<float>(n2), static_cast<float>(d), base_f0);
            const glm::dvec3 airy = airy_rgb(n2, n3, d);
            for (int c = 0; c < 3; ++c) {
                INFO("film " << n2 << ", " << d << " nm, channel " << c << ": model " << model[c]
                             << ", Airy " << airy[c]);
                CHECK(model[c] == Approx(airy[c]).margin(0.02));
                worst = std::max(worst, std::abs(model[c] - airy[c]));
            }
        }
    WARN("largest |model - Airy| reflectance: " << worst);
    // And the colours do change with thickness: not a constant.
    const lanes::Vec3<float> thin = film_at_normal(1.33f, 250.0f, 0.04f);
    const lanes::Vec3<float> thick = film_at_normal(1.33f, 500.0f, 0.04f);
    CHECK(std::abs(thin[0] - thick[0]) + std::abs(thin[2] - thick[2]) > 0.02f);
}

TEST_CASE("iridescence: a film of no thickness reflects as the bare surface head-on",
          "[shade][iridescence]") {
    for (const float f0 : {0.04f, 0.2f, 0.9f}) {
        const lanes::Vec3<float> bare = film_at_normal(1.3f, 0.0f, f0);
        for (int c = 0; c < 3; ++c) CHECK(bare[c] == Approx(f0).margin(0.01));
    }
}

TEST_CASE("iridescence: strength 0 keeps the bits, and a lane with a film is the one-point result",
          "[shade][iridescence]") {
    // Eight lanes, the odd ones with a film; metals and dielectrics; views
    // from head-on to grazing.
    test::PointTerms points;
    test::PointViews views;
    test::varied_lanes(points, views, [](int i, pbr::SurfaceTerms<float>& t) {
        const float f = static_cast<float>(i);
        t.iridescence = i % 2 ? 0.5f + 0.05f * f : 0.0f;
        t.iridescence_ior = 1.2f + 0.1f * f;
        t.iridescence_thickness = 150.0f + 60.0f * f;
    });
    test::check_layer_lanes(
        points, views,
        [](pbr::SurfaceTerms<float> t) {
            t.iridescence = 0.0f;
            return t;
        },
        [](int i) { return i % 2 == 1; });
}

TEST_CASE("iridescence: KHR_materials_iridescence is read with its maps as data", "[pbr][gltf]") {
    TempDir dir("iridescence");
    Gltf g;
    for (int i = 0; i < 2; ++i) {
        g.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}});
        g.doc["textures"].push_back({{"source", i}});
    }
    const json film = {{"iridescenceFactor", 0.8},
                       {"iridescenceIor", 1.45},
                       {"iridescenceThicknessMinimum", 200},
                       {"iridescenceThicknessMaximum", 800},
                       {"iridescenceTexture", {{"index", 0}}},
                       {"iridescenceThicknessTexture", {{"index", 1}}}};
    g.doc["materials"] = json::array({{{"extensions", {{"KHR_materials_iridescence", film}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_iridescence"};
    g.one_quad_scene();
    const Mesh mesh = load_gltf(g.write(dir.file("film.gltf")));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.iridescence == Approx(0.8f));
    CHECK(m.iridescence_ior == Approx(1.45f));
    CHECK(m.iridescence_thickness_min == 200.0f);
    CHECK(m.iridescence_thickness_max == 800.0f);
    REQUIRE(m.iridescence_map.texture);
    CHECK(m.iridescence_map.texture->format() == Texture::Format::data8);
    REQUIRE(m.iridescence_thickness_map.texture);
    CHECK(m.iridescence_thickness_map.texture->format() == Texture::Format::data8);
    // An index below 1 is refused by its path.
    json bad = film;
    bad["iridescenceIor"] = 0.5;
    g.doc["materials"] = json::array({{{"extensions", {{"KHR_materials_iridescence", bad}}}}});
    const std::string path = g.write(dir.file("bad.gltf"));
    require_input_error([&] { load_gltf(path); }, "iridescenceIor must be from 1 to 10");
}
