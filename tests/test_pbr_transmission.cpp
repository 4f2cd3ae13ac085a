// KHR_materials_transmission, _volume and _dispersion in the `pbr` model
// (render/transmission_stage.hpp, shade/transmission_backdrop.hpp,
// docs/pbr.md, "Transmission"): a slab against Beer-Lambert, a thin-walled
// pane against the specification's formula, panes seen through panes drawn
// back to front, a light from behind through the BTDF against the formula
// written out here, lighter shadows, the passes, the other styles, reading.
#include <catch2/catch.hpp>

#include <cmath>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "pbr_lane_support.hpp"
#include "render/transmission_stage.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"
#include "shade/brdf.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

// A scene lit by nothing: an unlit grey wall at z = -2 seen head-on from
// z = 3, and `glass` (objects' YAML) between. Only what passes through the
// glass reaches the camera; nothing is reflected.
std::string dark_room(const std::string& glass, const std::string& extra = "", int samples = 1) {
    return "output: { size: [160, 120], samples: " + std::to_string(samples) +
           R"(, tonemap: none, passes: [color, depth, object_id] }
camera: { position: [0, 0, 3], target: [0, 0, 0], fov: 30 }
style: pbr
environment: { color: [0, 0, 0] }
lights: []
)" + extra +
           R"(objects:
  - name: wall
    primitive: { type: plane, size: 20 }
    rotate: [90, 0, 0]
    translate: [0, 0, -2]
    material: { color: [0.5, 0.5, 0.5], unlit: true }
)" + glass;
}

// A pane facing the camera at depth z, of `material` (YAML keys; smooth
// unless they give a roughness).
std::string pane(const std::string& name, float z, const std::string& material,
                 const std::string& scale = "1") {
    const std::string smooth =
        material.find("roughness") == std::string::npos ? "roughness: 0, " : "";
    return "  - name: " + name +
           "\n    primitive: { type: plane, size: 2 }\n    rotate: [90, 0, 0]\n    scale: " +
           scale + "\n    translate: [0, 0, " + std::to_string(z) +
           "]\n    material: { metallic: 0, " + smooth + material + " }\n";
}

glm::vec3 centre(const FrameImages& images) {
    return glm::vec3(to_float(images.color.at(80, 60)));
}

glm::vec3 render_centre(const std::string& yaml) {
    TempDir dir("transmission");
    return centre(render_yaml(dir.path(), yaml, 1, 2));
}

// What a smooth dielectric of ior 1.5 passes at normal incidence: 1 - F0.
constexpr float kPassesSmooth = 0.96f;

// Vertical stripes, black and white, each `width` texels wide, in an RGB
// PNG `size` texels a side.
std::vector<uint8_t> stripes_png(int size, int width) {
    std::vector<uint8_t> samples;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) samples.insert(samples.end(), 3, (x / width) % 2 ? 255 : 0);
    return png_of(size, size, 3, samples);
}

