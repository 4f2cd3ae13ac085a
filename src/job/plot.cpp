#include "job/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "job/labels.hpp"

namespace facet {
namespace {

constexpr int kLabelScale = 1;
constexpr int kMargin = 44;  // pixels left of and below the axes, for tick labels
const glm::vec3 kAxisColor(0.1f, 0.1f, 0.1f);
const glm::vec3 kGridColor(0.82f, 0.82f, 0.82f);

void plot_pixel(ColorImage& image, int x, int y, const glm::vec3& color) {
    if (x >= 0 && y >= 0 && x < image.width && y < image.height)
        image.at(x, y) = glm::vec4(color, 1.0f);
}

// A line `thickness` pixels wide by stepping along its longer axis
// (a DDA: one step per pixel along that axis, the other coordinate
// rounded), optionally dashed.
void draw_line(ColorImage& image, glm::dvec2 a, glm::dvec2 b, const glm::vec3& color, int thickness,
               bool dashed = false) {
    const double steps = std::max({std::abs(b.x - a.x), std::abs(b.y - a.y), 1.0});
    for (int i = 0; i <= static_cast<int>(steps); ++i) {
        if (dashed && (i / 6) % 2 == 1) continue;
        const glm::dvec2 p = a + (b - a) * (i / steps);
        const int px = static_cast<int>(std::lround(p.x)), py = static_cast<int>(std::lround(p.y));
        for (int dy = -(thickness / 2); dy <= (thickness - 1) / 2; ++dy)
            for (int dx = -(thickness / 2); dx <= (thickness - 1) / 2; ++dx)
                plot_pixel(image, px + dx, py + dy, color);
    }
}

// 1, 2 or 5 times a power of ten, at least `value`.
double round_up(double value) {
    if (!(value > 0)) return 1;
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= value) return m * power;
    return 10 * power;
}

std::string format_tick(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

void draw_plot(ColorImage& image, int x0, int y0, int width, int height, const PlotPanel& panel) {
    double max_x = 0, max_y = 0;
    for (const PlotSeries& s : panel.series)
        for (const glm::dvec2& p : s.points) {
            max_x = std::max(max_x, p.x);
            max_y = std::max(max_y, p.y);
        }
    max_x = panel.integer_x ? std::max(1.0, std::ceil(max_x)) : round_up(max_x);
    max_y = round_up(max_y * 1.05);
    const int top = y0 + 2 * label_height(kLabelScale) + 8;
    const int left = x0 + kMargin, right = x0 + width - 12, bottom = y0 + height - kMargin;
    auto to_screen = [&](glm::dvec2 p) {
        return glm::dvec2(left + (right - left) * p.x / max_x,
                          bottom - (bottom - top) * p.y / max_y);
    };

    constexpr int kTicks = 5;
    const int x_ticks = panel.integer_x && max_x <= 16 ? static_cast<int>(max_x) : kTicks;
    for (int t = 0; t <= x_ticks; ++t) {
        const double fx = max_x * t / x_ticks;
        const glm::dvec2 gx = to_screen({fx, 0});
        draw_line(image, gx, to_screen({fx, max_y}), kGridColor, 1);
        const std::string tx = format_tick(fx);
        draw_label(image, static_cast<int>(gx.x) - label_width(tx, kLabelScale) / 2, bottom + 4, tx,
                   kAxisColor, kLabelScale);
    }
    for (int t = 0; t <= kTicks; ++t) {
        const double fy = max_y * t / kTicks;
        const glm::dvec2 gy = to_screen({0, fy});
        draw_line(image, gy, to_screen({max_x, fy}), kGridColor, 1);
        const std::string ty = format_tick(fy);
        draw_label(image, left - 6 - label_width(ty, kLabelScale),
                   static_cast<int>(gy.y) - label_height(kLabelScale) / 2, ty, kAxisColor,
                   kLabelScale);
    }
    draw_line(image, {left, bottom}, {right, bottom}, kAxisColor, 1);
    draw_line(image, {left, bottom}, {left, top}, kAxisColor, 1);
    draw_label(image, left, y0 + 2, panel.title, kAxisColor, kLabelScale);
    draw_label(image, (left + right - label_width(panel.x_label, kLabelScale)) / 2,
               bottom + 6 + label_height(kLabelScale), panel.x_label, kAxisColor, kLabelScale);
    draw_label(image, left + 4, top - label_height(kLabelScale) - 2, panel.y_label, kAxisColor,
               kLabelScale);

    int legend_y = top + 4;
    for (const PlotSeries& s : panel.series) {
        for (size_t i = 1; i < s.points.size(); ++i)
            draw_line(image, to_screen(s.points[i - 1]), to_screen(s.points[i]), s.color, 2,
                      s.dashed);
        for (const glm::dvec2& p : s.points) {
            const glm::dvec2 c = to_screen(p);
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx)
                    plot_pixel(image, static_cast<int>(c.x) + dx, static_cast<int>(c.y) + dy,
                               s.color);
        }
        draw_line(image, {right - 110.0, legend_y + 5.0}, {right - 90.0, legend_y + 5.0}, s.color,
                  2, s.dashed);
        draw_label(image, right - 84, legend_y, s.name, kAxisColor, kLabelScale);
        legend_y += label_height(kLabelScale) + 2;
    }
}

}  // namespace facet
