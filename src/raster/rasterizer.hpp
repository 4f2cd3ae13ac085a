#pragma once
// The raster core of one frame: primitive stage (clip, cull, set up, bin)
// then tile stage (rasterize each tile into a visibility buffer and hand it
// to a shading callback). Knows nothing of files, scenes or styles.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/thread_pool.hpp"
#include "raster/raster_limits.hpp"
#include "raster/setup_bins.hpp"

namespace facet {

struct RasterInput {
    const glm::vec4* clip = nullptr;  // clip-space positions, reversed-Z (render/camera.hpp)
    size_t vertex_count = 0;
    const uint32_t* indices = nullptr;  // three per triangle, counter-clockwise = front
    size_t triangle_count = 0;
    const uint8_t* cull_back = nullptr;  // per triangle: 1 drops back faces
    // Per triangle, or null: 1 where a mirroring transform (a negative
    // scale in a pose) has reversed the winding, so that clockwise on
    // screen is the front.
    const uint8_t* flip_winding = nullptr;
    // Per triangle, or null: 1 where the triangle covers a sample only if
    // the CoverageTest given to draw_tiles keeps it (cut-out and dithered
    // transparency: render/alpha_coverage.hpp).
    const uint8_t* coverage_tested = nullptr;
};

// Asked for each sample a coverage-tested triangle would win on depth:
// false leaves the sample to what is behind. `b1` and `b2` are the
// perspective-correct weights of the source triangle's second and third
// corners; x and y the sample's position. The rasterizer knows nothing of
// what decides.
struct CoverageTest {
    const void* context = nullptr;
    bool (*keep)(const void* context, uint32_t source_triangle, float b1, float b2, int x,
                 int y) = nullptr;
};

// Marks a visibility-buffer sample that no triangle covers.
constexpr uint32_t kNoTriangle = 0xffffffffu;

// A rasterized tile: for each pixel the nearest triangle's id and depth.
struct TileVisibility {
    int x0, y0, width, height;  // the tile's pixel rectangle
    const float* depth;         // reversed-Z, row stride kTileSize; 0 where empty
    const uint32_t* id;         // triangle id for Rasterizer::shade_setup, or kNoTriangle
};

class Rasterizer {
  public:
    // `tile_size` in [8, kTileSize]: the side of the screen tiles.
    Rasterizer(int width, int height, int tile_size = kTileSize);

    int width() const { return width_; }
    int height() const { return height_; }
    int tile_size() const { return tile_size_; }

    // Primitive stage, in parallel over fixed chunks of triangles.
    void set_geometry(const RasterInput& input, ThreadPool& pool);

    // Tile stage. `shade` runs once per tile, possibly on several threads at
    // once for different tiles; it must write only pixels inside its tile.
    // `test` decides the samples of coverage-tested triangles; without one
    // they cover as any other.
    // `tiles`, when not empty, holds a byte per tile (tile_index): only
    // those that are not 0 are drawn.
    void draw_tiles(ThreadPool& pool, const std::function<void(const TileVisibility&)>& shade,
                    const CoverageTest& test = {}, std::span<const uint8_t> tiles = {}) const;

    int tile_count() const { return tiles_x_ * tiles_y_; }
    // The tile that holds sample (x, y), and the tile whose top-left
    // sample is (x0, y0) (TileVisibility's).
    int tile_index(int x, int y) const { return (y / tile_size_) * tiles_x_ + x / tile_size_; }

    const ShadeSetup& shade_setup(uint32_t id) const {
        return chunks_[id >> kLocalIdBits].shading[id & kLocalIdMask];
    }

    // Triangles that survived culling and clipping in the last set_geometry.
    size_t setup_triangle_count() const;

    // What set_geometry keeps for `triangles` and `vertices`, for the
    // memory estimate: per vertex its screen position; per triangle its
    // set-up and shading records and its bin entries, counted for
    // kBinnedTilesPerTriangle tiles (a small triangle of a dense mesh lies
    // in one tile, one on a tile's edge in two; a large one in many, but
    // large ones are few).
    static uint64_t bytes(uint64_t triangles, uint64_t vertices) {
        constexpr uint64_t kBinnedTilesPerTriangle = 2;
        constexpr uint64_t kBinEntryBytes = 3 * sizeof(uint32_t);  // (tile, triangle), item
        return vertices * sizeof(ScreenVertex) +
               triangles * (sizeof(SetupTriangle) + sizeof(ShadeSetup) +
                            kBinnedTilesPerTriangle * kBinEntryBytes);
    }

  private:
    // A vertex on screen, computed once per frame by project_vertices.
    struct ScreenVertex {
        int32_t x, y;  // fixed point; valid where outcode is 0
        float inv_w, z;
        uint32_t outcode;  // clip planes it is outside of, and kNotFinite
    };

    // A triangle's corners on screen, as setup takes them.
    struct ScreenTriangle {
        int64_t x[3], y[3];  // fixed point
        float inv_w[3], z[3];
        glm::vec3 bary[3];  // the source triangle's weights at each corner
    };

    // A triangle id is (chunk << 16) | index in chunk. Clipping turns one
    // source triangle into at most 7, so a chunk produces at most
    // 7 * kTrianglesPerChunk triangles, which must fit in 16 bits.
    static constexpr uint32_t kLocalIdBits = 16;
    static constexpr uint32_t kLocalIdMask = (1u << kLocalIdBits) - 1;
    static_assert(7 * kTrianglesPerChunk <= (1u << kLocalIdBits));

    void project_vertices(const RasterInput& input, size_t first, size_t last);
    void setup_chunk(const RasterInput& input, size_t chunk);
    // How a source triangle's screen winding is read.
    struct Facing {
        bool cull_back;        // drop it when it faces away
        bool flipped;          // clockwise is its front (RasterInput::flip_winding)
        bool coverage_tested;  // RasterInput::coverage_tested
    };
    void emit_triangle(const ScreenTriangle& t, uint32_t source, Facing facing,
                       ChunkBins& bins) const;
    void emit_clipped(const RasterInput& input, const uint32_t* idx, uint32_t planes,
                      uint32_t source, Facing facing, ChunkBins& bins) const;
    void bin_chunk(ChunkBins& bins) const;
    void draw_tile(int tile, const std::function<void(const TileVisibility&)>& shade,
                   const CoverageTest& test) const;

    int width_, height_;
    int tile_size_;
    int tiles_x_, tiles_y_;
    float guard_x_, guard_y_;          // guard band half-size in NDC units
    BulkVector<ScreenVertex> screen_;  // per input vertex
    std::vector<ChunkBins> chunks_;
    size_t chunk_count_ = 0;
};

}  // namespace facet
