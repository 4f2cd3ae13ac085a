#pragma once
// Plain 2D pixel buffers. Rows are stored top to bottom.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "core/bulk_buffer.hpp"

namespace facet {

template <typename Pixel>
struct Image {
    static constexpr size_t kPixelBytes = sizeof(Pixel);  // for the memory estimate

    int width = 0;
    int height = 0;
    BulkVector<Pixel> pixels;  // see core/bulk_buffer.hpp

    Image() = default;
    Image(int w, int h, Pixel fill = Pixel{})
        : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}

    // An image whose pixels the caller writes in full before reading any.
    static Image uninitialized(int w, int h) {
        Image image;
        image.width = w;
        image.height = h;
        image.pixels.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
        return image;
    }

    Pixel& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Pixel& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
    bool empty() const { return pixels.empty(); }
};

using ColorImage = Image<glm::vec4>;  // linear RGBA
using DepthImage = Image<float>;      // linear view depth, +inf for background

}  // namespace facet
