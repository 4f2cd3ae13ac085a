#pragma once
// Decoded textures, kept as linear RGBA floats, sampled bilinearly.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace facet {

enum class Wrap { repeat, clamp };

struct Texture {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;  // linear RGBA, rows top to bottom
    Wrap wrap = Wrap::repeat;

    // Bilinear lookup. uv (0,0) is the top-left corner of the image, as in
    // glTF and as OBJ files are commonly authored after their v flip.
    glm::vec4 sample(glm::vec2 uv) const;
};

// Reads PNG or JPEG (8 or 16 bit, grey, grey+alpha, RGB, RGBA). Colour
// channels are taken as sRGB and converted to linear; alpha is linear.
Texture load_texture(const std::string& path);
Texture texture_from_pixels(int width, int height, int channels, int bits, const uint8_t* data);

}  // namespace facet
