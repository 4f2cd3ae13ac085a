#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>

#include "core/color.hpp"
#include "core/error.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

// Every half-float colour value -> its 8-bit sRGB byte (negative and NaN
// black, above 1 white), and -> its 8-bit linear byte for alpha. Built once
// (a constant, not state): a lookup per channel instead of pow.
struct HalfToByte {
    std::vector<uint8_t> srgb, linear;
    HalfToByte() : srgb(65536), linear(65536) {
        for (uint32_t h = 0; h < 65536; ++h) {
            const float v = half_to_float(static_cast<uint16_t>(h));
            const double unit = v > 0.0f ? std::min(static_cast<double>(v), 1.0) : 0.0;
            srgb[h] = static_cast<uint8_t>(std::lround(linear_to_srgb(unit) * 255.0));
            linear[h] = static_cast<uint8_t>(std::lround(unit * 255.0));
        }
    }
};

const HalfToByte& half_to_byte() {
    static const HalfToByte table;
    return table;
}

inline uint16_t unit_to_u16(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 65535;
    return static_cast<uint16_t>(v * 65535.0f + 0.5f);
}

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + length);
}

// libpng reports errors by longjmp; nothing with a destructor lives in this
// frame between setjmp and the write calls, and rows point into `pixels`.
bool write_png(std::vector<uint8_t>& out, int width, int height, int bit_depth, int color_type,
               const uint8_t* pixels, size_t row_bytes, int compression) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &out, append_bytes, nullptr);
    png_set_compression_level(png, compression);
    // Level 0-2 is asked for speed: skip the adaptive filter search.
    if (compression <= 2) png_set_filter(png, 0, PNG_FILTER_UP);
    png_set_IHDR(png, info, width, height, bit_depth, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (color_type != PNG_COLOR_TYPE_GRAY) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    if (bit_depth == 16) png_set_swap(png);  // our samples are little-endian in memory
    for (int y = 0; y < height; ++y)
        png_write_row(png, const_cast<png_bytep>(pixels + static_cast<size_t>(y) * row_bytes));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression) {
    const HalfToByte& table = half_to_byte();
    // Opaque images are written as RGB: a quarter less data to compress.
    const uint16_t one = 0x3c00;
    bool opaque = true;
    for (const Rgba16F& c : image.pixels) opaque = opaque && c.a == one;
    const size_t channels = opaque ? 3 : 4;
    std::vector<uint8_t> pixels(static_cast<size_t>(image.width) * image.height * channels);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const Rgba16F& c = image.pixels[i];
        uint8_t* p = &pixels[channels * i];
        p[0] = table.srgb[c.r];
        p[1] = table.srgb[c.g];
        p[2] = table.srgb[c.b];
        if (!opaque) p[3] = table.linear[c.a];
    }
    std::vector<uint8_t> out;
    if (!write_png(out, image.width, image.height, 8,
                   opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, pixels.data(),
                   static_cast<size_t>(image.width) * channels, compression))
        throw Error(ExitCode::runtime_failure, "PNG encoding failed");
    return out;
}

std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression) {
    return encode_png_color(to_half_image(image), compression);
}

std::vector<uint8_t> encode_png_depth(const DepthImage& depth, glm::vec2 range, int compression) {
    std::vector<uint16_t> samples(depth.pixels.size());
    const float span = range.y - range.x;
    for (size_t i = 0; i < depth.pixels.size(); ++i) {
        float d = depth.pixels[i];
        samples[i] = std::isinf(d) ? 0 : unit_to_u16((range.y - d) / span);
    }
    std::vector<uint8_t> out;
    if (!write_png(out, depth.width, depth.height, 16, PNG_COLOR_TYPE_GRAY,
                   reinterpret_cast<const uint8_t*>(samples.data()),
                   static_cast<size_t>(depth.width) * 2, compression))
        throw Error(ExitCode::runtime_failure, "PNG encoding failed");
    return out;
}

DecodedPng read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str()))
        throw Error(ExitCode::invalid_input, path + ": cannot read PNG: " + image.message);
    DecodedPng out;
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    const bool sixteen = (image.format & PNG_FORMAT_FLAG_LINEAR) != 0;
    const bool colour = (image.format & PNG_FORMAT_FLAG_COLOR) != 0;
    const bool alpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
    out.channels = (colour ? 3 : 1) + (alpha ? 1 : 0);
    out.bit_depth = sixteen ? 16 : 8;
    // Ask for the file's own layout, so values are not converted.
    image.format = (colour ? PNG_FORMAT_FLAG_COLOR : 0) | (alpha ? PNG_FORMAT_FLAG_ALPHA : 0) |
                   (sixteen ? PNG_FORMAT_FLAG_LINEAR : 0);
    const size_t count = static_cast<size_t>(out.width) * out.height * out.channels;
    if (sixteen) {
        out.samples.resize(count);
        if (!png_image_finish_read(&image, nullptr, out.samples.data(), 0, nullptr))
            throw Error(ExitCode::invalid_input, path + ": cannot read PNG: " + image.message);
    } else {
        std::vector<uint8_t> bytes(count);
        if (!png_image_finish_read(&image, nullptr, bytes.data(), 0, nullptr))
            throw Error(ExitCode::invalid_input, path + ": cannot read PNG: " + image.message);
        out.samples.assign(bytes.begin(), bytes.end());
    }
    png_image_free(&image);
    return out;
}

}  // namespace facet
