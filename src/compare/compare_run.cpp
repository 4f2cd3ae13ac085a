#include "compare/compare_run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

#include "compare/masks.hpp"
#include "compare/pairing.hpp"
#include "compare/report_images.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/sha256.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The hash of a file's bytes, or "" with `problem` set when it cannot be read.
std::string file_hash(const std::string& path, std::string& problem) {
    problem = input_file_problem(path);
    if (!problem.empty()) return "";
    try {
        return sha256_hex(read_input_file(path, "image"));
    } catch (const Error& e) {
        problem = e.detail().empty() ? e.what() : e.detail();
        return "";
    }
}

std::string image_file_name(const FileKey& key, const char* what) {
    std::string name = (key.camera.empty() ? "" : key.camera + "-") + key.pass + "-" +
                       std::to_string(key.frame) + "-" + key.format + "-" + what + ".png";
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
            c = '_';
    return "images/" + name;
}

struct Decoded {
    bool ok = false;
    CompareImage ref, candidate;
};

// One (camera, pass, format) sequence, its pairs in frame order.
class SequenceRun {
  public:
    SequenceRun(const CompareRequest& request, MaskBuilder& masks, std::vector<FilePair> pairs)
        : request_(request), masks_(masks), pairs_(std::move(pairs)) {}

    SequenceResult run(std::vector<FileResult>& out) {
        const size_t n = pairs_.size();
        SequenceResult seq;
        seq.camera = pairs_[0].key.camera;
        seq.pass = pairs_[0].key.pass;
        seq.format = pairs_[0].key.format;
        seq.kind = pairs_[0].kind;
        seq.frames = static_cast<int>(n);
        std::vector<FileResult> results(n);
        std::vector<bool> changed(n, false);
        for (size_t i = 0; i < n; ++i) changed[i] = check_hashes(pairs_[i], results[i]);
        const bool any_changed = std::count(changed.begin(), changed.end(), true) > 0;
        if (seq.kind == ImageKind::color_float && any_changed) {
            std::vector<std::string> paths;
            for (const FilePair& pair : pairs_) paths.push_back(pair.ref_path);
            seq.white = sequence_white(paths);
        }
        white_ = seq.white;
        Decoded previous;
        for (size_t i = 0; i < n; ++i) {
            // Neighbours of a changed frame are decoded too, for the flicker figure.
            const bool needed =
                changed[i] || (i > 0 && changed[i - 1]) || (i + 1 < n && changed[i + 1]);
            Decoded current;
            if (needed && (results[i].status == FileStatus::identical ||
                           results[i].status == FileStatus::compared))
                current = decode(pairs_[i], results[i], changed[i]);
            if (current.ok && changed[i]) judge(pairs_[i], current, results[i]);
            if (current.ok && previous.ok && (changed[i] || changed[i - 1]) &&
                same_size(previous, current)) {
                FileResult& r = results[i];
                r.change_ref = frame_change(previous.ref, current.ref, seq.kind, white_);
                r.change_new =
                    frame_change(previous.candidate, current.candidate, seq.kind, white_);
                r.flicker = change_difference(previous.ref, current.ref, previous.candidate,
                                              current.candidate, seq.kind, white_);
                const double flicker = *r.flicker;
                if (flicker > seq.flicker) {
                    seq.flicker = flicker;
                    seq.flicker_frame = pairs_[i].key.frame;
                }
            }
            previous = std::move(current);
            if (request_.on_file) request_.on_file(results[i]);
        }
        for (size_t i = 0; i < n; ++i)
            if (results[i].pixels && results[i].pixels->percent_failed() > seq.worst_percent) {
                seq.worst_percent = results[i].pixels->percent_failed();
                seq.worst_frame = pairs_[i].key.frame;
            }
        for (FileResult& r : results) out.push_back(std::move(r));
        return seq;
    }

  private:
    static bool same_size(const Decoded& a, const Decoded& b) {
        return a.ref.samples.size() == b.ref.samples.size() &&
               a.candidate.samples.size() == b.candidate.samples.size() &&
               a.ref.samples.size() == b.candidate.samples.size();
    }

