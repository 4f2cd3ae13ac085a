#include <png.h>

#include "core/error.hpp"
#include "output/encoders.hpp"

namespace facet {

namespace {

// The rest of a read once libpng has the header: `path` names the file in errors.
DecodedPng finish_reading(png_image& image, const std::string& path) {
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

}  // namespace

DecodedPng read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str()))
        throw Error(ExitCode::invalid_input, path + ": cannot read PNG: " + image.message);
    return finish_reading(image, path);
}

DecodedPng decode_png(std::span<const uint8_t> bytes, const std::string& what) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
        throw Error(ExitCode::invalid_input, what + ": cannot read PNG: " + image.message);
    return finish_reading(image, what);
}

}  // namespace facet
