#pragma once
// Image encoders: each returns the complete file as bytes, so the caller
// can hash it and write it atomically. The only libpng and OpenEXR users.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/half.hpp"
#include "core/image.hpp"

namespace facet {

// 8-bit sRGB PNG from linear colour: RGB when every pixel is opaque, RGBA
// otherwise. `compression` is zlib's 0..9. The float version converts to
// half first, so both give the same bytes for the same colour.
std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression);
std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression);

// 16-bit grey PNG view of linear depth: range.x (near) maps to 65535,
// range.y (far) to 0, linearly, clamped; background (+inf) is 0.
std::vector<uint8_t> encode_png_depth(const DepthImage& depth, glm::vec2 range, int compression);

// OpenEXR, half-float linear RGBA, ZIP compression.
std::vector<uint8_t> encode_exr_color(const HalfColorImage& image);

// OpenEXR, one float32 channel "Z" with linear view depth, +inf background.
std::vector<uint8_t> encode_exr_depth(const DepthImage& depth);

// A decoded PNG, samples widened to 16 bits (8-bit files keep 0..255).
struct DecodedPng {
    int width = 0, height = 0, channels = 0, bit_depth = 0;
    std::vector<uint16_t> samples;
};
DecodedPng read_png(const std::string& path);

// A decoded EXR: every channel as float, by name.
struct DecodedExr {
    int width = 0, height = 0;
    std::vector<std::string> channel_names;
    std::vector<std::vector<float>> channels;
};
DecodedExr read_exr(const std::string& path);

}  // namespace facet
