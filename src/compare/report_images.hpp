#pragma once
// The pictures of a comparison report, as 8-bit PNG bytes: the scaled
// absolute difference, a heat map, and a viewable preview of an image a
// browser cannot show (EXR).
#include <cstdint>
#include <vector>

#include "compare/compare_image.hpp"
#include "compare/judge.hpp"

namespace facet {

// |NEW - REF| * scale per channel: colour kinds in display values
// (judge.hpp), other kinds as grey from each pixel's difference over its
// fail limit (1 = the limit, shown as 1/8 * scale).
std::vector<uint8_t> difference_png(const CompareImage& ref, const CompareImage& candidate,
                                    ImageKind kind, double white, double scale,
                                    const Judgement& judgement);

// Colour kinds: 1 - SSIM per pixel on a black-red-yellow-white ramp
// (white at 0.5 and above). Other kinds: the pixels' verdicts: failed red,
// forgiven by position yellow, warned orange, masked blue, the rest black.
std::vector<uint8_t> heat_png(const CompareImage& ref, ImageKind kind, const Judgement& judgement);

// A PNG a browser shows: colour at the sequence's exposure (with alpha),
// depth as grey (near white, background black) over its finite range,
// normals as 0.5 + 0.5 n, ids as a colour per id, float data as grey of
// its first channel over its range.
std::vector<uint8_t> preview_png(const CompareImage& image, ImageKind kind, double white);

}  // namespace facet
