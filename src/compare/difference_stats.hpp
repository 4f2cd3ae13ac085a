#pragma once
// Statistics of the difference between two images of the same size, as
// idiff reports them and `facet compare` will judge them: mean, RMS and the
// largest absolute difference (with its pixel and channel), and the share
// of pixels where any channel differs by more than a threshold. Masked
// pixels (mask value 0) are left out of every figure.
#include <cstdint>
#include <span>

namespace facet {

// Interleaved samples: `channels` values per pixel, row by row.
struct SampleImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::span<const float> samples;
};

struct DifferenceStats {
    double mean = 0;  // mean absolute difference over the compared samples
    double rms = 0;   // root mean square of the differences
    double max = 0;   // largest absolute difference
    int max_x = -1, max_y = -1, max_channel = -1;  // where it is (-1: no difference)
    uint64_t pixels = 0;                           // pixels compared (not masked)
    uint64_t pixels_over = 0;  // pixels with a channel differing by more than the threshold
    double percent_over() const { return pixels ? 100.0 * pixels_over / pixels : 0.0; }
};

// Builds DifferenceStats one sample at a time, for judges whose
// differences are not plain subtractions (relative, angles, ids).
class DifferenceAccumulator {
  public:
    // One sample's absolute difference, at pixel (x, y), channel c.
    void add(double difference, int x, int y, int channel);
    // Ends a compared pixel; `over`: it counts among pixels_over.
    void end_pixel(bool over);
    DifferenceStats result() const;

  private:
    DifferenceStats stats_;
    double sum_ = 0, sum_squares_ = 0;
    uint64_t samples_ = 0;
};

// Throws std::invalid_argument when the images differ in size or channels,
// or the mask (one value per pixel, when not empty) in size.
DifferenceStats difference_stats(const SampleImage& a, const SampleImage& b, double threshold,
                                 std::span<const uint8_t> mask = {});

}  // namespace facet
