#pragma once
// One image file as `facet compare` judges it: samples as floats in the
// unit of its kind (compare/thresholds.hpp), with alpha apart.
#include <string>
#include <vector>

#include "compare/thresholds.hpp"

namespace facet {

struct CompareImage {
    int width = 0, height = 0;
    int channels = 0;            // per pixel in `samples`
    std::vector<float> samples;  // interleaved, row by row
    std::vector<float> alpha;    // one per pixel, or empty
    std::string description;     // "PNG 8-bit RGBA", "EXR R,G,B,A"
};

// The kind of a manifest entry: colour PNG -> color, colour EXR ->
// color_float, depth -> depth, normal -> normal, object_id and material_id
// -> id, alpha -> alpha, uv/position/motion EXR -> float, other PNG views
// -> color.
ImageKind kind_for_pass(const std::string& pass, const std::string& format);

// The kind of a lone file, from its contents: a one-channel 16-bit PNG is
// a depth view, other PNGs colour; an EXR with Z is depth, with R, G, B
// colour, with N.X normals, with a channel named like "id" ids, else float.
ImageKind guess_image_kind(const std::string& path);

// Reads `path` as `kind`:
//  - colour PNG: encoded values / 255 (or / 65535), R, G, B; alpha apart;
//  - colour EXR: linear R, G, B; A apart;
//  - depth EXR: Z (+inf background); depth PNG view: 1 - v / 65535, and
//    +inf where v is 0 (the view's background);
//  - normal: N.X, N.Y, N.Z (or X, Y, Z);
//  - id: the one channel (EXR, exact up to 2^24) or, for a PNG view, the
//    colour packed as R * 65536 + G * 256 + B;
//  - float: every channel.
// A file that cannot be read or lacks the kind's channels throws
// Error(io_failure) naming the file.
CompareImage read_compare_image(const std::string& path, ImageKind kind);

// The exposure of a colour EXR sequence, held for all its frames: the
// largest, over the reference's frames, of each frame's 99.9th-percentile
// luminance, so one bright pixel does not set it and a dark frame does not
// get its own. 1 when no frame has light. Unreadable files are skipped
// (their own comparison reports them).
double sequence_white(const std::vector<std::string>& ref_paths);

}  // namespace facet
