// Every shipped preset on a model as a user brings one (docs/styles.md,
// "PBR materials under every preset"): a glTF made here, three balls of
// metallic-roughness materials (a light metal, a light dielectric, a dark
// dielectric), on the turntable `facet scene` writes for it, with its
// shadow-catcher ground. Checked under each preset: no line along the
// catcher, no black shadow on it, metal darker than the dielectric under
// the Phong family, and the hatching presets' tones spread over the dark
// ball; and the contact sheet of them all against a reviewed reference.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "asset_support.hpp"
#include "core/color.hpp"
#include "core/half.hpp"
#include "render/style_eval.hpp"
#include "render_check.hpp"
#include "scene/scene_desc.hpp"
#include "shade/layers.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

enum Part : uint32_t { kMetal = 1, kLight = 2, kDark = 3 };  // material ids (index + 1)

// A ball of radius 0.5 at `centre` as one glTF primitive of `material`.
nlohmann::json ball(facet::test::Gltf& g, glm::vec3 centre, int material) {
    constexpr int kRings = 24, kSegments = 48;
    std::vector<float> positions, normals;
    std::vector<uint16_t> indices;
    for (int r = 0; r <= kRings; ++r)
        for (int s = 0; s <= kSegments; ++s) {
            const double theta = 3.14159265358979 * r / kRings;
            const double phi = 2 * 3.14159265358979 * s / kSegments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            const glm::vec3 p = centre + 0.5f * n;
            positions.insert(positions.end(), {p.x, p.y, p.z});
            normals.insert(normals.end(), {n.x, n.y, n.z});
        }
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            const uint16_t a = static_cast<uint16_t>(r * (kSegments + 1) + s),
                           b = static_cast<uint16_t>(a + kSegments + 1);
            indices.insert(indices.end(),
                           {a, b, static_cast<uint16_t>(a + 1), static_cast<uint16_t>(a + 1), b,
                            static_cast<uint16_t>(b + 1)});
        }
    return {{"attributes",
             {{"POSITION", g.floats(positions, "VEC3")}, {"NORMAL", g.floats(normals, "VEC3")}}},
            {"indices", g.indices(indices, facet::test::kUShort)},
            {"material", material}};
}

nlohmann::json material(const std::string& name, glm::vec3 colour, double metallic,
                        double roughness) {
    return {{"name", name},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {colour.x, colour.y, colour.z, 1.0}},
              {"metallicFactor", metallic},
              {"roughnessFactor", roughness}}}};
}

// The model, and its turntable scene (`facet scene`), with or without the ground.
struct Model {
    facet::test::TempDir dir{"presets-on-model"};
    std::string scene, bare_scene;
    Model() {
        facet::test::Gltf g;
        g.doc["materials"] = {material("metal", {0.95f, 0.78f, 0.45f}, 1.0, 0.3),
                              material("light", {0.8f, 0.8f, 0.78f}, 0.0, 0.45),
                              material("dark", {0.03f, 0.03f, 0.035f}, 0.0, 0.35)};
        g.doc["meshes"].push_back({{"primitives",
                                    {ball(g, {-1.1f, 0.5f, 0}, 0), ball(g, {0, 0.5f, 0}, 1),
                                     ball(g, {1.1f, 0.5f, 0}, 2)}}});
        g.scene({g.node({{"mesh", 0}})});
        const std::string model = g.write(dir.file("balls.gltf"));
        scene = dir.file("balls.yaml");
        bare_scene = dir.file("bare.yaml");
        REQUIRE(facet::test::run_facet("scene '" + model + "' -q -o '" + scene + "'").exit_code ==
                0);
        REQUIRE(
            facet::test::run_facet("scene '" + model + "' -q --ground none -o '" + bare_scene + "'")
                .exit_code == 0);
    }
};

facet::SceneDesc load(const std::string& path, const std::string& preset,
                      const std::string& style_override = {}) {
    facet::SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    options.overrides = {
        {"style", style_override.empty() ? preset : style_override, "test --style"},
        {"output.size", "[192, 108]", "test"},
        {"output.samples", "1", "test"},
        {"output.passes", "[color, material_id, object_id]", "test"},
        {"output.formats", "[png, exr]", "test"}};
    return facet::load_scene(path, options);
}

std::vector<std::string> presets() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(facet::test::styles_dir()))
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

float luminance(const facet::FrameImages& images, size_t i) {
    const glm::vec4 c = facet::to_float(images.color.pixels[i]);
    return facet::rec709_luminance(c.r, c.g, c.b);
}