bool world_warns(const World& world, const std::string& part) {
    for (const Warning& w : world.warnings)
        if (w.message.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("transmission: a slab's volume tints what it passes as Beer-Lambert says, at any scale",
          "[render][transmission]") {
    const glm::vec3 color(0.2f, 0.5f, 0.9f);
    const float distance = 0.5f;
    const std::string clear = "color: [1, 1, 1], transmission: 1";
    const std::string tint = "attenuation_color: [0.2, 0.5, 0.9], attenuation_distance: 0.5";
    const glm::vec3 open = render_centre(dark_room(pane("slab", 0, clear)));
    INFO("clear slab " << open.r << " " << open.g << " " << open.b);
    for (int c = 0; c < 3; ++c) CHECK(open[c] == Approx(0.5f * kPassesSmooth).epsilon(0.004));
    for (const float thickness : {0.25f, 0.6f}) {
        const std::string keys = clear + ", thickness: " + std::to_string(thickness) + ", " + tint;
        const glm::vec3 tinted = render_centre(dark_room(pane("slab", 0, keys)));
        // The same slab scaled up as a whole (as a turntable frames a model):
        // its thickness and its distance scale alike, so it looks the same.
        const glm::vec3 doubled = render_centre(dark_room(pane("slab", 0, keys, "2")));
        for (int c = 0; c < 3; ++c) {
            INFO("thickness " << thickness << ", channel " << c);
            // T = c^(d / D): the ratio to the clear slab, exactly the volume's.
            CHECK(tinted[c] / open[c] ==
                  Approx(std::pow(color[c], thickness / distance)).epsilon(0.004));
            CHECK(doubled[c] == Approx(tinted[c]).epsilon(0.002));
        }
    }
}

TEST_CASE("transmission: a thin-walled pane passes (1 - F) t times its colour",
          "[render][transmission]") {
    // thickness 0: thin-walled. Of the dielectric's base, t is the specular
    // BTDF tinted by the base colour, 1 - t the diffuse (dark here).
    for (const float t : {0.3f, 1.0f}) {
        const glm::vec3 got = render_centre(dark_room(
            pane("pane", 0, "color: [0.9, 0.5, 0.2], transmission: " + std::to_string(t))));
        const glm::vec3 base(0.9f, 0.5f, 0.2f);
        for (int c = 0; c < 3; ++c) {
            INFO("t " << t << ", channel " << c);
            CHECK(got[c] == Approx(0.5f * kPassesSmooth * t * base[c]).epsilon(0.005));
        }
    }
    // An opaque pane hides the wall.
    CHECK(render_centre(dark_room(pane("pane", 0, "color: [0.9, 0.5, 0.2]"))) == glm::vec3(0.0f));
}

TEST_CASE("transmission: panes seen through panes are drawn back to front, each passing its share",
          "[render][transmission]") {
    const std::string red = "color: [1, 0.3, 0.3], transmission: 1";
    const std::string blue = "color: [0.3, 0.4, 1], transmission: 0.8";
    const std::string green = "color: [0.5, 1, 0.5], transmission: 1";
    TempDir dir("transmission-layers");
    const FrameImages images = render_yaml(
        dir.path(),
        dark_room(pane("near", 1, red) + pane("middle", 0, blue) + pane("far", -1, green)), 1, 2);
    const glm::vec3 got = centre(images);
    const glm::vec3 expected = 0.5f * kPassesSmooth * glm::vec3(1, 0.3f, 0.3f) * kPassesSmooth *
                               0.8f * glm::vec3(0.3f, 0.4f, 1) * kPassesSmooth *
                               glm::vec3(0.5f, 1, 0.5f);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << ": " << got[c] << " against " << expected[c]);
        CHECK(got[c] == Approx(expected[c]).epsilon(0.01));
    }
    // The passes show the nearest surface: the near pane, at depth 2.
    CHECK(images.surface.object_id.at(80, 60) == 2);  // objects: wall 1, near 2
    CHECK(images.depth.at(80, 60) == Approx(2.0f).epsilon(1e-4));
    // With 4 samples a pixel, the same shares.
    const glm::vec3 sampled = centre(render_yaml(
        dir.path(),
        dark_room(pane("near", 1, red) + pane("middle", 0, blue) + pane("far", -1, green), "", 4),
        1, 2));
    for (int c = 0; c < 3; ++c) CHECK(sampled[c] == Approx(expected[c]).epsilon(0.01));
    // Eight threads (the frame is several tiles), the same bits.
    const FrameImages again = render_yaml(
        dir.path(),
        dark_room(pane("near", 1, red) + pane("middle", 0, blue) + pane("far", -1, green)), 1, 8);
    CHECK(std::equal(images.color.pixels.begin(), images.color.pixels.end(),
                     again.color.pixels.begin(), [](const Rgba16F& a, const Rgba16F& b) {
                         return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
                     }));
}

