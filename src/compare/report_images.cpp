#include "compare/report_images.hpp"

#include <algorithm>
#include <cmath>

#include "core/integer_hash.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

uint8_t to_byte(double v) {
    if (!(v > 0)) return 0;
    return static_cast<uint8_t>(std::lround(std::min(v, 1.0) * 255.0));
}

// Black -> red -> yellow -> white over 0..1.
void ramp(double v, uint8_t* rgb) {
    v = std::clamp(v, 0.0, 1.0) * 3.0;
    rgb[0] = to_byte(v);
    rgb[1] = to_byte(v - 1.0);
    rgb[2] = to_byte(v - 2.0);
}

size_t pixel_count(const CompareImage& image) {
    return static_cast<size_t>(image.width) * image.height;
}

bool colour_kind(ImageKind kind) {
    return kind == ImageKind::color || kind == ImageKind::color_float;
}

// An 8-bit PNG the size of `image`, of `channels` samples a pixel.
std::vector<uint8_t> report_png(const CompareImage& image, int channels,
                                std::vector<uint8_t> bytes) {
    return encode_png({.width = image.width,
                       .height = image.height,
                       .channels = channels,
                       .bit_depth = 8,
                       .bytes = std::move(bytes)},
                      6);
}

}  // namespace

std::vector<uint8_t> difference_png(const CompareImage& ref, const CompareImage& candidate,
                                    ImageKind kind, double white, double scale,
                                    const Judgement& judgement) {
    const size_t pixels = pixel_count(ref);
    std::vector<uint8_t> rgb(pixels * 3);
    if (colour_kind(kind)) {
        const std::vector<float> a = display_values(ref, kind, white);
        const std::vector<float> b = display_values(candidate, kind, white);
        for (size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < 3; ++c)
                rgb[p * 3 + c] = to_byte(std::abs(double(b[p * 3 + c]) - a[p * 3 + c]) * scale);
    } else {
        for (size_t p = 0; p < pixels; ++p)
            rgb[p * 3] = rgb[p * 3 + 1] = rgb[p * 3 + 2] =
                to_byte(judgement.excess[p] * scale / 8.0);
    }
    return report_png(ref, 3, std::move(rgb));
}

std::vector<uint8_t> heat_png(const CompareImage& ref, ImageKind kind, const Judgement& judgement) {
    const size_t pixels = pixel_count(ref);
    std::vector<uint8_t> rgb(pixels * 3, 0);
    for (size_t p = 0; p < pixels; ++p) {
        uint8_t* out = &rgb[p * 3];
        if (colour_kind(kind) && !judgement.ssim_map.empty()) {
            ramp((1.0 - judgement.ssim_map[p]) * 2.0, out);
            continue;
        }
        static constexpr uint8_t kStateColour[5][3] = {
            {0, 0, 0}, {255, 140, 0}, {255, 0, 0}, {255, 230, 0}, {40, 60, 160}};
        std::copy_n(kStateColour[std::min<int>(judgement.state[p], 4)], 3, out);
    }
    return report_png(ref, 3, std::move(rgb));
}

std::vector<uint8_t> preview_png(const CompareImage& image, ImageKind kind, double white) {
    const size_t pixels = pixel_count(image);
    const bool alpha = !image.alpha.empty();
    const int channels = alpha ? 4 : 3;
    std::vector<uint8_t> out(pixels * channels, 0);
    const int n = image.channels;
    // The finite range of the first channel, for depth and float data.
    double low = INFINITY, high = -INFINITY;
    for (size_t p = 0; p < pixels; ++p) {
        const double v = image.samples[p * n];
        if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
    }
    const double span = high > low ? high - low : 1.0;
    const std::vector<float> display =
        colour_kind(kind) ? display_values(image, kind, white) : std::vector<float>{};
    for (size_t p = 0; p < pixels; ++p) {
        uint8_t* px = &out[p * channels];
        const float* v = &image.samples[p * n];
        switch (kind) {
            case ImageKind::color:
            case ImageKind::color_float:
                for (int c = 0; c < 3; ++c) px[c] = to_byte(display[p * 3 + c]);
                break;
            case ImageKind::depth:
                px[0] = px[1] = px[2] =
                    std::isfinite(v[0]) ? to_byte(0.15 + 0.85 * (high - v[0]) / span) : 0;
                break;
            case ImageKind::normal:
                for (int c = 0; c < 3; ++c) px[c] = to_byte(0.5 + 0.5 * v[c]);
                break;
            case ImageKind::id: {
                const uint32_t h = hash32(static_cast<uint32_t>(v[0]));
                for (int c = 0; c < 3; ++c)
                    px[c] = v[0] == 0 ? 0 : static_cast<uint8_t>(64 + ((h >> (8 * c)) & 0xbf));
                break;
            }
            default:
                px[0] = px[1] = px[2] = std::isfinite(v[0]) ? to_byte((v[0] - low) / span) : 0;
        }
        if (alpha) px[3] = to_byte(image.alpha[p]);
    }
    return report_png(image, channels, std::move(out));
}

}  // namespace facet
