#pragma once
// Resolve of a frame shaded at every sample (when screen-space passes ran
// at the sample resolution): each output pixel from its k x k samples.
#include "core/half.hpp"
#include "core/image.hpp"
#include "core/thread_pool.hpp"

namespace facet {

// Colour is the mean of the samples in linear light (a box filter), stored
// as half floats. Depth is the nearest sample's, so an edge pixel keeps the
// depth of the object it partly shows rather than a depth between object
// and background that belongs to neither; it is +inf only if every sample
// missed. `out_color` and `out_depth` must already have the output size.
void resolve_supersampled(const ColorImage& color, const DepthImage& depth, int k,
                          HalfColorImage& out_color, DepthImage& out_depth, ThreadPool& pool);

}  // namespace facet
