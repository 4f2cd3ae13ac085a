#include "assets/texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>

#include "assets/image_decode.hpp"
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

// The 256 bytes as numbers 0..1, for data textures.
const std::array<float, 256>& unit8_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(i) / 255.0f;
        return t;
    }();
    return table;
}

// What an 8-bit level's R, G and B bytes mean.
const std::array<float, 256>& byte_table(Texture::Format format) {
    return format == Texture::Format::data8 ? unit8_table() : srgb8_table();
}

uint8_t to_byte(float unit) {
    return static_cast<uint8_t>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f));
}

uint32_t encode_data8(const glm::vec4& c) {
    return uint32_t(to_byte(c.r)) | uint32_t(to_byte(c.g)) << 8 | uint32_t(to_byte(c.b)) << 16 |
           uint32_t(to_byte(c.a)) << 24;
}

uint32_t encode_srgb8(const glm::vec4& c) {
    return uint32_t(to_byte(linear_to_srgb(std::clamp(c.r, 0.0f, 1.0f)))) |
           uint32_t(to_byte(linear_to_srgb(std::clamp(c.g, 0.0f, 1.0f)))) << 8 |
           uint32_t(to_byte(linear_to_srgb(std::clamp(c.b, 0.0f, 1.0f)))) << 16 |
           uint32_t(to_byte(c.a)) << 24;
}

glm::vec4 decode_bytes8(uint32_t t, const std::array<float, 256>& table) {
    return {table[t & 0xff], table[(t >> 8) & 0xff], table[(t >> 16) & 0xff],
            static_cast<float>(t >> 24) * (1.0f / 255.0f)};
}

glm::vec4 texel_at(const TextureLevel& l, size_t i, const std::array<float, 256>& table) {
    if (!l.bytes8.empty()) return decode_bytes8(l.bytes8[i], table);
    return to_float(l.half[i]);
}

