#include "compare/compare_image.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/color.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

bool has_extension(const std::string& path, const char* ext) {
    const std::string lower = [&] {
        std::string s = path.substr(path.size() >= 4 ? path.size() - 4 : 0);
        std::transform(s.begin(), s.end(), s.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        return s;
    }();
    return lower == ext;
}

// PNG and EXR are told apart by their first bytes, not their names.
bool is_exr(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {};
    if (!in.read(reinterpret_cast<char*>(magic), 4)) return has_extension(path, ".exr");
    return magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

[[noreturn]] void unreadable(const std::string& path, const std::string& why) {
    throw Error(ExitCode::io_failure, path + ": cannot compare: " + why);
}

int find_channel(const DecodedExr& exr, std::initializer_list<const char*> names) {
    for (const char* name : names)
        for (size_t c = 0; c < exr.channel_names.size(); ++c)
            if (exr.channel_names[c] == name) return static_cast<int>(c);
    return -1;
}

std::string channel_list(const DecodedExr& exr) {
    std::string s;
    for (const auto& n : exr.channel_names) s += (s.empty() ? "" : ",") + n;
    return s;
}

CompareImage from_exr(const std::string& path, ImageKind kind) {
    DecodedExr exr;
    try {
        exr = read_exr(path);
    } catch (const Error& e) {
        unreadable(path, e.detail().empty() ? e.what() : e.detail());
    }
    CompareImage image;
    image.width = exr.width;
    image.height = exr.height;
    image.description = "EXR " + channel_list(exr);
    std::vector<int> wanted;
    switch (kind) {
        case ImageKind::color:
        case ImageKind::color_float:
            wanted = {find_channel(exr, {"R"}), find_channel(exr, {"G"}), find_channel(exr, {"B"})};
            break;
        case ImageKind::depth:
            wanted = {find_channel(exr, {"Z", "depth.Z", "Depth.Z"})};
            break;
        case ImageKind::normal:
            wanted = {find_channel(exr, {"N.X", "X"}), find_channel(exr, {"N.Y", "Y"}),
                      find_channel(exr, {"N.Z", "Z"})};
            break;
        case ImageKind::alpha:
            wanted = {find_channel(exr, {"A"})};
            break;
        case ImageKind::id:
            if (exr.channel_names.size() != 1)
                unreadable(path, "an id image has one channel, this one has " + channel_list(exr));
            wanted = {0};
            break;
        case ImageKind::float_data:
            for (size_t c = 0; c < exr.channel_names.size(); ++c)
                if (exr.channel_names[c] != "A") wanted.push_back(static_cast<int>(c));
            break;
    }
    if (wanted.empty() || std::count(wanted.begin(), wanted.end(), -1))
        unreadable(path, std::string("has no channels for a ") + image_kind_name(kind) +
                             " image (it has " + channel_list(exr) + ")");
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    image.channels = static_cast<int>(wanted.size());
    image.samples.resize(pixels * wanted.size());
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < wanted.size(); ++c)
            image.samples[p * wanted.size() + c] = exr.channels[wanted[c]][p];
    if (kind != ImageKind::alpha)
        if (int a = find_channel(exr, {"A"}); a >= 0) image.alpha = exr.channels[a];
    return image;
}

CompareImage from_png(const std::string& path, ImageKind kind) {
    DecodedPng png;
    try {
        png = read_png(path);
    } catch (const Error& e) {
        unreadable(path, e.detail().empty() ? e.what() : e.detail());
    }
    CompareImage image;
    image.width = png.width;
    image.height = png.height;
    const bool has_alpha = png.channels == 2 || png.channels == 4;
    const int colour_channels = png.channels - (has_alpha ? 1 : 0);
    image.description = "PNG " + std::to_string(png.bit_depth) + "-bit " +
                        (colour_channels == 3 ? "RGB" : "grey") + (has_alpha ? "A" : "");
    const float scale = png.bit_depth == 16 ? 65535.0f : 255.0f;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    auto sample = [&](size_t p, int c) { return png.samples[p * png.channels + c]; };
    if (kind == ImageKind::depth) {
        if (colour_channels != 1)
            unreadable(path, "a depth view is a grey PNG, this is " + image.description);
        image.channels = 1;
        image.samples.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) {
            const float v = sample(p, 0);
            image.samples[p] = v == 0 ? std::numeric_limits<float>::infinity() : 1.0f - v / scale;
        }
        return image;
    }
    if (kind == ImageKind::id) {
        image.channels = 1;
        image.samples.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) {
            float packed = sample(p, 0);
            if (colour_channels == 3)
                packed = sample(p, 0) * 65536.0f + sample(p, 1) * 256.0f + sample(p, 2);
            image.samples[p] = packed;
        }
        return image;
    }
    if (kind == ImageKind::alpha) {
        image.channels = 1;
        image.samples.resize(pixels);
        for (size_t p = 0; p < pixels; ++p)
            image.samples[p] =
                has_alpha ? sample(p, png.channels - 1) / scale : sample(p, 0) / scale;
        return image;
    }
    // Colour and every other view: R, G, B (grey repeated), alpha apart.
    image.channels = 3;
    image.samples.resize(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c)
            image.samples[p * 3 + c] = sample(p, colour_channels == 3 ? c : 0) / scale;
    if (has_alpha) {
        image.alpha.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) image.alpha[p] = sample(p, png.channels - 1) / scale;
    }
    return image;
}

}  // namespace

