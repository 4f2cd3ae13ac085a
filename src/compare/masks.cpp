#include "compare/masks.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace facet {

std::vector<uint8_t> MaskBuilder::build(const std::string& camera, ImageKind kind, int width,
                                        int height) {
    std::vector<uint8_t> mask;
    for (const CompareMask& m : thresholds_.masks) {
        if (!m.camera.empty() && m.camera != camera) continue;
        if (m.kind && *m.kind != kind) continue;
        if (mask.empty()) mask.assign(static_cast<size_t>(width) * height, 1);
        if (m.image.empty()) {
            for (int y = std::max(0, m.y); y < std::min(height, m.y + m.height); ++y)
                for (int x = std::max(0, m.x); x < std::min(width, m.x + m.width); ++x)
                    mask[static_cast<size_t>(y) * width + x] = 0;
            continue;
        }
        const DecodedPng& image = mask_image(m.image);
        if (image.width != width || image.height != height)
            throw Error(ExitCode::invalid_input,
                        m.image + ": mask image is " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) + ", the images are " +
                            std::to_string(width) + "x" + std::to_string(height));
        // Non-black is left out; a mask's alpha channel plays no part.
        const int colour_channels = image.channels >= 3 ? 3 : 1;
        for (size_t p = 0; p < mask.size(); ++p)
            for (int c = 0; c < colour_channels; ++c)
                if (image.samples[p * image.channels + c] != 0) mask[p] = 0;
    }
    return mask;
}

const DecodedPng& MaskBuilder::mask_image(const std::string& path) {
    auto it = images_.find(path);
    if (it != images_.end()) return it->second;
    try {
        return images_.emplace(path, read_png(path)).first->second;
    } catch (const Error& e) {
        throw Error(ExitCode::invalid_input, std::string("mask image: ") + e.what());
    }
}

}  // namespace facet
