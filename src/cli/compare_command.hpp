#pragma once
// `facet compare` and the comparison half of `facet render --reference`
// (docs/regression.md).
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace facet {

struct CompareArgs {
    std::string ref, candidate;
    std::string thresholds_file;
    std::vector<std::string> thresholds;   // "[camera.]kind.key=value"
    std::vector<std::string> masks;        // "x,y,width,height"
    std::vector<std::string> mask_images;  // PNG files
    std::string report_dir;                // "" = compare/ beside NEW's manifest
    bool no_report = false;
    std::string update_reference;  // "", failed, missing, all
    bool self_test = false;
    bool quiet = false;
};

// The options `compare` and `render --reference` share: thresholds,
// masks, report folder, update mode.
void add_comparison_options(CLI::App* command, CompareArgs& args, bool report_is_output);

// `facet compare REF NEW` or `facet compare --self-test REFDIR`.
int compare_command(const CompareArgs& args);

// The thresholds the options name; errors (exit code 2) before any work,
// so `render --reference` fails before it renders.
struct CompareThresholds;
CompareThresholds comparison_thresholds(const CompareArgs& args);

// Compares a finished render's output folder with args.ref (render
// --reference); prints the summary and returns the exit code.
// Only the (camera, frame) pairs this render made are compared.
int compare_render_output(CompareArgs args, const CompareThresholds& thresholds,
                          const std::string& output_dir,
                          const std::set<std::pair<std::string, int>>& rendered);

}  // namespace facet
