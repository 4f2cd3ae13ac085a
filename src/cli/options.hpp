#pragma once
// The one vocabulary of the command line (README, "Command-line options"):
// options that mean the same in every subcommand are declared here once,
// and so are the checks that follow parsing (frames against the scene's
// range, unknown words with a did-you-mean).
#include <optional>
#include <string>
#include <vector>

#include "cli/option_values.hpp"
#include "core/plain_text.hpp"  // count_of
#include "scene/scene_desc.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace facet {

// A number option, read by option_values.hpp rather than by CLI11 (which
// takes "010" for eight, "0x10" for sixteen and " 4" for four), so that a
// bad value gets the error every other bad value gets. Errors name the
// option by the first of `names` ("-f" of "-f,--frame").
CLI::Option* add_whole_number_option(CLI::App* command, const std::string& names, int& value,
                                     int min, int max, const std::string& description);
CLI::Option* add_whole_number_option(CLI::App* command, const std::string& names,
                                     std::optional<int>& value, int min, int max,
                                     const std::string& description);
// A finite number (NaN and infinity are refused) from `min` to `max`.
CLI::Option* add_decimal_option(CLI::App* command, const std::string& names, double& value,
                                double min, double max, const std::string& description);

// --frames LIST, -f N, -s/--start N, -e/--end N, -j/--jump N, --allow-outside.
struct FrameSelection {
    std::string frames;
    std::optional<int> single, start, end;
    std::optional<int> jump;  // every Nth of the frames -s/-e (or the scene) give
    bool allow_outside = false;
};
void add_frame_options(CLI::App* command, FrameSelection& selection);

// The frames asked for, in order; empty when none was asked for (the
// scene's own). Checks that only one way was used, and that every frame
// lies within the scene's range unless allow_outside (exit code 2, naming
// the option and the range).
std::vector<int> resolve_frames(const FrameSelection& selection, const OutputDesc& output);

// -o/--output PATH (alias --out).
void add_output_option(CLI::App* command, std::string& output, const std::string& description);

// --threads N, 0 = one per core.
void add_threads_option(CLI::App* command, unsigned& threads);

// -q/--quiet.
void add_quiet_flag(CLI::App* command, bool& quiet);

// -D key.path=value, repeatable.
void add_define_option(CLI::App* command, std::vector<std::string>& defines);

// After parsing with extras allowed: the first word the command did not
// take becomes an error with a did-you-mean among its options (exit 2).
void reject_unknown_arguments(CLI::App* command);

// argv[1] when it names no subcommand: an error with a did-you-mean and the
// list of subcommands. Does nothing for options (-h, --version).
void check_subcommand_name(const CLI::App& app, int argc, char** argv);

}  // namespace facet
