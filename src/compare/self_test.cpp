#include "compare/self_test.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "compare/compare_image.hpp"
#include "compare/masks.hpp"
#include "compare/pairing.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/sha256.hpp"

namespace facet {
namespace {

double margin_of(const Judgement& j, const Tolerance& t, const Tolerance& alpha) {
    double margin = 0;
    const PixelVerdict& v = j.pixels;
    if (v.pixels_failed > t.allowed_failures)
        margin = t.fail_percent > 0 ? v.percent_failed() / t.fail_percent : 1e9;
    // A pair told apart by its alpha alone is told apart by that margin.
    if (j.alpha && j.alpha->pixels_failed > alpha.allowed_failures)
        margin = std::max(
            margin, alpha.fail_percent > 0 ? j.alpha->percent_failed() / alpha.fail_percent : 1e9);
    if (j.ssim && t.ssim_min > 0 && *j.ssim < t.ssim_min)
        margin = std::max(margin, t.ssim_min < 1 ? (1 - *j.ssim) / (1 - t.ssim_min) : 1e9);
    if (t.hard_fail < 1e29 && t.hard_fail > 0) margin = std::max(margin, v.stats.max / t.hard_fail);
    return margin;
}

}  // namespace

SelfTestReport run_self_test(const std::string& ref_dir, const CompareThresholds& thresholds,
                             const std::function<void(const NeighbourResult&)>& on_pair) {
    // The folder paired with itself lists each of its files once.
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<FilePair>> sequences;
    for (FilePair& pair : pair_files(ref_dir, ref_dir))
        sequences[{pair.key.camera, pair.key.pass, pair.key.format}].push_back(std::move(pair));
    SelfTestReport report;
    MaskBuilder masks(thresholds);
    for (auto& [key, pairs] : sequences) {
        std::sort(pairs.begin(), pairs.end(),
                  [](const FilePair& a, const FilePair& b) { return a.key.frame < b.key.frame; });
        double white = 1;
        if (pairs[0].kind == ImageKind::color_float) {
            std::vector<std::string> paths;
            for (const FilePair& pair : pairs) paths.push_back(pair.ref_path);
            white = sequence_white(paths);
        }
        for (size_t i = 0; i + 1 < pairs.size(); ++i) {
            const FilePair& a = pairs[i];
            const FilePair& b = pairs[i + 1];
            NeighbourResult r;
            r.camera = a.key.camera;
            r.pass = a.key.pass;
            r.format = a.key.format;
            r.frame = a.key.frame;
            r.next_frame = b.key.frame;
            const auto bytes_a = read_input_file(a.ref_path, "reference image");
            const auto bytes_b = read_input_file(b.ref_path, "reference image");
            if (sha256_hex(bytes_a) == sha256_hex(bytes_b)) {
                r.identical = true;
                ++report.identical;
            } else {
                const CompareImage ia = read_compare_image(a.ref_path, a.kind);
                const CompareImage ib = read_compare_image(b.ref_path, b.kind);
                if (ia.width != ib.width || ia.height != ib.height || ia.channels != ib.channels)
                    throw Error(ExitCode::invalid_input,
                                b.ref_path + ": not the size or channels of the frame before it");
                const std::vector<uint8_t> mask =
                    masks.build(a.key.camera, a.kind, ia.width, ia.height);
                JudgeInputs in;
                in.kind = a.kind;
                in.tolerance = tolerance_for(thresholds, a.key.camera, a.kind);
                in.alpha_tolerance = tolerance_for(thresholds, a.key.camera, ImageKind::alpha);
                in.mask = mask;
                in.white = white;
                const Judgement j = judge_images(ia, ib, in);
                r.outcome = j.outcome;
                r.reason = j.pixels.reason;
                r.margin = margin_of(j, in.tolerance, in.alpha_tolerance);
                if (j.outcome == Outcome::fail)
                    ++report.told_apart;
                else
                    ++report.not_told_apart;
            }
            report.pairs.push_back(r);
            if (on_pair) on_pair(report.pairs.back());
        }
    }
    for (const NeighbourResult& r : report.pairs)
        if (!r.identical && r.outcome == Outcome::fail &&
            (!report.smallest_margin || r.margin < report.smallest_margin->margin))
            report.smallest_margin = &r;
    return report;
}

}  // namespace facet
