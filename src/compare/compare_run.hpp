#pragma once
// `facet compare REF NEW`: pairs the files of two runs through their
// manifests by (camera, pass, frame, format), or two lone files; judges each
// pair (compare/judge.hpp); gathers per-sequence figures (worst frame,
// flicker); writes the difference images. The reports are written from the
// result by compare/report_*.hpp.
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "compare/judge.hpp"
#include "compare/thresholds.hpp"
#include "core/enum_names.hpp"

namespace facet {

struct FileKey {
    std::string camera;
    std::string pass;
    int frame = 0;
    std::string format;
    std::string label() const;  // "front/color/0012.png"
};

// What became of one pair, worst last.
enum class FileStatus { identical, compared, missing, extra, size_mismatch, unreadable };
inline constexpr EnumName<FileStatus> kFileStatuses[] = {
    {FileStatus::identical, "identical"},
    {FileStatus::compared, "compared"},
    {FileStatus::missing, "missing"},
    {FileStatus::extra, "extra"},
    {FileStatus::size_mismatch, "size_mismatch"},
    {FileStatus::unreadable, "unreadable"}};
inline const char* file_status_name(FileStatus status) {
    return c_name_of(kFileStatuses, status);
}

struct FileResult {
    FileKey key;
    ImageKind kind = ImageKind::color;
    std::string ref_path, new_path;  // empty when that side has no file
    FileStatus status = FileStatus::compared;
    Outcome outcome = Outcome::pass;
    bool decoded = false;
    std::string reason;  // why it warned or failed, or what went wrong
    int ref_width = 0, ref_height = 0, new_width = 0, new_height = 0;
    std::optional<PixelVerdict> pixels, alpha;
    std::optional<double> ssim;
    // Frame-to-frame change from the previous frame of the sequence, in
    // each run (compare/judge.hpp, frame_change); only where computed.
    std::optional<double> change_ref, change_new;
    // The mean, over samples, of |(NEW's change) - (REF's change)| from the
    // previous frame: 0 when NEW moves exactly as REF does.
    std::optional<double> flicker;
    // The report's pictures, relative to the report folder ("" when none).
    std::string diff_image, heat_image, ref_preview, new_preview;
};

// One (camera, pass, format) series of frames.
struct SequenceResult {
    std::string camera, pass, format;
    ImageKind kind = ImageKind::color;
    double white = 1;  // colour EXR: the exposure held for the whole sequence
    int frames = 0;
    std::optional<int>
        worst_frame;  // the frame with the most failing pixels (none: no pixel fails)
    double worst_percent = 0;
    // The largest difference, over neighbouring frames, between NEW's
    // frame-to-frame change and REF's: 0 when NEW moves as REF does.
    double flicker = 0;
    std::optional<int> flicker_frame;
};

struct CompareCounts {
    int files = 0, identical = 0, passed = 0, warned = 0, failed = 0, missing = 0, extra = 0,
        size_mismatch = 0, unreadable = 0;
};

// The counts with their names as report.json writes them ("size_mismatch").
std::vector<std::pair<const char*, int>> named_counts(const CompareCounts& counts);

struct CompareReport {
    static constexpr int kSchemaVersion = 1;
    std::string ref, candidate;  // as given
    std::string report_dir;
    CompareThresholds thresholds;
    std::vector<FileResult> files;  // failures first, then warnings, then the rest; each by key
    std::vector<SequenceResult> sequences;
    CompareCounts counts;
    Outcome outcome = Outcome::pass;
    // After --update-reference: the files written and the exit code that
    // follows (compare_exit_code returns it).
    std::vector<std::string> updated;
    std::optional<int> exit_code_after_update;
};

struct CompareRequest {
    std::string ref, candidate;  // two folders with manifest.json, or two image files
    CompareThresholds thresholds = default_thresholds();
    std::string report_dir;  // where images go ("" = write none)
    // When set, only these (camera, frame) pairs are compared (render
    // --reference of some frames: the others were not rendered this time).
    std::optional<std::set<std::pair<std::string, int>>> only;
    // Called as each file is judged (progress, terminal summary).
    std::function<void(const FileResult&)> on_file;
};

CompareReport run_compare(const CompareRequest& request);

// 0 all pass (warnings allowed), 3 a failure, missing, extra or size
// mismatch, 4 an unreadable file (design.md, exit codes).
int compare_exit_code(const CompareReport& report);

// The folder `facet compare` writes its report to by default: compare/
// beside NEW's manifest (or beside a lone NEW file).
std::string default_report_dir(const std::string& candidate);

}  // namespace facet
