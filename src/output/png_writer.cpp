// PNG files written directly (ISO/IEC 15948, the PNG specification): the
// chunks are simple, and writing them here lets the image data go through
// the fastest deflate available (output/deflate.cpp). Every row uses the Sub
// filter: nearly as small as an adaptive choice on rendered images, and
// cheap enough to vectorise.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/display_transform.hpp"
#include "core/error.hpp"
#include "output/deflate.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr uint8_t kFilterSub = 1;
constexpr uint8_t kColorGrey = 0, kColorRgb = 2, kColorRgba = 6;

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
    const uint8_t bytes[4] = {static_cast<uint8_t>(v >> 24), static_cast<uint8_t>(v >> 16),
                              static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
    out.insert(out.end(), bytes, bytes + 4);
}

// Length, type, data and the CRC of type and data.
void put_chunk(std::vector<uint8_t>& out, const char type[4], const uint8_t* data, size_t size) {
    put_u32(out, static_cast<uint32_t>(size));
    const size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data, data + size);
    put_u32(out, crc32(0, out.data() + start, out.size() - start));
}

// A whole PNG from filtered scanlines (each a filter byte and the row).
std::vector<uint8_t> png_file(int width, int height, int bit_depth, uint8_t color_type,
                              const std::vector<uint8_t>& scanlines,
                              const std::vector<PngText>& text, int compression) {
    std::vector<uint8_t> out(kSignature, kSignature + 8);
    uint8_t header[13];
    const uint32_t w = static_cast<uint32_t>(width), h = static_cast<uint32_t>(height);
    for (int i = 0; i < 4; ++i) {
        header[i] = static_cast<uint8_t>(w >> (24 - 8 * i));
        header[4 + i] = static_cast<uint8_t>(h >> (24 - 8 * i));
    }
    header[8] = static_cast<uint8_t>(bit_depth);
    header[9] = color_type;
    header[10] = header[11] = header[12] = 0;  // deflate, adaptive filters, no interlace
    put_chunk(out, "IHDR", header, sizeof header);
    if (color_type != kColorGrey) {
        const uint8_t perceptual = 0;
        put_chunk(out, "sRGB", &perceptual, 1);
    }
    for (const PngText& t : text) {  // tEXt: keyword, NUL, Latin-1 text
        std::vector<uint8_t> data(t.keyword.begin(), t.keyword.end());
        data.push_back(0);
        data.insert(data.end(), t.text.begin(), t.text.end());
        put_chunk(out, "tEXt", data.data(), data.size());
    }
    std::vector<uint8_t> idat;
    zlib_compress(scanlines.data(), scanlines.size(), std::clamp(compression, 0, kMaxDeflateLevel),
                  idat);
    put_chunk(out, "IDAT", idat.data(), idat.size());
    put_chunk(out, "IEND", nullptr, 0);
    return out;
}

// Sub filter in place over one scanline's bytes (after its filter byte):
// each byte minus the one `bpp` bytes to its left. Right to left, so every
// byte still reads its unfiltered neighbour.
void filter_sub(uint8_t* row, size_t bytes, size_t bpp) {
    row[-1] = kFilterSub;
    for (size_t i = bytes; i-- > bpp;) row[i] = static_cast<uint8_t>(row[i] - row[i - bpp]);
}

// Every half-float colour value -> its 8-bit sRGB byte (negative and NaN
// black, above 1 white), and -> its 8-bit linear byte for alpha. Built once
// (a constant, not state): a lookup per channel instead of pow.
struct HalfToByte {
    std::vector<uint8_t> srgb, linear;
    HalfToByte() : srgb(65536), linear(65536) {
        for (uint32_t h = 0; h < 65536; ++h) {
            const float v = half_to_float(static_cast<uint16_t>(h));
            const double unit = v > 0.0f ? std::min(static_cast<double>(v), 1.0) : 0.0;
            srgb[h] = display_byte(v);
            linear[h] = static_cast<uint8_t>(std::lround(unit * 255.0));
        }
    }
};

const HalfToByte& half_to_byte() {
    static const HalfToByte table;
    return table;
}

