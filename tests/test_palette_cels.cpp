// The palette preset (seed 000's method with tuned defaults) shows as many
// distinct cels on the demo knot as it is asked for: 2, 3, 4 and 6.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

namespace {

// The demo knot alone, lit by the turntable's key light, over black. The
// strokes are turned off: they are a layer over the cels, which are what
// is counted here.
facet::FrameImages render_knot(int cels) {
    facet::test::TempDir dir("palette-cels");
    const std::string text =
        "output: { size: [320, 180], samples: 1, background: [0, 0, 0, 1] }\n"
        "style: { extends: palette, cels: " +
        std::to_string(cels) +
        ", outlines: false, hatching: { strength: 0 } }\n"
        "camera: { fov: 40, orbit: { center: [0, 0.55, 0], radius: 3.4, elevation: 22 } }\n"
        "lights: [{ type: directional, direction: [-1.3, -1.1, -0.9], intensity: 0.9 }]\n"
        "objects:\n"
        "  - name: knot\n"
        "    mesh: " +
        facet::test::source_path("scenes/assets/knot.glb") +
        "\n"
        "    translate: [0, 0.46, 0]\n"
        "    rotate: [90, 0, 0]\n";
    return facet::test::render_yaml(dir.path(), text, 1, 2);
}

// The cel levels q = m/N that at least 2 % of the knot's pixels show: with
// `keep_hue` a cel's colour has length q exactly, so its pixels sit on a
// multiple of 1/N; highlights, strokes and edges fall between.
int cels_shown(const facet::FrameImages& images, int cels) {
    std::map<int, int> level_pixels;
    int knot = 0;
    for (const auto& p : images.color.pixels) {
        const glm::vec4 c = facet::to_float(p);
        const float length = std::sqrt(c.r * c.r + c.g * c.g + c.b * c.b);
        if (!(length > 0.0f)) continue;
        ++knot;
        const float scaled = length * static_cast<float>(cels);
        const float nearest = std::round(scaled);
        if (std::fabs(scaled - nearest) < 0.01f * static_cast<float>(cels))
            ++level_pixels[static_cast<int>(nearest)];
    }
    int shown = 0;
    for (const auto& [level, pixels] : level_pixels) {
        UNSCOPED_INFO("level " << level << "/" << cels << ": " << pixels << " of " << knot);
        if (pixels >= knot / 50) ++shown;
    }
    return shown;
}

}  // namespace

TEST_CASE("the palette preset shows distinct cels at 2, 3, 4 and 6 on the knot",
          "[render][style][palette]") {
    for (int cels : {2, 3, 4, 6}) {
        const int shown = cels_shown(render_knot(cels), cels);
        INFO(cels << " cels asked, " << shown << " shown");
        // Six cels span the knot's colour lengths 0.3 .. 0.9 in five steps.
        CHECK(shown >= std::min(cels, 5));
    }
}
