#include "video/gif_palette.hpp"

#include <algorithm>
#include <limits>

namespace facet {
namespace {

constexpr int kBins = 32 * 32 * 32;

int bin_of(const uint8_t* rgb) {
    return ((rgb[0] >> 3) << 10) | ((rgb[1] >> 3) << 5) | (rgb[2] >> 3);
}

// A box of histogram bins, split along its longest side at the median
// pixel until there are as many boxes as palette entries.
struct Box {
    std::vector<int> bins;  // bins with pixels
    uint64_t pixels = 0;
};

int channel(int bin, int c) {
    return (bin >> (10 - 5 * c)) & 31;
}

int longest_side(const Box& box) {
    int best = 0, best_range = -1;
    for (int c = 0; c < 3; ++c) {
        int low = 31, high = 0;
        for (int b : box.bins)
            low = std::min(low, channel(b, c)), high = std::max(high, channel(b, c));
        if (high - low > best_range) best_range = high - low, best = c;
    }
    return best_range > 0 ? best : -1;
}

}  // namespace

GifPalette make_gif_palette(const std::vector<std::vector<uint8_t>>& frames) {
    // Per bin: how many pixels, and the sum of their real colours, so an
    // entry is the mean of the colours it stands for (a flat background
    // keeps its exact value), not a bin's centre.
    std::vector<uint64_t> count(kBins, 0);
    std::vector<std::array<uint64_t, 3>> sums(kBins, {0, 0, 0});
    for (const auto& frame : frames)
        for (size_t i = 0; i + 2 < frame.size(); i += 3) {
            const auto b = static_cast<size_t>(bin_of(&frame[i]));
            ++count[b];
            for (size_t c = 0; c < 3; ++c) sums[b][c] += frame[i + c];
        }
    std::vector<Box> boxes(1);
    for (int b = 0; b < kBins; ++b)
        if (count[static_cast<size_t>(b)]) {
            boxes[0].bins.push_back(b);
            boxes[0].pixels += count[static_cast<size_t>(b)];
        }
    while (boxes.size() < 256) {
        // The box with the most pixels that can still be split; ties by order.
        int pick = -1, side = -1;
        for (size_t i = 0; i < boxes.size(); ++i) {
            const int s = longest_side(boxes[i]);
            if (s >= 0 && (pick < 0 || boxes[i].pixels > boxes[static_cast<size_t>(pick)].pixels))
                pick = static_cast<int>(i), side = s;
        }
        if (pick < 0) break;
        Box& box = boxes[static_cast<size_t>(pick)];
        std::stable_sort(box.bins.begin(), box.bins.end(),
                         [&](int a, int b) { return channel(a, side) < channel(b, side); });
        uint64_t seen = 0;
        size_t cut = 0;
        while (cut + 1 < box.bins.size() &&
               seen + count[static_cast<size_t>(box.bins[cut])] <= box.pixels / 2)
            seen += count[static_cast<size_t>(box.bins[cut++])];
        cut = std::max<size_t>(cut, 1);
        Box upper;
        upper.bins.assign(box.bins.begin() + static_cast<ptrdiff_t>(cut), box.bins.end());
        box.bins.resize(cut);
        box.pixels = 0;
        for (int b : box.bins) box.pixels += count[static_cast<size_t>(b)];
        for (int b : upper.bins) upper.pixels += count[static_cast<size_t>(b)];
        boxes.push_back(std::move(upper));
    }
    GifPalette palette;
    for (const Box& box : boxes) {
        if (box.pixels == 0) continue;
        uint64_t sum[3] = {0, 0, 0};
        for (int b : box.bins)
            for (size_t c = 0; c < 3; ++c) sum[c] += sums[static_cast<size_t>(b)][c];
        palette.colors.push_back({static_cast<uint8_t>(sum[0] / box.pixels),
                                  static_cast<uint8_t>(sum[1] / box.pixels),
                                  static_cast<uint8_t>(sum[2] / box.pixels)});
    }
    if (palette.colors.empty()) palette.colors.push_back({0, 0, 0});
    palette.nearest.resize(kBins);
    for (int b = 0; b < kBins; ++b) {
        int best = 0, best_distance = std::numeric_limits<int>::max();
        for (size_t i = 0; i < palette.colors.size(); ++i) {
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                const int diff = channel(b, c) * 8 + 4 - palette.colors[i][static_cast<size_t>(c)];
                d += diff * diff;
            }
            if (d < best_distance) best_distance = d, best = static_cast<int>(i);
        }
        palette.nearest[static_cast<size_t>(b)] = static_cast<uint8_t>(best);
    }
    return palette;
}

std::vector<uint8_t> map_to_palette(const GifPalette& palette, std::span<const uint8_t> rgb) {
    std::vector<uint8_t> indices(rgb.size() / 3);
    for (size_t p = 0; p < indices.size(); ++p)
        indices[p] = palette.nearest[static_cast<size_t>(bin_of(&rgb[p * 3]))];
    return indices;
}

}  // namespace facet
