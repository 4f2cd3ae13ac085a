#include "assets/texture.hpp"

#include <stb/stb_image.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>

#include "core/color.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"

namespace facet {
namespace {

// Linear values of the 256 sRGB bytes.
const std::array<float, 256>& srgb8_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
        return t;
    }();
    return table;
}

uint8_t to_byte(float unit) {
    return static_cast<uint8_t>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f));
}

uint32_t encode_srgb8(const glm::vec4& c) {
    return uint32_t(to_byte(linear_to_srgb(std::clamp(c.r, 0.0f, 1.0f)))) |
           uint32_t(to_byte(linear_to_srgb(std::clamp(c.g, 0.0f, 1.0f)))) << 8 |
           uint32_t(to_byte(linear_to_srgb(std::clamp(c.b, 0.0f, 1.0f)))) << 16 |
           uint32_t(to_byte(c.a)) << 24;
}

glm::vec4 decode_srgb8(uint32_t t, const std::array<float, 256>& table) {
    return {table[t & 0xff], table[(t >> 8) & 0xff], table[(t >> 16) & 0xff],
            static_cast<float>(t >> 24) * (1.0f / 255.0f)};
}

glm::vec4 texel_at(const TextureLevel& l, size_t i, const std::array<float, 256>& table) {
    if (!l.srgb8.empty()) return decode_srgb8(l.srgb8[i], table);
    const Rgba16F& h = l.half[i];
    return {half_to_float(h.r), half_to_float(h.g), half_to_float(h.b), half_to_float(h.a)};
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

glm::vec4 bilinear(const TextureLevel& l, Wrap wrap, glm::vec2 uv) {
    const auto& table = srgb8_table();
    const int width = l.width, height = l.height;
    // Texel centres sit at half-integer coordinates.
    float x = uv.x * static_cast<float>(width) - 0.5f;
    float y = uv.y * static_cast<float>(height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return texel_at(l, 0, table);
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
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const TexelPair xs = wrap_pair(static_cast<int>(fx), width, wrap);
    const TexelPair ys = wrap_pair(static_cast<int>(fy), height, wrap);
    const size_t row_a = static_cast<size_t>(ys.first) * width;
    const size_t row_b = static_cast<size_t>(ys.second) * width;
    const glm::vec4 a = texel_at(l, row_a + xs.first, table);
    const glm::vec4 b = texel_at(l, row_a + xs.second, table);
    const glm::vec4 c = texel_at(l, row_b + xs.first, table);
    const glm::vec4 d = texel_at(l, row_b + xs.second, table);
    const glm::vec4 top = a + (b - a) * tx;
    const glm::vec4 bottom = c + (d - c) * tx;
    return top + (bottom - top) * ty;
}

void store(TextureLevel& l, Texture::Format format, size_t i, const glm::vec4& c) {
    if (format == Texture::Format::srgb8)
        l.srgb8[i] = encode_srgb8(c);
    else
        l.half[i] = to_half(c);
}

TextureLevel empty_level(int width, int height, Texture::Format format) {
    TextureLevel l;
    l.width = width;
    l.height = height;
    const size_t n = static_cast<size_t>(width) * height;
    if (format == Texture::Format::srgb8)
        l.srgb8.resize(n);
    else
        l.half.resize(n);
    return l;
}

// Levels 1, 2, ... down to 1x1, each a 2x2 box filter of the one before in
// linear light, rounding up; an odd last row or column is averaged with
// itself.
void add_mipmaps(std::vector<TextureLevel>& levels, Texture::Format format) {
    const auto& table = srgb8_table();
    while (levels.back().width > 1 || levels.back().height > 1) {
        const TextureLevel& src = levels.back();
        const int w = src.width, h = src.height;
        TextureLevel next = empty_level((w + 1) / 2, (h + 1) / 2, format);
        for (int y = 0; y < next.height; ++y) {
            const size_t y0 = static_cast<size_t>(2 * y), y1 = std::min(2 * y + 1, h - 1);
            for (int x = 0; x < next.width; ++x) {
                const size_t x0 = static_cast<size_t>(2 * x), x1 = std::min(2 * x + 1, w - 1);
                const glm::vec4 sum =
                    texel_at(src, y0 * w + x0, table) + texel_at(src, y0 * w + x1, table) +
                    texel_at(src, y1 * w + x0, table) + texel_at(src, y1 * w + x1, table);
                store(next, format, static_cast<size_t>(y) * next.width + x, sum * 0.25f);
            }
        }
        levels.push_back(std::move(next));
    }
}

void check_size(int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide)
        throw Error(ExitCode::invalid_input,
                    "image of " + std::to_string(width) + "x" + std::to_string(height) +
                        " pixels (each side must be 1 to " + std::to_string(kMaxImageSide) + ")");
}

}  // namespace

