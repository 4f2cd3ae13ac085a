#include "job/labels.hpp"

#include <algorithm>
#include <vector>

#include <stb/stb_easy_font.h>

namespace facet {
namespace {

// stb_easy_font writes 4 vertices of 16 bytes per quad; about 270 bytes per
// character (its documentation), doubled for safety.
constexpr size_t kBytesPerCharacter = 540;
constexpr int kFontHeight = 12;  // font units of a line, descenders included

struct Vertex {
    float x, y, z;
    unsigned char color[4];
};

}  // namespace

int label_width(const std::string& text, int scale) {
    std::string copy = text;
    return stb_easy_font_width(copy.data()) * scale;
}

int label_height(int scale) {
    return kFontHeight * scale;
}

void draw_label(ColorImage& image, int x, int y, const std::string& text, const glm::vec3& color,
                int scale) {
    std::string copy = text;
    std::vector<Vertex> quads(copy.size() * kBytesPerCharacter / sizeof(Vertex) + 4);
    const int count = stb_easy_font_print(0, 0, copy.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(Vertex)));
    for (int q = 0; q < count; ++q) {
        const Vertex* v = &quads[static_cast<size_t>(4 * q)];
        // Quads are axis-aligned rectangles: corners 0 and 2 are opposite.
        const int x0 = x + static_cast<int>(std::min(v[0].x, v[2].x)) * scale;
        const int x1 = x + static_cast<int>(std::max(v[0].x, v[2].x)) * scale;
        const int y0 = y + static_cast<int>(std::min(v[0].y, v[2].y)) * scale;
        const int y1 = y + static_cast<int>(std::max(v[0].y, v[2].y)) * scale;
        for (int py = std::max(y0, 0); py < std::min(y1, image.height); ++py)
            for (int px = std::max(x0, 0); px < std::min(x1, image.width); ++px)
                image.at(px, py) = glm::vec4(color, 1.0f);
    }
}

}  // namespace facet