ImageKind kind_for_pass(const std::string& pass, const std::string& format) {
    const bool exr = format == "exr";
    if (pass == "color") return exr ? ImageKind::color_float : ImageKind::color;
    if (pass == "depth") return ImageKind::depth;
    if (pass == "alpha") return ImageKind::alpha;
    if (pass == "object_id" || pass == "material_id") return ImageKind::id;
    if (pass == "normal") return exr ? ImageKind::normal : ImageKind::color;
    return exr ? ImageKind::float_data : ImageKind::color;
}

ImageKind guess_image_kind(const std::string& path) {
    if (is_exr(path)) {
        DecodedExr exr;
        try {
            exr = read_exr(path);
        } catch (const Error& e) {
            unreadable(path, e.detail().empty() ? e.what() : e.detail());
        }
        if (find_channel(exr, {"R"}) >= 0) return ImageKind::color_float;
        if (find_channel(exr, {"N.X"}) >= 0) return ImageKind::normal;
        if (find_channel(exr, {"Z", "depth.Z", "Depth.Z"}) >= 0) return ImageKind::depth;
        if (exr.channel_names.size() == 1 && exr.channel_names[0].find("id") != std::string::npos)
            return ImageKind::id;
        return ImageKind::float_data;
    }
    DecodedPng png;
    try {
        png = read_png(path);
    } catch (const Error& e) {
        unreadable(path, e.detail().empty() ? e.what() : e.detail());
    }
    return png.channels == 1 && png.bit_depth == 16 ? ImageKind::depth : ImageKind::color;
}

CompareImage read_compare_image(const std::string& path, ImageKind kind) {
    if (is_exr(path)) {
        CompareImage image = from_exr(path, kind);
        return image;
    }
    return from_png(path, kind);
}

double sequence_white(const std::vector<std::string>& ref_paths) {
    double white = 0;
    for (const std::string& path : ref_paths) {
        if (path.empty() || !input_file_problem(path).empty()) continue;
        CompareImage image;
        try {
            image = read_compare_image(path, ImageKind::color_float);
        } catch (const Error&) {
            continue;  // reported when the frame itself is compared
        }
        std::vector<float> luminance;
        luminance.reserve(image.samples.size() / 3);
        for (size_t i = 0; i + 2 < image.samples.size(); i += 3) {
            const float y =
                rec709_luminance(image.samples[i], image.samples[i + 1], image.samples[i + 2]);
            if (std::isfinite(y) && y > 0) luminance.push_back(y);
        }
        if (luminance.empty()) continue;
        const size_t k = std::min(luminance.size() - 1, luminance.size() * 999 / 1000);
        std::nth_element(luminance.begin(), luminance.begin() + static_cast<ptrdiff_t>(k),
                         luminance.end());
        white = std::max(white, static_cast<double>(luminance[k]));
    }
    return white > 0 ? white : 1.0;
}

}  // namespace facet