// A whole texel index wrapped into [0, size). Repeat wraps with a mask
// when the size is a power of two (the usual texture), else with one
// remainder: the division is the dearest step of a lookup.
int wrap_index(int i, int size, Wrap wrap) {
    switch (wrap) {
        case Wrap::clamp:
            return i < 0 ? 0 : (i >= size ? size - 1 : i);
        case Wrap::mirror: {
            // Period 2·size: the image, then the image reversed.
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case Wrap::repeat:
            break;
    }
    if ((size & (size - 1)) == 0) return i & (size - 1);  // two's complement: right for negative i
    const int m = i % size;
    return m < 0 ? m + size : m;
}

// Texel coordinates of uv (texel centres at half-integers), finite and
// small enough for the float->int conversions below.
glm::vec2 texel_coordinates(const TextureLevel& l, const Sampler& s, glm::vec2 uv) {
    float x = uv.x * static_cast<float>(l.width) - 0.5f;
    float y = uv.y * static_cast<float>(l.height) - 0.5f;
    // Clamp before the fmod below: far outside the image the edge texel
    // must win, not whatever texel the remainder happens to land on.
    if (s.wrap_s == Wrap::clamp) x = std::clamp(x, -1.0f, static_cast<float>(l.width));
    if (s.wrap_t == Wrap::clamp) y = std::clamp(y, -1.0f, static_cast<float>(l.height));
    // Keep the conversion in range for huge repeat counts (at 2^24 and
    // beyond every float is whole, so this keeps x's fraction; 2^24 is a
    // multiple of every mirrored period up to 2^23).
    constexpr float kWhole = 16777216.0f;
    if (!(std::fabs(x) < kWhole)) x = std::fmod(x, kWhole);
    if (!(std::fabs(y) < kWhole)) y = std::fmod(y, kWhole);
    return {x, y};
}

// The two filters, over a level's texels as `fetch(index)` gives them:
// one instantiation per storage, so the per-texel test of which storage a
// level has is made once per lookup.
template <typename Fetch>
glm::vec4 nearest(const TextureLevel& l, const Sampler& s, glm::vec2 uv, Fetch fetch) {
    const glm::vec2 t = texel_coordinates(l, s, uv);
    if (!std::isfinite(t.x) || !std::isfinite(t.y)) return fetch(0);
    // The texel whose square holds the point: floor(x + 0.5) of the centres.
    const int x = wrap_index(static_cast<int>(std::floor(t.x + 0.5f)), l.width, s.wrap_s);
    const int y = wrap_index(static_cast<int>(std::floor(t.y + 0.5f)), l.height, s.wrap_t);
    return fetch(static_cast<size_t>(y) * l.width + x);
}

template <typename Fetch>
glm::vec4 bilinear(const TextureLevel& l, const Sampler& s, glm::vec2 uv, Fetch fetch) {
    const glm::vec2 t = texel_coordinates(l, s, uv);
    if (!std::isfinite(t.x) || !std::isfinite(t.y)) return fetch(0);
    const float fx = std::floor(t.x), fy = std::floor(t.y);
    const float tx = t.x - fx, ty = t.y - fy;
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const int x0 = wrap_index(ix, l.width, s.wrap_s), x1 = wrap_index(ix + 1, l.width, s.wrap_s);
    const size_t row_a = static_cast<size_t>(wrap_index(iy, l.height, s.wrap_t)) * l.width;
    const size_t row_b = static_cast<size_t>(wrap_index(iy + 1, l.height, s.wrap_t)) * l.width;
    const glm::vec4 a = fetch(row_a + x0);
    const glm::vec4 b = fetch(row_a + x1);
    const glm::vec4 c = fetch(row_b + x0);
    const glm::vec4 d = fetch(row_b + x1);
    const glm::vec4 top = a + (b - a) * tx;
    const glm::vec4 bottom = c + (d - c) * tx;
    return top + (bottom - top) * ty;
}

template <typename Fetch>
glm::vec4 filtered_with(const TextureLevel& l, const Sampler& s, Filter filter, glm::vec2 uv,
                        Fetch fetch) {
    return filter == Filter::nearest ? nearest(l, s, uv, fetch) : bilinear(l, s, uv, fetch);
}

glm::vec4 filtered(const TextureLevel& l, const Sampler& s, Filter filter, glm::vec2 uv,
                   const std::array<float, 256>& table) {
    if (!l.bytes8.empty())
        return filtered_with(l, s, filter, uv,
                             [&](size_t i) { return decode_bytes8(l.bytes8[i], table); });
    return filtered_with(l, s, filter, uv, [&](size_t i) { return to_float(l.half[i]); });
}

void store(TextureLevel& l, Texture::Format format, size_t i, const glm::vec4& c) {
    if (format == Texture::Format::srgb8)
        l.bytes8[i] = encode_srgb8(c);
    else if (format == Texture::Format::data8)
        l.bytes8[i] = encode_data8(c);
    else
        l.half[i] = to_half(c);
}

TextureLevel empty_level(int width, int height, Texture::Format format) {
    TextureLevel l;
    l.width = width;
    l.height = height;
    const size_t n = static_cast<size_t>(width) * height;
    if (format != Texture::Format::half)
        l.bytes8.resize(n);
    else
        l.half.resize(n);
    return l;
}

// Levels 1, 2, ... down to 1x1, each a 2x2 box filter of the one before in
// linear light, rounding up; an odd last row or column is averaged with
// itself.
void add_mipmaps(std::vector<TextureLevel>& levels, Texture::Format format) {
    const auto& table = byte_table(format);
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
    return texel_at(l, static_cast<size_t>(y) * l.width + x, byte_table(format_));
}

Texture Texture::as_data() const {
    if (!levels_ || format_ == Format::data8) return *this;
    const TextureLevel& colour = level(0);
    TextureLevel base =
        empty_level(width, height, format_ == Format::srgb8 ? Format::data8 : format_);
    if (format_ == Format::srgb8) {
        base.bytes8 = colour.bytes8;  // the file's bytes, now read as numbers
    } else {
        // 16-bit levels hold linear light decoded from sRGB: encode back.
        for (size_t i = 0; i < base.half.size(); ++i) {
            const glm::vec4 c = texel_at(colour, i, srgb8_table());
            base.half[i] = to_half(
                glm::vec4(linear_to_srgb(c.r), linear_to_srgb(c.g), linear_to_srgb(c.b), c.a));
        }
    }
    Texture data =
        from_base_level(format_ == Format::srgb8 ? Format::data8 : format_, std::move(base));
    data.sampler = sampler;
    return data;
}

uint64_t Texture::bytes() const {
    uint64_t n = 0;
    for (int i = 0; i < level_count(); ++i)
        n += level(i).bytes8.size() * sizeof(uint32_t) + level(i).half.size() * sizeof(Rgba16F);
    return n;
}

glm::vec4 Texture::sample(glm::vec2 uv) const {
    if (!levels_) return glm::vec4(1);
    return filtered(level(0), sampler, sampler.mag, uv, byte_table(format_));
}

glm::vec4 Texture::sample(glm::vec2 uv, float lod) const {
    if (!levels_) return glm::vec4(1);
    if (!(lod > 0.0f)) return sample(uv);  // also NaN
    const auto& table = byte_table(format_);
    if (!sampler.mipmaps || level_count() == 1)
        return filtered(level(0), sampler, sampler.min, uv, table);
    const float top = static_cast<float>(level_count() - 1);
    if (lod >= top) return filtered(level(level_count() - 1), sampler, sampler.min, uv, table);
    if (sampler.mip == Filter::nearest) {
        const int chosen = static_cast<int>(std::floor(lod + 0.5f));
        return filtered(level(chosen), sampler, sampler.min, uv, table);
    }
    const int fine_level = static_cast<int>(lod);
    const float t = lod - static_cast<float>(fine_level);
    const glm::vec4 fine = filtered(level(fine_level), sampler, sampler.min, uv, table);
    const glm::vec4 coarse = filtered(level(fine_level + 1), sampler, sampler.min, uv, table);
    return fine + (coarse - fine) * t;
}

glm::vec4 Texture::sample(const TextureFootprint& f) const {
    const float trilinear_lod = f.major > 1.0f ? std::log2(f.major) : 0.0f;
    if (sampler.max_anisotropy <= 1 || !(f.major > 1.0f) || !(f.major > f.minor))
        return sample(f.uv, trilinear_lod);
    const float ratio = f.minor > 0.0f ? std::ceil(f.major / f.minor) : 0.0f;
    const int probes = ratio > 0.0f && ratio < static_cast<float>(sampler.max_anisotropy)
                           ? static_cast<int>(ratio)
                           : sampler.max_anisotropy;
    if (probes <= 1) return sample(f.uv, trilinear_lod);
    const float n = static_cast<float>(probes);
    const float width = std::max(f.major / n, f.minor);
    const float lod = width > 1.0f ? std::log2(width) : 0.0f;
    glm::vec4 sum(0.0f);
    for (int i = 0; i < probes; ++i) {
        const float along = (static_cast<float>(i) + 0.5f) / n - 0.5f;
        sum += sample(f.uv + f.major_axis * along, lod);
    }
    return sum * (1.0f / n);
}

UvTransform UvTransform::from_trs(glm::dvec2 offset, double rotation, glm::dvec2 scale) {
    const double c = std::cos(rotation), s = std::sin(rotation);
    UvTransform t;
    t.offset = offset;
    // Columns: u' = c·sx·u + s·sy·v, v' = −s·sx·u + c·sy·v.
    t.linear =
        glm::dmat2(glm::dvec2(c * scale.x, -s * scale.x), glm::dvec2(s * scale.y, c * scale.y));
    return t;
}

UvTransform UvTransform::scaled(glm::dvec2 scale) const {
    UvTransform t;
    t.offset = offset * scale;
    t.linear = glm::dmat2(linear[0] * scale, linear[1] * scale);
    return t;
}

glm::vec2 UvTransform::apply(glm::vec2 uv) const {
    return {static_cast<float>(offset.x + linear[0].x * uv.x + linear[1].x * uv.y),
            static_cast<float>(offset.y + linear[0].y * uv.x + linear[1].y * uv.y)};
}

void UvTransform::apply(simd::vf& u, simd::vf& v) const {
    typedef double vd __attribute__((vector_size(64)));  // eight doubles, as apply() computes
    const vd x = __builtin_convertvector(u, vd), y = __builtin_convertvector(v, vd);
    u = __builtin_convertvector((offset.x + linear[0].x * x) + linear[1].x * y, simd::vf);
    v = __builtin_convertvector((offset.y + linear[0].y * x) + linear[1].y * y, simd::vf);
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
            base.bytes8[i] = r | g << 8 | b << 16 | a << 24;
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
    return decode_texture(bytes.data(), bytes.size(), path, budget);
}

struct TextureBudget::State {
    std::mutex mutex;
    uint64_t used = 0;
    std::vector<Charge> charged;
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
    auto describe = [](const Charge& c) {
        return c.name + " (" + std::to_string(c.width) + "x" + std::to_string(c.height) + ", " +
               describe_bytes(c.bytes) + ")";
    };
    if (bytes > limit_ || s.used > limit_ - bytes) {
        // A texture is charged in parts (its texels as NAME, then what its
        // decoder holds as "NAME (while decoding)"): its earlier parts count
        // as its own, not as textures already loaded.
        const std::string texture = name.ends_with(kWhileDecoding)
                                        ? name.substr(0, name.size() - kWhileDecoding.size())
                                        : name;
        uint64_t own = bytes;
        std::vector<Charge> largest;
        for (const Charge& c : s.charged)
            if (c.name == name || c.name == texture)
                own += c.bytes;
            else
                largest.push_back(c);
        std::stable_sort(largest.begin(), largest.end(),
                         [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
        std::string others;
        for (size_t i = 0; i < largest.size() && i < 5; ++i)
            others += (i ? ", " : "") + describe(largest[i]);
        throw Error(ExitCode::invalid_input,
                    describe({name, width, height, own}) + " would bring the textures to " +
                        describe_bytes(s.used + bytes) + ", over the texture budget of " +
                        describe_bytes(limit_) +
                        (others.empty() ? std::string() : "; already loaded: " + others) +
                        " (raise it with assets.texture_budget_mb in the scene or -D)");
    }
    s.used += bytes;
    s.charged.push_back({name, width, height, bytes});
}

std::vector<TextureBudget::Charge> TextureBudget::charges() const {
    std::lock_guard lock(state_->mutex);
    return state_->charged;
}

void TextureBudget::release(const std::string& name) {
    std::lock_guard lock(state_->mutex);
    State& s = *state_;
    for (auto it = s.charged.rbegin(); it != s.charged.rend(); ++it)
        if (it->name == name) {
            s.used -= it->bytes;
            s.charged.erase(std::next(it).base());
            return;
        }
}

}  // namespace facet
