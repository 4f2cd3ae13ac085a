#pragma once
// Tonal art maps (Praun, Hoppe, Webb & Finkelstein 2001, "Real-Time
// Hatching"): K tone levels of tileable stroke textures, each with a mip
// chain, generated procedurally here instead of from scanned strokes.
//
// - Strokes are drawn at the same width in pixels at every mip level, so
//   they stay crisp at any scale (their §4.1); mips smaller than
//   `min_stroke_size` are box-filtered instead, where strokes would be
//   wider than the gaps between them.
// - Nesting: every level holds all strokes of the lighter levels, and every
//   mip all strokes of the coarser mips of the same level. Blending two
//   levels then never makes a stroke fade in and out, only others appear
//   (their "stroke coherence"). Here every image is a prefix of one ordered
//   list of strokes, which gives both properties by construction.
// - Each image is filled until its mean coverage reaches its level's
//   target; each new stroke is the best of a few random candidates (the one
//   that darkens most where it is still light), as in their §4.2.
// - Strokes are slight arcs (quadratic Bézier curves, flattened into a few
//   segments) with tapered ends and a jittered length and angle.
// - Darker levels add cross strokes at `cross_angle` to the hatching.
// - Pencil: lighter, softer strokes whose deposit follows a paper grain
//   (graphite catches on the peaks), and the grain itself for the paper.
//
// Everything is integer hashing and IEEE-exact arithmetic: the same seed
// gives the same texels on every machine. No global state.
//
// Per frame: build once per style (it depends on the parameters only), e.g.
//   const TonalArtMap tam = generate_tonal_art_map(TamParams{});
// Per pixel: tone in [0, 1] (1 = white, no strokes), uv in texture tiles
// (object UV times a scale, or screen pixel / params.size), lod = log2 of
// TAM texels per pixel step (0 for screen-space uv):
//   float coverage = tam_coverage(tam, tone, uv, lod);
//   colour = mix(paper * tam_paper_shade(tam, uv, lod), ink, coverage)
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace facet {

struct TamParams {
    int levels = 6;  // K tone levels, lightest first
    int size = 256;  // finest mip, a power of two in [16, 2048]
    uint32_t seed = 1;
    float max_darkness = 0.8f;  // mean coverage of the darkest level; level i gets (i+1)/K of it

    float stroke_width = 1.5f;    // pixels, at every mip level
    float edge_softness = 1.0f;   // anti-aliasing ramp across a stroke's edge, in pixels
    float stroke_length = 0.4f;   // fraction of the tile
    float length_jitter = 0.25f;  // each stroke's length varies by up to this fraction
    float taper = 0.06f;          // fraction of the length over which each end fades out
    // How far each stroke bows from its chord, as a fraction of its length,
    // drawn in [-curvature, curvature]: a hand's strokes are slight arcs.
    float curvature = 0.04f;
    float pressure_min = 1.0f;  // each stroke's darkness, drawn in [min, max]
    float pressure_max = 1.0f;

    float hatch_angle = 45.0f;  // degrees from +u towards +v (u right, v down)
    float angle_jitter = 5.0f;  // degrees, either way
    float cross_angle = 90.0f;  // cross strokes, degrees from the hatching
    int cross_from_level = 3;   // levels from this one on add cross strokes; >= levels: never

    int candidates = 8;        // best of this many random strokes per stroke
    int min_stroke_size = 16;  // smaller mips are box-filtered

    // Pencil only (grain > 0): strokes deposit g-weighted graphite,
    // 1 − grain·(1 − g), g the paper's height; the paper is shaded
    // 1 − paper_shading·(1 − g).
    float grain = 0.0f;
    int grain_cells = 32;  // paper lattice cells per tile
    float paper_shading = 0.0f;

    // A pencil look: lighter, softer, thinner strokes on grainy paper.
    static TamParams pencil();

    bool operator==(const TamParams&) const = default;
};

struct TamImage {
    int size = 0;
    std::vector<uint8_t> texels;  // coverage * 255, rows top to bottom
    uint8_t at(int x, int y) const { return texels[static_cast<size_t>(y) * size + x]; }
};

struct TonalArtMap {
    TamParams params;
    std::vector<std::vector<TamImage>> levels;  // [tone level, lightest first][mip, finest first]
    std::vector<TamImage> paper;                // paper height mips (pencil only, else empty)
    std::vector<float> level_darkness;          // mean coverage of each level's finest mip
    std::vector<int> level_strokes;             // strokes in each level's finest mip
};

// Throws facet::Error (invalid_input) for parameters out of range (the style
// parser is expected to have reported those with a file position already).
TonalArtMap generate_tonal_art_map(const TamParams& params);

// Bilinear in a mip, linear between mips; uv wraps. Coverage in [0, 1].
float tam_level_coverage(const TonalArtMap& tam, int level, glm::vec2 uv, float lod);

// Stroke coverage for a tone (1 = white): the two tone levels nearest to
// darkness 1 − tone blended linearly, the blank page below the first level.
float tam_coverage(const TonalArtMap& tam, float tone, glm::vec2 uv, float lod);

// Brightness of the paper at uv: 1 without grain, else in [1 − paper_shading, 1].
float tam_paper_shade(const TonalArtMap& tam, glm::vec2 uv, float lod);

}  // namespace facet
