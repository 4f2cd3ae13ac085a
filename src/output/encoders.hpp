#pragma once
// Image encoders: each returns the complete file as bytes, so the caller
// can hash it and write it atomically; and readers. The only users of
// libdeflate (deflate), libpng (reading) and OpenEXR.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/half.hpp"
#include "core/image.hpp"

namespace facet {

// A tEXt chunk of a PNG: keyword (1-79 Latin-1 characters) and text.
struct PngText {
    std::string keyword, text;
};

// 8-bit sRGB PNG from linear premultiplied colour: RGB when every pixel is
// opaque, RGBA with straight alpha (as PNG defines it) otherwise. `compression` is 0..9 as zlib
// counts (0 fastest, 9 smallest), mapped onto the deflate library's levels. The float version
// converts to half first, so both give the same bytes for the same colour.
std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression,
                                      const std::vector<PngText>& text = {});
std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression);

// 16-bit grey PNG view of linear depth: range.x (near) maps to 65535,
// range.y (far) to 0, linearly, clamped; background (+inf) is 0.
std::vector<uint8_t> encode_png_depth(const DepthImage& depth, glm::vec2 range, int compression,
                                      const std::vector<PngText>& text = {});

// An 8-bit PNG of samples already encoded (sRGB colour, as displays show
// them): `channels` 1 (grey), 3 (RGB) or 4 (RGBA), row by row. For
// pictures made for people, such as comparison reports.
std::vector<uint8_t> encode_png_bytes(int width, int height, int channels,
                                      std::span<const uint8_t> samples, int compression,
                                      const std::vector<PngText>& text = {});

// 8-bit RGB views of the data passes (docs/passes.md), written as plain
// bytes without the sRGB curve; the background is black.
// Normal: each axis from [-1, 1] to [0, 255].
std::vector<uint8_t> encode_png_normal(const Image<glm::vec3>& normal, int compression,
                                       const std::vector<PngText>& text = {});
// Ids: a fixed colour per id (id_view_color), the same in every frame and run.
std::vector<uint8_t> encode_png_ids(const Image<uint32_t>& ids, int compression,
                                    const std::vector<PngText>& text = {});
// uv: u in red, v in green, each clamped to [0, 1].
std::vector<uint8_t> encode_png_uv(const Image<glm::vec2>& uv, int compression,
                                   const std::vector<PngText>& text = {});
// The id view's colour: black for 0, else a bright colour from a hash of the id.
std::array<uint8_t, 3> id_view_color(uint32_t id);

// OpenEXR scanline files, ZIP compression (16 scanlines a chunk).
enum class ExrSample { half, float32, uint32 };

// One channel: its samples at base + y * row_stride + x * x_stride.
struct ExrChannel {
    std::string name;
    ExrSample type;
    const uint8_t* base;
    size_t x_stride, row_stride;
};

// A string attribute in the header (facet's provenance).
struct ExrAttribute {
    std::string name, value;
};

std::vector<uint8_t> encode_exr(int width, int height, std::vector<ExrChannel> channels,
                                const std::vector<ExrAttribute>& attributes = {});

// Half-float linear RGBA: channels R, G, B, A.
std::vector<uint8_t> encode_exr_color(const HalfColorImage& image,
                                      const std::vector<ExrAttribute>& attributes = {});

// One float32 channel "Z" with linear view depth, +inf background.
std::vector<uint8_t> encode_exr_depth(const DepthImage& depth,
                                      const std::vector<ExrAttribute>& attributes = {});

// A decoded PNG, samples widened to 16 bits (8-bit files keep 0..255).
struct DecodedPng {
    int width = 0, height = 0, channels = 0, bit_depth = 0;
    std::vector<uint16_t> samples;
};
DecodedPng read_png(const std::string& path);
// The same from a PNG file's bytes in memory; `what` names them in errors.
DecodedPng decode_png(std::span<const uint8_t> bytes, const std::string& what);

// A decoded EXR: every channel as float, by name.
struct DecodedExr {
    int width = 0, height = 0;
    std::vector<std::string> channel_names;
    std::vector<std::vector<float>> channels;
};
DecodedExr read_exr(const std::string& path);

}  // namespace facet