    // Fills the result's paths and status from the files alone. True when
    // both files exist, are readable and differ.
    bool check_hashes(const FilePair& pair, FileResult& r) {
        r.key = pair.key;
        r.kind = pair.kind;
        r.ref_path = pair.ref_path;
        r.new_path = pair.new_path;
        if (pair.new_path.empty()) {
            return fail(r, FileStatus::missing, "missing from NEW (the reference has it)");
        }
        if (pair.ref_path.empty()) {
            return fail(r, FileStatus::extra, "not in the reference (only NEW has it)");
        }
        // A reference image deleted by hand (to have it made again, as
        // snapshot tools work) is missing from the reference, not damage.
        std::error_code absent;
        if (!std::filesystem::exists(pair.ref_path, absent) && !absent) {
            r.ref_path.clear();
            return fail(r, FileStatus::extra,
                        "not in the reference folder, although its manifest lists it "
                        "(--update-reference missing writes it)");
        }
        std::string ref_problem, new_problem;
        const std::string ref_hash = file_hash(pair.ref_path, ref_problem);
        const std::string new_hash = file_hash(pair.new_path, new_problem);
        if (!ref_problem.empty())
            return fail(r, FileStatus::unreadable, pair.ref_path + ": " + ref_problem);
        if (!new_problem.empty())
            return fail(r, FileStatus::unreadable, pair.new_path + ": " + new_problem);
        // A file that is not what its manifest says was damaged or replaced
        // after the run: neither passing nor failing it would be honest.
        for (const auto& [path, actual, recorded] :
             {std::tuple{pair.ref_path, ref_hash, pair.ref_sha256},
              std::tuple{pair.new_path, new_hash, pair.new_sha256}})
            if (!recorded.empty() && actual != recorded)
                return fail(r, FileStatus::unreadable,
                            path +
                                ": does not match the SHA-256 its manifest records (damaged "
                                "or replaced after the run)");
        if (ref_hash == new_hash) {
            r.status = FileStatus::identical;
            check_mask_images(pair);
            return false;
        }
        r.status = FileStatus::compared;
        return true;
    }

    static bool fail(FileResult& r, FileStatus status, const std::string& reason) {
        r.status = status;
        r.outcome = Outcome::fail;
        r.reason = reason;
        return false;
    }

    // A mask image of another size than the images is the command's error
    // whether or not a file differs (MaskBuilder::build throws), so
    // identical files are measured too when a mask image applies.
    void check_mask_images(const FilePair& pair) {
        const auto& masks = request_.thresholds.masks;
        if (std::none_of(masks.begin(), masks.end(),
                         [](const CompareMask& m) { return !m.image.empty(); }))
            return;
        CompareImage image;
        try {
            image = read_compare_image(pair.ref_path, pair.kind);
        } catch (const Error&) {
            return;  // identical bytes: the size is only needed to check the masks
        }
        masks_.build(pair.key.camera, pair.kind, image.width, image.height);
    }

    // A frame decoded only as a changed frame's neighbour (identical in
    // both runs) has passed already: if it cannot be decoded, it only
    // leaves the flicker figure out.
    Decoded decode(const FilePair& pair, FileResult& r, bool judged) {
        Decoded d;
        try {
            d.ref = read_compare_image(pair.ref_path, pair.kind);
            d.candidate = read_compare_image(pair.new_path, pair.kind);
        } catch (const Error& e) {
            if (judged) fail(r, FileStatus::unreadable, e.what());
            return d;
        }
        if (!judged) {
            d.ok = d.ref.samples.size() == d.candidate.samples.size();
            return d;
        }
        r.decoded = true;
        r.ref_width = d.ref.width;
        r.ref_height = d.ref.height;
        r.new_width = d.candidate.width;
        r.new_height = d.candidate.height;
        if (d.ref.width != d.candidate.width || d.ref.height != d.candidate.height ||
            d.ref.channels != d.candidate.channels) {
            fail(r, FileStatus::size_mismatch,
                 "size mismatch: REF is " + std::to_string(d.ref.width) + "x" +
                     std::to_string(d.ref.height) + " " + d.ref.description + ", NEW is " +
                     std::to_string(d.candidate.width) + "x" + std::to_string(d.candidate.height) +
                     " " + d.candidate.description);
            return d;
        }
        d.ok = true;
        return d;
    }

