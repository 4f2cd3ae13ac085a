#pragma once
// Image encoders: each returns the complete file as bytes, so the caller
// can hash it and write it atomically; the samples of PNG views before
// compression; and readers. The only users of libdeflate (deflate),
// libpng (reading) and OpenEXR.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/half.hpp"
#include "core/image.hpp"
#include "output/exr_compression.hpp"

namespace facet {

// A tEXt chunk of a PNG: keyword (1-79 Latin-1 characters) and text.
struct PngText {
    std::string keyword, text;
};

// The samples of a PNG file before its rows are filtered and compressed:
// `channels` 1 (grey), 3 (RGB) or 4 (RGBA) per pixel, row by row, top
// down; 8-bit samples one byte each, 16-bit ones two, most significant
// first, as PNG stores them. What decode_png gives back from the file, so
// whoever only shows an image can take these and skip the round trip.
struct PngSamples {
    int width = 0, height = 0, channels = 0, bit_depth = 8;
    std::vector<uint8_t> bytes;

    // Sample i (pixel i / channels, channel i % channels) widened to 16
    // bits as DecodedPng holds it: 8-bit ones keep 0..255.
    uint16_t sample(size_t i) const {
        if (bit_depth == 16) return static_cast<uint16_t>(bytes[2 * i] << 8 | bytes[2 * i + 1]);
        return bytes[i];
    }
};

// A PNG file of `samples`, with `text` in tEXt chunks. `compression` is
// 0..9 as zlib counts (0 fastest, 9 smallest), mapped onto the deflate
// library's levels.
std::vector<uint8_t> encode_png(const PngSamples& samples, int compression,
                                const std::vector<PngText>& text = {});

// The views of images as people look at them (output/png_views.cpp).
// Colour: 8-bit sRGB from linear premultiplied colour, RGB when every
// pixel is opaque, RGBA with straight alpha (as PNG defines it) otherwise.
PngSamples png_color_samples(const HalfColorImage& image);
// Depth: 16-bit grey, range.x (near) mapped to 65535, range.y (far) to 0,
// linearly, clamped; background (+inf) is 0.
PngSamples png_depth_samples(const DepthImage& depth, glm::vec2 range);
// The data passes (docs/passes.md) as 8-bit RGB, plain bytes without the
// sRGB curve, the background black. Normal: each axis from [-1, 1] to
// [0, 255].
PngSamples png_normal_samples(const Image<glm::vec3>& normal);
// Ids: a fixed colour per id (id_view_color), the same in every frame and run.
PngSamples png_id_samples(const Image<uint32_t>& ids);
// uv: u in red, v in green, each clamped to [0, 1].
PngSamples png_uv_samples(const Image<glm::vec2>& uv);
// The id view's colour: black for 0, else a bright colour from a hash of the id.
std::array<uint8_t, 3> id_view_color(uint32_t id);

// encode_png(png_color_samples(image)): the PNG of a colour image. The
// float version converts to half first, so both give the same bytes for
// the same colour.
std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression,
                                      const std::vector<PngText>& text = {});
std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression);

// OpenEXR scanline files, compressed as output/exr_compression.hpp says.
enum class ExrSample { half, float32, uint32 };

constexpr size_t exr_sample_bytes(ExrSample type) {
    return type == ExrSample::half ? 2 : 4;
}

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

// The channels' samples uncompressed, in bytes: what a file of them holds
// at most, but for its header and offset table (methods that cannot shrink
// the samples store them as they are).
size_t exr_raw_bytes(int width, int height, const std::vector<ExrChannel>& channels);

// The same pixels give the same bytes with every compression, whatever
// the thread count.
std::vector<uint8_t> encode_exr(int width, int height, std::vector<ExrChannel> channels,
                                const std::vector<ExrAttribute>& attributes = {},
                                ExrCompression compression = ExrCompression::zip);

// Half-float linear RGBA: channels R, G, B, A.
std::vector<uint8_t> encode_exr_color(const HalfColorImage& image,
                                      const std::vector<ExrAttribute>& attributes = {},
                                      ExrCompression compression = ExrCompression::zip);

// One float32 channel "Z" with linear view depth, +inf background.
std::vector<uint8_t> encode_exr_depth(const DepthImage& depth,
                                      const std::vector<ExrAttribute>& attributes = {},
                                      ExrCompression compression = ExrCompression::zip);

// rle, piz and dwaa: the file written by OpenEXR's C++ library into memory,
// channels sorted by name (output/exr_library_writer.cpp).
std::vector<uint8_t> encode_exr_with_library(int width, int height,
                                             const std::vector<ExrChannel>& channels,
                                             const std::vector<ExrAttribute>& attributes,
                                             ExrCompression compression);

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
// The size and channel names alone, from the header, with `channels` left
// empty: to refuse a size before read_exr allocates for it.
DecodedExr read_exr_header(const std::string& path);

}  // namespace facet
