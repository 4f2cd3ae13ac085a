#pragma once
// The plain records the primitive stage hands to the tile stage (the
// "bins"), in the manner of Mesa llvmpipe's setup/rasterizer split: the
// tile stage reads only these.
#include <cstdint>
#include <vector>

#include "core/bulk_buffer.hpp"

namespace facet {

// Edge function E(px, py) = dx * px + dy * py + c with dx = a << 8 and
// dy = b << 8 (kSubpixelBits), evaluated at the centre of pixel (px, py);
// the pixel is covered when all three are >= 0. The top-left fill rule is
// folded into c (Pineda 1988; D3D10 fill rules). a and b are differences of
// fixed-point coordinates inside the guard band, so 32 bits hold them; c
// needs 64. Compact records matter: a frame of a million triangles writes
// and reads every one of them.
struct EdgeFunction {
    int32_t a, b;
    int64_t c;
};

struct SetupTriangle {
    EdgeFunction edge[3];
    int16_t min_x, min_y, max_x, max_y;  // pixel bounding box, inclusive, on screen
    // Reversed-Z depth (1 at the near plane, 0 at the far plane), affine in
    // screen space: z = z0 + dzdx * (x - x0) + dzdy * (y - y0), x and y in pixels.
    float x0, y0, z0, dzdx, dzdy;
    // 1: each covered sample also asks the CoverageTest (raster/rasterizer.hpp).
    // In what would be padding: the record stays 80 bytes.
    uint32_t coverage_tested;
};

// What shading needs to recover perspective-correct barycentrics of the
// *source* triangle at a pixel, also for pieces produced by clipping.
// Each plane p gives p[0] + p[1] * (x - x0) + p[2] * (y - y0).
struct ShadeSetup {
    float x0, y0;
    float inv_w[3];  // 1/w
    float b1_w[3];   // b1/w, b1 = weight of the source triangle's second vertex
    float b2_w[3];   // b2/w
    uint32_t source_triangle;
    uint32_t back_facing;  // 1 when the triangle faces away from the camera
};

// Triangles set up by one chunk of the primitive stage, and their bins:
// the triangles touching tile t are tile_items[tile_start[t] .. tile_start[t+1]),
// in submission order.
struct ChunkBins {
    BulkVector<SetupTriangle> triangles;
    BulkVector<ShadeSetup> shading;
    std::vector<uint32_t> tile_start;
    BulkVector<uint32_t> tile_items;
    BulkVector<uint32_t> scratch_tiles;  // (tile, triangle) pairs before sorting
};

}  // namespace facet