TEST_CASE("transmission: a rough pane blurs what lies behind, a smooth one keeps it sharp",
          "[render][transmission]") {
    // A wall of stripes one pixel wide, seen through the pane.
    const auto contrast = [](float roughness) {
        TempDir dir("transmission-blur");
        const std::string text =
            R"(output: { size: [64, 64], tonemap: none }
camera: { position: [0, 0, 3], target: [0, 0, 0], fov: 30 }
style: pbr
environment: { color: [0, 0, 0] }
lights: []
objects:
  - name: wall
    primitive: { type: plane, size: 2 }
    rotate: [90, 0, 0]
    translate: [0, 0, -0.001]
    material: { unlit: true, color: [1, 1, 1], texture: stripes.png }
)" + pane("pane", 0.2f,
          "color: [1, 1, 1], transmission: 1, roughness: " + std::to_string(roughness));
        write_bytes(dir.file("stripes.png"), stripes_png(64, 2));
        const FrameImages images = render_yaml(dir.path(), text, 1, 2);
        float low = 1e9f, high = 0.0f;
        for (int x = 20; x < 44; ++x) {
            const float g = to_float(images.color.at(x, 32)).g;
            low = std::min(low, g), high = std::max(high, g);
        }
        return high - low;
    };
    const float sharp = contrast(0.0f), blurred = contrast(0.6f);
    INFO("contrast smooth " << sharp << ", rough " << blurred);
    CHECK(sharp > 0.3f);
    CHECK(blurred < 0.25f * sharp);
}

TEST_CASE("transmission: a light behind the surface passes as the specular BTDF",
          "[shade][transmission]") {
    const lanes::Vec3<float> v = {0.0f, 0.0f, 1.0f};
    pbr::SurfaceTerms<float> t =
        pbr::surface_terms({glm::vec3(0.9f, 0.6f, 0.3f), 0.0f, 0.4f, pbr::kDefaultIor});
    t.transmission = 0.7f;
    const pbr::PbrPoint<float> p = pbr::prepare_point<float>(
        {0.0f, 0.0f, 1.0f}, v, t, pbr::MultipleScattering::compensated, pbr::dfg_table());
    const double length = std::sqrt(0.04 + 0.01 + 1.0);
    const lanes::Vec3<float> l = {static_cast<float>(0.2 / length),
                                  static_cast<float>(0.1 / length),
                                  static_cast<float>(-1.0 / length)};
    const lanes::Vec3<float> got = pbr::brdf_cosine(p, l);
    // (1 - F(v.h')) t base D V |n.l| in double: l mirrored to the front,
    // alpha from the roughness times clamp(2 ior - 2, 0, 1) = 1, GGX D,
    // height-correlated Smith V, Schlick F with f0 0.04.
    const glm::dvec3 lm(l[0], l[1], -l[2]), vv(0, 0, 1);
    const glm::dvec3 h = glm::normalize(lm + vv);
    const double alpha = 0.4 * 0.4, a2 = alpha * alpha;
    const double nh = h.z, nl = lm.z, nv = 1.0;
    const double d = a2 / (3.14159265358979 * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
    const double vis =
        0.5 / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
    const double f = 0.04 + 0.96 * std::pow(1.0 - glm::dot(vv, h), 5.0);
    const double base[3] = {0.9, 0.6, 0.3};
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        CHECK(got[c] == Approx((1.0 - f) * 0.7 * base[c] * d * vis * nl).epsilon(1e-4));
    }
    // Without the transmission, nothing comes through.
    t.transmission = 0.0f;
    const pbr::PbrPoint<float> opaque = pbr::prepare_point<float>(
        {0.0f, 0.0f, 1.0f}, v, t, pbr::MultipleScattering::compensated, pbr::dfg_table());
    CHECK(pbr::brdf_cosine(opaque, l) == lanes::Vec3<float>{0.0f, 0.0f, 0.0f});
}

TEST_CASE("transmission: 0 keeps the bits, and a lane with it is the one-point result",
          "[shade][transmission]") {
    test::PointTerms points;
    test::PointViews views;
    test::varied_lanes(points, views, [](int i, pbr::SurfaceTerms<float>& t) {
        const float f = static_cast<float>(i);
        t.transmission = i % 2 ? 0.3f + 0.1f * f : 0.0f;
        t.thickness = 0.1f * f;
        t.attenuation_color = {0.9f, 0.5f, 0.2f};
        t.attenuation_distance = 0.4f;
    });
    test::check_layer_lanes(
        points, views,
        [](pbr::SurfaceTerms<float> t) {
            t.transmission = 0.0f;
            return t;
        },
        // A metal (every third lane) has no diffuse to replace.
        [](int i) { return i % 2 == 1 && i % 3 != 0; });
}

