#include "post/ambient_occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/integer_hash.hpp"

namespace facet {
namespace {

constexpr int kBlurReach = 4;         // the blur's half-width, in pixels
constexpr float kSpiralTurns = 7.0f;  // co-prime with the tap counts used, so taps spread
constexpr float kBias = 0.05f;  // β: what rises less than ~3° over the plane (tessellation) is open

bool is_surface(float depth) {
    return depth > 0.0f && depth < std::numeric_limits<float>::infinity();
}

// View-space position of the buffer sample (x, y) at linear depth `depth`,
// for a perspective or an orthographic projection.
// `centre` is where in its cell the buffer's value was taken (0.5: the
// middle; a pixel-level buffer made from each pixel's first sample of k x k
// has it at 0.5 / k).
struct Unproject {
    float width, height;
    glm::mat4 projection;
    bool orthographic;
    float centre;

    glm::vec3 operator()(float x, float y, float depth) const {
        const float ndc_x = (x + centre) / width * 2.0f - 1.0f;
        const float ndc_y = 1.0f - (y + centre) / height * 2.0f;
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

// The taps' directions on a spiral, before each sample's own turn: the
// trigonometry once per frame, not once per tap.
std::vector<glm::vec2> spiral_directions(int samples) {
    std::vector<glm::vec2> directions;
    for (int i = 0; i < samples; ++i) {
        const float along = (static_cast<float>(i) + 0.5f) / static_cast<float>(samples);
        const float angle = along * kSpiralTurns * 2.0f * std::numbers::pi_v<float>;
        directions.push_back({std::cos(angle), std::sin(angle)});
    }
    return directions;
}

float occlusion_at(const OutlineBuffers& b, const Unproject& unproject, const glm::mat3& to_view,
                   const OcclusionStyle& style, const std::vector<glm::vec2>& spiral, int x,
                   int y) {
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
    const float turn_cos = std::cos(turn), turn_sin = std::sin(turn);
    const float r2 = style.radius * style.radius;
    float sum = 0.0f;
    int counted = 0;
    for (int i = 0; i < style.samples; ++i) {
        const float along = (static_cast<float>(i) + jitter) / static_cast<float>(style.samples);
        const float reach = along * radius_samples;
        const glm::vec2 u = spiral[static_cast<size_t>(i)];
        const float dx = u.x * turn_cos - u.y * turn_sin, dy = u.x * turn_sin + u.y * turn_cos;
        const int sx = x + static_cast<int>(std::floor(reach * dx + 0.5f));
        const int sy = y + static_cast<int>(std::floor(reach * dy + 0.5f));
        ++counted;
        if (sx < 0 || sy < 0 || sx >= b.width || sy >= b.height) continue;
        const float tap_depth = b.depth[b.index(sx, sy)];
        if (!is_surface(tap_depth)) continue;
        const glm::vec3 v =
            unproject(static_cast<float>(sx), static_cast<float>(sy), tap_depth) - p;
        const float vv = glm::dot(v, v);
        if (!(vv > 0.0f) || vv > r2) continue;  // beyond the radius: not this point's
        // How far above the tangent plane the tap rises, as the cosine of
        // its direction with the normal, fading to nothing at the radius.
        const float rise = glm::dot(v, n) / std::sqrt(vv) - kBias;
        sum += std::max(0.0f, rise) * (1.0f - vv / r2);
    }
    const float a = 1.0f - 2.0f * style.strength * sum / static_cast<float>(std::max(counted, 1));
    return std::clamp(a, 0.0f, 1.0f);
}

// One pass of a box blur, 9 cells along (step_x, step_y), over cells of
// the same surface (depth within 2%), so the taps' noise averages out and
// edges stay sharp.
void blur_same_surface(const OutlineBuffers& cells, int reach, const std::vector<float>& from,
                       std::vector<float>& to, int step_x, int step_y, ThreadPool& pool) {
    const int w = cells.width, h = cells.height;
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < w; ++x) {
            const size_t at = cells.index(x, y);
            const float depth = cells.depth[at];
            if (!is_surface(depth)) {
                to[at] = 1.0f;
                continue;
            }
            float sum = 0.0f, weight = 0.0f;
            for (int r = -reach; r <= reach; ++r) {
                const int sx = x + r * step_x, sy = y + r * step_y;
                if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
                const size_t other = cells.index(sx, sy);
                if (!(std::fabs(cells.depth[other] - depth) < 0.02f * depth)) continue;
                sum += from[other];
                weight += 1.0f;
            }
            to[at] = sum / weight;  // the cell itself always counts
        }
    });
}

// Each sample takes the value of its own cell when the cell's depth is
// within 1% of its own (a surface seen whole: most samples), else of the
// cell, among its own and the eight around it, whose depth is nearest its
// own (the first on a tie), so a silhouette's samples take their own
// surface's value.
void hand_out_to_samples(const OutlineBuffers& samples, const OutlineBuffers& cells, int k,
                         const std::vector<float>& values, std::vector<float>& factor,
                         ThreadPool& pool) {
    const int w = cells.width, h = cells.height;
    factor.assign(static_cast<size_t>(samples.width) * static_cast<size_t>(samples.height), 1.0f);
    pool.parallel_for(static_cast<size_t>(samples.height), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < samples.width; ++x) {
            const size_t at = samples.index(x, y);
            const float depth = samples.depth[at];
            if (!is_surface(depth)) continue;
            const int px = std::min(x / k, w - 1), py = std::min(y / k, h - 1);
            const size_t own = cells.index(px, py);
            if (std::fabs(cells.depth[own] - depth) <= 0.01f * depth) {
                factor[at] = values[own];
                continue;
            }
            float best_gap = std::numeric_limits<float>::infinity();
            float value = 1.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = px + dx, qy = py + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const size_t q = cells.index(qx, qy);
                    const float gap = std::fabs(cells.depth[q] - depth);
                    if (gap < best_gap) {
                        best_gap = gap;
                        value = values[q];
                    }
                }
            factor[at] = value;
        }
    });
}

}  // namespace

