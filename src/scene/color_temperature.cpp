#include "scene/color_temperature.hpp"

#include <algorithm>

namespace facet {

LinearRgb kelvin_to_linear_srgb(double kelvin) {
    const double t = std::clamp(kelvin, kMinKelvin, kMaxKelvin);
    const double t1 = 1e3 / t, t2 = t1 * t1, t3 = t2 * t1;
    // Chromaticity x, then y from x (Kang et al. 2002, three pieces of y).
    const double x = t <= 4000 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                               : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
    const double x2 = x * x, x3 = x2 * x;
    double y;
    if (t <= 2222)
        y = -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683;
    else if (t <= 4000)
        y = -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867;
    else
        y = 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    // XYZ with Y = 1, then the XYZ -> linear sRGB matrix of IEC 61966-2-1.
    const double X = x / y, Y = 1.0, Z = (1.0 - x - y) / y;
    double r = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
    double g = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
    double b = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
    r = std::max(r, 0.0);
    g = std::max(g, 0.0);
    b = std::max(b, 0.0);
    const double peak = std::max({r, g, b});
    return {r / peak, g / peak, b / peak};
}

}  // namespace facet
