// The plain shading path (render/shade_batch.cpp): batches whose draws have
// no feature their style draws (MaterialFeature), under a Phong,
// Blinn-Phong or unlit style without layers, take the surface path
// compiled without the features' steps. It must write the same bits as the
// general instantiation for every combination of features, and be taken
// exactly when the batch's drawn features are none.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "asset_support.hpp"
#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using facet::ShadingPaths;

namespace {

// The scene: a sphere, a cube and a two-sided plane seen partly from
// behind, lit by a shadow-casting sun, a point light with a range and a
// spot light, over a coloured background. `style` and `output` are added
// into the YAML; `extra_object` is appended to the objects.
std::string scene_text(const std::string& style, const std::string& output,
                       const std::string& extra_object = "") {
    return "output: { size: [160, 120], background: [0.2, 0.3, 0.5, 1]" + output +
           " }\n"
           "camera: { position: [0.5, 2.5, 5], target: [0, 0.3, 0], fov: 45 }\n"
           "style: " +
           style +
           "\n"
           "lights:\n"
           "  - { type: directional, direction: [-0.5, -1, -0.3], intensity: 0.8, shadows: true }\n"
           "  - { type: point, position: [2, 2, 2], intensity: 6, range: 8 }\n"
           "  - { type: spot, position: [-2, 3, 1], direction: [2, -3, -1], intensity: 8, "
           "outer_angle: "
           "30 }\n"
           "objects:\n"
           "  - name: floor\n"
           "    primitive: { type: plane, size: 6 }\n"
           "    material: { color: [0.8, 0.8, 0.75], ambient: 0.2 }\n"
           "  - name: ball\n"
           "    primitive: { type: sphere, radius: 0.7 }\n"
           "    translate: [-0.5, 0.7, 0]\n"
           "    material: { color: [0.7, 0.25, 0.2], specular: 0.5, shininess: 48 }\n"
           "  - name: box\n"
           "    primitive: { type: cube, size: 0.8 }\n"
           "    translate: [1, 0.4, -0.3]\n"
           "    rotate: [0, 30, 0]\n"
           "    material: { color: [0.2, 0.5, 0.8], ambient: 0.1, specular: 0.2 }\n"
           "  - name: card\n"
           "    primitive: { type: plane, size: 1.2 }\n"
           "    translate: [0.2, 1.2, -1]\n"
           "    rotate: [-70, 20, 0]\n"
           "    material: { color: [0.3, 0.7, 0.3], double_sided: true }\n" +
           extra_object;
}

template <typename Image>
bool same_bytes(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
        return false;
    // An image not asked for is empty, its data null: memcmp must not see it.
    return a.pixels.empty() || std::memcmp(a.pixels.data(), b.pixels.data(),
                                           a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

// A 4 x 4 checker texture, checker.png, in `folder`.
void write_checker(const std::string& folder) {
    facet::ColorImage image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            image.at(x, y) =
                (x + y) % 2 ? glm::vec4(0.9f, 0.8f, 0.2f, 1) : glm::vec4(0.1f, 0.2f, 0.7f, 1);
    facet::write_file_atomically(folder + "/checker.png", facet::encode_png_color(image, 1));
}

// A normal map with relief, normal.png, in `folder`.
void write_normal_map(const std::string& folder) {
    facet::ColorImage image(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            image.at(x, y) = glm::vec4(0.5f + 0.3f * std::sin(x * 1.3f),
                                       0.5f + 0.3f * std::cos(y * 0.9f), 0.9f, 1.0f);
    facet::write_file_atomically(folder + "/normal.png", facet::encode_png_color(image, 1));
}

// Renders the scene both ways and requires every pass to be byte-identical.
void require_same_bits(const std::string& yaml) {
    facet::test::TempDir dir("shade-plain");
    write_checker(dir.path());
    write_normal_map(dir.path());
    const facet::FrameImages plain =
        facet::test::render_yaml(dir.path(), yaml, 1, 2, ShadingPaths::specialised);
    const facet::FrameImages general =
        facet::test::render_yaml(dir.path(), yaml, 1, 2, ShadingPaths::general_only);
    CHECK(same_bytes(plain.color, general.color));
    CHECK(same_bytes(plain.depth, general.depth));
    CHECK(same_bytes(plain.alpha, general.alpha));
}

}  // namespace

TEST_CASE("plain batches write the same bits as the general path", "[render][shade_plain]") {
    const std::string one = "", four = ", samples: 4";
    const std::string glowing =
        "  - name: lamp\n"
        "    primitive: { type: sphere, radius: 0.3 }\n"
        "    translate: [0, 0.3, 1.2]\n"
        "    material: { color: [0.9, 0.9, 0.2], emissive: [0.4, 0.3, 0] }\n";
    const std::string textured =
        "  - name: crate\n"
        "    primitive: { type: cube, size: 0.5 }\n"
        "    translate: [-1.6, 0.25, 0.8]\n"
        "    material: { texture: checker.png }\n";
    struct Case {
        const char* name;
        std::string style, output, extra_object;
    };
    const Case cases[] = {
        {"phong, one sample a pixel", "phong", one, ""},
        {"phong, four samples", "phong", four, ""},
        {"blinn-phong with the alpha pass", "blinn-phong", four + ", passes: [color, depth, alpha]",
         ""},
        {"unlit", "unlit", four, ""},
        {"a style's base colour", "clay", four, ""},
        {"occlusion's G-buffer, lit", "{ extends: blinn-phong, occlusion: { radius: 0.4 } }", four,
         ""},
        {"occlusion's G-buffer, unlit", "{ extends: unlit, occlusion: { radius: 0.4 } }", one, ""},
        {"outlines: shading at the samples", "{ extends: phong, outlines: true }", four, ""},
        {"the lines pass: the general path throughout", "phong",
         four + ", passes: [color, lines], formats: [exr]", ""},
        {"plain and general materials side by side", "phong", four, glowing + textured},
        {"unlit ignores emission: plain throughout", "unlit", four, glowing},
        {"a style's colour over a texture: plain", "clay", four, textured},
    };
    for (const Case& c : cases) DYNAMIC_SECTION(c.name) {
            require_same_bits(scene_text(c.style, c.output, c.extra_object));
        }
}

namespace {

// A 4 x 4 grid of quads (a gentle dome, so light varies across it), one
// unit wide, facing +Z, with texture coordinates, and vertex colours when
// `colored`: the mesh of each generated object.
std::string write_dome(const facet::test::TempDir& dir, bool colored) {
    facet::test::Gltf g;
    std::vector<float> positions, normals, uvs, colors;
    for (int y = 0; y <= 4; ++y)
        for (int x = 0; x <= 4; ++x) {
            const float u = x / 4.0f, v = y / 4.0f;
            const float px = u - 0.5f, py = v - 0.5f;
            const glm::vec3 n = glm::normalize(glm::vec3(px, py, 1.5f));
            positions.insert(positions.end(), {px, py, 0.3f - 0.4f * (px * px + py * py)});
            normals.insert(normals.end(), {n.x, n.y, n.z});
            uvs.insert(uvs.end(), {u, v});
            colors.insert(colors.end(), {0.3f + 0.7f * u, 0.9f - 0.5f * v, 0.5f});
        }
    std::vector<uint16_t> indices;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const uint16_t a = static_cast<uint16_t>(y * 5 + x), b = a + 1, c = a + 5, d = a + 6;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    nlohmann::json attributes = {{"POSITION", g.floats(positions, "VEC3")},
                                 {"NORMAL", g.floats(normals, "VEC3")},
                                 {"TEXCOORD_0", g.floats(uvs, "VEC2")}};
    if (colored) attributes["COLOR_0"] = g.floats(colors, "VEC3");
    g.one_node_scene({{"attributes", attributes}, {"indices", g.indices(indices, 5123)}});
    return g.write(dir.file(colored ? "dome_colored.gltf" : "dome.gltf"));
}

// The scene material (YAML) that gives a dome the features `bits`
// (MaterialFeature); vertex colours come from the mesh.
std::string material_with(uint32_t bits) {
    std::string m = "{ color: [0.7, 0.6, 0.5], clearcoat: 0.5";
    // Metal and roughness make a metal-rough material; Phong terms a Phong one.
    m += (bits & facet::kMetalRough) ? ", metallic: 0.3, roughness: 0.4"
                                     : ", specular: 0.4, shininess: 32";
    if (bits & facet::kBaseColorMap) m += ", texture: checker.png";
    if (bits & facet::kPhysicalMaps) m += ", metal_rough_map: checker.png";
    if (bits & facet::kNormalMaps) m += ", normal_map: normal.png";
    if (bits & facet::kEmission) m += ", emissive: [0.3, 0.1, 0]";
    if (bits & facet::kShadowCatcher) m += ", shadow_catcher: true";
    if (bits & facet::kFade) m += ", fade: [0.2, 0.6]";
    if (bits & facet::kExtraLobes) m += ", sheen_color: [0.6, 0.3, 0.2], iridescence: 0.7";
    return m + " }";
}

// One dome per feature set in `sets`, in rows of 16 over a floor, lit by
// a shadow-casting sun, a point light and an ambient light.
std::string feature_scene(const facet::test::TempDir& dir, const std::vector<uint32_t>& sets,
                          const std::string& style, const std::string& output, bool floor = true) {
    const std::string plain = write_dome(dir, false), colored = write_dome(dir, true);
    std::string text = "output: { size: [320, 200], background: [0.2, 0.3, 0.5, 1]" + output +
                       " }\n"
                       "camera: { position: [0, 3, 12], target: [0, 0.2, 0], fov: 55 }\n"
                       "style: " +
                       style +
                       "\n"
                       "lights:\n"
                       "  - { type: directional, direction: [-0.3, -1, -0.5], intensity: 0.8, "
                       "shadows: true }\n"
                       "  - { type: point, position: [2, 3, 3], intensity: 10, range: 12 }\n"
                       "  - { type: ambient, intensity: 0.2 }\n"
                       "objects:\n";
    if (floor)
        text +=
            "  - { name: floor, primitive: { type: plane, size: 20 }, translate: [0, -1.5, 0] }\n";
    for (size_t i = 0; i < sets.size(); ++i) {
        const float x = -7.5f + static_cast<float>(i % 16), y = 2.5f - static_cast<float>(i / 16);
        text += "  - { mesh: " + ((sets[i] & facet::kVertexColors) ? colored : plain) +
                ", translate: [" + std::to_string(x) + ", " + std::to_string(y) +
                ", 0], rotate: [-15, 10, 0], material: " + material_with(sets[i]) + " }\n";
    }
    return text;
}

// Every feature set, in scenes of at most 128 (eight rows of domes).
std::vector<std::vector<uint32_t>> every_feature_set() {
    std::vector<std::vector<uint32_t>> scenes(1);
    for (uint32_t bits = 0; bits < (1u << facet::kMaterialFeatureCount); ++bits) {
        if (scenes.back().size() == 128) scenes.emplace_back();
        scenes.back().push_back(bits);
    }
    return scenes;
}

}  // namespace

TEST_CASE("every combination of features gives the same bits on the plain and general paths",
          "[render][shade_plain]") {
    // Each of the 512 feature sets on its own object, under each model, at
    // one and four samples, with the G-buffer and the lines pass: batches
    // with no feature under a plain style take the plain path, the others
    // the general one, and shading everything the general way must change
    // no bit.
    facet::test::TempDir dir("shade-plain-features");
    write_checker(dir.path());
    write_normal_map(dir.path());
    const std::vector<std::vector<uint32_t>> scenes = every_feature_set();
    const std::string four = ", samples: 4";
    const std::pair<const char*, const char*> cases[] = {
        {"phong", ""},
        {"blinn-phong", four.c_str()},
        {"unlit", four.c_str()},
        {"clay", ""},
        {"pbr", four.c_str()},
        {"gouraud", ""},
        {"flat", ""},
        {"toon", ""},
        {"{ extends: phong, outlines: true }", ", samples: 4, passes: [color, depth, alpha]"},
        {"{ extends: blinn-phong, occlusion: { radius: 0.4 } }", ""},
        {"phong", ", samples: 4, passes: [color, lines], formats: [exr]"},
        {"hatching", ""},
    };
    for (const auto& [style, output] : cases) DYNAMIC_SECTION(style << output) {
            for (const std::vector<uint32_t>& sets : scenes)
                require_same_bits(feature_scene(dir, sets, style, output));
        }
}

TEST_CASE("the plain path shades the batches it can take, and only with the specialised paths",
          "[render][shade_plain]") {
    facet::test::TempDir dir("shade-plain-counts");
    write_checker(dir.path());
    auto counts = [&](const std::string& style, const std::string& extra, ShadingPaths paths) {
        const std::string path =
            facet::test::write_text(dir.file("scene.yaml"), scene_text(style, "", extra));
        const facet::SceneDesc scene = facet::test::load(path);
        const facet::World world = facet::build_world(scene);
        facet::ThreadPool pool(2);
        facet::FrameRenderer renderer(scene, world, pool, paths);
        facet::FrameImages images;
        renderer.render(1, 0, images);
        return renderer.shading_counts();
    };
    // Every object plain, so every batch, those with several meshes'
    // pixels too.
    const facet::ShadeCounts phong = counts("phong", "", ShadingPaths::specialised);
    CHECK(phong.batches > 1000);
    CHECK(phong.plain == phong.batches);
    CHECK(counts("unlit", "", ShadingPaths::specialised).plain > phong.batches * 9 / 10);
    // The same frame on the general path alone, and a model the plain path
    // does not take.
    const facet::ShadeCounts general = counts("phong", "", ShadingPaths::general_only);
    CHECK(general.batches == phong.batches);
    CHECK(general.plain == 0);
    CHECK(counts("gooch", "", ShadingPaths::specialised).plain == 0);
    // A textured object's batches go the general way.
    const std::string textured =
        "  - name: crate\n"
        "    primitive: { type: cube, size: 1.5 }\n"
        "    translate: [0, 0.75, 1.2]\n"
        "    material: { texture: checker.png }\n";
    const facet::ShadeCounts mixed = counts("phong", textured, ShadingPaths::specialised);
    CHECK(mixed.plain < phong.plain);
    CHECK(mixed.plain > 0);
}

TEST_CASE("a batch takes the plain path when its style draws none of its features",
          "[render][shade_plain]") {
    facet::test::TempDir dir("shade-plain-choice");
    write_checker(dir.path());
    write_normal_map(dir.path());
    auto counts = [&](uint32_t feature, const std::string& style) {
        const std::vector<uint32_t> sets(16, feature);
        const std::string path = facet::test::write_text(
            dir.file("scene.yaml"), feature_scene(dir, sets, style, "", false));
        const facet::SceneDesc scene = facet::test::load(path);
        const facet::World world = facet::build_world(scene);
        facet::ThreadPool pool(2);
        facet::FrameRenderer renderer(scene, world, pool, ShadingPaths::specialised);
        facet::FrameImages images;
        renderer.render(1, 0, images);
        return renderer.shading_counts();
    };
    // Which models draw which feature (docs/architecture.md): a style's own
    // colour replaces the maps and vertex colours, only pbr reads its maps,
    // unlit adds no emission; catchers and fades are drawn by every model.
    struct Expectation {
        uint32_t feature;
        bool phong, clay, unlit;  // whether the style draws it
    };
    const Expectation expectations[] = {
        {facet::kBaseColorMap, true, false, true},
        {facet::kVertexColors, true, false, true},
        {facet::kPhysicalMaps, false, false, false},
        {facet::kNormalMaps, false, false, false},
        {facet::kEmission, true, true, false},
        {facet::kShadowCatcher, true, true, true},
        {facet::kFade, true, true, true},
        {facet::kExtraLobes, false, false, false},
        {facet::kMetalRough, true, false, false},
    };
    const facet::ShadeCounts none = counts(0, "phong");
    CHECK(none.batches > 200);
    CHECK(none.plain == none.batches);
    for (const Expectation& e : expectations) {
        INFO("feature bit " << e.feature);
        for (const auto& [style, drawn] : {std::pair<const char*, bool>{"phong", e.phong},
                                           {"clay", e.clay},
                                           {"unlit", e.unlit}}) {
            INFO(style);
            const facet::ShadeCounts c = counts(e.feature, style);
            CHECK(c.batches > 0);
            CHECK(c.plain == (drawn ? 0 : c.batches));
        }
    }
    // Other models and layers never take it.
    for (const char* style : {"pbr", "gouraud", "flat", "toon", "gooch", "wireframe-shaded"})
        CHECK(counts(0, style).plain == 0);
}