Texture Texture::from_linear(int width, int height, const std::vector<glm::vec4>& texels,
                             Format format) {
    check_size(width, height);
    if (texels.size() != static_cast<size_t>(width) * height)
        throw Error(ExitCode::invalid_input, "texel count does not match the texture's size");
    TextureLevel base = empty_level(width, height, format);
    for (size_t i = 0; i < texels.size(); ++i) store(base, format, i, texels[i]);
    return from_base_level(format, std::move(base));
}

Texture Texture::from_base_level(Format format, TextureLevel base) {
    Texture t;
    t.width = base.width;
    t.height = base.height;
    t.format_ = format;
    std::vector<TextureLevel> levels{std::move(base)};
    add_mipmaps(levels, format);
    t.levels_ = std::make_shared<const std::vector<TextureLevel>>(std::move(levels));
    return t;
}

glm::vec4 Texture::texel(int level_index, int x, int y) const {
    const TextureLevel& l = level(level_index);
    return texel_at(l, static_cast<size_t>(y) * l.width + x, srgb8_table());
}

uint64_t Texture::bytes() const {
    uint64_t n = 0;
    for (int i = 0; i < level_count(); ++i)
        n += level(i).srgb8.size() * sizeof(uint32_t) + level(i).half.size() * sizeof(Rgba16F);
    return n;
}

glm::vec4 Texture::sample(glm::vec2 uv) const {
    if (!levels_) return glm::vec4(1);
    return bilinear(level(0), wrap, uv);
}

glm::vec4 Texture::sample(glm::vec2 uv, float lod) const {
    if (!levels_) return glm::vec4(1);
    if (!(lod > 0.0f) || level_count() == 1) return sample(uv);  // also NaN
    const float top = static_cast<float>(level_count() - 1);
    if (lod >= top) return bilinear(level(level_count() - 1), wrap, uv);
    const int fine_level = static_cast<int>(lod);
    const float t = lod - static_cast<float>(fine_level);
    const glm::vec4 fine = bilinear(level(fine_level), wrap, uv);
    const glm::vec4 coarse = bilinear(level(fine_level + 1), wrap, uv);
    return fine + (coarse - fine) * t;
}

