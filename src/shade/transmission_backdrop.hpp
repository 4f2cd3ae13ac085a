#pragma once
// What a transmitting surface (KHR_materials_transmission) shows through
// itself: the image of everything behind it, drawn before it, read where
// the refracted view leaves the volume, blurred by the surface's
// roughness. This is how real-time renderers draw glass (the Khronos
// sample viewer, three.js, Filament's screen-space refraction): the
// opaque surfaces first, a mip chain of their colour, then the glass
// reading it (render/transmission_stage.hpp draws the layers). docs/pbr.md,
// "Transmission", gives the formulas.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "assets/texture.hpp"

namespace facet {

struct EnvironmentLighting;  // shade/model_pbr.hpp

struct TransmissionBackdrop {
    // Linear RGB of what lies behind, with its mip chain, clamped at the
    // frame's edges.
    Texture image;
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
