#include <png.h>

#include <csetjmp>
#include <cstring>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/memory.hpp"
#include "output/encoders.hpp"

namespace facet {

namespace {

// libpng's classic reader, not its simplified one: the simplified reader
// treats 16-bit samples as linear light, so it converts sRGB-tagged files
// and premultiplies colour by alpha. A compare must see the stored values.
struct PngSource {
    std::span<const uint8_t> bytes;
    size_t offset = 0;
    char message[200] = "";
};

void read_from_memory(png_structp png, png_bytep out, png_size_t count) {
    auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
    if (count > source->bytes.size() - source->offset) png_error(png, "the file ends early");
    std::memcpy(out, source->bytes.data() + source->offset, count);
    source->offset += count;
}

void on_png_error(png_structp png, png_const_charp message) {
    auto* source = static_cast<PngSource*>(png_get_error_ptr(png));
    std::strncpy(source->message, message, sizeof source->message - 1);
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// Buffers that outlive a longjmp: C++ allows one only past objects with
// trivial destructors, so decode_rows keeps none of its own.
struct PngRows {
    std::vector<uint8_t> bytes;
    std::vector<png_bytep> pointers;
    uint64_t needed_bytes = 0;  // rows and 16-bit samples; over `max_bytes`, nothing is read
    uint64_t max_bytes = 0;
};

// libpng's read structs, freed on every way out, an exception included.
struct PngReadStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngReadStructs() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// Expands palettes, low-bit grey and tRNS to whole 8-bit channels and
// keeps 16-bit samples as stored; false when libpng reports an error.
bool decode_rows(png_structp png, png_infop info, DecodedPng& out, PngRows& rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_set_expand(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out.width = static_cast<int>(png_get_image_width(png, info));
    out.height = static_cast<int>(png_get_image_height(png, info));
    out.channels = png_get_channels(png, info);
    out.bit_depth = png_get_bit_depth(png, info);
    const size_t row_bytes = png_get_rowbytes(png, info);
    // A header may ask for a million pixels a side: refused before any
    // buffer is made, rather than met by the allocator.
    rows.needed_bytes = uint64_t{row_bytes} * static_cast<uint64_t>(out.height) * 3;
    if (rows.needed_bytes > rows.max_bytes) return true;
    rows.bytes.resize(row_bytes * static_cast<size_t>(out.height));
    rows.pointers.resize(static_cast<size_t>(out.height));
    for (size_t y = 0; y < rows.pointers.size(); ++y)
        rows.pointers[y] = rows.bytes.data() + y * row_bytes;
    png_read_image(png, rows.pointers.data());
    png_read_end(png, nullptr);
    return true;
}

}  // namespace

DecodedPng decode_png(std::span<const uint8_t> bytes, const std::string& what) {
    PngSource source{bytes};
    PngReadStructs structs;
    structs.png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, on_png_error, on_png_warning);
    if (structs.png) structs.info = png_create_info_struct(structs.png);
    if (!structs.info) throw Error(ExitCode::io_failure, what + ": cannot read PNG: out of memory");
    png_set_read_fn(structs.png, &source, read_from_memory);
    DecodedPng out;
    PngRows rows;
    rows.max_bytes = memory_available();
    if (!decode_rows(structs.png, structs.info, out, rows))
        throw Error(ExitCode::invalid_input, what + ": cannot read PNG: " + source.message);
    if (rows.needed_bytes > rows.max_bytes)
        throw Error(ExitCode::invalid_input,
                    what + ": cannot read PNG: " + std::to_string(out.width) + "x" +
                        std::to_string(out.height) + " needs " + describe_bytes(rows.needed_bytes) +
                        ", more than the " + describe_bytes(rows.max_bytes) + " available");
    const size_t count = static_cast<size_t>(out.width) * out.height * out.channels;
    if (out.bit_depth == 16) {
        out.samples.resize(count);
        for (size_t i = 0; i < count; ++i)
            out.samples[i] = static_cast<uint16_t>(rows.bytes[2 * i] << 8 | rows.bytes[2 * i + 1]);
    } else {
        out.samples.assign(rows.bytes.begin(), rows.bytes.end());
    }
    return out;
}

DecodedPng read_png(const std::string& path) {
    return decode_png(read_input_file(path, "PNG"), path);
}

}  // namespace facet
