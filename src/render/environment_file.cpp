// Environment image files (render/environment_file.hpp,
// read_environment_image): a Radiance .hdr or an OpenEXR .exr, checked
// before it is decoded (size, shape) and after (every texel a finite,
// non-negative radiance), with messages that name the file.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "assets/image_decode.hpp"
#include "assets/radiance_image.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/memory.hpp"
#include "core/plain_text.hpp"
#include "output/encoders.hpp"
#include "render/environment_file.hpp"

namespace facet::pbr {

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw Error(ExitCode::invalid_input, path + ": " + why);
}

bool is_openexr(const std::vector<uint8_t>& bytes) {
    static constexpr uint8_t kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
    return bytes.size() >= 4 && std::memcmp(bytes.data(), kMagic, 4) == 0;
}

std::string size_text(int64_t width, int64_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// Before decoding: the shape an equirectangular image must have, the
// limit, and the memory the texels will take while they are filtered.
void check_size(const std::string& path, int width, int height, int channels) {
    if (width != 2 * static_cast<int64_t>(height))
        refuse(path, "is " + size_text(width, height) +
                         " texels, not an equirectangular (latitude-longitude) environment: "
                         "its width must be twice its height");
    if (width > kMaxEnvironmentWidth)
        refuse(path, "is " + size_text(width, height) + " texels, over the limit of " +
                         size_text(kMaxEnvironmentWidth, kMaxEnvironmentWidth / 2) +
                         " for an environment; scale it down");
    const uint64_t texels = static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
    check_memory("environment " + path,
                 {{"decoded channels", texels * static_cast<uint64_t>(channels) * 4},
                  {"RGB radiance", texels * 3 * 4}},
                 memory_available());
}

EquirectRadiance read_radiance_hdr(const std::string& path, const std::vector<uint8_t>& bytes) {
    const RadianceHdrSize size = radiance_hdr_size(bytes.data(), bytes.size(), path);
    check_size(path, size.width, size.height, 3);
    RgbFloatImage decoded = decode_radiance_hdr(bytes.data(), bytes.size(), path);
    return {decoded.width, decoded.height, std::move(decoded.rgb)};
}

EquirectRadiance read_openexr(const std::string& path) {
    const DecodedExr header = read_exr_header(path);
    const auto channel = [&](const DecodedExr& exr, const std::string& name) {
        const auto found = std::find(exr.channel_names.begin(), exr.channel_names.end(), name);
        return found == exr.channel_names.end()
                   ? -1
                   : static_cast<int>(found - exr.channel_names.begin());
    };
    if (channel(header, "R") < 0 || channel(header, "G") < 0 || channel(header, "B") < 0) {
        const std::string names = comma_list(header.channel_names);
        refuse(path, "an environment EXR needs channels R, G and B; this one has " +
                         (names.empty() ? std::string("none") : names));
    }
    check_size(path, header.width, header.height, static_cast<int>(header.channel_names.size()));
    const DecodedExr exr = read_exr(path);
    const size_t texels = static_cast<size_t>(exr.width) * static_cast<size_t>(exr.height);
    EquirectRadiance image{exr.width, exr.height, std::vector<float>(texels * 3)};
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>& values =
            exr.channels[static_cast<size_t>(channel(exr, std::string(1, "RGB"[c])))];
        for (size_t i = 0; i < texels; ++i) image.rgb[i * 3 + c] = values[i];
    }
    return image;
}

// After decoding: NaN and infinity are refused (one would spread over
// every level and every lookup), negative values set to 0 with a warning.
void check_texels(const std::string& path, EquirectRadiance& image, Warnings& warnings) {
    size_t negative = 0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        float& value = image.rgb[i];
        if (!std::isfinite(value)) {
            const size_t texel = i / 3;
            refuse(path, "texel (column " + std::to_string(texel % image.width) + ", row " +
                             std::to_string(texel / image.width) + ") is " +
                             (std::isnan(value) ? "NaN" : "infinite") +
                             ": an environment's radiance must be finite; repair the image");
        }
        if (value < 0.0f) {
            ++negative;
            value = 0.0f;
        }
    }
    if (negative > 0)
        warnings.push_back(file_warning(
            path, std::to_string(negative) +
                      " negative texel values (left by a resampling filter?) were set to 0"));
}

// The format from the first bytes, never from the name.
EquirectRadiance read_by_content(const std::string& path) {
    std::vector<uint8_t> bytes = read_input_file(path, "environment image", kMaxImageFileBytes);
    if (is_radiance_hdr(bytes.data(), bytes.size())) return read_radiance_hdr(path, bytes);
    if (is_openexr(bytes)) {
        std::vector<uint8_t>().swap(bytes);  // OpenEXR reads the file itself
        return read_openexr(path);
    }
    const ImageFormat format = sniff_image(bytes.data(), bytes.size());
    const std::string looks_like = format == ImageFormat::unknown || format == ImageFormat::other
                                       ? ""
                                       : " (it is " + image_format_name(format) + ")";
    refuse(path, "is not a Radiance .hdr or OpenEXR .exr image" + looks_like +
                     ": an environment must be one of the two, high dynamic range and "
                     "equirectangular");
}

}  // namespace

EquirectRadiance read_environment_image(const std::string& path, Warnings& warnings) {
    EquirectRadiance image = read_by_content(path);
    check_texels(path, image, warnings);
    return image;
}

SharedEnvironment load_environment(const std::string& path, Warnings& warnings, unsigned threads) {
    return build_environment(read_environment_image(path, warnings), threads);
}

}  // namespace facet::pbr
