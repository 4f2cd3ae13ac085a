#pragma once
// The visible pieces of a rasterized tile's pixels. With k x k samples per
// pixel, each pixel holds one fragment per distinct triangle among its
// samples, with the number of samples it covers and their centroid; each
// fragment is shaded once, at that centroid, and its colour weighted by its
// coverage (multisample anti-aliasing in the manner of Akeley 1993,
// "RealityEngine Graphics", with centroid sampling so that no fragment is
// shaded outside its triangle). Without anti-aliasing (k = 1) a fragment is
// a covered pixel, shaded at its centre.
#include <cstdint>

#include "raster/rasterizer.hpp"

namespace facet {

constexpr int kMaxTileFragments = kTileSize * kTileSize;  // every sample its own

struct TileFragments {
    int count = 0;
    int side = 1;                    // k: samples per pixel side
    int pixels_x = 0, pixels_y = 0;  // the tile's size in pixels
    float x[kMaxTileFragments];      // centroid, in the rasterizer's sample units
    float y[kMaxTileFragments];
    uint32_t id[kMaxTileFragments];       // the rasterizer's triangle id
    uint16_t pixel[kMaxTileFragments];    // pixel index in the tile, row by row
    uint16_t pixel_x[kMaxTileFragments];  // the pixel's column and row in the tile
    uint16_t pixel_y[kMaxTileFragments];
    uint8_t samples[kMaxTileFragments];  // samples covered, 1 .. k * k
    uint8_t empty[kMaxTileFragments];    // per pixel: samples no triangle covers
};

// `tile` must start on a pixel boundary (its x0, y0 multiples of k) and
// hold whole pixels. Fragments come pixel by pixel, in the order their
// triangles first appear among the pixel's samples. With `mixed_only`, only
// pixels whose samples show more than one thing (two triangles, or a
// triangle and the background) get fragments. `empty` is set for the
// pixels that get fragments.
void build_tile_fragments(const TileVisibility& tile, int side, bool mixed_only,
                          TileFragments& out);

// Starts a list of fragments for a tile (of k x k sample pixels); then
// add_pixel_fragments for each pixel that needs them.
void begin_tile_fragments(const TileVisibility& tile, int side, TileFragments& out);
void add_pixel_fragments(const TileVisibility& tile, int px, int py, TileFragments& out);

// The triangle id all of a pixel's samples show, kNoTriangle when none
// covers any, or kMixedPixel.
constexpr uint32_t kMixedPixel = 0xfffffffeu;
uint32_t pixel_id(const TileVisibility& tile, int side, int px, int py);

}  // namespace facet
