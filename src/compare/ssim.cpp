#include "compare/ssim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace facet {
namespace {

constexpr double kSigma = 1.5;
constexpr int kRadius = 5;  // scipy's gaussian_filter: int(3.5 sigma + 0.5)
constexpr double kK1 = 0.01, kK2 = 0.03;

std::array<double, 2 * kRadius + 1> gaussian_weights() {
    std::array<double, 2 * kRadius + 1> w{};
    double sum = 0;
    for (int i = -kRadius; i <= kRadius; ++i) {
        w[static_cast<size_t>(i + kRadius)] = std::exp(-0.5 * i * i / (kSigma * kSigma));
        sum += w[static_cast<size_t>(i + kRadius)];
    }
    for (double& v : w) v /= sum;
    return w;
}

// The Gaussian-weighted mean of `f(x, y)` round every pixel whose window is
// inside the image (others are left 0): separable, rows then columns.
template <typename F>
std::vector<double> window_mean(int width, int height, F&& f) {
    static const std::array<double, 2 * kRadius + 1> w = gaussian_weights();
    std::vector<double> rows(static_cast<size_t>(width) * height, 0.0);
    for (int y = 0; y < height; ++y)
        for (int x = kRadius; x < width - kRadius; ++x) {
            double sum = 0;
            for (int i = -kRadius; i <= kRadius; ++i)
                sum += w[static_cast<size_t>(i + kRadius)] * f(x + i, y);
            rows[static_cast<size_t>(y) * width + x] = sum;
        }
    std::vector<double> out(rows.size(), 0.0);
    for (int y = kRadius; y < height - kRadius; ++y)
        for (int x = kRadius; x < width - kRadius; ++x) {
            double sum = 0;
            for (int i = -kRadius; i <= kRadius; ++i)
                sum += w[static_cast<size_t>(i + kRadius)] *
                       rows[static_cast<size_t>(y + i) * width + x];
            out[static_cast<size_t>(y) * width + x] = sum;
        }
    return out;
}

}  // namespace

SsimResult ssim(const ImagePlane& a, const ImagePlane& b, double data_range) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("ssim: the planes differ in size");
    const int w = a.width, h = a.height;
    SsimResult result;
    result.map.assign(static_cast<size_t>(w) * h, 1.0f);
    if (w <= 2 * kRadius || h <= 2 * kRadius) {
        result.mean = std::equal(a.values.begin(), a.values.end(), b.values.begin()) ? 1.0 : 0.0;
        return result;
    }
    auto at = [w](std::span<const float> v, int x, int y) {
        return static_cast<double>(v[static_cast<size_t>(y) * w + x]);
    };
    const auto mx = window_mean(w, h, [&](int x, int y) { return at(a.values, x, y); });
    const auto my = window_mean(w, h, [&](int x, int y) { return at(b.values, x, y); });
    const auto xx =
        window_mean(w, h, [&](int x, int y) { return at(a.values, x, y) * at(a.values, x, y); });
    const auto yy =
        window_mean(w, h, [&](int x, int y) { return at(b.values, x, y) * at(b.values, x, y); });
    const auto xy =
        window_mean(w, h, [&](int x, int y) { return at(a.values, x, y) * at(b.values, x, y); });
    const double c1 = (kK1 * data_range) * (kK1 * data_range);
    const double c2 = (kK2 * data_range) * (kK2 * data_range);
    double sum = 0;
    for (int y = kRadius; y < h - kRadius; ++y)
        for (int x = kRadius; x < w - kRadius; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            const double vx = xx[i] - mx[i] * mx[i], vy = yy[i] - my[i] * my[i];
            const double cov = xy[i] - mx[i] * my[i];
            const double s = ((2 * mx[i] * my[i] + c1) * (2 * cov + c2)) /
                             ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
            result.map[i] = static_cast<float>(s);
            sum += s;
        }
    result.mean = sum / (static_cast<double>(w - 2 * kRadius) * (h - 2 * kRadius));
    return result;
}

}  // namespace facet
