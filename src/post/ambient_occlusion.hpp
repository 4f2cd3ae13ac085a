#pragma once
// Screen-space ambient occlusion from the depth and normal buffers, in the
// manner of McGuire, Osman, Bukowski and Hennessy 2011, "The Alchemy
// Screen-Space Ambient Obscurance Algorithm": each sample looks at points
// of the visible surface within `radius` (scene units) around it, and the
// ones above its tangent plane darken it. Where the paper weighs a point by
// v.n / (v.v + eps), which depends on the scene's scale, we weigh it by the
// cosine of its direction with the normal, faded to zero at the radius:
//   A = max(0, 1 - (2 strength / n) * sum_i max(0, v_i.n / |v_i| - beta) (1 - |v_i|^2 / r^2))
// so an open face gives A = 1 and a right-angled corner about one half at
// strength 1, whatever the units.
// A corner where a floor meets a wall, or a model resting on its floor,
// gets darker; an open face keeps A = 1.
//
// Determinism: the taps of a spiral are turned and spaced by a hash of the
// pixel's coordinates, and a 9 x 9 depth-aware box blur averages the
// noise, so the result depends on nothing but the buffers, not on threads
// or earlier frames.
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/thread_pool.hpp"
#include "post/outlines.hpp"

namespace facet {

struct OcclusionStyle {
    float radius = 0.5f;    // scene units around each point
    float strength = 1.0f;  // σ: 0 none, 1 the paper's, 2 twice as dark
    int samples = 16;       // taps per sample
    // Output pixels per value across: 1 finds it for every pixel, 2 for
    // every 2 x 2 (a quarter of the work; occlusion varies slowly, and the
    // depth-aware hand-out to samples keeps silhouettes sharp).
    int pixels_per_value = 2;
};

// Buffers kept from frame to frame.
struct OcclusionScratch {
    OutlineBuffers pixels;  // depth and normal of each pixel's first sample
    std::vector<float> raw, blurred;
};

// `factor` gets one value in [0, 1] per sample of `samples` (1: open, and
// on the background), a buffer of `samples_per_side` x `samples_per_side`
// samples per pixel. `view` turns the buffer's world-space normals to view
// space; `projection` is the camera's.
void ambient_occlusion(const OutlineBuffers& samples, int samples_per_side, const glm::mat4& view,
                       const glm::mat4& projection, const OcclusionStyle& style,
                       OcclusionScratch& scratch, std::vector<float>& factor, ThreadPool& pool);

}  // namespace facet
