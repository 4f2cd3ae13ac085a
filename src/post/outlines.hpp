#pragma once
// Screen-space outlines from per-pixel depth, normal and object id (Saito &
// Takahashi 1990, "Comprehensible Rendering of 3-D Shapes": lines where
// the G-buffer is discontinuous). Four kinds of line, each with its own
// switch, width and colour:
//
//   silhouette    a jump in depth (including object against background)
//   crease        no jump, but normals differ by more than crease_angle
//   boundary      the object id changes (including object against background)
//   intersection  two different objects meet without a jump in depth:
//                 where they pass through each other (docs/references.md, seed 001's display
//                 mode "the lines where models intersect")
//
// Method, in passes over rows, each row written by one task only, so the
// result is the same for any thread count:
//  0. 1/z and the object id per pixel (background: 0 and kNoObject).
//  1. Edges are found between each pixel and its right and lower
//     neighbour, so an edge sits on the border between two pixels, not on
//     either pixel; that is what makes lines symmetric and of even width.
//  2. A row pass marks pixels near any edge, so pass 3 skips the rest.
//  3. Each pixel takes its distance d to the nearest edge (the midpoint of
//     a pixel pair) of each kind: a dilation by a disc. Coverage is
//     clamp(w/2 + 0.5 − d, 0, 1), a line of width w with a pixel-wide
//     anti-aliasing ramp, so fractional widths work: across a straight
//     edge the coverages add up to w.
// Depth jumps are judged on inverse depth 1/z, which is affine in screen
// space on a plane: each side predicts the other's 1/z from its own slope,
// and only when both predictions miss by more than depth_threshold · 1/z
// is there a jump. So the threshold is relative (the same at any distance)
// and planes seen at grazing angles do not fill with false lines.
//
// Per frame: fill an OutlineBuffers from the renderer (at output
// resolution after the resolve, or at sample resolution with widths
// scaled by k before it), then
//   draw_outlines(buffers, style, lines, pool, scratch);
//   composite_lines(lines, colour, pool);
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.hpp"
#include "core/thread_pool.hpp"

namespace facet {

inline constexpr uint32_t kNoObject = 0xffffffffu;

// Plain per-pixel arrays, rows top to bottom, index y * width + x.
struct OutlineBuffers {
    int width = 0;
    int height = 0;
    std::vector<float> depth;       // linear view depth; +inf (not in (0, inf)) = background
    std::vector<glm::vec3> normal;  // world or view space, one space per frame; any length
    // kNoObject on background, and on surfaces that draw no lines (shadow
    // catchers, which show only the shadows on them): both read as
    // background here, while ambient occlusion still reads their depth.
    std::vector<uint32_t> object_id;

    // Sets the size and fills everything with background.
    void reset(int w, int h);
    size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
};
// What one element of an OutlineBuffers holds: its depth, normal and object.
inline constexpr size_t kOutlineElementBytes =
    sizeof(decltype(OutlineBuffers::depth)::value_type) +
    sizeof(decltype(OutlineBuffers::normal)::value_type) +
    sizeof(decltype(OutlineBuffers::object_id)::value_type);

// In order of precedence, lowest first. Where kinds overlap, coverage is
// the largest of theirs, and a lower kind shows only where it reaches
// beyond the higher ones: an edge that is silhouette, boundary and crease
// at once is drawn once, in the silhouette's colour.
enum class LineKind : int { crease = 0, boundary = 1, intersection = 2, silhouette = 3 };
inline constexpr int kLineKinds = 4;

struct LineStyle {
    bool enabled = false;
    float width = 1.0f;     // pixels, may be fractional
    glm::vec3 color{0.0f};  // linear RGB
};

struct OutlineStyle {
    LineStyle silhouette{true, 1.5f, glm::vec3(0.0f)};
    LineStyle crease{true, 1.0f, glm::vec3(0.0f)};
    LineStyle boundary{false, 1.0f, glm::vec3(0.0f)};
    LineStyle intersection{false, 1.0f, glm::vec3(0.8f, 0.0f, 0.0f)};
    float depth_threshold = 0.02f;  // a depth jump of more than 2% is a silhouette
    float crease_angle = 30.0f;     // degrees between the two normals

    const LineStyle& line(LineKind kind) const;
};

// Edge flags between pixel (x, y) and its neighbours: bit k for the pair
// with (x+1, y), bit 4 + k for the pair with (x, y+1), k = int(LineKind).
constexpr uint8_t edge_bit(LineKind kind, bool with_lower) {
    return static_cast<uint8_t>(1u << (static_cast<int>(kind) + (with_lower ? 4 : 0)));
}

// Buffers reused from frame to frame, all width * height.
struct OutlineScratch {
    std::vector<uint8_t> edges;        // edge_bit flags per pixel (the result of find_edges)
    std::vector<float> inverse_depth;  // 1/z, 0 on background
    std::vector<uint32_t> id;          // object id, kNoObject on background
    std::vector<uint8_t> near_row;     // 1 where an edge in the same row is within reach
};

// Object pairs that really cross (sorted keys, the smaller id in the high
// 32 bits; render/crossing_stage.hpp): when given, intersection lines are
// drawn only between them, since an image alone cannot tell flush contact
// from crossing. Null: between any two objects that meet in the image.
using CrossingPairs = const std::vector<uint64_t>*;

// Pass 1 alone: scratch.edges gets the flags, for enabled kinds only.
// Throws facet::Error (runtime_failure) if the buffers do not match their size.
void find_edges(const OutlineBuffers& buffers, const OutlineStyle& style, OutlineScratch& scratch,
                ThreadPool& pool, CrossingPairs crossing = nullptr);

// All passes. `lines` gets the buffers' size (reused if it has it already):
// rgb the line colour (linear, not premultiplied), a its coverage in [0, 1].
void draw_outlines(const OutlineBuffers& buffers, const OutlineStyle& style, ColorImage& lines,
                   ThreadPool& pool, OutlineScratch& scratch, CrossingPairs crossing = nullptr);

// Lines over a linear RGBA image of the same size: rgb mixed by coverage,
// alpha = a + alpha · (1 − a).
void composite_lines(const ColorImage& lines, ColorImage& color, ThreadPool& pool);

// Lines over a premultiplied RGBA image (Porter & Duff 1984, "over"):
// rgb = line · a + rgb · (1 − a), alpha as above.
void composite_lines_premultiplied(const ColorImage& lines, ColorImage& image, ThreadPool& pool);

}  // namespace facet