TEST_CASE("transmission: glass casts a shadow lighter by what it lets through",
          "[render][transmission][shadows]") {
    // A sun straight down on a white floor; a pane out of the camera's view
    // above the floor's middle.
    const auto floor_ratio = [](const std::string& glass_keys) {
        TempDir dir("transmission-shadow");
        const std::string text = R"(output: { size: [64, 48], tonemap: none }
camera: { position: [0, 1, 4], target: [0, 0, 0], fov: 30 }
style: pbr
environment: { color: [0, 0, 0] }
lights: [{ type: directional, direction: [0, -1, 0], intensity: 1, shadows: true, shadow_softness: 0 }]
objects:
  - name: floor
    primitive: { type: plane, size: 8 }
    cast_shadows: false
    material: { color: [1, 1, 1], roughness: 1 }
  - name: pane
    primitive: { type: plane, size: 1 }
    translate: [0, 3, 0]
    material: { double_sided: true, roughness: 0, )" +
                                 glass_keys + " }\n";
        const FrameImages images = render_yaml(dir.path(), text, 1, 2);
        const float shadowed = pixel_at(images, images.color, {0.0f, 0.0f, 0.0f}).g;
        const float lit = pixel_at(images, images.color, {1.5f, 0.0f, 0.0f}).g;
        INFO("shadowed " << shadowed << ", lit " << lit);
        REQUIRE(lit > 0.1f);
        return shadowed / lit;
    };
    CHECK(floor_ratio("color: [0.5, 0.5, 0.5]") < 0.01f);
    Material glass;
    glass.color = {0.9f, 0.6f, 0.3f};
    glass.metallic = 0.0f;
    glass.transmission = 0.8f;
    const float pass = shadow_pass(glass);
    CHECK(pass == Approx(0.8f * 0.6f));
    CHECK(floor_ratio("color: [0.9, 0.6, 0.3], transmission: 0.8") == Approx(pass).epsilon(0.02));
}

TEST_CASE("transmission: only pbr draws glass, other styles draw it opaque and say so",
          "[render][transmission]") {
    const std::string glass = pane("pane", 0, "color: [1, 1, 1], transmission: 1");
    std::string phong = dark_room(glass, "");
    phong.replace(phong.find("style: pbr"), 10, "style: { shading: phong }");
    phong.replace(phong.find("lights: []"), 10,
                  "lights: [{ type: directional, direction: [0, 0, -1], intensity: 1 }]");
    TempDir dir("transmission-phong");
    const SceneDesc scene = load(write_text(dir.file("scene.yaml"), phong));
    const World world = build_world(scene);
    CHECK(world_warns(world, "glass that only `shading: pbr` draws"));
    const glm::vec3 got = centre(render_images(scene, 1, 2));
    CHECK(got.r > 0.5f);  // a lit white pane, not the grey wall behind
}

