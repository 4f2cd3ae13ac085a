#pragma once
// Text labels drawn into images (contact sheets), with the public-domain
// stb_easy_font glyphs: ASCII, built from rectangles, scaled by whole pixels.
#include <string>

#include <glm/vec3.hpp>

#include "core/image.hpp"

namespace facet {

// Size of `text` in pixels at `scale` (pixels per font unit).
int label_width(const std::string& text, int scale);
int label_height(int scale);

// Draws `text` with its top-left corner at (x, y), clipped to the image.
void draw_label(ColorImage& image, int x, int y, const std::string& text, const glm::vec3& color,
                int scale);

}  // namespace facet
