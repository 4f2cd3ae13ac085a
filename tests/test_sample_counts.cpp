// Every anti-aliasing grid draws the same picture: output.samples 1, 4, 9,
// 16 and 25 differ only along edges. With 9 and 25 samples the frame's
// tiles are 63 and 60 samples wide (whole pixels of 3 x 3 and 5 x 5), which
// once drew tiles at the wrong places.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

namespace {

facet::ColorImage render_at(int samples) {
    facet::test::TempDir dir("sample-counts");
    const std::string text = "output: { size: [160, 100], samples: " + std::to_string(samples) +
                             R"(, background: [0, 0, 0, 1] }
camera: { position: [0, 2.2, 4], target: [0, 0.3, -0.5], fov: 40 }
style: { shading: unlit }
objects:
  - { primitive: { type: plane, size: 8 }, material: { color: [0.8, 0.8, 0.8] } }
  - { primitive: { type: sphere, radius: 0.6 }, translate: [0, 0.6, 0], material: { color: [0.9, 0.4, 0.1] } }
)";
    return facet::to_float_image(facet::test::render_yaml(dir.path(), text, 1, 2).color);
}

}  // namespace

TEST_CASE("every sample count draws the same picture, up to its edges", "[render][antialiasing]") {
    const facet::ColorImage reference = render_at(16);
    for (const int samples : {1, 4, 9, 25}) {
        INFO(samples << " samples");
        const facet::ColorImage image = render_at(samples);
        double sum = 0.0;
        size_t far_off = 0;
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            const float difference = std::abs(image.pixels[i].r - reference.pixels[i].r);
            sum += difference;
            if (difference > 0.5f) ++far_off;  // a pixel showing something else altogether
        }
        CHECK(sum / static_cast<double>(image.pixels.size()) < 0.01);
        CHECK(far_off < 60);  // along the sphere's and the floor's edges at most
    }
}