TEST_CASE("transmission: KHR_materials_transmission, _volume and _dispersion are read",
          "[pbr][gltf]") {
    TempDir dir("transmission-read");
    Gltf g;
    for (int i = 0; i < 2; ++i) {
        g.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}});
        g.doc["textures"].push_back({{"source", i}});
    }
    const json transmission = {{"transmissionFactor", 0.9},
                               {"transmissionTexture", {{"index", 0}}}};
    const json volume = {{"thicknessFactor", 0.4},
                         {"thicknessTexture", {{"index", 1}}},
                         {"attenuationDistance", 0.25},
                         {"attenuationColor", {0.8, 0.6, 0.4}}};
    const auto write = [&](const json& t, const json& v, const std::string& name) {
        g.doc["materials"] = json::array({{{"extensions",
                                            {{"KHR_materials_transmission", t},
                                             {"KHR_materials_volume", v},
                                             {"KHR_materials_dispersion", {{"dispersion", 2.0}}},
                                             {"KHR_materials_ior", {{"ior", 1.7}}}}}}});
        g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume",
                                   "KHR_materials_dispersion", "KHR_materials_ior"};
        g.one_quad_scene();
        return g.write(dir.file(name));
    };
    const Mesh mesh = load_gltf(write(transmission, volume, "glass.gltf"));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.transmission == Approx(0.9f));
    CHECK(m.thickness == Approx(0.4f));
    CHECK(m.attenuation_distance == Approx(0.25f));
    CHECK(m.attenuation_color == glm::vec3(0.8f, 0.6f, 0.4f));
    CHECK(m.dispersion == Approx(2.0f));
    CHECK(m.ior == Approx(1.7f));
    REQUIRE(m.transmission_map.texture);
    CHECK(m.transmission_map.texture->format() == Texture::Format::data8);
    REQUIRE(m.thickness_map.texture);
    CHECK((m.features() & kExtraLobes) != 0);
    // Double-sided with a volume: drawn, with a warning that the tint is
    // applied at both faces.
    g.doc["materials"][0]["doubleSided"] = true;
    const Mesh both = load_gltf(g.write(dir.file("both.gltf")));
    CHECK(warns(both, "double-sided glass with a volume"));
    // Without a volume: thin-walled, untinted, the distance infinite.
    const Mesh thin = load_gltf(write(transmission, json::object(), "thin.gltf"));
    CHECK(thin.materials[0].thickness == 0.0f);
    CHECK(std::isinf(thin.materials[0].attenuation_distance));
    json bad = volume;
    bad["attenuationDistance"] = 0;
    const std::string zero = write(transmission, bad, "zero.gltf");
    require_input_error([&] { load_gltf(zero); }, "attenuationDistance must be from");
    bad = volume;
    bad["attenuationColor"] = "blue";
    const std::string typed = write(transmission, bad, "typed.gltf");
    require_input_error([&] { load_gltf(typed); }, "attenuationColor");
    json over = transmission;
    over["transmissionFactor"] = 1.5;
    const std::string high = write(over, volume, "high.gltf");
    require_input_error([&] { load_gltf(high); }, "transmissionFactor must be from 0 to 1");
}

TEST_CASE("transmission: a volume placed by a scaled node has its thickness scaled",
          "[pbr][gltf]") {
    TempDir dir("transmission-node-scale");
    Gltf g;
    g.doc["materials"] = json::array(
        {{{"extensions",
           {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
            {"KHR_materials_volume", {{"thicknessFactor", 0.4}, {"attenuationDistance", 1.0}}}}}}});
    // A variant draws the part in a second glass.
    g.doc["materials"].push_back(g.doc["materials"][0]);
    g.doc["materials"][1]["extensions"]["KHR_materials_volume"]["thicknessFactor"] = 0.1;
    g.doc["extensions"]["KHR_materials_variants"]["variants"] = {{{"name", "thin"}}};
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume",
                               "KHR_materials_variants"};
    g.one_quad_scene();
    g.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] = {
        {{"material", 1}, {"variants", {0}}}};
    const int mesh = g.doc["nodes"][0]["mesh"];
    const int scaled = g.node({{"mesh", mesh}, {"scale", {2.0, 2.0, 2.0}}});
    const int again = g.node({{"mesh", mesh}, {"scale", {2.0, 2.0, 2.0}}});
    g.scene({0, scaled, again});
    const Mesh m = load_gltf(g.write(dir.file("scaled.gltf")));
    REQUIRE(m.parts.size() == 3);
    const Material& plain = m.materials[m.parts[0].material];
    const Material& doubled = m.materials[m.parts[1].material];
    CHECK(plain.thickness == Approx(0.4f));
    CHECK(doubled.thickness == Approx(0.8f));
    CHECK(doubled.attenuation_distance == Approx(1.0f));  // the file's world units already
    CHECK(m.parts[2].material == m.parts[1].material);    // one copy per scale
    // The variant's glass is scaled alike.
    REQUIRE(m.parts[1].variant_materials.size() == 1);
    CHECK(m.materials[m.parts[0].variant_materials[0]].thickness == Approx(0.1f));
    CHECK(m.materials[m.parts[1].variant_materials[0]].thickness == Approx(0.2f));
}
