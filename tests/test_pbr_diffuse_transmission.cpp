// KHR_materials_diffuse_transmission in the `pbr` model (shade/brdf_layers.hpp,
// docs/pbr.md, "Diffuse transmission"): a light behind the surface against
// the extension's formula written out here, the front's diffuse less the
// share that passes, energy kept, a strength of 0 keeping the bits, a
// back-lit pane in a render, and reading the extension.
#include <catch2/catch.hpp>

#include <cmath>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "pbr_lane_support.hpp"
#include "render_check.hpp"
#include "shade/brdf.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

using V3 = lanes::Vec3<float>;

V3 unit(double x, double y, double z) {
    const double length = std::sqrt(x * x + y * y + z * z);
    return {static_cast<float>(x / length), static_cast<float>(y / length),
            static_cast<float>(z / length)};
}

pbr::SurfaceTerms<float> translucent(float strength, const V3& color) {
    pbr::SurfaceTerms<float> t =
        pbr::surface_terms({glm::vec3(0.2f, 0.6f, 0.3f), 0.0f, 0.5f, pbr::kDefaultIor});
    t.diffuse_transmission = strength;
    t.diffuse_transmission_color = color;
    return t;
}

pbr::PbrPoint<float> point_of(const pbr::SurfaceTerms<float>& t, const V3& v) {
    return pbr::prepare_point<float>({0.0f, 0.0f, 1.0f}, v, t, pbr::MultipleScattering::compensated,
                                     pbr::dfg_table());
}

}  // namespace

TEST_CASE("diffuse transmission: a light from behind passes as the extension's Lambertian BTDF",
          "[shade][diffuse_transmission]") {
    const V3 v = unit(0.2, 0.1, 1.0);
    const V3 color = {1.0f, 0.4f, 0.1f};
    for (const float strength : {0.25f, 1.0f}) {
        const pbr::PbrPoint<float> p = point_of(translucent(strength, color), v);
        const V3 l = unit(-0.3, 0.2, -0.9);  // behind
        const V3 got = pbr::brdf_cosine(p, l);
        // (1 - F(v.h')) t c_t / pi |n.l|, h' the half vector of v and l
        // mirrored to the front; F Schlick's with f0 0.04 and F90 1.
        const glm::dvec3 lm(l[0], l[1], -l[2]);
        const glm::dvec3 h = glm::normalize(lm + glm::dvec3(v[0], v[1], v[2]));
        const double vh = glm::dot(h, glm::dvec3(v[0], v[1], v[2]));
        const double f = 0.04 + 0.96 * std::pow(1.0 - vh, 5.0);
        for (int c = 0; c < 3; ++c) {
            const double expected = (1.0 - f) * strength * color[c] / 3.14159265358979 * -l[2];
            INFO("strength " << strength << ", channel " << c);
            CHECK(got[c] == Approx(expected).epsilon(1e-4));
        }
        // From the front, the diffuse keeps 1 - t of the base colour.
        const pbr::PbrPoint<float> opaque = point_of(translucent(0.0f, color), v);
        const V3 front = unit(0.3, -0.2, 0.9);
        const V3 lit = pbr::brdf_cosine(p, front), bare = pbr::brdf_cosine(opaque, front);
        const V3 specular =
            pbr::brdf_cosine(point_of(
                                 [] {
                                     pbr::SurfaceTerms<float> black = translucent(0.0f, {0, 0, 0});
                                     black.base = {0.0f, 0.0f, 0.0f};
                                     return black;
                                 }(),
                                 v),
                             front);
        for (int c = 0; c < 3; ++c)
            CHECK(lit[c] - specular[c] ==
                  Approx((1.0f - strength) * (bare[c] - specular[c])).epsilon(1e-5));
    }
    // A surface without it is dark from behind.
    const V3 dark = pbr::brdf_cosine(point_of(translucent(0.0f, color), v), unit(0.1, 0.0, -1.0));
    CHECK(dark == V3{0.0f, 0.0f, 0.0f});
}

TEST_CASE("diffuse transmission: what passes and what is reflected never exceed what arrives",
          "[shade][diffuse_transmission]") {
    // A white pane passing all its diffuse, lit from every direction of
    // both hemispheres: reflected + passed, per unit of irradiance, at most 1.
    constexpr int kTheta = 128, kPhi = 128;
    pbr::SurfaceTerms<float> t = translucent(0.6f, {1.0f, 1.0f, 1.0f});
    t.base = {1.0f, 1.0f, 1.0f};
    const pbr::PbrPoint<float> p = point_of(t, unit(0.3, 0.0, 1.0));
    double front = 0.0, back = 0.0;
    for (int i = 0; i < kTheta; ++i) {
        const double mu = (i + 0.5) / kTheta;
        const double s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < kPhi; ++j) {
            const double phi = 2.0 * 3.14159265358979 * (j + 0.5) / kPhi;
            front += pbr::brdf_cosine(p, unit(s * std::cos(phi), s * std::sin(phi), mu))[1];
            back += pbr::brdf_cosine(p, unit(s * std::cos(phi), s * std::sin(phi), -mu))[1];
        }
    }
    const double scale = (1.0 / kTheta) * (2.0 * 3.14159265358979 / kPhi);
    INFO("reflected " << front * scale << ", passed " << back * scale);
    CHECK(back * scale == Approx(0.6).margin(0.08));  // t, less the specular layer's share
    CHECK(front * scale <= 1.0);
    CHECK(back * scale < 0.6);
}

