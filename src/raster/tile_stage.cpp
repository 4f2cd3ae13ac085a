// Tile stage: each tile replays its bins in submission order into a
// visibility buffer (nearest depth and triangle id per pixel), then hands it
// to shading. A tile is owned by one thread, so results never depend on
// the thread count.
#include <algorithm>
#include <array>

#include "raster/rasterizer.hpp"

namespace facet {
namespace {

// The source triangle's weights at a sample, from its shading planes (as
// shading reconstructs them), for a coverage test.
struct SampleWeights {
    const ShadeSetup& s;
    void at(int x, int y, float& b1, float& b2) const {
        const float fx = (static_cast<float>(x) + 0.5f) - s.x0;
        const float fy = (static_cast<float>(y) + 0.5f) - s.y0;
        const float inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
        b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) / inv_w;
        b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) / inv_w;
    }
};

// Tested: the triangle's samples also pass `test` (instantiated apart, so
// the usual loop carries no branch for it).
template <bool Tested>
void rasterize(const SetupTriangle& tri, uint32_t id, int tile_x0, int tile_y0, int tile_x1,
               int tile_y1, float* depth, uint32_t* ids, const ShadeSetup* shading = nullptr,
               const CoverageTest* test = nullptr) {
    const int x_lo = std::max<int>(tri.min_x, tile_x0), x_hi = std::min<int>(tri.max_x, tile_x1);
    const int y_lo = std::max<int>(tri.min_y, tile_y0), y_hi = std::min<int>(tri.max_y, tile_y1);
    if (x_lo > x_hi || y_lo > y_hi) return;
    const int64_t dx0 = int64_t{tri.edge[0].a} * kSubpixelScale;
    const int64_t dx1 = int64_t{tri.edge[1].a} * kSubpixelScale;
    const int64_t dx2 = int64_t{tri.edge[2].a} * kSubpixelScale;
    const int64_t dy0 = int64_t{tri.edge[0].b} * kSubpixelScale;
    const int64_t dy1 = int64_t{tri.edge[1].b} * kSubpixelScale;
    const int64_t dy2 = int64_t{tri.edge[2].b} * kSubpixelScale;
    for (int y = y_lo; y <= y_hi; ++y) {
        int64_t w0 = dx0 * x_lo + dy0 * y + tri.edge[0].c;
        int64_t w1 = dx1 * x_lo + dy1 * y + tri.edge[1].c;
        int64_t w2 = dx2 * x_lo + dy2 * y + tri.edge[2].c;
        const float z_row = tri.z0 + tri.dzdy * ((static_cast<float>(y) + 0.5f) - tri.y0);
        float* depth_row = depth + (y - tile_y0) * kTileSize - tile_x0;
        uint32_t* id_row = ids + (y - tile_y0) * kTileSize - tile_x0;
        for (int x = x_lo; x <= x_hi; ++x) {
            if ((w0 | w1 | w2) >= 0) {
                float z = z_row + tri.dzdx * ((static_cast<float>(x) + 0.5f) - tri.x0);
                // Reversed-Z: larger is nearer. Strictly greater keeps the
                // first-submitted triangle on ties, the same on every run.
                bool wins = z > depth_row[x];
                if constexpr (Tested) {
                    if (wins) {
                        float b1, b2;
                        SampleWeights{*shading}.at(x, y, b1, b2);
                        wins = test->keep(test->context, shading->source_triangle, b1, b2, x, y);
                    }
                }
                if (wins) {
                    depth_row[x] = z;
                    id_row[x] = id;
                }
            }
            w0 += dx0;
            w1 += dx1;
            w2 += dx2;
        }
    }
}

}  // namespace

void Rasterizer::draw_tiles(ThreadPool& pool,
                            const std::function<void(const TileVisibility&)>& shade,
                            const CoverageTest& test, std::span<const uint8_t> wanted) const {
    // A thread takes a few neighbouring tiles at a time: they mostly show
    // the same triangles, whose setup and vertices are then still in its
    // cache (taking tiles one by one, two threads alternate and each misses
    // what the other loaded).
    const size_t tiles = static_cast<size_t>(tiles_x_) * tiles_y_;
    const size_t runs = (tiles + kTilesPerTask - 1) / kTilesPerTask;
    pool.parallel_for(runs, [&](size_t run) {
        const size_t last = std::min(tiles, (run + 1) * kTilesPerTask);
        for (size_t tile = run * kTilesPerTask; tile < last; ++tile)
            if (wanted.empty() || wanted[tile]) draw_tile(static_cast<int>(tile), shade, test);
    });
}

void Rasterizer::draw_tile(int tile, const std::function<void(const TileVisibility&)>& shade,
                           const CoverageTest& test) const {
    std::array<float, kTileSize * kTileSize> depth;
    std::array<uint32_t, kTileSize * kTileSize> ids;
    depth.fill(0.0f);
    ids.fill(kNoTriangle);
    const int x0 = (tile % tiles_x_) * tile_size_;
    const int y0 = (tile / tiles_x_) * tile_size_;
    const int x1 = std::min(x0 + tile_size_, width_) - 1;
    const int y1 = std::min(y0 + tile_size_, height_) - 1;
    for (size_t c = 0; c < chunk_count_; ++c) {
        const ChunkBins& bins = chunks_[c];
        for (uint32_t k = bins.tile_start[tile]; k < bins.tile_start[tile + 1]; ++k) {
            const uint32_t local = bins.tile_items[k];
            const SetupTriangle& tri = bins.triangles[local];
            const uint32_t id = static_cast<uint32_t>(c << kLocalIdBits) | local;
            if (tri.coverage_tested && test.keep)
                rasterize<true>(tri, id, x0, y0, x1, y1, depth.data(), ids.data(),
                                &bins.shading[local], &test);
            else
                rasterize<false>(tri, id, x0, y0, x1, y1, depth.data(), ids.data());
        }
    }
    TileVisibility vis{x0, y0, x1 - x0 + 1, y1 - y0 + 1, depth.data(), ids.data()};
    shade(vis);
}

}  // namespace facet
