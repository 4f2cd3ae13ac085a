// OpenEXR files written through OpenEXR's C core (the header, the chunk
// offset table and the file layout are the library's), with the ZIP and
// ZIPS compression of each chunk done here by libdeflate (NONE stores the
// packed chunk as it is): OpenEXR 3.1 compresses
// with zlib, several times slower. The chunk data follows the OpenEXR file
// layout: 16 scanlines per chunk, within each scanline the channels in name
// order, little-endian samples; ZIP splits the bytes into two halves (even
// and odd positions), replaces each byte by its difference to the one
// before plus 128, and deflates the result as a zlib stream.
#include <OpenEXR/openexr.h>

#include <algorithm>
#include <cstring>

#include "core/error.hpp"
#include "output/deflate.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

// Scanlines per chunk, as the format fixes them: 16 for ZIP, 1 for ZIPS and NONE.
int scanlines_per_chunk(ExrCompression compression) {
    return compression == ExrCompression::zip ? 16 : 1;
}

exr_compression_t core_compression(ExrCompression compression) {
    return compression == ExrCompression::zip    ? EXR_COMPRESSION_ZIP
           : compression == ExrCompression::zips ? EXR_COMPRESSION_ZIPS
                                                 : EXR_COMPRESSION_NONE;
}
// libdeflate level for EXR chunks: its fastest, level 1, is about as small
// as zlib's 6 on rendered half and float data.
constexpr int kExrDeflateLevel = 1;

// The file grows in memory: OpenEXR writes the header, the chunks, then
// seeks back for the offset table.
int64_t write_to_memory(exr_const_context_t, void* userdata, const void* buffer, uint64_t size,
                        uint64_t offset, exr_stream_error_func_ptr_t) {
    auto* out = static_cast<std::vector<uint8_t>*>(userdata);
    const auto* bytes = static_cast<const uint8_t*>(buffer);
    if (offset == out->size()) {  // the usual case: appended, not zeroed first
        out->insert(out->end(), bytes, bytes + size);
        return static_cast<int64_t>(size);
    }
    if (offset + size > out->size()) out->resize(offset + size);
    std::memcpy(out->data() + offset, bytes, size);
    return static_cast<int64_t>(size);
}

void check(exr_result_t result, const char* what) {
    if (result != EXR_ERR_SUCCESS)
        throw Error(ExitCode::runtime_failure, std::string("EXR encoding failed (") + what +
                                                   "): " + exr_get_default_error_message(result));
}

exr_pixel_type_t pixel_type(ExrSample type) {
    switch (type) {
        case ExrSample::half:
            return EXR_PIXEL_HALF;
        case ExrSample::float32:
            return EXR_PIXEL_FLOAT;
        case ExrSample::uint32:
            return EXR_PIXEL_UINT;
    }
    return EXR_PIXEL_FLOAT;
}

// Every fourth half of `row` from the first, `width` of them: one channel
// of RGBA half pixels. With the stride a constant the loop has no multiply
// and no reload of the stride per sample, which made the copy of the
// colour file's channels most of its packing time.
void copy_every_fourth_half(const uint8_t* row, int width, uint8_t* out) {
    for (size_t x = 0; x < static_cast<size_t>(width); ++x) {
        uint16_t v;
        std::memcpy(&v, row + 8 * x, 2);
        std::memcpy(out + 2 * x, &v, 2);
    }
}

// One chunk's raw bytes: scanline by scanline, channel by channel.
void pack_chunk(const std::vector<ExrChannel>& channels, int width, int y0, int y1,
                std::vector<uint8_t>& raw) {
    size_t row_bytes = 0;
    for (const ExrChannel& c : channels)
        row_bytes += exr_sample_bytes(c.type) * static_cast<size_t>(width);
    raw.resize(row_bytes * static_cast<size_t>(y1 - y0));
    uint8_t* out = raw.data();
    for (int y = y0; y < y1; ++y)
        for (const ExrChannel& c : channels) {
            const size_t bytes = exr_sample_bytes(c.type);
            const uint8_t* row = c.base + static_cast<size_t>(y) * c.row_stride;
            if (c.x_stride == bytes) {
                std::memcpy(out, row, bytes * static_cast<size_t>(width));
            } else if (bytes == 2 && c.x_stride == 4 * bytes) {
                copy_every_fourth_half(row, width, out);
            } else if (bytes == 2) {  // a channel of interleaved half pixels
                for (int x = 0; x < width; ++x) {
                    uint16_t v;
                    std::memcpy(&v, row + c.x_stride * static_cast<size_t>(x), 2);
                    std::memcpy(out + 2 * static_cast<size_t>(x), &v, 2);
                }
            } else {
                for (int x = 0; x < width; ++x)
                    std::memcpy(out + bytes * static_cast<size_t>(x),
                                row + c.x_stride * static_cast<size_t>(x), bytes);
            }
            out += bytes * static_cast<size_t>(width);
        }
}

