#include "render/occlusion_stage.hpp"

namespace facet {
namespace {

// A sample of colour `c` (rgb over the background, a the share of it
// hidden) darkened by occlusion `f`: darker, and for a shadow catcher
// (which shows the background darkened by how much it hides) hiding more.
glm::vec4 occluded(const glm::vec4& c, float f) {
    return {glm::vec3(c) * f, 1.0f - (1.0f - c.a) * f};
}

// A pixel `p` whose samples show a surface over `share` of it and
// `behind` (premultiplied) over the rest, its surface samples darkened by
// `f`: the same sum as darkening each of them with occluded() and resolving.
glm::vec4 occluded_pixel(const glm::vec4& p, float share, const glm::vec4& behind, float f) {
    const glm::vec4 rest = behind * (1.0f - share);
    const glm::vec4 surfaces = p - rest;
    return glm::vec4(glm::vec3(surfaces) * f, share - (share - surfaces.a) * f) + rest;
}

}  // namespace

void OcclusionStage::apply_to_samples(const OutlineBuffers& gbuffer, int samples_per_side,
                                      const CameraMatrices& camera, const OcclusionStyle& style,
                                      ColorImage& samples, ThreadPool& pool) {
    ambient_occlusion(gbuffer, samples_per_side, camera.view, camera.projection, style, scratch_,
                      factor_, pool);
    pool.parallel_for(static_cast<size_t>(samples.height), [&](size_t row) {
        const size_t first = row * static_cast<size_t>(samples.width);
        for (size_t i = first; i < first + static_cast<size_t>(samples.width); ++i)
            samples.pixels[i] = occluded(samples.pixels[i], factor_[i]);
    });
}

void OcclusionStage::apply_to_pixels(const OutlineBuffers& gbuffer,
                                     const Image<float>& surface_share,
                                     const CameraMatrices& camera, const OcclusionStyle& style,
                                     const glm::vec4& background, HalfColorImage& color,
                                     HalfColorImage* over_nothing, ThreadPool& pool) {
    ambient_occlusion(gbuffer, 1, camera.view, camera.projection, style, scratch_, factor_, pool);
    pool.parallel_for(static_cast<size_t>(color.height), [&](size_t row) {
        const size_t first = row * static_cast<size_t>(color.width);
        for (size_t i = first; i < first + static_cast<size_t>(color.width); ++i) {
            const float f = factor_[i], share = surface_share.pixels[i];
            if (f == 1.0f || share == 0.0f) continue;  // open, or the background alone
            color.pixels[i] =
                to_half(occluded_pixel(to_float(color.pixels[i]), share, background, f));
            if (over_nothing)
                over_nothing->pixels[i] = to_half(
                    occluded_pixel(to_float(over_nothing->pixels[i]), share, glm::vec4(0.0f), f));
        }
    });
}

}  // namespace facet
