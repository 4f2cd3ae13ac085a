// KHR_materials_anisotropy in the `pbr` model (shade/brdf_layers.hpp,
// docs/pbr.md, "Anisotropy"): the lobe against its closed form written
// here in another algebraic form, in double; its distribution's
// normalisation; a white furnace; a strength of 0 keeping the bits; the
// highlight stretched along the direction, and turned with the rotation
// and with the direction map; reading the extension.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "gltf_quad_support.hpp"
#include "pbr_lane_support.hpp"
#include "render_check.hpp"
#include "shade/brdf.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

using V3 = lanes::Vec3<float>;

glm::dvec3 as_double(const V3& v) {
    return {v[0], v[1], v[2]};
}

V3 unit(double x, double y, double z) {
    const double length = std::sqrt(x * x + y * y + z * z);
    return {static_cast<float>(x / length), static_cast<float>(y / length),
            static_cast<float>(z / length)};
}

// Burley 2012's anisotropic GGX (Appendix B.2, eq. 13) and the
// height-correlated Smith term with its anisotropic Lambda (Heitz 2014,
// eq. 99), divided by 4 (n.l)(n.v): D G2 / (4 n.l n.v), in the frame
// t = +X, b = +Y, n = +Z.
double burley_heitz_lobe(const glm::dvec3& l, const glm::dvec3& v, double at, double ab) {
    const glm::dvec3 h = glm::normalize(l + v);
    const double e = (h.x / at) * (h.x / at) + (h.y / ab) * (h.y / ab) + h.z * h.z;
    const double d = 1.0 / (kPi * at * ab * e * e);
    const auto lambda = [&](const glm::dvec3& w) {
        const double a2_tan2 = ((at * w.x) * (at * w.x) + (ab * w.y) * (ab * w.y)) / (w.z * w.z);
        return 0.5 * (std::sqrt(1.0 + a2_tan2) - 1.0);
    };
    const double g2 = 1.0 / (1.0 + lambda(l) + lambda(v));
    return d * g2 / (4.0 * l.z * v.z);
}

// A surface facing +Z with the anisotropy along `direction`.
pbr::SurfaceTerms<float> brushed(float roughness, float strength, const V3& direction,
                                 float metallic = 1.0f) {
    pbr::SurfaceTerms<float> t =
        pbr::surface_terms({glm::vec3(1.0f), metallic, roughness, pbr::kDefaultIor});
    t.anisotropy = strength;
    t.anisotropy_direction = direction;
    return t;
}

pbr::PbrPoint<float> point_of(const pbr::SurfaceTerms<float>& t, const V3& v,
                              pbr::MultipleScattering scattering) {
    return pbr::prepare_point<float>({0.0f, 0.0f, 1.0f}, v, t, scattering, pbr::dfg_table());
}

}  // namespace

TEST_CASE("anisotropy: the lobe is Burley's anisotropic GGX with Heitz's correlated Smith term",
          "[shade][anisotropy]") {
    // A white metal without compensation reflects F = 1 times the lobe.
    for (const float roughness : {0.3f, 0.6f})
        for (const float strength : {0.4f, 1.0f}) {
            const pbr::PbrPoint<float> p =
                point_of(brushed(roughness, strength, {1.0f, 0.0f, 0.0f}), unit(0.3, -0.2, 0.9),
                         pbr::MultipleScattering::ignored);
            const double alpha = double(roughness) * roughness;
            const double at = alpha + (1.0 - alpha) * strength * strength;
            for (const V3& l : {unit(-0.4, 0.1, 0.8), unit(0.5, 0.5, 0.5), unit(0.0, -0.7, 0.3)}) {
                const double expected = burley_heitz_lobe(as_double(l), as_double(p.v), at, alpha);
                const V3 got = pbr::brdf_cosine(p, l);
                INFO("roughness " << roughness << ", strength " << strength);
                CHECK(got[0] / l[2] == Approx(expected).epsilon(1e-4));
            }
        }
}

