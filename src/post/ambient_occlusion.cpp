#include "post/ambient_occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/integer_hash.hpp"

namespace facet {
namespace {

constexpr int kBlurReach = 4;         // the blur's half-width, in samples
constexpr float kSpiralTurns = 7.0f;  // co-prime with the tap counts used, so taps spread
constexpr float kBias = 0.05f;  // β: what rises less than ~3° over the plane (tessellation) is open

bool is_surface(float depth) {
    return depth > 0.0f && depth < std::numeric_limits<float>::infinity();
}

// View-space position of the buffer sample (x, y) at linear depth `depth`,
// for a perspective or an orthographic projection.
struct Unproject {
    float width, height;
    glm::mat4 projection;
    bool orthographic;

    glm::vec3 operator()(float x, float y, float depth) const {
        const float ndc_x = (x + 0.5f) / width * 2.0f - 1.0f;
        const float ndc_y = 1.0f - (y + 0.5f) / height * 2.0f;
        if (orthographic)
            return {(ndc_x - projection[3][0]) / projection[0][0],
                    (ndc_y - projection[3][1]) / projection[1][1], -depth};
        return {ndc_x * depth / projection[0][0], ndc_y * depth / projection[1][1], -depth};
    }

    // Buffer samples per scene unit at that depth, across x.
    float samples_per_unit(float depth) const {
        const float scale = 0.5f * width * projection[0][0];
        return orthographic ? scale : scale / depth;
    }
};

float occlusion_at(const OutlineBuffers& b, const Unproject& unproject, const glm::mat3& to_view,
                   const OcclusionStyle& style, int x, int y) {
    const size_t at = b.index(x, y);
    const float depth = b.depth[at];
    if (!is_surface(depth)) return 1.0f;
    glm::vec3 n = to_view * b.normal[at];
    const float length = glm::length(n);
    if (!(length > 0.0f)) return 1.0f;
    n /= length;
    const glm::vec3 p = unproject(static_cast<float>(x), static_cast<float>(y), depth);
    const float radius_samples = style.radius * unproject.samples_per_unit(depth);
    if (radius_samples < 1.0f) return 1.0f;  // the whole disc within one sample
    // A turn of the spiral per sample, from its coordinates alone: fine
    // noise that the blur removes, where one fixed spiral would draw streaks.
    const float turn =
        static_cast<float>(hash32(static_cast<uint32_t>(x), static_cast<uint32_t>(y)) >> 8) /
        16777216.0f * 2.0f * std::numbers::pi_v<float>;
    // A jitter of the taps' distances, likewise, so rings do not show.
    const float jitter =
        static_cast<float>(hash32(static_cast<uint32_t>(y), static_cast<uint32_t>(x) + 7u) >> 8) /
        16777216.0f;
    float sum = 0.0f;
    int counted = 0;
    for (int i = 0; i < style.samples; ++i) {
        const float along = (static_cast<float>(i) + jitter) / static_cast<float>(style.samples);
        const float angle = along * kSpiralTurns * 2.0f * std::numbers::pi_v<float> + turn;
        const float reach = along * radius_samples;
        const int sx = x + static_cast<int>(std::lround(reach * std::cos(angle)));
        const int sy = y + static_cast<int>(std::lround(reach * std::sin(angle)));
        ++counted;
        if (sx < 0 || sy < 0 || sx >= b.width || sy >= b.height) continue;
        const float tap_depth = b.depth[b.index(sx, sy)];
        if (!is_surface(tap_depth)) continue;
        const glm::vec3 v =
            unproject(static_cast<float>(sx), static_cast<float>(sy), tap_depth) - p;
        const float vv = glm::dot(v, v);
        const float r2 = style.radius * style.radius;
        if (!(vv > 0.0f) || vv > r2) continue;  // beyond the radius: not this point's
        // How far above the tangent plane the tap rises, as the cosine of
        // its direction with the normal, fading to nothing at the radius.
        const float rise = glm::dot(v, n) / std::sqrt(vv) - kBias;
        sum += std::max(0.0f, rise) * (1.0f - vv / r2);
    }
    const float a = 1.0f - 2.0f * style.strength * sum / static_cast<float>(std::max(counted, 1));
    return std::clamp(a, 0.0f, 1.0f);
}

}  // namespace

void ambient_occlusion(const OutlineBuffers& buffers, const glm::mat4& view,
                       const glm::mat4& projection, const OcclusionStyle& style,
                       std::vector<float>& factor, std::vector<float>& scratch, ThreadPool& pool) {
    const int w = buffers.width, h = buffers.height;
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    scratch.assign(n, 1.0f);
    factor.assign(n, 1.0f);
    const Unproject unproject{static_cast<float>(w), static_cast<float>(h), projection,
                              projection[3][3] == 1.0f};
    const glm::mat3 to_view(view);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < w; ++x)
            scratch[buffers.index(x, y)] = occlusion_at(buffers, unproject, to_view, style, x, y);
    });
    // A separable box blur, 9 samples each way, over samples of the same
    // surface (depth within 2%), so the taps' noise averages out and edges
    // stay sharp: rows from `scratch` into `factor`, then columns back.
    auto blur = [&](const std::vector<float>& from, std::vector<float>& to, int step_x,
                    int step_y) {
        pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
            const int y = static_cast<int>(row);
            for (int x = 0; x < w; ++x) {
                const size_t at = buffers.index(x, y);
                const float depth = buffers.depth[at];
                if (!is_surface(depth)) {
                    to[at] = 1.0f;
                    continue;
                }
                float sum = 0.0f, weight = 0.0f;
                for (int k = -kBlurReach; k <= kBlurReach; ++k) {
                    const int sx = x + k * step_x, sy = y + k * step_y;
                    if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
                    const size_t other = buffers.index(sx, sy);
                    if (!(std::fabs(buffers.depth[other] - depth) < 0.02f * depth)) continue;
                    sum += from[other];
                    weight += 1.0f;
                }
                to[at] = sum / weight;  // the sample itself always counts
            }
        });
    };
    blur(scratch, factor, 1, 0);
    blur(factor, scratch, 0, 1);
    factor.swap(scratch);
}

}  // namespace facet
