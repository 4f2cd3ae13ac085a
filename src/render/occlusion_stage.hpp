#pragma once
// Stage 7c of a frame: ambient occlusion (post/ambient_occlusion.hpp) from
// the G-buffer the shading stage filled. Beside outlines or lines it runs
// on the samples, multiplied into their colour before lines are drawn over
// them, so the resolve anti-aliases it with the surfaces. Alone, it runs on
// the resolved pixels: each pixel takes the value of its nearest sample's
// surface, and only its samples that show a surface are darkened.
#include <cstdint>
#include <vector>

#include "core/half.hpp"
#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "post/ambient_occlusion.hpp"
#include "post/outlines.hpp"
#include "render/camera.hpp"

namespace facet {

class OcclusionStage {
  public:
    // What the stage holds for `elements` G-buffer elements and `cells`
    // cells (a pixel's, or 2 x 2 pixels' at half resolution): a factor per
    // element; per cell a depth, normal and object, the raw and the blurred
    // occlusion.
    static uint64_t bytes(uint64_t elements, uint64_t cells) {
        return elements * sizeof(float) + cells * (kOutlineElementBytes + 2 * sizeof(float));
    }

    // `samples` and `gbuffer` have the same size; the background (alpha 0)
    // is left alone.
    void apply_to_samples(const OutlineBuffers& gbuffer, int samples_per_side,
                          const CameraMatrices& camera, const OcclusionStyle& style,
                          ColorImage& samples, ThreadPool& pool);

    // `gbuffer`, `surface_share`, `color` and `over_nothing` (the alpha
    // pass; may be null) have the output's size; `background` is the colour
    // shading put behind `color`.
    void apply_to_pixels(const OutlineBuffers& gbuffer, const Image<float>& surface_share,
                         const CameraMatrices& camera, const OcclusionStyle& style,
                         const glm::vec4& background, HalfColorImage& color,
                         HalfColorImage* over_nothing, ThreadPool& pool);

  private:
    OcclusionScratch scratch_;  // reused from frame to frame
    std::vector<float> factor_;
};

}  // namespace facet
