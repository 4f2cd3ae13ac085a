#pragma once
// Where on a tonal art map (shade/tonal_art_map.hpp) a point of a surface
// reads its strokes, so that strokes keep their width and length in pixels
// and follow a direction field.
//
// A point is seen through one or more charts: 2D coordinates in tiles (a
// plane of the object's own space, its UVs, or the screen), their
// derivatives per output pixel, and the angle the strokes should take in
// them. Each chart becomes up to four weighted taps:
//
// - Octaves. The coordinates are scaled by a power of two so that the
//   tile's texels per pixel fall within one octave of a target; two
//   neighbouring octaves are blended so the switch never shows (the
//   self-similar zoom of Bénard et al. 2010, "Dynamic Solid Textures for
//   Real-Time Coherent Stylization"). With the tonal art map's mips, whose
//   strokes are the same width in texels at every level (Praun et al. 2001,
//   §4.1), strokes stay a fixed width and length in pixels at any distance
//   and any UV scale.
// - Orientations. Rotating the coordinates by the field's angle at each
//   point would shear the pattern wherever the angle changes, and more the
//   further from the origin. Instead the coordinates are rotated by fixed
//   angles, kHatchOrientations of them over 180°, and the two nearest the
//   field's angle are blended: each rotation is rigid, so strokes stay
//   straight, and the direction still turns smoothly with the field.
#include <glm/vec2.hpp>

#include "shade/tonal_art_map.hpp"

namespace facet {

constexpr int kHatchOrientations = 16;  // every 11.25°: strokes within 4° of the field
constexpr int kMaxHatchCharts = 3;      // the planes of a triplanar mapping
constexpr int kMaxHatchTaps = kMaxHatchCharts * 4;

struct HatchChart {
    glm::vec2 coords;    // in tiles
    glm::vec2 ddx, ddy;  // derivatives of coords per output pixel
    float angle;         // radians from the coords' first axis towards the second
    float weight;        // the chart's share, the charts of a point summing to 1
};

struct HatchTap {
    glm::vec2 uv;   // in [0, 1), already rotated, scaled and wrapped
    float lod;      // log2 of the finest mip's texels per output pixel
    float weight;   // the tap's share; a point's shares sum to 1
    float strokes;  // how much of its strokes show: less where the chart is seen edge-on
};

struct HatchFootprint {
    HatchTap taps[kMaxHatchTaps];
    int count;
};

// Appends a chart's taps. In object and uv space (`octaves`), strokes
// fade out where the chart is seen edge-on (its screen footprint more than
// 3:1, gone at 8:1) instead of stretching into streaks. `target_lod` is the lod the octaves aim at,
// log2(tam size / tile pixels): the tile then covers between tile_pixels/2
// and tile_pixels pixels. Without `octaves` (screen space, where the
// coordinates are already in pixels) the chart keeps its own scale.
void add_hatch_chart(const HatchChart& chart, int tam_size, float target_lod, bool octaves,
                     HatchFootprint& out);

// The stroke coverage of a tone (1 = white) over the footprint's taps.
float hatch_coverage(const TonalArtMap& tam, float tone, const HatchFootprint& footprint);

// The paper's brightness (pencil), over the same taps.
float hatch_paper_shade(const TonalArtMap& tam, const HatchFootprint& footprint);

}  // namespace facet
