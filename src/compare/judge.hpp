#pragma once
// The verdict on one pair of images of one kind: the rule of
// compare/thresholds.hpp applied to every pixel, with the figures a report
// shows (docs/regression.md, "Metrics").
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "compare/compare_image.hpp"
#include "compare/difference_stats.hpp"
#include "compare/thresholds.hpp"
#include "core/enum_names.hpp"

namespace facet {

enum class Outcome { pass, warn, fail };
inline constexpr EnumName<Outcome> kOutcomes[] = {
    {Outcome::pass, "pass"}, {Outcome::warn, "warn"}, {Outcome::fail, "fail"}};
inline const char* outcome_name(Outcome outcome) {
    return c_name_of(kOutcomes, outcome);
}

struct JudgeInputs {
    ImageKind kind = ImageKind::color;
    Tolerance tolerance;
    Tolerance alpha_tolerance;      // for colour images with alpha
    std::span<const uint8_t> mask;  // one per pixel, 0 = left out; empty: none
    double white = 1;               // colour_float: the sequence's white point
};

// One channel group's figures (the image's own channels, or its alpha).
struct PixelVerdict {
    Outcome outcome = Outcome::pass;
    std::string reason;     // why it warned or failed; "" when it passed
    DifferenceStats stats;  // in the kind's unit (max: largest sample difference)
    uint64_t pixels_failed = 0;
    uint64_t pixels_warned = 0;
    uint64_t forgiven_by_position = 0;  // over the threshold, but matched within `position`
    uint64_t background_mismatch = 0;   // depth: +inf against a finite depth
    double percent_failed() const {
        return stats.pixels ? 100.0 * pixels_failed / stats.pixels : 0.0;
    }
};

struct Judgement {
    Outcome outcome = Outcome::pass;  // the worse of the parts
    PixelVerdict pixels;
    std::optional<PixelVerdict> alpha;  // colour images with alpha
    std::optional<double> ssim;         // colour kinds: mean SSIM over the unmasked pixels
    // Per pixel, for the report's images:
    std::vector<float> excess;    // largest difference / fail limit (0 where masked)
    std::vector<uint8_t> state;   // 0 pass, 1 warn, 2 fail, 3 forgiven by position, 4 masked
    std::vector<float> ssim_map;  // colour kinds
};

// Both images must have the kind's layout and the same size (the caller
// reports size mismatches before judging).
Judgement judge_images(const CompareImage& ref, const CompareImage& candidate,
                       const JudgeInputs& inputs);

// The display values of a colour image as SSIM and the report see them:
// PNG values as they are, EXR colour divided by `white`, clamped to 0..1
// and encoded as sRGB (one exposure for the whole sequence, as HDR-FLIP
// holds one range for a test set).
std::vector<float> display_values(const CompareImage& image, ImageKind kind, double white);

// The mean absolute frame-to-frame change of two images of one sequence,
// in display values for colour and the kind's unit otherwise; non-finite
// samples (depth background) count when they change, as 1.
double frame_change(const CompareImage& a, const CompareImage& b, ImageKind kind, double white);

// The flicker of one frame: the mean, over samples, of
// |(candidate - candidate_prev) - (ref - ref_prev)|, in display values for
// colour and the kind's unit otherwise; a sample whose change is not
// finite in one run only counts 1.
double change_difference(const CompareImage& ref_prev, const CompareImage& ref,
                         const CompareImage& candidate_prev, const CompareImage& candidate,
                         ImageKind kind, double white);

}  // namespace facet
