// The plain shading path (render/shade_batch.cpp): batches of one triangle
// whose material only its constants colour, under Phong, Blinn-Phong or
// unlit, take a path of their own. It must write the same bits as the
// general path, and be taken exactly when the general path's extra
// features do not apply.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <string>

#include "render/shade_batch.hpp"
#include "render_check.hpp"
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
           "  - { type: spot, position: [-2, 3, 1], direction: [2, -3, -1], intensity: 8, outer_angle: "
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
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) ==
               0;
}

// Renders the scene both ways and requires every pass to be byte-identical.
void require_same_bits(const std::string& yaml) {
    facet::test::TempDir dir("shade-plain");
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
    const std::string one = "";
    const std::string four = ", samples: 4";
    const std::string alpha = ", samples: 4, passes: [color, depth, alpha]";
    SECTION("phong, one sample a pixel") {
        require_same_bits(scene_text("phong", one));
    }
    SECTION("phong, four samples") {
        require_same_bits(scene_text("phong", four));
    }
    SECTION("blinn-phong with the alpha pass") {
        require_same_bits(scene_text("blinn-phong", alpha));
    }
    SECTION("unlit") {
        require_same_bits(scene_text("unlit", four));
    }
    SECTION("a style's base colour") {
        require_same_bits(scene_text("clay", four));
    }
    SECTION("occlusion: the G-buffer's normals and objects") {
        require_same_bits(scene_text("{ extends: blinn-phong, occlusion: { radius: 0.4 } }", four));
        require_same_bits(scene_text("{ extends: unlit, occlusion: { radius: 0.4 } }", one));
    }
    SECTION("plain and general materials side by side") {
        const std::string glowing =
            "  - name: lamp\n"
            "    primitive: { type: sphere, radius: 0.3 }\n"
            "    translate: [0, 0.3, 1.2]\n"
            "    material: { color: [0.9, 0.9, 0.2], emissive: [0.4, 0.3, 0] }\n";
        require_same_bits(scene_text("phong", four, glowing));
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
