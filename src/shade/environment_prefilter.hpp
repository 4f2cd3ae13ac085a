#pragma once
// The stages of build_environment (shade/environment_map.hpp) that turn an
// equirectangular image into the specular chain: resampling it onto the
// sharp octahedral map, and convolving that map with GGX lobes.
// docs/pbr.md, "Environment lighting: the prefiltered maps", gives the
// formulas. Every texel is computed on its own, its sums in a fixed order,
// so the maps have the same bits for any thread count.
#include <vector>

#include "core/thread_pool.hpp"
#include "shade/octahedral_map.hpp"
#include "shade/spherical_harmonics.hpp"

namespace facet::pbr {

// The sharp map's size for an image `image_height` rows tall: the power of
// two nearest above it, 32 to 2048. Near the horizon an octahedral texel
// is then about as wide as the image's, and the image's many thin texels
// near the poles are averaged.
int sharp_map_size(int image_height);

// The size of the chain's level for perceptual roughness `roughness` > 0
// under a sharp map of `sharp_size`: the power of two nearest 11 / alpha
// (alpha = roughness^2), so that the lobe's half width at half maximum
// (1.29 alpha) spans about four texels; 32 to 256, and at most sharp_size.
int prefiltered_level_size(double roughness, int sharp_size);

// Row `row` of the sharp map: each texel the mean of four bilinear reads of
// the image, at the centres of its four quarters (the columns wrap round,
// the rows stop at the poles). Directions become image coordinates through
// atan2_turns (core/exact_trig.hpp), not the C library's.
void resample_equirect_row(const EquirectRadiance& image, int row, OctahedralMap& sharp);

// Levels 1 to level_count - 1 of the chain, convolved from the sharp map
// (which becomes level 0) with GGX lobes by filtered importance sampling.
// Rows of all levels are spread over `pool`.
std::vector<OctahedralMap> prefilter_chain(OctahedralMap sharp, int level_count, ThreadPool& pool);

}  // namespace facet::pbr
