// 8-bit PNG views of the data passes: pictures to look at, not values to
// read back (the EXR files hold those).
#include <algorithm>
#include <cmath>

#include "core/integer_hash.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

uint8_t unit_byte(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 255;
    return static_cast<uint8_t>(std::lround(v * 255.0f));
}

// RGB bytes of an image, three per pixel, from `view(pixel)`.
template <typename Pixel, typename View>
std::vector<uint8_t> encode_view(const Image<Pixel>& image, int compression,
                                 const std::vector<PngText>& text, View view) {
    std::vector<uint8_t> bytes(static_cast<size_t>(image.width) * image.height * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const std::array<uint8_t, 3> rgb = view(image.pixels[i]);
        std::copy(rgb.begin(), rgb.end(), bytes.begin() + static_cast<std::ptrdiff_t>(3 * i));
    }
    return encode_png_bytes(image.width, image.height, 3, bytes, compression, text);
}

}  // namespace

std::array<uint8_t, 3> id_view_color(uint32_t id) {
    if (id == 0) return {0, 0, 0};
    // Hue from the hash, so neighbouring ids get unrelated colours;
    // saturation and value kept high so that no id looks like the background.
    const uint32_t h = hash32(id, 0x1d5u);
    const float hue = static_cast<float>(h & 0xffffu) / 65536.0f * 6.0f;
    const float saturation = 0.55f + 0.4f * static_cast<float>((h >> 16) & 0xffu) / 255.0f;
    const float value = 0.75f + 0.25f * static_cast<float>(h >> 24) / 255.0f;
    const int sector = static_cast<int>(hue);
    const float f = hue - static_cast<float>(sector);
    const float p = value * (1 - saturation), q = value * (1 - saturation * f),
                t = value * (1 - saturation * (1 - f));
    float r = value, g = t, b = p;
    switch (sector) {
        case 1:
            r = q, g = value, b = p;
            break;
        case 2:
            r = p, g = value, b = t;
            break;
        case 3:
            r = p, g = q, b = value;
            break;
        case 4:
            r = t, g = p, b = value;
            break;
        case 5:
            r = value, g = p, b = q;
            break;
        default:
            break;
    }
    return {unit_byte(r), unit_byte(g), unit_byte(b)};
}

std::vector<uint8_t> encode_png_normal(const Image<glm::vec3>& normal, int compression,
                                       const std::vector<PngText>& text) {
    return encode_view(normal, compression, text, [](const glm::vec3& n) {
        if (n == glm::vec3(0.0f)) return std::array<uint8_t, 3>{0, 0, 0};
        return std::array<uint8_t, 3>{unit_byte(n.x * 0.5f + 0.5f), unit_byte(n.y * 0.5f + 0.5f),
                                      unit_byte(n.z * 0.5f + 0.5f)};
    });
}

std::vector<uint8_t> encode_png_ids(const Image<uint32_t>& ids, int compression,
                                    const std::vector<PngText>& text) {
    return encode_view(ids, compression, text, [](uint32_t id) { return id_view_color(id); });
}

std::vector<uint8_t> encode_png_uv(const Image<glm::vec2>& uv, int compression,
                                   const std::vector<PngText>& text) {
    return encode_view(uv, compression, text, [](const glm::vec2& t) {
        return std::array<uint8_t, 3>{unit_byte(t.x), unit_byte(t.y), 0};
    });
}

}  // namespace facet