    void judge(const FilePair& pair, const Decoded& d, FileResult& r) {
        const std::vector<uint8_t> mask =
            masks_.build(pair.key.camera, pair.kind, d.ref.width, d.ref.height);
        // Masks that leave out every pixel compare nothing: that is no pass.
        if (!mask.empty() &&
            std::all_of(mask.begin(), mask.end(), [](uint8_t m) { return m == 0; })) {
            fail(r, FileStatus::compared,
                 "the masks leave out every pixel of the image, so nothing was compared; "
                 "narrow them");
            return;
        }
        JudgeInputs in;
        in.kind = pair.kind;
        in.tolerance = tolerance_for(request_.thresholds, pair.key.camera, pair.kind);
        in.alpha_tolerance = tolerance_for(request_.thresholds, pair.key.camera, ImageKind::alpha);
        in.mask = mask;
        in.white = white_;
        const Judgement j = judge_images(d.ref, d.candidate, in);
        r.outcome = j.outcome;
        r.pixels = j.pixels;
        r.alpha = j.alpha;
        r.ssim = j.ssim;
        r.reason = j.pixels.reason;
        if (j.alpha && !j.alpha->reason.empty())
            r.reason += (r.reason.empty() ? "" : "; ") + j.alpha->reason;
        if (request_.report_dir.empty()) return;
        const fs::path dir(request_.report_dir);
        auto write = [&](const char* what, const std::vector<uint8_t>& png) {
            const std::string name = image_file_name(pair.key, what);
            write_file_atomically((dir / name).string(), png);
            return name;
        };
        make_directories((dir / "images").string());
        r.diff_image = write("diff", difference_png(d.ref, d.candidate, pair.kind, white_,
                                                    request_.thresholds.diff_scale, j));
        r.heat_image = write("heat", heat_png(d.ref, pair.kind, j));
        if (pair.key.format != "png" || pair.kind == ImageKind::id) {
            r.ref_preview = write("ref", preview_png(d.ref, pair.kind, white_));
            r.new_preview = write("new", preview_png(d.candidate, pair.kind, white_));
        }
    }

    const CompareRequest& request_;
    MaskBuilder& masks_;
    std::vector<FilePair> pairs_;
    double white_ = 1;
};

int severity(const FileResult& r) {
    if (r.status != FileStatus::identical && r.status != FileStatus::compared) return 0;
    return r.outcome == Outcome::fail ? 0 : r.outcome == Outcome::warn ? 1 : 2;
}

}  // namespace

std::string FileKey::label() const {
    char frame_text[16];
    std::snprintf(frame_text, sizeof frame_text, "%04d", frame);
    return (camera.empty() ? "" : camera + "/") + pass + "/" + frame_text + "." + format;
}

CompareReport run_compare(const CompareRequest& request) {
    CompareReport report;
    report.ref = request.ref;
    report.candidate = request.candidate;
    report.report_dir = request.report_dir;
    report.thresholds = request.thresholds;
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<FilePair>> sequences;
    for (FilePair& pair : pair_files(request.ref, request.candidate)) {
        if (request.only && !request.only->count({pair.key.camera, pair.key.frame})) continue;
        sequences[{pair.key.camera, pair.key.pass, pair.key.format}].push_back(std::move(pair));
    }
    MaskBuilder masks(request.thresholds);
    for (auto& [key, pairs] : sequences) {
        std::sort(pairs.begin(), pairs.end(),
                  [](const FilePair& a, const FilePair& b) { return a.key.frame < b.key.frame; });
        SequenceRun run(request, masks, std::move(pairs));
        report.sequences.push_back(run.run(report.files));
    }
    std::stable_sort(
        report.files.begin(), report.files.end(),
        [](const FileResult& a, const FileResult& b) { return severity(a) < severity(b); });
    CompareCounts& c = report.counts;
    c.files = static_cast<int>(report.files.size());
    for (const FileResult& r : report.files) {
        switch (r.status) {
            case FileStatus::identical:
                ++c.identical;
                break;
            case FileStatus::missing:
                ++c.missing;
                break;
            case FileStatus::extra:
                ++c.extra;
                break;
            case FileStatus::size_mismatch:
                ++c.size_mismatch;
                break;
            case FileStatus::unreadable:
                ++c.unreadable;
                break;
            case FileStatus::compared:
                r.outcome == Outcome::fail   ? ++c.failed
                : r.outcome == Outcome::warn ? ++c.warned
                                             : ++c.passed;
        }
        report.outcome = std::max(report.outcome, r.outcome);
    }
    return report;
}

std::vector<std::pair<const char*, int>> named_counts(const CompareCounts& c) {
    return {{"files", c.files},          {"identical", c.identical},
            {"passed", c.passed},        {"warned", c.warned},
            {"failed", c.failed},        {"missing", c.missing},
            {"extra", c.extra},          {"size_mismatch", c.size_mismatch},
            {"unreadable", c.unreadable}};
}

int compare_exit_code(const CompareReport& report) {
    if (report.exit_code_after_update) return *report.exit_code_after_update;
    if (report.counts.unreadable) return static_cast<int>(ExitCode::io_failure);
    if (report.outcome == Outcome::fail) return static_cast<int>(ExitCode::comparison_failed);
    return 0;
}

std::string default_report_dir(const std::string& candidate) {
    std::error_code ec;
    const fs::path path(candidate);
    const fs::path base = fs::is_directory(path, ec) ? path : path.parent_path();
    return (base / "compare").string();
}

}  // namespace facet
