#pragma once
// Helpers shared by the tests on files real tools wrote (gltfpack,
// Blender, Khronos' samples): a front view's depth image of a mesh file,
// and how two depth images differ.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

namespace facet::test {

// Frame `frame` of `scene`, on one thread.
inline FrameImages render_frame(const SceneDesc& scene, int frame) {
    const World world = build_world(scene);
    ThreadPool pool(1);
    FrameRenderer renderer(scene, world, pool);
    FrameImages images;
    renderer.render(frame, 0, images);
    return images;
}

// The depth image of `mesh` (a path) at frame `frame`, framed from the
// front; `animation` is the scene's `animation:` value, or "".
inline DepthImage depth_of(const TempDir& dir, const std::string& mesh,
                           const std::string& animation, int frame) {
    const std::string text =
        "output: { size: [160, 120], frames: \"1-48\", fps: 24 }\n"
        "style: unlit\n"
        "camera: { frame: all }\n"
        "objects:\n  - mesh: " +
        mesh + "\n" + (animation.empty() ? "" : "    animation: " + animation + "\n");
    return render_frame(load(write_text(dir.file("view.yaml"), text)), frame).depth;
}

// Share of pixels covered in one image and not the other, and the largest
// depth difference where both are covered, relative to the depth there.
inline std::pair<double, double> depth_difference(const DepthImage& a, const DepthImage& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    size_t coverage = 0;
    double largest = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const bool ha = std::isfinite(a.pixels[i]), hb = std::isfinite(b.pixels[i]);
        if (ha != hb) ++coverage;
        if (ha && hb)
            largest = std::max(largest, std::abs(double(a.pixels[i]) - b.pixels[i]) / a.pixels[i]);
    }
    return {double(coverage) / double(a.pixels.size()), largest};
}

// Of the pixels where both images show a surface, the share whose depths
// differ by more than `relative` of the depth: where a model has thin
// parts, an edge pixel can see another part in either image.
inline double share_of_depth_differences(const DepthImage& a, const DepthImage& b, float relative) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    size_t covered = 0, different = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const float da = a.pixels[i], db = b.pixels[i];
        if (!std::isfinite(da) || !std::isfinite(db)) continue;
        ++covered;
        if (std::abs(da - db) > relative * da) ++different;
    }
    REQUIRE(covered > 200);
    return double(different) / double(covered);
}

inline std::string asset(const std::string& name) {
    return source_path("tests/assets/" + name);
}

}  // namespace facet::test
