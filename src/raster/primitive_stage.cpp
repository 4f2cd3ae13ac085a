// Primitive stage: assemble, cull, clip, set up fixed-point edge functions
// and bin triangles to screen tiles. Each chunk writes only its own record.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "raster/clip.hpp"
#include "raster/rasterizer.hpp"

namespace facet {
namespace {

// Snaps a screen coordinate in pixels to fixed point (round to nearest).
inline int64_t to_fixed(float pixels) {
    return static_cast<int64_t>(std::nearbyint(pixels * static_cast<float>(kSubpixelScale)));
}

// Smallest pixel index whose centre is >= the fixed-point coordinate.
inline int64_t first_pixel_at_or_after(int64_t fixed) {
    int64_t v = fixed - kSubpixelScale / 2;
    return v >= 0 ? (v + kSubpixelScale - 1) / kSubpixelScale : -((-v) / kSubpixelScale);
}

// Largest pixel index whose centre is <= the fixed-point coordinate.
inline int64_t last_pixel_at_or_before(int64_t fixed) {
    int64_t v = fixed - kSubpixelScale / 2;
    return v >= 0 ? v / kSubpixelScale : -((-v + kSubpixelScale - 1) / kSubpixelScale);
}

struct PlaneSolver {
    double x0, y0, d1x, d1y, d2x, d2y, det;
    void solve(double v0, double v1, double v2, float out[3]) const {
        double dv1 = v1 - v0, dv2 = v2 - v0;
        out[0] = static_cast<float>(v0);
        out[1] = static_cast<float>((dv1 * d2y - dv2 * d1y) / det);
        out[2] = static_cast<float>((dv2 * d1x - dv1 * d2x) / det);
    }
};

}  // namespace

Rasterizer::Rasterizer(int width, int height, int tile_size)
    : width_(width), height_(height), tile_size_(tile_size) {
    if (tile_size < 8 || tile_size > kTileSize)
        throw Error(ExitCode::runtime_failure, "tile size " + std::to_string(tile_size) +
                                                   " is out of range (8.." +
                                                   std::to_string(kTileSize) + ")");
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        throw Error(ExitCode::invalid_input, "image size " + std::to_string(width) + "x" +
                                                 std::to_string(height) + " is out of range (1.." +
                                                 std::to_string(kMaxImageSide) + ")");
    tiles_x_ = (width + tile_size - 1) / tile_size;
    tiles_y_ = (height + tile_size - 1) / tile_size;
    guard_x_ = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(width);
    guard_y_ = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(height);
}

size_t Rasterizer::setup_triangle_count() const {
    size_t n = 0;
    for (size_t c = 0; c < chunk_count_; ++c) n += chunks_[c].triangles.size();
    return n;
}

void Rasterizer::set_geometry(const RasterInput& input, ThreadPool& pool) {
    chunk_count_ = (input.triangle_count + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
    if (chunks_.size() < chunk_count_) chunks_.resize(chunk_count_);
    pool.parallel_for(chunk_count_, [&](size_t chunk) { setup_chunk(input, chunk); });
}

void Rasterizer::setup_chunk(const RasterInput& input, size_t chunk) {
    ChunkBins& bins = chunks_[chunk];
    bins.triangles.clear();
    bins.shading.clear();
    bins.scratch_tiles.clear();
    const size_t tile_count = static_cast<size_t>(tiles_x_) * tiles_y_;
    const float half_w = 0.5f * static_cast<float>(width_);
    const float half_h = 0.5f * static_cast<float>(height_);

    // Sets up one (possibly clipped) triangle; v are clip-space positions,
    // bary the source-triangle weights of each corner.
    auto emit = [&](glm::vec4 v[3], glm::vec3 bary[3], uint32_t source, bool cull_back) {
        int64_t X[3], Y[3];
        float inv_w[3], z[3];
        for (int i = 0; i < 3; ++i) {
            inv_w[i] = 1.0f / v[i].w;
            const glm::vec2 screen = clip_to_screen(v[i], half_w, half_h);
            X[i] = to_fixed(screen.x);
            Y[i] = to_fixed(screen.y);
            z[i] = v[i].z * inv_w[i];
        }
        int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
        if (area == 0) return;
        // Screen y points down, so counter-clockwise front faces have negative area.
        bool back_facing = area > 0;
        if (back_facing && cull_back) return;
        int order[3] = {0, 1, 2};
        if (!back_facing) std::swap(order[1], order[2]);  // make the area positive

        int64_t min_x = std::min({X[0], X[1], X[2]}), max_x = std::max({X[0], X[1], X[2]});
        int64_t min_y = std::min({Y[0], Y[1], Y[2]}), max_y = std::max({Y[0], Y[1], Y[2]});
        int64_t px0 = std::max<int64_t>(first_pixel_at_or_after(min_x), 0);
        int64_t px1 = std::min<int64_t>(last_pixel_at_or_before(max_x), width_ - 1);
        int64_t py0 = std::max<int64_t>(first_pixel_at_or_after(min_y), 0);
        int64_t py1 = std::min<int64_t>(last_pixel_at_or_before(max_y), height_ - 1);
        if (px0 > px1 || py0 > py1) return;  // covers no pixel centre

        SetupTriangle tri;
        for (int e = 0; e < 3; ++e) {
            int a = order[e], b = order[(e + 1) % 3];
            int64_t A = Y[a] - Y[b];
            int64_t B = X[b] - X[a];
            int64_t C = -(A * X[a] + B * Y[a]);
            // Top-left rule: a centre exactly on an edge belongs to the
            // triangle only if that edge is a left edge (A > 0) or a top
            // edge (A == 0, B > 0); otherwise nudge the edge inwards by one.
            bool top_left = A > 0 || (A == 0 && B > 0);
            tri.edge[e].dx = A * kSubpixelScale;
            tri.edge[e].dy = B * kSubpixelScale;
            tri.edge[e].c = C + (A + B) * (kSubpixelScale / 2) - (top_left ? 0 : 1);
        }
        tri.min_x = static_cast<int32_t>(px0);
        tri.max_x = static_cast<int32_t>(px1);
        tri.min_y = static_cast<int32_t>(py0);
        tri.max_y = static_cast<int32_t>(py1);

        const double scale = 1.0 / static_cast<double>(kSubpixelScale);
        PlaneSolver ps;
        ps.x0 = X[0] * scale;
        ps.y0 = Y[0] * scale;
        ps.d1x = (X[1] - X[0]) * scale;
        ps.d1y = (Y[1] - Y[0]) * scale;
        ps.d2x = (X[2] - X[0]) * scale;
        ps.d2y = (Y[2] - Y[0]) * scale;
        ps.det = ps.d1x * ps.d2y - ps.d2x * ps.d1y;
        float zp[3];
        ps.solve(z[0], z[1], z[2], zp);
        tri.x0 = static_cast<float>(ps.x0);
        tri.y0 = static_cast<float>(ps.y0);
        tri.z0 = zp[0];
        tri.dzdx = zp[1];
        tri.dzdy = zp[2];

        ShadeSetup shade;
        shade.x0 = tri.x0;
        shade.y0 = tri.y0;
        ps.solve(inv_w[0], inv_w[1], inv_w[2], shade.inv_w);
        ps.solve(double(bary[0].y) * inv_w[0], double(bary[1].y) * inv_w[1],
                 double(bary[2].y) * inv_w[2], shade.b1_w);
        ps.solve(double(bary[0].z) * inv_w[0], double(bary[1].z) * inv_w[1],
                 double(bary[2].z) * inv_w[2], shade.b2_w);
        shade.source_triangle = source;
        shade.back_facing = back_facing ? 1 : 0;

        uint32_t local = static_cast<uint32_t>(bins.triangles.size());
        bins.triangles.push_back(tri);
        bins.shading.push_back(shade);
        for (int64_t ty = py0 / tile_size_; ty <= py1 / tile_size_; ++ty)
            for (int64_t tx = px0 / tile_size_; tx <= px1 / tile_size_; ++tx) {
                bins.scratch_tiles.push_back(static_cast<uint32_t>(ty * tiles_x_ + tx));
                bins.scratch_tiles.push_back(local);
            }
    };

    const size_t first = chunk * kTrianglesPerChunk;
    const size_t last = std::min(first + kTrianglesPerChunk, input.triangle_count);
    for (size_t t = first; t < last; ++t) {
        const uint32_t* idx = input.indices + 3 * t;
        glm::vec4 v[3] = {input.clip[idx[0]], input.clip[idx[1]], input.clip[idx[2]]};
        // Values that overflowed to infinity or NaN upstream (absurd
        // transforms) would make the fixed-point maths meaningless: drop them.
        bool finite = true;
        for (int i = 0; i < 3; ++i)
            finite = finite && std::isfinite(v[i].x) && std::isfinite(v[i].y) &&
                     std::isfinite(v[i].z) && std::isfinite(v[i].w);
        if (!finite) continue;
        uint32_t oc[3];
        for (int i = 0; i < 3; ++i) oc[i] = clip_outcode(v[i], guard_x_, guard_y_);
        if (oc[0] & oc[1] & oc[2]) continue;  // entirely outside one plane
        bool cull = input.cull_back && input.cull_back[t];
        glm::vec3 corners[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        if ((oc[0] | oc[1] | oc[2]) == 0) {
            emit(v, corners, static_cast<uint32_t>(t), cull);
            continue;
        }
        ClipVertex in[3], out[kMaxClippedVertices];
        for (int i = 0; i < 3; ++i) in[i] = {v[i], corners[i]};
        int n = clip_triangle(in, oc[0] | oc[1] | oc[2], guard_x_, guard_y_, out);
        for (int i = 1; i + 1 < n; ++i) {  // fan
            glm::vec4 fv[3] = {out[0].position, out[i].position, out[i + 1].position};
            glm::vec3 fb[3] = {out[0].bary, out[i].bary, out[i + 1].bary};
            emit(fv, fb, static_cast<uint32_t>(t), cull);
        }
    }

    // Counting sort of (tile, triangle) pairs by tile; stable, so each bin
    // keeps submission order.
    bins.tile_start.assign(tile_count + 1, 0);
    const size_t pairs = bins.scratch_tiles.size() / 2;
    for (size_t i = 0; i < pairs; ++i) ++bins.tile_start[bins.scratch_tiles[2 * i] + 1];
    for (size_t i = 1; i <= tile_count; ++i) bins.tile_start[i] += bins.tile_start[i - 1];
    bins.tile_items.resize(pairs);
    std::vector<uint32_t> fill(bins.tile_start.begin(), bins.tile_start.end() - 1);
    for (size_t i = 0; i < pairs; ++i)
        bins.tile_items[fill[bins.scratch_tiles[2 * i]]++] = bins.scratch_tiles[2 * i + 1];
}

}  // namespace facet