// ZIP's reordering and predictor, then deflate; the raw bytes instead when
// that is not smaller (as the format allows). Each pass reads one buffer
// and writes another, so the compiler vectorises it.
void zip_chunk(const std::vector<uint8_t>& raw, std::vector<uint8_t>& split,
               std::vector<uint8_t>& predicted, std::vector<uint8_t>& out) {
    const size_t n = raw.size();  // even: samples are 2 or 4 bytes
    split.resize(n);
    predicted.resize(n);
    const size_t half = n / 2;
    const uint8_t* in = raw.data();
    uint8_t* even = split.data();
    uint8_t* odd = split.data() + half;
    for (size_t i = 0; i < half; ++i) {
        even[i] = in[2 * i];
        odd[i] = in[2 * i + 1];
    }
    const uint8_t* s = split.data();
    uint8_t* p = predicted.data();
    if (n > 0) p[0] = s[0];
    for (size_t i = 1; i < n; ++i) p[i] = static_cast<uint8_t>(s[i] - s[i - 1] + 128);
    out.clear();
    zlib_compress(p, n, kExrDeflateLevel, out);
    if (out.size() >= n) out = raw;
}

}  // namespace

size_t exr_raw_bytes(int width, int height, const std::vector<ExrChannel>& channels) {
    size_t bytes = 0;
    for (const ExrChannel& c : channels)
        bytes +=
            exr_sample_bytes(c.type) * static_cast<size_t>(width) * static_cast<size_t>(height);
    return bytes;
}

std::vector<uint8_t> encode_exr(int width, int height, std::vector<ExrChannel> channels,
                                const std::vector<ExrAttribute>& attributes,
                                ExrCompression compression) {
    std::sort(channels.begin(), channels.end(),
              [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
    if (!written_by_facet(compression))
        return encode_exr_with_library(width, height, channels, attributes, compression);
    // Room for the whole file at once: a chunk is never stored larger than
    // its raw bytes, and growing a 16 MB buffer step by step cost more than
    // the writing (copies, and the kernel clearing each fresh page).
    const size_t raw_bytes = exr_raw_bytes(width, height, channels);
    size_t header_bytes = 4096;
    for (const ExrAttribute& a : attributes) header_bytes += a.name.size() + a.value.size() + 32;
    const size_t chunk_count = static_cast<size_t>(height) / scanlines_per_chunk(compression) + 1;
    std::vector<uint8_t> file;
    file.reserve(header_bytes + raw_bytes + chunk_count * 16);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &file;
    init.write_fn = write_to_memory;
    exr_context_t ctxt = nullptr;
    check(exr_start_write(&ctxt, "memory", EXR_WRITE_FILE_DIRECTLY, &init), "start");
    try {
        int part = 0;
        check(exr_add_part(ctxt, "", EXR_STORAGE_SCANLINE, &part), "part");
        check(exr_initialize_required_attr_simple(ctxt, part, width, height,
                                                  core_compression(compression)),
              "attributes");
        for (const ExrChannel& c : channels)
            check(exr_add_channel(ctxt, part, c.name.c_str(), pixel_type(c.type),
                                  EXR_PERCEPTUALLY_LINEAR, 1, 1),
                  "channel");
        for (const ExrAttribute& a : attributes)
            check(exr_attr_set_string(ctxt, part, a.name.c_str(), a.value.c_str()), "attribute");
        check(exr_write_header(ctxt), "header");
        std::vector<uint8_t> raw, split, predicted, packed;
        const int step = scanlines_per_chunk(compression);
        for (int y = 0; y < height; y += step) {
            pack_chunk(channels, width, y, std::min(height, y + step), raw);
            const std::vector<uint8_t>* chunk = &raw;
            if (compression != ExrCompression::none) {
                zip_chunk(raw, split, predicted, packed);
                chunk = &packed;
            }
            check(exr_write_scanline_chunk(ctxt, part, y, chunk->data(), chunk->size()), "chunk");
        }
    } catch (...) {
        exr_finish(&ctxt);
        throw;
    }
    check(exr_finish(&ctxt), "finish");
    return file;
}

std::vector<uint8_t> encode_exr_color(const HalfColorImage& image,
                                      const std::vector<ExrAttribute>& attributes,
                                      ExrCompression compression) {
    const uint8_t* base = reinterpret_cast<const uint8_t*>(image.pixels.data());
    const size_t row = sizeof(Rgba16F) * static_cast<size_t>(image.width);
    std::vector<ExrChannel> channels;
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
        channels.push_back({names[c], ExrSample::half, base + 2 * c, sizeof(Rgba16F), row});
    return encode_exr(image.width, image.height, channels, attributes, compression);
}

std::vector<uint8_t> encode_exr_depth(const DepthImage& depth,
                                      const std::vector<ExrAttribute>& attributes,
                                      ExrCompression compression) {
    const uint8_t* base = reinterpret_cast<const uint8_t*>(depth.pixels.data());
    return encode_exr(depth.width, depth.height,
                      {{"Z", ExrSample::float32, base, sizeof(float),
                        sizeof(float) * static_cast<size_t>(depth.width)}},
                      attributes, compression);
}

}  // namespace facet
