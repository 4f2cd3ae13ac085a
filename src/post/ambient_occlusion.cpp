#include "post/ambient_occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/integer_hash.hpp"
#include "core/simd_math.hpp"

namespace facet {
namespace {

constexpr int kBlurReach = 4;         // the blur's half-width, in pixels
constexpr float kSpiralTurns = 7.0f;  // co-prime with the tap counts used, so taps spread
constexpr float kBias = 0.05f;  // β: what rises less than ~3° over the plane (tessellation) is open

bool is_surface(float depth) {
    return depth > 0.0f && depth < std::numeric_limits<float>::infinity();
}
simd::vi is_surface(simd::vf depth) {
    return (depth > 0.0f) & (depth < std::numeric_limits<float>::infinity());
}

// View-space position of the buffer sample (x, y) at linear depth `depth`,
// for a perspective or an orthographic projection: T is float, or eight
// lanes of them (the same operations, so the same bits).
// `centre` is where in its cell the buffer's value was taken (0.5: the
// middle; a pixel-level buffer made from each pixel's first sample of k x k
// has it at 0.5 / k).
template <typename T>
struct ViewPoint {
    T x, y, z;
};

struct Unproject {
    float width, height;
    glm::mat4 projection;
    bool orthographic;
    float centre;

    template <typename T>
    ViewPoint<T> operator()(T x, T y, T depth) const {
        const T ndc_x = (x + centre) / width * 2.0f - 1.0f;
        const T ndc_y = 1.0f - (y + centre) / height * 2.0f;
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

// The taps' directions on a spiral, before each sample's own turn, in
// groups of eight lanes (lanes past `samples` are left out by the mask):
// the trigonometry once per frame, not once per tap.
struct Spiral {
    std::vector<simd::vf> x, y, index;  // per group of eight taps
    std::vector<simd::vi> used;         // -1 in the lanes of real taps
};

Spiral spiral_directions(int samples) {
    Spiral spiral;
    for (int first = 0; first < samples; first += simd::kLanes) {
        simd::vf x{}, y{}, index{};
        simd::vi used{};
        for (int lane = 0; lane < simd::kLanes; ++lane) {
            const int i = first + lane;
            const float along = (static_cast<float>(i) + 0.5f) / static_cast<float>(samples);
            const float angle = along * kSpiralTurns * 2.0f * std::numbers::pi_v<float>;
            x[lane] = std::cos(angle);
            y[lane] = std::sin(angle);
            index[lane] = static_cast<float>(i);
            used[lane] = i < samples ? -1 : 0;
        }
        spiral.x.push_back(x);
        spiral.y.push_back(y);
        spiral.index.push_back(index);
        spiral.used.push_back(used);
    }
    return spiral;
}

// The buffer's depth at eight taps; 0 (not a surface) where a tap is off
// the buffer.
simd::vf gather_depth(const OutlineBuffers& b, simd::vi sx, simd::vi sy, simd::vi inside) {
    simd::vf depth;
    for (int i = 0; i < simd::kLanes; ++i)
        depth[i] = inside[i] ? b.depth[b.index(sx[i], sy[i])] : 0.0f;
    return depth;
}

float occlusion_at(const OutlineBuffers& b, const Unproject& unproject, const glm::mat3& to_view,
                   const OcclusionStyle& style, const Spiral& spiral, int x, int y) {
    using simd::vf;
    using simd::vi;
    const size_t at = b.index(x, y);
    const float depth = b.depth[at];
    if (!is_surface(depth)) return 1.0f;
    glm::vec3 n = to_view * b.normal[at];
    const float length = glm::length(n);
    if (!(length > 0.0f)) return 1.0f;
    n /= length;
    const ViewPoint<float> p = unproject(static_cast<float>(x), static_cast<float>(y), depth);
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
    // Taps far off the buffer are off it whatever their exact place: the
    // clamp keeps the conversion to integers defined.
    const float far_off = 2.0f * static_cast<float>(std::max(b.width, b.height)) + 2.0f;
    vf sum = simd::splat(0.0f);
    for (size_t g = 0; g < spiral.x.size(); ++g) {
        const vf along = (spiral.index[g] + jitter) / static_cast<float>(style.samples);
        const vf reach = along * radius_samples;
        const vf dx = spiral.x[g] * turn_cos - spiral.y[g] * turn_sin;
        const vf dy = spiral.x[g] * turn_sin + spiral.y[g] * turn_cos;
        const vf off = simd::splat(far_off);
        const vi sx = x + simd::floor_to_int(simd::vmin(simd::vmax(reach * dx + 0.5f, -off), off));
        const vi sy = y + simd::floor_to_int(simd::vmin(simd::vmax(reach * dy + 0.5f, -off), off));
        const vi inside = spiral.used[g] & (sx >= 0) & (sy >= 0) & (sx < b.width) & (sy < b.height);
        const vf tap_depth = gather_depth(b, sx, sy, inside);
        const vi surface = is_surface(tap_depth);
        const ViewPoint<vf> t =
            unproject(__builtin_convertvector(sx, vf), __builtin_convertvector(sy, vf), tap_depth);
        const vf vx = t.x - p.x, vy = t.y - p.y, vz = t.z - p.z;
        const vf vv = vx * vx + vy * vy + vz * vz;
        // Beyond the radius: not this point's.
        const vi near = surface & (vv > 0.0f) & (vv <= r2);
        // How far above the tangent plane the tap rises, as the cosine of
        // its direction with the normal, fading to nothing at the radius.
        const vf safe_vv = near ? vv : simd::splat(1.0f);
        const vf rise = (vx * n.x + vy * n.y + vz * n.z) / simd::vsqrt(safe_vv) - kBias;
        const vf weight = simd::vmax(rise, simd::splat(0.0f)) * (1.0f - safe_vv / r2);
        sum += near ? weight : simd::splat(0.0f);
    }
    float total = 0.0f;
    for (int i = 0; i < simd::kLanes; ++i)
        total += sum[i];  // in lane order: the same bits anywhere
    const float a = 1.0f - 2.0f * style.strength * total / static_cast<float>(style.samples);
    return std::clamp(a, 0.0f, 1.0f);
}

// One cell of a blur pass: the mean of `from` over the cells within
// `reach` along (step_x, step_y) on the same surface as (x, y).
float blurred_cell(const OutlineBuffers& cells, int reach, const std::vector<float>& from, int x,
                   int y, int step_x, int step_y) {
    const float depth = cells.depth[cells.index(x, y)];
    if (!is_surface(depth)) return 1.0f;
    float sum = 0.0f, weight = 0.0f;
    for (int r = -reach; r <= reach; ++r) {
        const int sx = x + r * step_x, sy = y + r * step_y;
        if (sx < 0 || sy < 0 || sx >= cells.width || sy >= cells.height) continue;
        const size_t other = cells.index(sx, sy);
        if (!(std::fabs(cells.depth[other] - depth) < 0.02f * depth)) continue;
        sum += from[other];
        weight += 1.0f;
    }
    return sum / weight;  // the cell itself always counts
}

// blurred_cell for the eight cells from (x, y) along the row, every tap
// of which lies inside the buffer: the same operations lane by lane (a tap
// left out adds nothing, as the one-cell loop skips it), so the same bits.
void blurred_cells8(const OutlineBuffers& cells, int reach, const std::vector<float>& from, int x,
                    int y, int step_x, int step_y, float* to) {
    using simd::vf;
    using simd::vi;
    vf depth, sum = simd::splat(0.0f), weight = simd::splat(0.0f);
    std::memcpy(&depth, &cells.depth[cells.index(x, y)], sizeof depth);
    const vi surface = is_surface(depth);
    const vf near = 0.02f * depth;
    for (int r = -reach; r <= reach; ++r) {
        const size_t other = cells.index(x + r * step_x, y + r * step_y);
        vf other_depth, value;
        std::memcpy(&other_depth, &cells.depth[other], sizeof other_depth);
        std::memcpy(&value, &from[other], sizeof value);
        const vf gap = other_depth - depth;
        const vi same = (gap < near) & (-gap < near);  // |gap| < near, and never for NaN
        sum += same ? value : simd::splat(0.0f);
        weight += same ? simd::splat(1.0f) : simd::splat(0.0f);
    }
    const vf mean = sum / (surface ? weight : simd::splat(1.0f));
    const vf result = surface ? mean : simd::splat(1.0f);
    std::memcpy(to, &result, sizeof result);
}

// One pass of a box blur, 9 cells along (step_x, step_y), over cells of
// the same surface (depth within 2%), so the taps' noise averages out and
// edges stay sharp. Eight cells at a time where all their taps are inside.
void blur_same_surface(const OutlineBuffers& cells, int reach, const std::vector<float>& from,
                       std::vector<float>& to, int step_x, int step_y, ThreadPool& pool) {
    const int w = cells.width, h = cells.height;
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        const bool rows_inside = y - reach * step_y >= 0 && y + reach * step_y < h;
        const int first = reach * step_x, last = w - 1 - reach * step_x;  // cells whose taps fit
        int x = 0;
        for (; x < w && (x < first || !rows_inside); ++x)
            to[cells.index(x, y)] = blurred_cell(cells, reach, from, x, y, step_x, step_y);
        for (; x + simd::kLanes - 1 <= last; x += simd::kLanes)
            blurred_cells8(cells, reach, from, x, y, step_x, step_y, &to[cells.index(x, y)]);
        for (; x < w; ++x)
            to[cells.index(x, y)] = blurred_cell(cells, reach, from, x, y, step_x, step_y);
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
    if (w == 0 || h == 0) {  // an image narrower than one cell: nothing to find it from
        factor.assign(static_cast<size_t>(samples.width) * static_cast<size_t>(samples.height),
                      1.0f);
        return;
    }
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
    const Spiral spiral = spiral_directions(std::max(style.samples, 1));
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