TEST_CASE("anisotropy: the stretched distribution's D(h)(n.h) integrates to 1",
          "[shade][anisotropy]") {
    // Over the hemisphere of h by the midpoint rule in (theta, phi), D as
    // Burley writes it.
    constexpr int kTheta = 2000, kPhi = 400;
    for (const auto& [at, ab] : {std::pair{0.5, 0.1}, std::pair{1.0, 0.3}}) {
        double sum = 0.0;
        for (int i = 0; i < kTheta; ++i) {
            const double theta = 0.5 * kPi * (i + 0.5) / kTheta;
            for (int j = 0; j < kPhi; ++j) {
                const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
                const glm::dvec3 h(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                   std::cos(theta));
                const double e = (h.x / at) * (h.x / at) + (h.y / ab) * (h.y / ab) + h.z * h.z;
                sum += h.z * std::sin(theta) / (kPi * at * ab * e * e);
            }
        }
        CHECK(sum * (0.5 * kPi / kTheta) * (2.0 * kPi / kPhi) == Approx(1.0).epsilon(2e-3));
    }
}

TEST_CASE("anisotropy: white furnace: a brushed white metal never reflects more than it receives",
          "[shade][anisotropy]") {
    constexpr int kTheta = 256, kPhi = 256;
    for (const float roughness : {0.2f, 0.5f, 0.9f})
        for (const float strength : {0.5f, 1.0f})
            for (const double view : {0.0, 0.8, 1.3}) {
                const pbr::PbrPoint<float> p =
                    point_of(brushed(roughness, strength, {0.0f, 1.0f, 0.0f}),
                             unit(std::sin(view), 0.0, std::cos(view)),
                             pbr::MultipleScattering::compensated);
                double sum = 0.0;  // the integral of f (n.l) over the hemisphere
                for (int i = 0; i < kTheta; ++i) {
                    const double mu = (i + 0.5) / kTheta;  // n.l, uniform in cos
                    const double s = std::sqrt(1.0 - mu * mu);
                    for (int j = 0; j < kPhi; ++j) {
                        const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
                        sum +=
                            pbr::brdf_cosine(p, unit(s * std::cos(phi), s * std::sin(phi), mu))[0];
                    }
                }
                const double albedo = sum * (1.0 / kTheta) * (2.0 * kPi / kPhi);
                INFO("roughness " << roughness << ", strength " << strength << ", view " << view);
                CHECK(albedo <= 1.01);
                CHECK(albedo > 0.5);
            }
}

TEST_CASE("anisotropy: strength 0 keeps the bits, and a lane with it is the one-point result",
          "[shade][anisotropy]") {
    test::PointTerms points;
    test::PointViews views;
    test::varied_lanes(points, views, [](int i, pbr::SurfaceTerms<float>& t) {
        const float f = static_cast<float>(i);
        t.anisotropy = i % 2 ? 0.3f + 0.1f * f : 0.0f;
        // Any length and not yet in the plane: the point makes it so.
        t.anisotropy_direction = {std::cos(f), std::sin(f), 0.3f * f};
    });
    const auto without = [](pbr::SurfaceTerms<float> t) {
        t.anisotropy = 0.0f;
        return t;
    };
    test::check_layer_lanes(points, views, without, [](int i) { return i % 2 == 1; });
    // The environment's reflection normal: n itself without an anisotropy,
    // bent with one, and each lane its one-point value.
    lanes::Vec3<simd::vf> n8, v8;
    for (int i = 0; i < simd::kLanes; ++i)
        for (int a = 0; a < 3; ++a) n8[a][i] = a == 2 ? 1.0f : 0.0f, v8[a][i] = views[i][a];
    const auto compensated = pbr::MultipleScattering::compensated;
    const pbr::PbrPoint<simd::vf> p8 =
        pbr::prepare_point(n8, v8, test::lanes_of(points), compensated, pbr::dfg_table());
    for (int i = 0; i < simd::kLanes; ++i) {
        const pbr::PbrPoint<float> one = point_of(points[i], views[i], compensated);
        for (int a = 0; a < 3; ++a) CHECK(p8.reflection_normal[a][i] == one.reflection_normal[a]);
        if (i % 2 == 0) CHECK(one.reflection_normal == V3{0.0f, 0.0f, 1.0f});
    }
}

