// The samples PNG views hold (output/png_writer.cpp compresses them into
// files; the preview shows them as they are): colour as displays show it,
// depth as 16-bit grey, and 8-bit pictures of the data passes to look at,
// not values to read back (the EXR files hold those).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/display_transform.hpp"
#include "core/integer_hash.hpp"
#include "core/simd_math.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

uint8_t unit_byte(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 255;
    return static_cast<uint8_t>(std::lround(v * 255.0f));
}

// Every half-float colour value -> its 8-bit sRGB byte (negative and NaN
// black, above 1 white), and -> its 8-bit linear byte for alpha. Built once
// (a constant, not state): a lookup per channel instead of pow.
struct HalfToByte {
    std::vector<uint8_t> srgb, linear;
    HalfToByte() : srgb(65536), linear(65536) {
        for (uint32_t h = 0; h < 65536; ++h) {
            const float v = half_to_float(static_cast<uint16_t>(h));
            const double unit = v > 0.0f ? std::min(static_cast<double>(v), 1.0) : 0.0;
            srgb[h] = display_byte(v);
            linear[h] = static_cast<uint8_t>(std::lround(unit * 255.0));
        }
    }
};

const HalfToByte& half_to_byte() {
    static const HalfToByte table;
    return table;
}

// A premultiplied pixel that is not opaque, as PNG stores it: straight
// (colour divided by alpha) and then sRGB-encoded; transparent is black.
void straight_srgb(const Rgba16F& c, uint8_t* rgb) {
    const float a = half_to_float(c.a);
    const uint16_t channel[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) {
        rgb[i] = display_byte(a > 0.0f ? half_to_float(channel[i]) / a : 0.0f);
    }
}

inline uint16_t unit_to_u16(float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 65535;
    return static_cast<uint16_t>(v * 65535.0f + 0.5f);
}

// Eight depths as png_depth_samples writes them: unit_to_u16 of
// (far - d) / span with selects for its branches, the same IEEE operations
// lane by lane, so the same values; infinity (background) gives 0.
void depth_to_png_lanes(const float* depth, float far, float span, uint8_t* out) {
    simd::vf d;
    std::memcpy(&d, depth, sizeof d);
    const simd::vf t = (simd::splat(far) - d) / simd::splat(span);
    simd::vf unit = simd::vmax(t, simd::splat(0.0f));  // NaN gives 0
    unit = simd::vmin(unit, simd::splat(1.0f));
    const simd::vi infinite = ((simd::vi)d & simd::splat_i(0x7fffffff)) == 0x7f800000;
    unit = (simd::vf)((simd::vi)unit & ~infinite);
    const simd::vi v =
        __builtin_convertvector(unit * simd::splat(65535.0f) + simd::splat(0.5f), simd::vi);
    const simd::vi big_endian = (v >> 8 & 0xff) | (v & 0xff) << 8;  // as PNG stores samples
    const simd::vh samples = __builtin_convertvector(big_endian, simd::vh);
    std::memcpy(out, &samples, sizeof samples);
}

// Room for `width` x `height` pixels of `channels` samples each, for the
// caller to fill.
PngSamples blank_samples(int width, int height, int channels, int bit_depth) {
    PngSamples samples{width, height, channels, bit_depth, {}};
    samples.bytes.resize(static_cast<size_t>(width) * height * channels * (bit_depth / 8));
    return samples;
}

// 8-bit RGB samples of an image, three per pixel, from `view(pixel)`.
template <typename Pixel, typename View>
PngSamples rgb_view(const Image<Pixel>& image, View view) {
    PngSamples samples = blank_samples(image.width, image.height, 3, 8);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const std::array<uint8_t, 3> rgb = view(image.pixels[i]);
        std::copy(rgb.begin(), rgb.end(),
                  samples.bytes.begin() + static_cast<std::ptrdiff_t>(3 * i));
    }
    return samples;
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

PngSamples png_color_samples(const HalfColorImage& image) {
    const HalfToByte& table = half_to_byte();
    // Opaque images are written as RGB: a quarter less data to compress.
    const uint16_t one = 0x3c00;
    bool opaque = true;
    for (const Rgba16F& c : image.pixels) opaque = opaque && c.a == one;
    PngSamples samples = blank_samples(image.width, image.height, opaque ? 3 : 4, 8);
    uint8_t* out = samples.bytes.data();
    // Two loops, not one with a test per pixel: the opaque one is the
    // common case and stays a plain table lookup.
    if (opaque) {
        for (const Rgba16F& c : image.pixels) {
            out[0] = table.srgb[c.r];
            out[1] = table.srgb[c.g];
            out[2] = table.srgb[c.b];
            out += 3;
        }
        return samples;
    }
    for (const Rgba16F& c : image.pixels) {
        if (c.a == one) {
            out[0] = table.srgb[c.r];
            out[1] = table.srgb[c.g];
            out[2] = table.srgb[c.b];
        } else {
            straight_srgb(c, out);
        }
        out[3] = table.linear[c.a];
        out += 4;
    }
    return samples;
}

PngSamples png_depth_samples(const DepthImage& depth, glm::vec2 range) {
    PngSamples samples = blank_samples(depth.width, depth.height, 1, 16);
    const float span = range.y - range.x;
    uint8_t* out = samples.bytes.data();
    const size_t count = depth.pixels.size();
    size_t i = 0;
    for (; i + simd::kLanes <= count; i += simd::kLanes)
        depth_to_png_lanes(depth.pixels.data() + i, range.y, span, out + 2 * i);
    for (; i < count; ++i) {
        const float d = depth.pixels[i];
        const uint16_t v = std::isinf(d) ? 0 : unit_to_u16((range.y - d) / span);
        out[2 * i] = static_cast<uint8_t>(v >> 8);  // PNG samples are big-endian
        out[2 * i + 1] = static_cast<uint8_t>(v);
    }
    return samples;
}

PngSamples png_normal_samples(const Image<glm::vec3>& normal) {
    return rgb_view(normal, [](const glm::vec3& n) {
        if (n == glm::vec3(0.0f)) return std::array<uint8_t, 3>{0, 0, 0};
        return std::array<uint8_t, 3>{unit_byte(n.x * 0.5f + 0.5f), unit_byte(n.y * 0.5f + 0.5f),
                                      unit_byte(n.z * 0.5f + 0.5f)};
    });
}

PngSamples png_id_samples(const Image<uint32_t>& ids) {
    return rgb_view(ids, [](uint32_t id) { return id_view_color(id); });
}

PngSamples png_uv_samples(const Image<glm::vec2>& uv) {
    return rgb_view(uv, [](const glm::vec2& t) {
        return std::array<uint8_t, 3>{unit_byte(t.x), unit_byte(t.y), 0};
    });
}

}  // namespace facet
