#include "compare/difference_stats.hpp"

#include <cmath>
#include <stdexcept>

namespace facet {

DifferenceStats difference_stats(const SampleImage& a, const SampleImage& b, double threshold,
                                 std::span<const uint8_t> mask) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw std::invalid_argument("difference_stats: the images differ in size or channels");
    const size_t pixels = static_cast<size_t>(a.width) * a.height;
    if (!mask.empty() && mask.size() != pixels)
        throw std::invalid_argument("difference_stats: the mask is not the images' size");
    DifferenceStats s;
    double sum = 0, sum_squares = 0;
    uint64_t samples = 0;
    for (size_t p = 0; p < pixels; ++p) {
        if (!mask.empty() && mask[p] == 0) continue;
        ++s.pixels;
        bool over = false;
        for (int c = 0; c < a.channels; ++c) {
            const size_t i = p * static_cast<size_t>(a.channels) + static_cast<size_t>(c);
            const double d = std::abs(static_cast<double>(a.samples[i]) - b.samples[i]);
            sum += d;
            sum_squares += d * d;
            ++samples;
            over = over || d > threshold;
            if (d > s.max) {
                s.max = d;
                s.max_x = static_cast<int>(p % static_cast<size_t>(a.width));
                s.max_y = static_cast<int>(p / static_cast<size_t>(a.width));
                s.max_channel = c;
            }
        }
        s.pixels_over += over;
    }
    if (samples > 0) {
        s.mean = sum / static_cast<double>(samples);
        s.rms = std::sqrt(sum_squares / static_cast<double>(samples));
    }
    return s;
}

}  // namespace facet
