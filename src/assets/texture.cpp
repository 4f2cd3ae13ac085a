#include "assets/texture.hpp"

#include <stb/stb_image.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "core/color.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

const std::array<float, 256>& srgb8_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
        return t;
    }();
    return table;
}

// The texel column (or row) at whole texel index i and the one after it,
// for the wrap mode. Repeat wraps with a mask when the size is a power of
// two (the usual texture), else with one remainder: the division is the
// dearest step of a lookup.
struct TexelPair {
    int first, second;
};

TexelPair wrap_pair(int i, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) {
        auto clamp = [size](int v) { return v < 0 ? 0 : (v >= size ? size - 1 : v); };
        return {clamp(i), clamp(i + 1)};
    }
    int first;
    if ((size & (size - 1)) == 0) {
        first = i & (size - 1);  // two's complement: right for negative i too
    } else {
        first = i % size;
        if (first < 0) first += size;
    }
    return {first, first + 1 == size ? 0 : first + 1};
}

}  // namespace

namespace {

glm::vec4 bilinear(const glm::vec4* texels, int width, int height, Wrap wrap, glm::vec2 uv) {
    // Texel centres sit at half-integer coordinates.
    float x = uv.x * static_cast<float>(width) - 0.5f;
    float y = uv.y * static_cast<float>(height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return texels[0];
    if (wrap == Wrap::clamp) {
        // Clamp before the fmod below: far outside the image the edge texel
        // must win, not whatever texel the remainder happens to land on.
        x = std::clamp(x, -1.0f, static_cast<float>(width));
        y = std::clamp(y, -1.0f, static_cast<float>(height));
    }
    // Keep the float->int conversion in range for huge repeat counts (at
    // 2^24 and beyond every float is whole, so this keeps x's fraction).
    constexpr float kWhole = 16777216.0f;
    if (!(std::fabs(x) < kWhole)) x = std::fmod(x, kWhole);
    if (!(std::fabs(y) < kWhole)) y = std::fmod(y, kWhole);
    float fx = std::floor(x), fy = std::floor(y);
    float tx = x - fx, ty = y - fy;
    const TexelPair xs = wrap_pair(static_cast<int>(fx), width, wrap);
    const TexelPair ys = wrap_pair(static_cast<int>(fy), height, wrap);
    const int xa = xs.first, xb = xs.second, ya = ys.first, yb = ys.second;
    const glm::vec4& a = texels[static_cast<size_t>(ya) * width + xa];
    const glm::vec4& b = texels[static_cast<size_t>(ya) * width + xb];
    const glm::vec4& c = texels[static_cast<size_t>(yb) * width + xa];
    const glm::vec4& d = texels[static_cast<size_t>(yb) * width + xb];
    glm::vec4 top = a + (b - a) * tx;
    glm::vec4 bottom = c + (d - c) * tx;
    return top + (bottom - top) * ty;
}

}  // namespace

glm::vec4 Texture::sample(glm::vec2 uv) const {
    if (texels.empty()) return glm::vec4(1);
    return bilinear(texels.data(), width, height, wrap, uv);
}

glm::vec4 Texture::sample(glm::vec2 uv, float lod) const {
    if (texels.empty()) return glm::vec4(1);
    if (!(lod > 0.0f) || mips.empty()) return sample(uv);  // also NaN
    const float top = static_cast<float>(mips.size());
    if (lod >= top) {
        const MipLevel& m = mips.back();
        return bilinear(m.texels.data(), m.width, m.height, wrap, uv);
    }
    const int level = static_cast<int>(lod);
    const float t = lod - static_cast<float>(level);
    auto at = [&](int l) {
        if (l == 0) return bilinear(texels.data(), width, height, wrap, uv);
        const MipLevel& m = mips[static_cast<size_t>(l - 1)];
        return bilinear(m.texels.data(), m.width, m.height, wrap, uv);
    };
    glm::vec4 fine = at(level);
    glm::vec4 coarse = at(level + 1);
    return fine + (coarse - fine) * t;
}

void Texture::build_mipmaps() {
    mips.clear();
    int w = width, h = height;
    const glm::vec4* src = texels.data();
    while (w > 1 || h > 1) {
        // Halve, rounding up; an odd last row or column is averaged with itself.
        MipLevel next;
        next.width = (w + 1) / 2;
        next.height = (h + 1) / 2;
        next.texels.resize(static_cast<size_t>(next.width) * next.height);
        for (int y = 0; y < next.height; ++y) {
            const int y0 = 2 * y, y1 = std::min(2 * y + 1, h - 1);
            for (int x = 0; x < next.width; ++x) {
                const int x0 = 2 * x, x1 = std::min(2 * x + 1, w - 1);
                next.texels[static_cast<size_t>(y) * next.width + x] =
                    (src[static_cast<size_t>(y0) * w + x0] + src[static_cast<size_t>(y0) * w + x1] +
                     src[static_cast<size_t>(y1) * w + x0] +
                     src[static_cast<size_t>(y1) * w + x1]) *
                    0.25f;
            }
        }
        mips.push_back(std::move(next));
        w = mips.back().width;
        h = mips.back().height;
        src = mips.back().texels.data();
    }
}

Texture texture_from_pixels(int width, int height, int channels, int bits, const uint8_t* data) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || (bits != 8 && bits != 16))
        throw Error(ExitCode::invalid_input, "unsupported image layout (" + std::to_string(width) +
                                                 "x" + std::to_string(height) + ", " +
                                                 std::to_string(channels) + " channels, " +
                                                 std::to_string(bits) + " bits)");
    Texture tex;
    tex.width = width;
    tex.height = height;
    tex.texels.resize(static_cast<size_t>(width) * height);
    const auto& table = srgb8_table();
    for (size_t i = 0; i < tex.texels.size(); ++i) {
        float v[4] = {0, 0, 0, 1};
        for (int c = 0; c < channels; ++c) {
            size_t at = i * channels + c;
            if (bits == 8) {
                uint8_t byte = data[at];
                bool alpha = (channels == 2 && c == 1) || (channels == 4 && c == 3);
                v[c] = alpha ? byte / 255.0f : table[byte];
            } else {
                uint16_t word;
                std::memcpy(&word, data + 2 * at, 2);
                bool alpha = (channels == 2 && c == 1) || (channels == 4 && c == 3);
                float f = word / 65535.0f;
                v[c] = alpha ? f : srgb_to_linear(f);
            }
        }
        if (channels <= 2)
            tex.texels[i] = {v[0], v[0], v[0], channels == 2 ? v[1] : 1.0f};
        else
            tex.texels[i] = {v[0], v[1], v[2], channels == 4 ? v[3] : 1.0f};
    }
    tex.build_mipmaps();
    return tex;
}

Texture load_texture(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    bool is16 = stbi_is_16_bit(path.c_str());
    void* data = is16 ? static_cast<void*>(stbi_load_16(path.c_str(), &w, &h, &channels, 0))
                      : static_cast<void*>(stbi_load(path.c_str(), &w, &h, &channels, 0));
    if (!data)
        throw Error(ExitCode::invalid_input,
                    path + ": cannot decode image (" + stbi_failure_reason() + ")");
    try {
        Texture tex =
            texture_from_pixels(w, h, channels, is16 ? 16 : 8, static_cast<const uint8_t*>(data));
        stbi_image_free(data);
        return tex;
    } catch (const Error& e) {
        stbi_image_free(data);
        throw Error(ExitCode::invalid_input, path + ": " + e.what());
    }
}

}  // namespace facet
