#pragma once
// `facet compare --self-test REFDIR`: judges each reference frame against
// the next one of its sequence with the thresholds in use. Neighbouring
// frames of an animation are genuinely different images, so thresholds
// that pass them cannot catch a regression of that size; the smallest
// margin by which they fail says how much room the thresholds leave.
#include <functional>
#include <string>
#include <vector>

#include "compare/judge.hpp"
#include "compare/thresholds.hpp"

namespace facet {

struct NeighbourResult {
    std::string camera, pass, format;
    int frame = 0, next_frame = 0;
    bool identical = false;  // the same bytes: the scene does not change there
    Outcome outcome = Outcome::pass;
    std::string reason;
    // How far the pair is past the fail rule: the largest of
    // percent failed / fail_percent, (1 - SSIM) / (1 - ssim_min) and
    // max / hard_fail. Above 1: told apart; at or below 1: not.
    double margin = 0;
};

struct SelfTestReport {
    std::vector<NeighbourResult> pairs;
    int told_apart = 0, not_told_apart = 0, identical = 0;
    const NeighbourResult* smallest_margin = nullptr;  // among pairs told apart
};

SelfTestReport run_self_test(const std::string& ref_dir, const CompareThresholds& thresholds,
                             const std::function<void(const NeighbourResult&)>& on_pair);

}  // namespace facet
