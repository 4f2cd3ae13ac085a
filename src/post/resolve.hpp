#pragma once
// Resolve of a frame shaded at every sample (when screen-space passes ran
// at the sample resolution): each output pixel from its k x k samples.
#include "core/half.hpp"
#include "core/image.hpp"
#include "core/thread_pool.hpp"

namespace facet {

// The sample-resolution images. In `color`, rgb is each sample's final
// colour (the background already under it) and a its coverage: 1 where a
// surface or an opaque line is, 0 on the background, a line's coverage
// in between.
struct SampleImages {
    const ColorImage& color;
    const DepthImage& depth;
    const ColorImage* lines;  // premultiplied strokes alone, or null
    int k;                    // samples per pixel side
    glm::vec4 background;     // premultiplied RGBA
};

// The output-size images to fill; alpha and lines may be null.
struct ResolvedImages {
    HalfColorImage& color;
    DepthImage& depth;
    HalfColorImage* alpha;  // the colour over nothing, premultiplied
    HalfColorImage* lines;
};

// Colour is the mean of the samples in linear light (a box filter), stored
// as half floats; its alpha is the mean of each sample's coverage over the
// background's alpha. The alpha pass is the mean of the samples with the
// background taken out (rgb − background.rgb · (1 − a)), so it is the
// colour over nothing, premultiplied. Depth is the nearest sample's, so an
// edge pixel keeps the depth of the object it partly shows rather than a
// depth between object and background that belongs to neither; it is +inf
// only if every sample missed. Identical results for any thread count.
void resolve_supersampled(const SampleImages& in, const ResolvedImages& out, ThreadPool& pool);

}  // namespace facet
