#include "render/occlusion_stage.hpp"

namespace facet {

void OcclusionStage::apply(const OutlineBuffers& gbuffer, int samples_per_side,
                           const CameraMatrices& camera, const OcclusionStyle& style,
                           ColorImage& samples, ThreadPool& pool) {
    ambient_occlusion(gbuffer, samples_per_side, camera.view, camera.projection, style, scratch_,
                      factor_, pool);
    pool.parallel_for(static_cast<size_t>(samples.height), [&](size_t row) {
        const size_t first = row * static_cast<size_t>(samples.width);
        for (size_t i = first; i < first + static_cast<size_t>(samples.width); ++i) {
            // Darker, and for a shadow catcher (which shows the background
            // darkened by how much it hides) hiding more: 1 - (1 - a) f.
            glm::vec4& c = samples.pixels[i];
            c = glm::vec4(glm::vec3(c) * factor_[i], 1.0f - (1.0f - c.a) * factor_[i]);
        }
    });
}

}  // namespace facet
