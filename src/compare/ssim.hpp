#pragma once
// The structural similarity index (Wang, Bovik, Sheikh & Simoncelli 2004,
// "Image quality assessment: from error visibility to structural
// similarity", IEEE TIP 13(4)), the perceptual metric of `facet compare`
// (docs/regression.md): the paper's form with an 11 x 11 Gaussian window of
// sigma 1.5, K1 = 0.01, K2 = 0.03, population (not sample) statistics, and
// the mean taken over the pixels whose window lies inside the image. These
// are the choices of scikit-image's structural_similarity with
// gaussian_weights=True, use_sample_covariance=False, against which the
// tests check it.
#include <span>
#include <vector>

namespace facet {

// One channel of an image, row by row.
struct ImagePlane {
    int width = 0;
    int height = 0;
    std::span<const float> values;
};

struct SsimResult {
    double mean = 1;  // the mean SSIM over the valid pixels: 1 for identical planes
    // Per pixel (width x height); pixels too near the border for a whole
    // window are 1.
    std::vector<float> map;
};

// SSIM of two planes of the same size, whose values span `data_range`
// (255 for 8-bit images). A plane with a side of 11 pixels or less has no
// pixel with a whole window: its result is 1 when the planes are equal and
// 0 otherwise. Throws std::invalid_argument for planes of different sizes.
SsimResult ssim(const ImagePlane& a, const ImagePlane& b, double data_range);

}  // namespace facet
