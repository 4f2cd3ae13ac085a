#pragma once
// Stage 7c of a frame: ambient occlusion (post/ambient_occlusion.hpp) from
// the G-buffer the shading stage filled, multiplied into the surface
// samples' colour before lines are drawn over them, at the sample
// resolution so the resolve anti-aliases it with the surfaces.
#include <vector>

#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "post/ambient_occlusion.hpp"
#include "post/outlines.hpp"
#include "render/camera.hpp"

namespace facet {

class OcclusionStage {
  public:
    // `samples` and `gbuffer` have the same size; the background (alpha 0)
    // is left alone.
    void apply(const OutlineBuffers& gbuffer, int samples_per_side, const CameraMatrices& camera,
               const OcclusionStyle& style, ColorImage& samples, ThreadPool& pool);

  private:
    OcclusionScratch scratch_;  // reused from frame to frame
    std::vector<float> factor_;
};

}  // namespace facet
