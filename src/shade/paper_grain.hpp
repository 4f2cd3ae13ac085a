#pragma once
// Paper grain for pencil hatching: tileable value noise (Perlin 1985's
// lattice noise with random values instead of gradients), a few octaves,
// from integer hashes only, so it is identical on every platform.
#include <cstdint>
#include <vector>

namespace facet {

struct PaperGrainParams {
    int size = 256;   // texels along each side
    int cells = 32;   // lattice cells along each side at the first octave; divides size
    int octaves = 3;  // each doubles the frequency and halves the amplitude
    uint32_t seed = 1;
};

// size x size heights in [0, 1], rows top to bottom, mean about 0.5. The
// lattice wraps every `cells` cells, so the texture tiles seamlessly.
// Octaves finer than one texel are left out (they would only alias).
std::vector<float> make_paper_grain(const PaperGrainParams& params);

}  // namespace facet
