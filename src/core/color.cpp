#include "core/color.hpp"

#include <algorithm>
#include <cmath>

namespace facet {

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

double linear_to_srgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

float cie_lightness(float y) {
    y = std::clamp(y, 0.0f, 1.0f);
    constexpr float kKnee = 216.0f / 24389.0f;  // (6/29)^3
    return y <= kKnee ? y * (24389.0f / 27.0f) / 100.0f : 1.16f * std::cbrt(y) - 0.16f;
}

}  // namespace facet
