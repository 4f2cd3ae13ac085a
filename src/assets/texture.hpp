#pragma once
// Decoded textures, kept as linear RGBA floats with a mipmap chain, sampled
// trilinearly (Williams 1983, "Pyramidal Parametrics").
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace facet {

enum class Wrap { repeat, clamp };

struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;
};

struct Texture {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;  // level 0: linear RGBA, rows top to bottom
    std::vector<MipLevel> mips;     // levels 1, 2, ... each half the size, down to 1x1
    Wrap wrap = Wrap::repeat;

    // Bilinear lookup in level 0. uv (0,0) is the top-left corner of the
    // image, as in glTF and as OBJ files are commonly authored after their v flip.
    glm::vec4 sample(glm::vec2 uv) const;

    // Trilinear lookup: `lod` is log2 of the texels one pixel step covers;
    // 0 or less is level 0, and each step up halves the resolution.
    glm::vec4 sample(glm::vec2 uv, float lod) const;

    // Fills `mips` from `texels` with a 2x2 box filter.
    void build_mipmaps();
};

// Reads PNG or JPEG (8 or 16 bit, grey, grey+alpha, RGB, RGBA). Colour
// channels are taken as sRGB and converted to linear; alpha is linear.
Texture load_texture(const std::string& path);
Texture texture_from_pixels(int width, int height, int channels, int bits, const uint8_t* data);

}  // namespace facet