// The median luminance of the pixels showing material id `part` (its
// highlight, a few pixels far brighter than the rest, left out).
float median_of(const facet::FrameImages& images, uint32_t part) {
    std::vector<float> values;
    for (size_t i = 0; i < images.color.pixels.size(); ++i)
        if (images.surface.material_id.pixels[i] == part) values.push_back(luminance(images, i));
    REQUIRE(values.size() > 200);
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

bool phong_family(const std::string& preset) {
    for (const char* name : {"phong", "blinn-phong", "flat", "gouraud", "lit", "lit-shadows"})
        if (preset == name) return true;
    return false;
}

}  // namespace

TEST_CASE("every preset on a glTF model's turntable: no catcher line, grey shadows, metal as metal",
          "[render][styles][shadow_catcher][metal_rough_phong]") {
    const Model model;
    const std::vector<std::string> names = presets();
    REQUIRE(names.size() >= 20);
    for (const std::string& name : names) {
        INFO("preset " << name);
        const facet::FrameImages with = facet::test::render_images(load(model.scene, name));
        const facet::FrameImages bare = facet::test::render_images(load(model.bare_scene, name));
        const size_t pixels = with.color.pixels.size();
        // Rows above the model: the catcher may change nothing there.
        const int width = with.color.width;
        int top = with.color.height;
        for (size_t i = 0; i < pixels; ++i)
            if (bare.surface.object_id.pixels[i] != 0) top = std::min(top, int(i / width));
        REQUIRE(top > 10);
        float largest = 0;
        for (size_t i = 0; i < size_t(top - 2) * width; ++i)
            largest = std::max(largest, std::abs(luminance(with, i) - luminance(bare, i)));
        CHECK(largest < 0.02f);
        // Where the ground is, it darkens what is behind it by the light
        // blocked, never to black.
        float darkest = 1;
        for (size_t i = 0; i < pixels; ++i) {
            if (bare.surface.object_id.pixels[i] != 0 || with.surface.object_id.pixels[i] != 2)
                continue;
            const float behind = luminance(bare, i);
            if (behind > 0.01f) darkest = std::min(darkest, luminance(with, i) / behind);
        }
        CHECK(darkest > 0.05f);
        if (phong_family(name)) CHECK(median_of(with, kMetal) < 0.5f * median_of(with, kLight));
    }
}

TEST_CASE("hatching and pencil on a glTF model: the dark ball's tones span the maps, densest there",
          "[render][styles][hatching]") {
    const Model model;
    for (const std::string name : {"hatching", "pencil"}) {
        INFO("preset " << name);
        // The preset's style as its strokes see it, and the shading under
        // its strokes: the same preset with the strokes and lines off.
        const facet::SceneDesc scene = load(model.scene, name);
        facet::TamCache tams;
        const facet::StyleState style =
            facet::evaluate_style(scene.style, facet::FrameTime{1, 0}, tams);
        REQUIRE(style.hatching);
        const std::string shading = "{ extends: " + name + ", hatching: false, outlines: false }";
        const facet::FrameImages lit = facet::test::render_images(load(model.scene, name, shading));
        float lowest[4] = {1, 1, 1, 1}, highest[4] = {0, 0, 0, 0};
        double sum[4] = {0, 0, 0, 0};
        size_t count[4] = {0, 0, 0, 0};
        for (size_t i = 0; i < lit.color.pixels.size(); ++i) {
            const uint32_t part = lit.surface.material_id.pixels[i];
            if (part < kMetal || part > kDark) continue;
            const glm::vec4 c = facet::to_float(lit.color.pixels[i]);
            const float tone = facet::hatch_tone(style, glm::vec3(c), -1.0f);
            lowest[part] = std::min(lowest[part], tone);
            highest[part] = std::max(highest[part], tone);
            sum[part] += tone, ++count[part];
        }
        REQUIRE(count[kDark] > 200);
        REQUIRE(count[kLight] > 200);
        INFO("dark ball's tones " << lowest[kDark] << " to " << highest[kDark]);
        CHECK(lowest[kDark] <= 0.1f);
        CHECK(highest[kDark] >= 0.9f);
        CHECK(sum[kDark] / count[kDark] < sum[kLight] / count[kLight] - 0.25);
    }
}

TEST_CASE("every preset on a glTF model's turntable matches the reviewed contact sheet",
          "[render][styles][sheet]") {
    const Model model;
    const std::string sheet = model.dir.file("sheet.png");
    REQUIRE(facet::test::run_facet("sheet '" + model.scene +
                                   "' --styles all --size 160x90 -q -o '" + sheet + "' --threads 2")
                .exit_code == 0);
    const std::string bytes = facet::test::read_file(sheet);
    facet::test::check_against_baseline(std::vector<uint8_t>(bytes.begin(), bytes.end()),
                                        "presets-on-model-sheet.png");
}
