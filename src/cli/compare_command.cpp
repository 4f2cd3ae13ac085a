#include "cli/compare_command.hpp"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/option_values.hpp"
#include "cli/options.hpp"
#include "compare/compare_run.hpp"
#include "compare/reference_update.hpp"
#include "compare/reports.hpp"
#include "compare/self_test.hpp"
#include "compare/thresholds.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"
#include "output/encoders.hpp"
#include "scene/thresholds_file.hpp"

namespace facet {
namespace {

// --mask x,y,width,height, in pixels.
CompareMask mask_rectangle(const std::string& text) {
    constexpr int kMost = 1 << 20;  // as the thresholds file allows
    const std::string expected = "x,y,width,height in pixels (e.g. 0,0,120,40)";
    const std::vector<int> numbers = parse_whole_number_list(text, "--mask", 0, kMost, expected);
    if (numbers.size() != 4)
        fail_option_value("--mask", text, expected,
                          count_of(numbers.size(), "number", "numbers") + ", not 4");
    CompareMask m;
    m.x = numbers[0];
    m.y = numbers[1];
    m.width = numbers[2];
    m.height = numbers[3];
    if (m.width < 1 || m.height < 1)
        fail_option_value("--mask", text, expected, "the width and height are at least 1");
    return m;
}

}  // namespace

CompareThresholds comparison_thresholds(const CompareArgs& args) {
    CompareThresholds t = args.thresholds_file.empty() ? default_thresholds()
                                                       : load_thresholds_file(args.thresholds_file);
    for (const std::string& text : args.thresholds)
        if (std::string problem = apply_threshold_override(t, text); !problem.empty())
            fail_input(command_line("--threshold " + text), "", problem);
    for (const std::string& text : args.masks) t.masks.push_back(mask_rectangle(text));
    for (const std::string& path : args.mask_images) {
        CompareMask m;
        m.image = path;
        t.masks.push_back(m);
    }
    // Every mask image is read now, so a bad one stops the command before
    // any work (render --reference: before rendering).
    for (const CompareMask& m : t.masks) {
        if (m.image.empty()) continue;
        try {
            read_png(m.image);
        } catch (const Error& e) {
            fail_input(command_line("mask image " + m.image), "",
                       "cannot be read as a PNG: " + e.detail());
        }
    }
    return t;
}

namespace {

const char* line_tag(const FileResult& r) {
    if (r.status == FileStatus::identical || r.status == FileStatus::compared)
        return r.outcome == Outcome::fail ? "FAIL" : r.outcome == Outcome::warn ? "warn" : "pass";
    return r.status == FileStatus::unreadable ? "ERROR" : "FAIL";
}

void print_summary(const CompareReport& report, bool quiet) {
    const CompareCounts& c = report.counts;
    if (quiet) return;
    for (const SequenceResult& s : report.sequences)
        if (s.frames > 1 && (s.worst_frame || s.flicker_frame))
            std::printf(
                "sequence %s%s%s (%s): %s, flicker %.4g%s\n", s.camera.c_str(),
                s.camera.empty() ? "" : "/", s.pass.c_str(), s.format.c_str(),
                s.worst_frame ? ("worst frame " + std::to_string(*s.worst_frame) + " (" +
                                 format_number(s.worst_percent, 4) + "% failing)")
                                    .c_str()
                              : "no failing pixels",
                s.flicker,
                s.flicker_frame ? (" at frame " + std::to_string(*s.flicker_frame)).c_str() : "");
    std::printf("compare: %zu files: %d identical, %d passed, %d warned, %d failed",
                report.files.size(), c.identical, c.passed, c.warned, c.failed);
    for (auto [count, word] : {std::pair{c.missing, "missing"},
                               {c.extra, "extra"},
                               {c.size_mismatch, "size mismatch"},
                               {c.unreadable, "unreadable"}})
        if (count) std::printf(", %d %s", count, word);
    std::printf(" -> %s\n", report.outcome == Outcome::fail ? "FAILED" : "passed");
    if (!report.report_dir.empty())
        std::printf("report: %s\n",
                    (std::filesystem::path(report.report_dir) / "index.html").string().c_str());
}

int self_test_command(const CompareArgs& args, const CompareThresholds& thresholds) {
    const SelfTestReport report =
        run_self_test(args.ref, thresholds, [&](const NeighbourResult& r) {
            if (args.quiet) return;
            const std::string name =
                (r.camera.empty() ? "" : r.camera + "/") + r.pass + "." + r.format;
            if (r.identical)
                std::printf("  %s %d -> %d: identical (nothing changes)\n", name.c_str(), r.frame,
                            r.next_frame);
            else
                std::printf("  %s %d -> %d: %s, margin x%.3g%s%s\n", name.c_str(), r.frame,
                            r.next_frame,
                            r.outcome == Outcome::fail ? "told apart" : "NOT told apart", r.margin,
                            r.reason.empty() ? "" : ": ", r.reason.c_str());
        });
    std::printf("self-test: %zu neighbour pairs: %d told apart, %d not, %d identical",
                report.pairs.size(), report.told_apart, report.not_told_apart, report.identical);
    if (const NeighbourResult* m = report.smallest_margin)
        std::printf("; smallest margin x%.3g (%s%s %d -> %d)", m->margin,
                    m->camera.empty() ? "" : (m->camera + "/").c_str(), m->pass.c_str(), m->frame,
                    m->next_frame);
    std::printf("\n");
    return report.not_told_apart ? static_cast<int>(ExitCode::comparison_failed) : 0;
}

int run_comparison(const CompareArgs& args, const CompareThresholds& thresholds,
                   const std::optional<std::set<std::pair<std::string, int>>>& only) {
    std::optional<UpdateMode> mode;
    if (!args.update_reference.empty()) {
        mode = parse_choice(args.update_reference, "--update-reference", kUpdateModes);
        std::error_code ec;
        if (!std::filesystem::is_directory(args.candidate, ec))
            fail_input(command_line("--update-reference"), "",
                       "updates need two output folders, not image files");
        prepare_reference_folder(args.ref, args.candidate);
    }
    CompareRequest request;
    request.ref = args.ref;
    request.candidate = args.candidate;
    request.thresholds = thresholds;
    request.only = only;
    if (!args.no_report)
        request.report_dir =
            args.report_dir.empty() ? default_report_dir(args.candidate) : args.report_dir;
    request.on_file = [&](const FileResult& r) {
        // A file that cannot be read is an error, which -q still prints.
        if (args.quiet && r.status == FileStatus::unreadable)
            std::fprintf(stderr, "facet: error: %s: %s\n", r.key.label().c_str(), r.reason.c_str());
        if (args.quiet || r.outcome == Outcome::pass) return;
        std::printf("%-5s %s: %s\n", line_tag(r), r.key.label().c_str(), r.reason.c_str());
    };
    CompareReport report = run_compare(request);
    int code = compare_exit_code(report);
    if (mode) {
        // The reports are written after the update, with the exit code it leaves.
        UpdateResult updated;
        try {
            updated = update_reference(report, args.ref, args.candidate, *mode);
        } catch (const Error&) {
            if (!request.report_dir.empty()) write_reports(report);
            throw;
        }
        if (!args.quiet) {
            for (const std::string& label : updated.written)
                std::printf("updated %s\n", label.c_str());
            std::printf("reference %s: %s updated (%s)\n", args.ref.c_str(),
                        count_of(updated.written.size(), "file", "files").c_str(),
                        args.update_reference.c_str());
        }
        if (code == static_cast<int>(ExitCode::comparison_failed) &&
            updated.unresolved_failures == 0)
            code = 0;
        report.updated = updated.written;
        report.exit_code_after_update = code;
    }
    // The reports first: a run that cannot write its report has not
    // passed, and must not say so before it fails.
    if (!request.report_dir.empty()) write_reports(report);
    print_summary(report, args.quiet);
    return code;
}

}  // namespace

void add_comparison_options(CLI::App* cmd, CompareArgs& args, bool report_is_output) {
    cmd->add_option("--thresholds", args.thresholds_file, "Thresholds file (YAML)");
    cmd->add_option("-t,--threshold", args.thresholds,
                    "Override one threshold: [camera.]kind.key=value, e.g. color.hard_fail=0.1")
        ->take_all()
        ->allow_extra_args(false);
    cmd->add_option("--mask", args.masks, "Leave out a rectangle: x,y,width,height (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
    cmd->add_option("--mask-image", args.mask_images,
                    "Leave out the non-black pixels of a PNG of the images' size")
        ->take_all()
        ->allow_extra_args(false);
    // In `compare` the report is the output, so it is also -o/--output;
    // in `render` that name is the render's.
    cmd->add_option(report_is_output ? "-o,--output,--out,--report" : "--report", args.report_dir,
                    "Report folder (default: compare/ beside NEW's manifest)");
    cmd->add_flag("--no-report", args.no_report, "Write no report folder");
    cmd->add_option("--update-reference", args.update_reference,
                    "Write NEW's files into the reference: failed, missing or all");
}

int compare_command(const CompareArgs& args) {
    const CompareThresholds thresholds = comparison_thresholds(args);
    if (args.self_test) {
        std::error_code ec;
        if (!args.candidate.empty() || !std::filesystem::is_directory(args.ref, ec))
            fail_input(command_line("--self-test " + args.ref), "",
                       "give one reference folder (with manifest.json)");
        return self_test_command(args, thresholds);
    }
    if (args.candidate.empty())
        fail_input(command_line("compare"), "", "give REF and NEW (or --self-test REFDIR)");
    return run_comparison(args, thresholds, std::nullopt);
}

int compare_render_output(CompareArgs args, const CompareThresholds& thresholds,
                          const std::string& output_dir,
                          const std::set<std::pair<std::string, int>>& rendered) {
    args.candidate = output_dir;
    return run_comparison(args, thresholds, rendered);
}

}  // namespace facet