void ambient_occlusion(const OutlineBuffers& samples, int samples_per_side, const glm::mat4& view,
                       const glm::mat4& projection, const OcclusionStyle& style,
                       OcclusionScratch& scratch, std::vector<float>& factor, ThreadPool& pool) {
    // Occlusion changes slowly across a surface, so it is found per pixel
    // or per 2 x 2 pixels (style.pixels_per_value), from each cell's first
    // sample (a quarter of the work and of the memory the taps wander over
    // at 2 x 2 samples, and a quarter again at half resolution), then handed
    // to every sample from a neighbouring cell at its depth, which keeps
    // silhouettes sharp and anti-aliased.
    const int k = std::max(samples_per_side, 1) * std::max(style.pixels_per_value, 1);
    const int w = samples.width / k, h = samples.height / k;
    OutlineBuffers& pixels = scratch.pixels;
    if (pixels.width != w || pixels.height != h) pixels.reset(w, h);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < w; ++x) {
            const size_t from = samples.index(x * k, y * k), to = pixels.index(x, y);
            pixels.depth[to] = samples.depth[from];
            pixels.normal[to] = samples.normal[from];
        }
    });
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    std::vector<float>& raw = scratch.raw;
    std::vector<float>& blurred = scratch.blurred;
    raw.assign(n, 1.0f);
    blurred.assign(n, 1.0f);
    const Unproject unproject{static_cast<float>(w), static_cast<float>(h), projection,
                              projection[3][3] == 1.0f, 0.5f / static_cast<float>(k)};
    const glm::mat3 to_view(view);
    const std::vector<glm::vec2> spiral = spiral_directions(style.samples);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < w; ++x)
            raw[pixels.index(x, y)] = occlusion_at(pixels, unproject, to_view, style, spiral, x, y);
    });
    // A separable box blur: rows from `raw` into `blurred`, then columns back.
    const int reach = std::max(kBlurReach / std::max(style.pixels_per_value, 1), 1);
    blur_same_surface(pixels, reach, raw, blurred, 1, 0, pool);
    blur_same_surface(pixels, reach, blurred, raw, 0, 1, pool);
    hand_out_to_samples(samples, pixels, k, raw, factor, pool);
}

}  // namespace facet
