#pragma once
// The environment behind the scene (`environment: { background: true }`):
// after shading, which ran over a transparent background, each pixel's
// colour (premultiplied over nothing) gets the environment's radiance along
// the pixel's ray times the share of the pixel nothing covers:
//   colour + radiance(ray) (1 - alpha),  alpha = 1
// Shadow catchers and fading floors, which cover the background by their
// shadow's strength, darken it as they darken a background colour.
#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/camera.hpp"
#include "shade/model_pbr.hpp"

namespace facet {

// `blur` 0..1 reads the environment's prefiltered levels, sharp to the
// roughest. Each pixel on its own: the same bits for any thread count.
void composite_environment_background(HalfColorImage& color, const CameraMatrices& camera,
                                      const EnvironmentLighting& environment, float blur,
                                      ThreadPool& pool);

}  // namespace facet
