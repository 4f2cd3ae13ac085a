#include "core/half.hpp"

namespace facet {

ColorImage to_float_image(const HalfColorImage& image) {
    ColorImage out(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) out.pixels[i] = to_float(image.pixels[i]);
    return out;
}

HalfColorImage to_half_image(const ColorImage& image) {
    HalfColorImage out(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) out.pixels[i] = to_half(image.pixels[i]);
    return out;
}

}  // namespace facet
