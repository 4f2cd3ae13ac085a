#pragma once
// Limits and precision of the rasterizer, named in one place.
#include <cstddef>
#include <cstdint>

#include "core/limits.hpp"

namespace facet {

// Vertex positions snap to 1/256 of a pixel (8 fractional bits, as D3D11
// and Vulkan implementations commonly use). Shared edges therefore use
// exactly the same coordinates in both triangles, which the fill rule needs.
constexpr int kSubpixelBits = 8;
constexpr int64_t kSubpixelScale = int64_t(1) << kSubpixelBits;

// Triangles are clipped geometrically only where they leave this band
// around the screen; inside it the tile bounding boxes do the clipping.
// It also bounds fixed-point coordinates to about 2^23, so edge function
// values (products of two coordinate differences) fit easily in int64.
constexpr float kGuardBandPixels = 8192.0f;

// Screen tiles: each is rasterized and shaded by one thread at a time. A
// tile is at most kTileSize wide and high (the row stride of its buffers);
// a rasterizer may use a smaller size, so that a tile holds whole pixels of
// a k x k sample grid (63 for k = 3, 60 for k = 5).
constexpr int kTileSize = 64;

// Consecutive tiles one thread takes at a time (raster/tile_stage.cpp).
constexpr size_t kTilesPerTask = 4;

// Source triangles per primitive-stage chunk. Fixed, so that the set of
// chunks (and therefore the per-tile bin order) does not depend on the
// thread count.
constexpr uint32_t kTrianglesPerChunk = 8192;

// Vertices per chunk of the per-vertex screen pass (any fixed number).
constexpr size_t kVerticesPerSetupChunk = 16384;

// The largest image side is core/limits.hpp's kMaxImageSide: it keeps
// tile and pixel indices well inside int32.

}  // namespace facet
