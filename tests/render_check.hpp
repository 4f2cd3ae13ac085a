#pragma once
// Render tests compare a frame against a reviewed reference image in
// tests/baselines. A test is one line: scene, frame, reference, thresholds.
#include <string>
#include <vector>

#include "core/image.hpp"
#include "render/frame_renderer.hpp"
#include "scene/scene_desc.hpp"

namespace facet::test {

struct Tolerance {
    double mean = 0.5;        // mean over pixels of the largest channel difference (0..255)
    double outliers = 0.002;  // fraction of pixels allowed to differ by more than 24
};

struct RenderCase {
    std::string scene;  // relative to the repository
    int frame = 1;
    std::string reference;  // file name in tests/baselines
    Tolerance tolerance;
    std::vector<std::string> defines;  // -D style overrides, "key=value"
    std::string style;                 // --style, if not empty
    // The pass compared (docs/passes.md), through its PNG view; position
    // and motion, which have none, through render_check's own views.
    std::string pass = "color";
};

// Renders the case and compares. A missing reference (or FACET_UPDATE_BASELINES=1)
// writes the rendered image into tests/baselines for review and fails.
void check_render(const RenderCase& c);

// Compares a PNG with tests/baselines/`reference` as check_render does
// (the same update rule and diff image).
void check_against_baseline(const std::vector<uint8_t>& png, const std::string& reference,
                            const Tolerance& tolerance = {});

// One frame of a loaded scene, rendered on `threads` threads, as linear
// float colour (for tests that compute what each pixel must be).
ColorImage render_color(const SceneDesc& scene, int frame = 1, unsigned threads = 1);

// Every image of one frame of a loaded scene.
FrameImages render_images(const SceneDesc& scene, int frame = 1, unsigned threads = 2,
                          ShadingPaths paths = ShadingPaths::specialised);

// The same for a scene given as YAML text: written to `folder`/scene.yaml
// (so relative asset paths resolve there) and loaded with the shipped
// styles.
FrameImages render_yaml(const std::string& folder, const std::string& yaml, int frame = 1,
                        unsigned threads = 2, ShadingPaths paths = ShadingPaths::specialised);

// The pixel of `image` (one of `images`' passes) that shows world point p.
glm::vec4 pixel_at(const FrameImages& images, const HalfColorImage& image, glm::vec3 p);

}  // namespace facet::test
