#pragma once
// Small line charts drawn into images (the thread study of `facet bench`):
// axes with labelled ticks, one or more series as lines with markers.
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image.hpp"

namespace facet {

struct PlotSeries {
    std::string name;
    std::vector<glm::dvec2> points;  // data coordinates
    glm::vec3 color{0, 0, 0};
    bool dashed = false;
};

struct PlotPanel {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    bool integer_x = false;  // x ticks at whole numbers (thread counts)
};

// Draws the panel into the rectangle (x0, y0, width, height) of `image`.
// Axes start at zero and end at a round number above the largest value.
void draw_plot(ColorImage& image, int x0, int y0, int width, int height, const PlotPanel& panel);

}  // namespace facet