// A premultiplied pixel that is not opaque, as PNG stores it: straight
// (colour divided by alpha) and then sRGB-encoded; transparent is black.
void straight_srgb(const Rgba16F& c, uint8_t* rgb) {
    const float a = half_to_float(c.a);
    const uint16_t channel[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) {
        rgb[i] = display_byte(a > 0.0f ? half_to_float(channel[i]) / a : 0.0f);
    }
}

inline uint16_t unit_to_u16(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 65535;
    return static_cast<uint16_t>(v * 65535.0f + 0.5f);
}

}  // namespace

std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression,
                                      const std::vector<PngText>& text) {
    const HalfToByte& table = half_to_byte();
    // Opaque images are written as RGB: a quarter less data to compress.
    const uint16_t one = 0x3c00;
    bool opaque = true;
    for (const Rgba16F& c : image.pixels) opaque = opaque && c.a == one;
    const size_t channels = opaque ? 3 : 4;
    const size_t row_bytes = static_cast<size_t>(image.width) * channels;
    std::vector<uint8_t> scanlines((row_bytes + 1) * static_cast<size_t>(image.height));
    for (int y = 0; y < image.height; ++y) {
        uint8_t* row = &scanlines[(row_bytes + 1) * static_cast<size_t>(y) + 1];
        const Rgba16F* c = &image.at(0, y);
        // Two loops, not one with a test per pixel: the opaque one is the
        // common case and stays a plain table lookup.
        if (opaque) {
            for (int x = 0; x < image.width; ++x, row += 3) {
                row[0] = table.srgb[c[x].r];
                row[1] = table.srgb[c[x].g];
                row[2] = table.srgb[c[x].b];
            }
        } else {
            for (int x = 0; x < image.width; ++x, row += 4) {
                if (c[x].a == one) {
                    row[0] = table.srgb[c[x].r];
                    row[1] = table.srgb[c[x].g];
                    row[2] = table.srgb[c[x].b];
                } else {
                    straight_srgb(c[x], row);
                }
                row[3] = table.linear[c[x].a];
            }
        }
        filter_sub(row - row_bytes, row_bytes, channels);
    }
    return png_file(image.width, image.height, 8, opaque ? kColorRgb : kColorRgba, scanlines, text,
                    compression);
}

std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression) {
    return encode_png_color(to_half_image(image), compression);
}

std::vector<uint8_t> encode_png_depth(const DepthImage& depth, glm::vec2 range, int compression,
                                      const std::vector<PngText>& text) {
    const size_t row_bytes = static_cast<size_t>(depth.width) * 2;
    std::vector<uint8_t> scanlines((row_bytes + 1) * static_cast<size_t>(depth.height));
    const float span = range.y - range.x;
    for (int y = 0; y < depth.height; ++y) {
        uint8_t* row = &scanlines[(row_bytes + 1) * static_cast<size_t>(y) + 1];
        const float* d = &depth.at(0, y);
        for (int x = 0; x < depth.width; ++x) {
            const uint16_t v = std::isinf(d[x]) ? 0 : unit_to_u16((range.y - d[x]) / span);
            row[2 * x] = static_cast<uint8_t>(v >> 8);  // PNG samples are big-endian
            row[2 * x + 1] = static_cast<uint8_t>(v);
        }
        filter_sub(row, row_bytes, 2);
    }
    return png_file(depth.width, depth.height, 16, kColorGrey, scanlines, text, compression);
}

std::vector<uint8_t> encode_png_bytes(int width, int height, int channels,
                                      std::span<const uint8_t> samples, int compression,
                                      const std::vector<PngText>& text) {
    const size_t bpp = static_cast<size_t>(channels);
    const size_t row_bytes = static_cast<size_t>(width) * bpp;
    std::vector<uint8_t> scanlines((row_bytes + 1) * static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) {
        uint8_t* row = &scanlines[(row_bytes + 1) * static_cast<size_t>(y) + 1];
        std::copy_n(samples.data() + row_bytes * static_cast<size_t>(y), row_bytes, row);
        filter_sub(row, row_bytes, bpp);
    }
    const uint8_t type = channels == 4 ? kColorRgba : channels == 3 ? kColorRgb : kColorGrey;
    return png_file(width, height, 8, type, scanlines, text, compression);
}

}  // namespace facet
