// The plain shading path (render/shade_batch.cpp): batches whose
// triangles belong to one mesh part with a material of constants, under a
// Phong, Blinn-Phong or unlit style without layers, take a path of their own. It must write the
// same bits as the general path, and be taken exactly when the general path's extra features do not
// apply.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <string>

#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "render/shade_batch.hpp"
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

// Renders the scene both ways and requires every pass to be byte-identical.
void require_same_bits(const std::string& yaml) {
    facet::test::TempDir dir("shade-plain");
    write_checker(dir.path());
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

TEST_CASE("the plain path is taken only where the general path's features do not apply",
          "[render][shade_plain]") {
    facet::StyleState phong;
    phong.model = facet::ShadingModel::phong;
    facet::Draw draw{};
    facet::Material m;
    CHECK(facet::takes_plain_path(phong, draw, m));
    facet::StyleState blinn = phong;
    blinn.model = facet::ShadingModel::blinn_phong;
    CHECK(facet::takes_plain_path(blinn, draw, m));
    facet::StyleState unlit = phong;
    unlit.model = facet::ShadingModel::unlit;
    CHECK(facet::takes_plain_path(unlit, draw, m));

    SECTION("other models and layers take the general path") {
        for (facet::ShadingModel model :
             {facet::ShadingModel::flat, facet::ShadingModel::gouraud, facet::ShadingModel::pbr,
              facet::ShadingModel::toon, facet::ShadingModel::gooch, facet::ShadingModel::palette,
              facet::ShadingModel::normal, facet::ShadingModel::depth}) {
            facet::StyleState other = phong;
            other.model = model;
            CHECK_FALSE(facet::takes_plain_path(other, draw, m));
        }
        facet::StyleState wire = phong;
        wire.wireframe = true;
        CHECK_FALSE(facet::takes_plain_path(wire, draw, m));
    }
    SECTION("a base colour texture, unless the style sets the colour") {
        m.base_color_map.texture = std::make_shared<const facet::Texture>(
            facet::Texture::from_linear(1, 1, {{1, 1, 1, 1}}, facet::Texture::Format::half));
        CHECK_FALSE(facet::takes_plain_path(phong, draw, m));
        CHECK_FALSE(facet::takes_plain_path(unlit, draw, m));
        facet::StyleState clay = phong;
        clay.base_color = glm::vec3(0.6f, 0.5f, 0.4f);
        CHECK(facet::takes_plain_path(clay, draw, m));
    }
    SECTION("vertex colours, unless the style sets the colour") {
        draw.has_colors = true;
        CHECK_FALSE(facet::takes_plain_path(phong, draw, m));
        facet::StyleState clay = phong;
        clay.base_color = glm::vec3(0.6f, 0.5f, 0.4f);
        CHECK(facet::takes_plain_path(clay, draw, m));
    }
    SECTION("emission, under the lit models only") {
        m.emissive = glm::vec3(0.1f, 0, 0);
        CHECK_FALSE(facet::takes_plain_path(phong, draw, m));
        CHECK(facet::takes_plain_path(unlit, draw, m));
        m.emissive = glm::vec3(0);
        m.unlit = true;
        CHECK_FALSE(facet::takes_plain_path(blinn, draw, m));
    }
    SECTION("shadow catchers and fades") {
        facet::Material catcher = m;
        catcher.shadow_catcher = true;
        CHECK_FALSE(facet::takes_plain_path(phong, draw, catcher));
        CHECK_FALSE(facet::takes_plain_path(unlit, draw, catcher));
        facet::Material fading = m;
        fading.fade_start = 2;
        fading.fade_end = 3;
        CHECK_FALSE(facet::takes_plain_path(phong, draw, fading));
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
    // Every object plain: each batch but those with several meshes' pixels.
    const facet::ShadeCounts phong = counts("phong", "", ShadingPaths::specialised);
    CHECK(phong.batches > 1000);
    CHECK(phong.plain > phong.batches * 9 / 10);
    CHECK(phong.plain < phong.batches);
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