TEST_CASE("anisotropy: the highlight reaches further along the direction, and turns with it",
          "[shade][anisotropy]") {
    // The same tilt of h towards t and towards b: the lobe is wider along t.
    const V3 v = {0.0f, 0.0f, 1.0f};
    const auto response = [&](const V3& direction, const V3& l) {
        return pbr::brdf_cosine(
            point_of(brushed(0.3f, 0.8f, direction), v, pbr::MultipleScattering::ignored), l)[0];
    };
    const V3 towards_x = unit(0.5, 0.0, 1.0), towards_y = unit(0.0, 0.5, 1.0);
    const float along = response({1.0f, 0.0f, 0.0f}, towards_x);
    const float across = response({1.0f, 0.0f, 0.0f}, towards_y);
    CHECK(along > 3.0f * across);
    // Turned a quarter, the two swap.
    CHECK(response({0.0f, 1.0f, 0.0f}, towards_y) == Approx(along).epsilon(1e-5));
    CHECK(response({0.0f, 1.0f, 0.0f}, towards_x) == Approx(across).epsilon(1e-5));
}

namespace {

// The highlight's spread on the image: the second moments, about its
// centroid, of the pixels above half the brightest.
struct Spread {
    double xx = 0.0, yy = 0.0;
};

Spread highlight_spread(const FrameImages& images) {
    const auto& c = images.color;
    const auto green = [&](int x, int y) { return to_float(c.at(x, y)).g; };
    float peak = 0.0f;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) peak = std::max(peak, green(x, y));
    double w = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            if (!(green(x, y) > 0.5f * peak)) continue;
            w += 1.0, sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y;
        }
    REQUIRE(w > 4.0);
    return {sxx / w - (sx / w) * (sx / w), syy / w - (sy / w) * (sy / w)};
}

// A brushed metal sphere seen from +Z under a light from the camera.
FrameImages brushed_sphere(const std::string& keys) {
    TempDir dir("anisotropy-sphere");
    const std::string text = R"(output: { size: [96, 96], tonemap: none }
camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 35 }
style: pbr
environment: { color: [0, 0, 0] }
lights: [{ type: directional, direction: [0, 0, -1], intensity: 1 }]
objects:
  - name: ball
    primitive: { type: sphere, radius: 1, segments: 96, rings: 48 }
    material: { color: [0.9, 0.9, 0.9], metallic: 1, roughness: 0.35)" +
                             keys + " }\n";
    return render_yaml(dir.path(), text, 1, 2);
}

}  // namespace

TEST_CASE(
    "anisotropy: on a sphere the highlight stretches along the tangent, and the rotation "
    "turns it a quarter",
    "[render][anisotropy]") {
    // The sphere's tangent runs along +u, round its axis (+Y): horizontal
    // where the light falls.
    const Spread round = highlight_spread(brushed_sphere(""));
    const Spread along = highlight_spread(brushed_sphere(", anisotropy: 0.8"));
    const Spread turned =
        highlight_spread(brushed_sphere(", anisotropy: 0.8, anisotropy_rotation: 90"));
    INFO("round " << round.xx << " " << round.yy << ", along " << along.xx << " " << along.yy
                  << ", turned " << turned.xx << " " << turned.yy);
    CHECK(round.xx == Approx(round.yy).epsilon(0.2));
    CHECK(along.xx > 2.0 * along.yy);
    CHECK(turned.yy > 2.0 * turned.xx);
    // Strength 0 is the isotropic material, to the bit.
    const FrameImages zero = brushed_sphere(", anisotropy: 0, anisotropy_rotation: 30");
    const FrameImages none = brushed_sphere("");
    REQUIRE(zero.color.pixels.size() == none.color.pixels.size());
    CHECK(std::memcmp(zero.color.pixels.data(), none.color.pixels.data(),
                      sizeof(none.color.pixels[0]) * none.color.pixels.size()) == 0);
}

