#pragma once
// What a transmitting surface (KHR_materials_transmission) shows through
// itself: the image of everything behind it, drawn before it, read where
// the refracted view leaves the volume, blurred by the surface's
// roughness. This is how real-time renderers draw glass (the Khronos
// sample viewer, three.js, Filament's screen-space refraction): the
// opaque surfaces first, a mip chain of their colour, then the glass
// reading it (render/transmission_stage.hpp draws the layers). docs/pbr.md,
// "Transmission", gives the formulas.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/half.hpp"
#include "core/thread_pool.hpp"

namespace facet {

struct EnvironmentLighting;  // shade/model_pbr.hpp

// A frame's linear colour as a pyramid of float RGB levels (Williams 1983):
// level 0 the frame's pixels, each next the 2 x 2 box average of the one
// before (an odd last row or column averaged with itself), read
// trilinearly and clamped at the frame's edges, as a GPU reads a
// mipmapped render target. Its own, not a material Texture's: float
// texels, built every layer of every frame, read only this way. Rebuilt
// in place, so its buffers last from frame to frame.
class BackdropPyramid {
  public:
    // From `color` (linear RGBA, premultiplied: its RGB is what shows), on
    // `pool`'s threads; the same bits for any thread count.
    void build(const HalfColorImage& color, ThreadPool& pool);
    // log2 of the frame's width: the level that spans the whole frame.
    float widest_level() const { return widest_level_; }
    // `lod` log2 of the pixels a lookup spans; uv (0, 0) the frame's
    // top-left corner, (1, 1) its bottom-right.
    glm::vec3 sample(glm::vec2 uv, float lod) const;

    // What the pyramid of a frame of `pixels` holds: its levels add up to
    // 4/3 of the frame.
    static uint64_t bytes(uint64_t pixels) { return pixels * sizeof(glm::vec3) * 4 / 3; }

  private:
    struct Level {
        int width = 0, height = 0;
        std::vector<glm::vec3> texels;  // row by row, top to bottom
    };
    glm::vec3 bilinear(const Level& level, glm::vec2 uv) const;
    std::vector<Level> levels_;
    size_t count_ = 0;  // levels in use (levels_ keeps the buffers of more)
    float widest_level_ = 0.0f;
};

struct TransmissionBackdrop {
    BackdropPyramid image;      // what lies behind
    glm::mat4 view_projection;  // world -> clip, the frame's camera
};

// One point's refraction: where it is, its unit normal (on the viewer's
// side) and view, and the terms that bend and blur the view.
struct RefractedView {
    glm::vec3 position, normal, view;
    float ior;
    float thickness;   // world units; 0 a thin wall: the view goes straight through
    float roughness;   // the refraction's perceptual roughness (PbrPoint::transmission_roughness)
    float dispersion;  // 20 / Abbe number; 0: one index for every channel
};

// The radiance behind the point along its refracted view: with a
// backdrop, the backdrop's colour where the view refracted by
// refract(-v, n, 1 / ior) leaves the volume, position + thickness * that
// direction, projected to the frame (the Khronos sample viewer's
// getVolumeTransmissionRay), read at level log2(width) * roughness.
// With dispersion each channel refracts by its own index,
//   ior -+ (ior - 1) * 0.025 * dispersion  (red -, blue +)
// (KHR_materials_dispersion's sample implementation). Without a backdrop
// (a point shaded outside a frame, as tests do) the environment along -v,
// else black.
glm::vec3 radiance_behind(const RefractedView& point, const TransmissionBackdrop* backdrop,
                          const EnvironmentLighting* environment);

}  // namespace facet
