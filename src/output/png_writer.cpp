// PNG files written directly (ISO/IEC 15948, the PNG specification): the
// chunks are simple, and writing them here lets the image data go through
// the fastest deflate available (output/deflate.cpp). Every row uses the Sub
// filter: nearly as small as an adaptive choice on rendered images, and
// cheap enough to vectorise.
#include <algorithm>
#include <cstring>

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
                              const std::vector<PngText>& text, int compression,
                              size_t bytes_per_pixel) {
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
                  idat, bytes_per_pixel);
    put_chunk(out, "IDAT", idat.data(), idat.size());
    put_chunk(out, "IEND", nullptr, 0);
    return out;
}

// One row of samples as its Sub-filtered scanline: the filter byte, then
// each byte minus the one `bpp` bytes to its left (the first pixel's as
// they are).
void filter_sub(const uint8_t* __restrict row, size_t bytes, size_t bpp,
                uint8_t* __restrict scanline) {
    scanline[0] = kFilterSub;
    ++scanline;
    std::copy_n(row, std::min(bpp, bytes), scanline);
    for (size_t i = bpp; i < bytes; ++i) scanline[i] = static_cast<uint8_t>(row[i] - row[i - bpp]);
}

}  // namespace

std::vector<uint8_t> encode_png(const PngSamples& samples, int compression,
                                const std::vector<PngText>& text) {
    const size_t bpp = static_cast<size_t>(samples.channels) * (samples.bit_depth / 8);
    const size_t row_bytes = static_cast<size_t>(samples.width) * bpp;
    std::vector<uint8_t> scanlines((row_bytes + 1) * static_cast<size_t>(samples.height));
    for (size_t y = 0; y < static_cast<size_t>(samples.height); ++y)
        filter_sub(&samples.bytes[row_bytes * y], row_bytes, bpp, &scanlines[(row_bytes + 1) * y]);
    const uint8_t type = samples.channels == 4   ? kColorRgba
                         : samples.channels == 3 ? kColorRgb
                                                 : kColorGrey;
    return png_file(samples.width, samples.height, samples.bit_depth, type, scanlines, text,
                    compression, bpp);
}

std::vector<uint8_t> encode_png_color(const HalfColorImage& image, int compression,
                                      const std::vector<PngText>& text) {
    return encode_png(png_color_samples(image), compression, text);
}

std::vector<uint8_t> encode_png_color(const ColorImage& image, int compression) {
    return encode_png_color(to_half_image(image), compression);
}

}  // namespace facet