TEST_CASE(
    "diffuse transmission: strength 0 keeps the bits, and a lane with it is the one-point "
    "result",
    "[shade][diffuse_transmission]") {
    test::PointTerms points;
    test::PointViews views;
    test::varied_lanes(points, views, [](int i, pbr::SurfaceTerms<float>& t) {
        const float f = static_cast<float>(i);
        t.diffuse_transmission = i % 2 ? 0.2f + 0.1f * f : 0.0f;
        t.diffuse_transmission_color = {0.9f, 0.5f + 0.05f * f, 0.2f};
    });
    test::check_layer_lanes(
        points, views,
        [](pbr::SurfaceTerms<float> t) {
            t.diffuse_transmission = 0.0f;
            return t;
        },
        // A metal (every third lane) has no diffuse to pass: it shows no change.
        [](int i) { return i % 2 == 1 && i % 3 != 0; });
}

TEST_CASE("diffuse transmission: a pane lit from behind shows the light through it",
          "[render][diffuse_transmission]") {
    const auto render = [](const std::string& keys) {
        TempDir dir("diffuse-transmission");
        const std::string text = R"(output: { size: [48, 48], tonemap: none }
camera: { position: [0, 0, 3], target: [0, 0, 0], fov: 30 }
style: pbr
environment: { color: [0, 0, 0] }
lights: [{ type: directional, direction: [0, 0, 1], intensity: 1 }]
objects:
  - name: pane
    primitive: { type: plane, size: 2 }
    rotate: [90, 0, 0]
    material: { color: [0.2, 0.8, 0.2], metallic: 0, roughness: 0.6, double_sided: true)" +
                                 keys + " }\n";
        const FrameImages images = render_yaml(dir.path(), text, 1, 2);
        return to_float(images.color.at(24, 24));
    };
    const glm::vec4 opaque = render("");
    const glm::vec4 lampshade =
        render(", diffuse_transmission: 0.8, diffuse_transmission_color: [1, 0.6, 0.2]");
    INFO("opaque " << opaque.r << " " << opaque.g << ", lampshade " << lampshade.r << " "
                   << lampshade.g << " " << lampshade.b);
    CHECK(opaque.r < 0.01f);  // lit from behind, an opaque pane is dark
    CHECK(lampshade.r > 0.1f);
    CHECK(lampshade.r > lampshade.g);  // in the transmission's colour
    CHECK(lampshade.g > lampshade.b);
}

TEST_CASE("diffuse transmission: KHR_materials_diffuse_transmission is read with its maps",
          "[pbr][gltf]") {
    TempDir dir("diffuse-transmission-read");
    Gltf g;
    for (int i = 0; i < 2; ++i) {
        g.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}});
        g.doc["textures"].push_back({{"source", i}});
    }
    const json leaf = {{"diffuseTransmissionFactor", 0.7},
                       {"diffuseTransmissionColorFactor", {0.9, 0.8, 0.1}},
                       {"diffuseTransmissionTexture", {{"index", 0}}},
                       {"diffuseTransmissionColorTexture", {{"index", 1}}}};
    g.doc["materials"] =
        json::array({{{"extensions", {{"KHR_materials_diffuse_transmission", leaf}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_diffuse_transmission"};
    g.one_quad_scene();
    const Mesh mesh = load_gltf(g.write(dir.file("leaf.gltf")));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.diffuse_transmission == Approx(0.7f));
    CHECK(m.diffuse_transmission_color == glm::vec3(0.9f, 0.8f, 0.1f));
    REQUIRE(m.diffuse_transmission_map.texture);
    CHECK(m.diffuse_transmission_map.texture->format() == Texture::Format::data8);
    REQUIRE(m.diffuse_transmission_color_map.texture);
    CHECK(m.diffuse_transmission_color_map.texture->format() == Texture::Format::srgb8);
    json bad = leaf;
    bad["diffuseTransmissionFactor"] = 2;
    g.doc["materials"] =
        json::array({{{"extensions", {{"KHR_materials_diffuse_transmission", bad}}}}});
    const std::string path = g.write(dir.file("bad.gltf"));
    require_input_error([&] { load_gltf(path); }, "diffuseTransmissionFactor must be from 0 to 1");
}
