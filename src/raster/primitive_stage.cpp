// Primitive stage: assemble, cull, clip, set up fixed-point edge functions
// and bin triangles to screen tiles. Each chunk writes only its own record.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "raster/clip.hpp"
#include "raster/rasterizer.hpp"

namespace facet {
namespace {

// A clip-space value that overflowed to infinity or NaN upstream (absurd
// transforms) makes the fixed-point maths meaningless: its triangles are
// dropped. Marked in the outcode, beside the six planes.
constexpr uint32_t kNotFinite = 1u << 6;

// Snaps a screen coordinate in pixels to fixed point (round to nearest).
// Inside the guard band it fits 32 bits: |x| < 2^15 pixels times 2^8.
inline int32_t to_fixed(float pixels) {
    return static_cast<int32_t>(std::nearbyint(pixels * static_cast<float>(kSubpixelScale)));
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

// Values at the three corners to planes p0 + p1 (x - x0) + p2 (y - y0), by
// Cramer's rule in double on the snapped positions.
struct PlaneSolver {
    double x0, y0, d1x, d1y, d2x, d2y, inv_det;
    void solve(double v0, double v1, double v2, float out[3]) const {
        const double dv1 = v1 - v0, dv2 = v2 - v0;
        out[0] = static_cast<float>(v0);
        out[1] = static_cast<float>((dv1 * d2y - dv2 * d1y) * inv_det);
        out[2] = static_cast<float>((dv2 * d1x - dv1 * d2x) * inv_det);
    }
};

constexpr glm::vec3 kCorners[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

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
    // Every vertex once on screen first: a vertex is shared by about six
    // triangles, which then only look it up.
    screen_.resize(input.vertex_count);
    pool.parallel_for_chunks(
        input.vertex_count, kVerticesPerSetupChunk,
        [&](size_t first, size_t last) { project_vertices(input, first, last); });
    chunk_count_ = (input.triangle_count + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
    if (chunks_.size() < chunk_count_) chunks_.resize(chunk_count_);
    pool.parallel_for(chunk_count_, [&](size_t chunk) { setup_chunk(input, chunk); });
}

void Rasterizer::project_vertices(const RasterInput& input, size_t first, size_t last) {
    const float half_w = 0.5f * static_cast<float>(width_);
    const float half_h = 0.5f * static_cast<float>(height_);
    for (size_t i = first; i < last; ++i) {
        const glm::vec4& v = input.clip[i];
        ScreenVertex& s = screen_[i];
        if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
              std::isfinite(v.w))) {
            s.outcode = kNotFinite;
            continue;
        }
        s.outcode = clip_outcode(v, guard_x_, guard_y_);
        if (s.outcode != 0) continue;  // its triangles are clipped from clip space
        // Inside every plane with w <= 0 means x = y = z = w = 0: a vertex no
        // triangle of this pass uses (stages leave those zero) or one at the
        // eye itself. It has no screen position; 1/w would make one of NaN.
        if (!(v.w > 0.0f)) {
            s.outcode = kNotFinite;
            continue;
        }
        s.inv_w = 1.0f / v.w;
        const glm::vec2 screen = clip_to_screen(v, half_w, half_h);
        s.x = to_fixed(screen.x);
        s.y = to_fixed(screen.y);
        s.z = v.z * s.inv_w;
    }
}

// One triangle (a source triangle, or a piece of one that clipping made):
// cull, bound, set up edges and planes, and list the tiles it touches.
void Rasterizer::emit_triangle(const ScreenTriangle& t, uint32_t source, Facing facing,
                               ChunkBins& bins) const {
    const int64_t* X = t.x;
    const int64_t* Y = t.y;
    const int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
    if (area == 0) return;
    // Screen y points down, so counter-clockwise front faces have negative
    // area; a mirrored triangle's front is the other way round.
    const bool clockwise = area > 0;
    const bool back_facing = clockwise != facing.flipped;
    if (back_facing && facing.cull_back) return;
    int order[3] = {0, 1, 2};
    if (!clockwise) std::swap(order[1], order[2]);  // make the area positive

    const int64_t px0 = std::max<int64_t>(first_pixel_at_or_after(std::min({X[0], X[1], X[2]})), 0);
    const int64_t px1 =
        std::min<int64_t>(last_pixel_at_or_before(std::max({X[0], X[1], X[2]})), width_ - 1);
    const int64_t py0 = std::max<int64_t>(first_pixel_at_or_after(std::min({Y[0], Y[1], Y[2]})), 0);
    const int64_t py1 =
        std::min<int64_t>(last_pixel_at_or_before(std::max({Y[0], Y[1], Y[2]})), height_ - 1);
    if (px0 > px1 || py0 > py1) return;  // covers no pixel centre

    SetupTriangle tri;
    for (int e = 0; e < 3; ++e) {
        const int a = order[e], b = order[(e + 1) % 3];
        const int64_t A = Y[a] - Y[b], B = X[b] - X[a];
        const int64_t C = -(A * X[a] + B * Y[a]);
        // Top-left rule: a centre exactly on an edge belongs to the
        // triangle only if that edge is a left edge (A > 0) or a top edge
        // (A == 0, B > 0); otherwise nudge the edge inwards by one.
        const bool top_left = A > 0 || (A == 0 && B > 0);
        tri.edge[e].a = static_cast<int32_t>(A);
        tri.edge[e].b = static_cast<int32_t>(B);
        tri.edge[e].c = C + (A + B) * (kSubpixelScale / 2) - (top_left ? 0 : 1);
    }
    tri.min_x = static_cast<int16_t>(px0);
    tri.max_x = static_cast<int16_t>(px1);
    tri.min_y = static_cast<int16_t>(py0);
    tri.max_y = static_cast<int16_t>(py1);

    const double scale = 1.0 / static_cast<double>(kSubpixelScale);
    PlaneSolver ps;
    ps.x0 = X[0] * scale;
    ps.y0 = Y[0] * scale;
    ps.d1x = (X[1] - X[0]) * scale;
    ps.d1y = (Y[1] - Y[0]) * scale;
    ps.d2x = (X[2] - X[0]) * scale;
    ps.d2y = (Y[2] - Y[0]) * scale;
    ps.inv_det = 1.0 / (ps.d1x * ps.d2y - ps.d2x * ps.d1y);
    float zp[3];
    ps.solve(t.z[0], t.z[1], t.z[2], zp);
    tri.x0 = static_cast<float>(ps.x0);
    tri.y0 = static_cast<float>(ps.y0);
    tri.z0 = zp[0];
    tri.dzdx = zp[1];
    tri.dzdy = zp[2];
    tri.coverage_tested = facing.coverage_tested ? 1 : 0;

    ShadeSetup shade;
    shade.x0 = tri.x0;
    shade.y0 = tri.y0;
    const float* w = t.inv_w;
    ps.solve(w[0], w[1], w[2], shade.inv_w);
    ps.solve(double(t.bary[0].y) * w[0], double(t.bary[1].y) * w[1], double(t.bary[2].y) * w[2],
             shade.b1_w);
    ps.solve(double(t.bary[0].z) * w[0], double(t.bary[1].z) * w[1], double(t.bary[2].z) * w[2],
             shade.b2_w);
    shade.source_triangle = source;
    shade.back_facing = back_facing ? 1 : 0;

    const uint32_t local = static_cast<uint32_t>(bins.triangles.size());
    bins.triangles.push_back(tri);
    bins.shading.push_back(shade);
    for (int64_t ty = py0 / tile_size_; ty <= py1 / tile_size_; ++ty)
        for (int64_t tx = px0 / tile_size_; tx <= px1 / tile_size_; ++tx) {
            bins.scratch_tiles.push_back(static_cast<uint32_t>(ty * tiles_x_ + tx));
            bins.scratch_tiles.push_back(local);
        }
}

// A triangle that leaves the guard band or crosses the near or far plane:
// clipped in clip space (raster/clip.cpp), the polygon emitted as a fan.
void Rasterizer::emit_clipped(const RasterInput& input, const uint32_t* idx, uint32_t planes,
                              uint32_t source, Facing facing, ChunkBins& bins) const {
    const float half_w = 0.5f * static_cast<float>(width_);
    const float half_h = 0.5f * static_cast<float>(height_);
    ClipVertex in[3], out[kMaxClippedVertices];
    for (int i = 0; i < 3; ++i) in[i] = {input.clip[idx[i]], kCorners[i]};
    const int n = clip_triangle(in, planes, guard_x_, guard_y_, out);
    for (int i = 1; i + 1 < n; ++i) {
        const ClipVertex* corner[3] = {&out[0], &out[i], &out[i + 1]};
        ScreenTriangle t;
        for (int k = 0; k < 3; ++k) {
            const glm::vec4& v = corner[k]->position;
            t.inv_w[k] = 1.0f / v.w;
            const glm::vec2 screen = clip_to_screen(v, half_w, half_h);
            t.x[k] = to_fixed(screen.x);
            t.y[k] = to_fixed(screen.y);
            t.z[k] = v.z * t.inv_w[k];
            t.bary[k] = corner[k]->bary;
        }
        emit_triangle(t, source, facing, bins);
    }
}

void Rasterizer::setup_chunk(const RasterInput& input, size_t chunk) {
    ChunkBins& bins = chunks_[chunk];
    bins.triangles.clear();
    bins.shading.clear();
    bins.scratch_tiles.clear();
    const size_t first = chunk * kTrianglesPerChunk;
    const size_t last = std::min(first + kTrianglesPerChunk, input.triangle_count);
    ScreenTriangle t;
    for (int k = 0; k < 3; ++k) t.bary[k] = kCorners[k];
    for (size_t tri = first; tri < last; ++tri) {
        const uint32_t* idx = input.indices + 3 * tri;
        const ScreenVertex* v[3] = {&screen_[idx[0]], &screen_[idx[1]], &screen_[idx[2]]};
        const uint32_t any = v[0]->outcode | v[1]->outcode | v[2]->outcode;
        if (any & kNotFinite) continue;
        if (v[0]->outcode & v[1]->outcode & v[2]->outcode) continue;  // outside one plane
        const Facing facing{input.cull_back && input.cull_back[tri],
                            input.flip_winding && input.flip_winding[tri],
                            input.coverage_tested && input.coverage_tested[tri]};
        const uint32_t source = static_cast<uint32_t>(tri);
        if (any != 0) {
            emit_clipped(input, idx, any, source, facing, bins);
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            t.x[k] = v[k]->x;
            t.y[k] = v[k]->y;
            t.inv_w[k] = v[k]->inv_w;
            t.z[k] = v[k]->z;
        }
        emit_triangle(t, source, facing, bins);
    }
    bin_chunk(bins);
}

// Counting sort of (tile, triangle) pairs by tile; stable, so each bin
// keeps submission order.
void Rasterizer::bin_chunk(ChunkBins& bins) const {
    const size_t tile_count = static_cast<size_t>(tiles_x_) * tiles_y_;
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
