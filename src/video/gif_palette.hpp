#pragma once
// One 256-colour palette for a whole animated GIF, so colours do not
// shimmer from frame to frame: median cut (Heckbert 1982, "Color image
// quantization for frame buffer display") over a histogram of all frames'
// colours at 5 bits per channel, and each pixel mapped to its nearest
// entry. Deterministic: the same frames give the same palette and indices.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace facet {

struct GifPalette {
    std::vector<std::array<uint8_t, 3>> colors;  // at most 256
    std::vector<uint8_t> nearest;                // per 15-bit colour (r5 g5 b5): its entry
};

// `frames`: 8-bit RGB images, all of the same size.
GifPalette make_gif_palette(const std::vector<std::vector<uint8_t>>& frames);

// Palette indices of one RGB image.
std::vector<uint8_t> map_to_palette(const GifPalette& palette, std::span<const uint8_t> rgb);

}  // namespace facet
