#include "compare/difference_stats.hpp"

#include <cmath>
#include <stdexcept>

namespace facet {

void DifferenceAccumulator::add(double difference, int x, int y, int channel) {
    sum_ += difference;
    sum_squares_ += difference * difference;
    ++samples_;
    if (difference > stats_.max) {
        stats_.max = difference;
        stats_.max_x = x;
        stats_.max_y = y;
        stats_.max_channel = channel;
    }
}

void DifferenceAccumulator::end_pixel(bool over) {
    ++stats_.pixels;
    stats_.pixels_over += over;
}

DifferenceStats DifferenceAccumulator::result() const {
    DifferenceStats s = stats_;
    if (samples_ > 0) {
        s.mean = sum_ / static_cast<double>(samples_);
        s.rms = std::sqrt(sum_squares_ / static_cast<double>(samples_));
    }
    return s;
}

DifferenceStats difference_stats(const SampleImage& a, const SampleImage& b, double threshold,
                                 std::span<const uint8_t> mask) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw std::invalid_argument("difference_stats: the images differ in size or channels");
    const size_t pixels = static_cast<size_t>(a.width) * a.height;
    if (!mask.empty() && mask.size() != pixels)
        throw std::invalid_argument("difference_stats: the mask is not the images' size");
    DifferenceAccumulator sum;
    for (size_t p = 0; p < pixels; ++p) {
        if (!mask.empty() && mask[p] == 0) continue;
        const int x = static_cast<int>(p % static_cast<size_t>(a.width));
        const int y = static_cast<int>(p / static_cast<size_t>(a.width));
        bool over = false;
        for (int c = 0; c < a.channels; ++c) {
            const size_t i = p * static_cast<size_t>(a.channels) + static_cast<size_t>(c);
            const double d = std::abs(static_cast<double>(a.samples[i]) - b.samples[i]);
            sum.add(d, x, y, c);
            over = over || d > threshold;
        }
        sum.end_pixel(over);
    }
    return sum.result();
}

}  // namespace facet
