#pragma once
// Plain 2D pixel buffers. Rows are stored top to bottom.
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include <glm/vec4.hpp>

namespace facet {

// Pixel buffers start on a cache line, so threads shading neighbouring
// tiles never write the same line where their tiles meet (tile rows span
// whole lines), and large ones on huge pages: a tile touches a row of the
// image per pixel row, 64 pages of 4 KiB where one huge page holds them all,
// and TLB misses cost more than the shading (core/image.cpp).
void* allocate_pixels(size_t bytes);
void free_pixels(void* p, size_t bytes);

template <typename T>
struct PixelAllocator {
    using value_type = T;
    PixelAllocator() = default;
    template <typename U>
    PixelAllocator(const PixelAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(allocate_pixels(n * sizeof(T))); }
    void deallocate(T* p, size_t n) { free_pixels(p, n * sizeof(T)); }
    friend bool operator==(const PixelAllocator&, const PixelAllocator&) { return true; }
};

template <typename Pixel>
struct Image {
    int width = 0;
    int height = 0;
    std::vector<Pixel, PixelAllocator<Pixel>> pixels;

    Image() = default;
    Image(int w, int h, Pixel fill = Pixel{})
        : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}

    Pixel& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Pixel& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
    bool empty() const { return pixels.empty(); }
};

using ColorImage = Image<glm::vec4>;  // linear RGBA
using DepthImage = Image<float>;      // linear view depth, +inf for background

}  // namespace facet