namespace {

// A glTF quad facing +Z whose anisotropy map is one texel of direction
// (rg) and strength 1, lit from just in front.
FrameImages brushed_quad(TempDir& dir, const std::string& name, uint8_t r, uint8_t g) {
    Gltf gltf;
    gltf.doc["images"] = {
        {{"uri", "data:image/png;base64," + base64(png_of(1, 1, 3, {r, g, 255}))}}};
    gltf.doc["textures"] = {{{"source", 0}}};
    const json brushed = {{"anisotropyStrength", 0.8}, {"anisotropyTexture", {{"index", 0}}}};
    quad_mesh(gltf, {{"pbrMetallicRoughness",
                      {{"baseColorFactor", {0.9, 0.9, 0.9, 1}},
                       {"metallicFactor", 1.0},
                       {"roughnessFactor", 0.3}}},
                     {"extensions", {{"KHR_materials_anisotropy", brushed}}}});
    gltf.doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
    const std::string mesh = gltf.write(dir.file(name + ".gltf"));
    const std::string text =
        "output: { size: [96, 96], tonemap: none }\nstyle: pbr\n"
        "environment: { color: [0, 0, 0] }\n"
        "lights: [{ type: point, position: [0, 0, 0.6], intensity: 1 }]\n"
        "camera: { position: [0, 0, 2], target: [0, 0, 0], fov: 53.130102354 }\n"
        "objects:\n  - name: quad\n    mesh: " +
        mesh + "\n";
    return render_yaml(dir.file(name), text, 1, 2);
}

}  // namespace

TEST_CASE("anisotropy: the direction map's RG turns the highlight, through the glTF file",
          "[render][anisotropy][gltf]") {
    TempDir dir("anisotropy-map");
    // RG (1, 0.5): +u, across the image; (0.5, 1): the bitangent, up it.
    const Spread across = highlight_spread(brushed_quad(dir, "u", 255, 128));
    const Spread up = highlight_spread(brushed_quad(dir, "v", 128, 255));
    INFO("across " << across.xx << " " << across.yy << ", up " << up.xx << " " << up.yy);
    CHECK(across.xx > 2.0 * across.yy);
    CHECK(up.yy > 2.0 * up.xx);
}

TEST_CASE("anisotropy: KHR_materials_anisotropy is read with its map as data", "[pbr][gltf]") {
    TempDir dir("anisotropy-read");
    Gltf g;
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}}};
    g.doc["textures"] = {{{"source", 0}}};
    const json brushed = {{"anisotropyStrength", 0.6},
                          {"anisotropyRotation", 1.25},
                          {"anisotropyTexture", {{"index", 0}}}};
    g.doc["materials"] = json::array({{{"extensions", {{"KHR_materials_anisotropy", brushed}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
    g.one_quad_scene();
    const Mesh mesh = load_gltf(g.write(dir.file("brushed.gltf")));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.anisotropy == Approx(0.6f));
    CHECK(m.anisotropy_cos == Approx(std::cos(1.25)).margin(1e-6));
    CHECK(m.anisotropy_sin == Approx(std::sin(1.25)).margin(1e-6));
    REQUIRE(m.anisotropy_map.texture);
    CHECK(m.anisotropy_map.texture->format() == Texture::Format::data8);
    CHECK((m.features() & kExtraLobes) != 0);
    CHECK(m.tangent_uv_set() == 0);
    // A map on another texture set than the normal map's, whose tangent
    // frames it would be read in, is dropped with a warning.
    json other_set = brushed;
    other_set["anisotropyTexture"] = {{"index", 0}, {"texCoord", 1}};
    g.doc["materials"] = json::array({{{"normalTexture", {{"index", 0}}},
                                       {"extensions", {{"KHR_materials_anisotropy", other_set}}}}});
    const Mesh dropped = load_gltf(g.write(dir.file("other-set.gltf")));
    INFO(all_warnings(dropped));
    CHECK_FALSE(dropped.materials[0].anisotropy_map);
    CHECK(dropped.materials[0].anisotropy == Approx(0.6f));
    CHECK(warns(dropped,
                "anisotropyTexture reads TEXCOORD_1 but the tangent frames follow the "
                "normal map's TEXCOORD_0: drawn along its anisotropyRotation alone"));
    // A strength above 1 is refused by its path.
    json bad = brushed;
    bad["anisotropyStrength"] = 1.5;
    g.doc["materials"] = json::array({{{"extensions", {{"KHR_materials_anisotropy", bad}}}}});
    const std::string path = g.write(dir.file("bad.gltf"));
    require_input_error([&] { load_gltf(path); }, "anisotropyStrength must be from 0 to 1");
}