uint64_t texture_bytes(int width, int height, int bits) {
    const uint64_t texel = bits == 8 ? sizeof(uint32_t) : sizeof(Rgba16F);
    uint64_t n = 0;
    uint64_t w = static_cast<uint64_t>(std::max(width, 1)),
             h = static_cast<uint64_t>(std::max(height, 1));
    for (;;) {
        n += w * h * texel;
        if (w == 1 && h == 1) break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    return n;
}

Texture texture_from_pixels(int width, int height, int channels, int bits, const uint8_t* data) {
    if (channels < 1 || channels > 4 || (bits != 8 && bits != 16))
        throw Error(ExitCode::invalid_input, "unsupported image layout (" + std::to_string(width) +
                                                 "x" + std::to_string(height) + ", " +
                                                 std::to_string(channels) + " channels, " +
                                                 std::to_string(bits) + " bits)");
    check_size(width, height);
    const Texture::Format format = bits == 8 ? Texture::Format::srgb8 : Texture::Format::half;
    TextureLevel base = empty_level(width, height, format);
    const size_t n = static_cast<size_t>(width) * height;
    const bool has_alpha = channels == 2 || channels == 4;
    for (size_t i = 0; i < n; ++i) {
        const size_t at = i * static_cast<size_t>(channels);
        if (bits == 8) {
            // Bytes stay as they are: colour sRGB, alpha linear.
            const uint8_t* p = data + at;
            const uint32_t r = p[0], g = channels >= 3 ? p[1] : r, b = channels >= 3 ? p[2] : r;
            const uint32_t a = has_alpha ? p[channels - 1] : 255;
            base.srgb8[i] = r | g << 8 | b << 16 | a << 24;
        } else {
            float v[4];
            for (int c = 0; c < channels; ++c) {
                uint16_t word;
                std::memcpy(&word, data + 2 * (at + static_cast<size_t>(c)), 2);
                v[c] = word / 65535.0f;
            }
            const float r = v[0], g = channels >= 3 ? v[1] : r, b = channels >= 3 ? v[2] : r;
            const float a = has_alpha ? v[channels - 1] : 1.0f;
            base.half[i] =
                to_half(glm::vec4(srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a));
        }
    }
    return Texture::from_base_level(format, std::move(base));
}

Texture load_texture(const std::string& path, TextureBudget* budget) {
    const std::vector<uint8_t> bytes = read_input_file(path, "image", kMaxImageFileBytes);
    if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        throw Error(ExitCode::invalid_input, path + ": cannot read image: the file is too large");
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels))
        throw Error(ExitCode::invalid_input,
                    path + ": cannot decode image (" + stbi_failure_reason() + ")");
    const bool is16 = stbi_is_16_bit_from_memory(bytes.data(), size);
    try {
        check_size(w, h);
    } catch (const Error& e) {
        throw Error(ExitCode::invalid_input, path + ": " + e.what());
    }
    if (budget) budget->charge(path, w, h, texture_bytes(w, h, is16 ? 16 : 8));
    void* data =
        is16
            ? static_cast<void*>(stbi_load_16_from_memory(bytes.data(), size, &w, &h, &channels, 0))
            : static_cast<void*>(stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 0));
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

struct TextureBudget::State {
    std::mutex mutex;
    uint64_t used = 0;
    struct Charged {
        std::string name;
        int width, height;
        uint64_t bytes;
    };
    std::vector<Charged> charged;
};

TextureBudget::TextureBudget(uint64_t limit_bytes)
    : limit_(limit_bytes), state_(std::make_unique<State>()) {}

TextureBudget::~TextureBudget() = default;

uint64_t TextureBudget::used() const {
    std::lock_guard lock(state_->mutex);
    return state_->used;
}

void TextureBudget::charge(const std::string& name, int width, int height, uint64_t bytes) {
    std::lock_guard lock(state_->mutex);
    State& s = *state_;
    auto describe = [](const State::Charged& c) {
        return c.name + " (" + std::to_string(c.width) + "x" + std::to_string(c.height) + ", " +
               describe_bytes(c.bytes) + ")";
    };
    if (bytes > limit_ || s.used > limit_ - bytes) {
        std::vector<State::Charged> largest = s.charged;
        std::stable_sort(largest.begin(), largest.end(),
                         [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
        std::string others;
        for (size_t i = 0; i < largest.size() && i < 5; ++i)
            others += (i ? ", " : "") + describe(largest[i]);
        throw Error(ExitCode::invalid_input,
                    describe({name, width, height, bytes}) + " would bring the textures to " +
                        describe_bytes(s.used + bytes) + ", over the texture budget of " +
                        describe_bytes(limit_) +
                        (others.empty() ? std::string() : "; already loaded: " + others) +
                        " (raise it with assets.texture_budget_mb in the scene or -D)");
    }
    s.used += bytes;
    s.charged.push_back({name, width, height, bytes});
}

}  // namespace facet
