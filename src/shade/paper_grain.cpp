#include "shade/paper_grain.hpp"

#include "core/error.hpp"
#include "core/integer_hash.hpp"

namespace facet {

namespace {

// Quintic fade 6t^5 − 15t^4 + 10t^3 (Perlin 2002): smooth second
// derivative, so the grain shows no lattice creases.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lattice_value(uint32_t seed, int octave, int i, int j) {
    return hash_unit(hash32(seed, static_cast<uint32_t>(octave), static_cast<uint32_t>(i),
                            static_cast<uint32_t>(j)));
}

}  // namespace

std::vector<float> make_paper_grain(const PaperGrainParams& p) {
    if (p.size < 1 || p.cells < 1 || p.octaves < 1 || p.size % p.cells != 0)
        throw Error(ExitCode::invalid_input,
                    "paper grain: size must be a multiple of cells, both >= 1");
    std::vector<float> grain(static_cast<size_t>(p.size) * p.size, 0.0f);
    float amplitude = 1.0f, total = 0.0f;
    for (int octave = 0, period = p.cells; octave < p.octaves && period <= p.size;
         ++octave, period *= 2, amplitude *= 0.5f) {
        total += amplitude;
        const float cells_per_texel = static_cast<float>(period) / static_cast<float>(p.size);
        for (int y = 0; y < p.size; ++y) {
            const float gy = (static_cast<float>(y) + 0.5f) * cells_per_texel;
            const int j0 = static_cast<int>(gy);  // gy >= 0: truncation is floor
            const float ty = fade(gy - static_cast<float>(j0));
            const int j1 = (j0 + 1) % period;
            for (int x = 0; x < p.size; ++x) {
                const float gx = (static_cast<float>(x) + 0.5f) * cells_per_texel;
                const int i0 = static_cast<int>(gx);
                const float tx = fade(gx - static_cast<float>(i0));
                const int i1 = (i0 + 1) % period;
                const float v00 = lattice_value(p.seed, octave, i0, j0);
                const float v10 = lattice_value(p.seed, octave, i1, j0);
                const float v01 = lattice_value(p.seed, octave, i0, j1);
                const float v11 = lattice_value(p.seed, octave, i1, j1);
                const float top = v00 + (v10 - v00) * tx;
                const float bottom = v01 + (v11 - v01) * tx;
                grain[static_cast<size_t>(y) * p.size + x] +=
                    amplitude * (top + (bottom - top) * ty);
            }
        }
    }
    for (float& g : grain) g /= total;
    return grain;
}

}  // namespace facet
