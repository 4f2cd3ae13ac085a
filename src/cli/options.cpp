#include "cli/options.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>

#include <CLI/CLI.hpp>

#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/plain_text.hpp"
#include "core/suggest.hpp"

namespace facet {
namespace {

std::string range_text(const std::vector<int>& frames) {
    if (frames.empty()) return "none";
    return std::to_string(frames.front()) + "-" + std::to_string(frames.back());
}

// The name an option's errors give it: the first of its names.
std::string reported_name(const std::string& names) {
    return names.substr(0, names.find(','));
}

// Whole numbers go through parse_whole_number into `store`. The help shows
// the range as CLI::Range did.
CLI::Option* add_whole_number_setter(CLI::App* cmd, const std::string& names,
                                     std::function<void(int)> store, int min, int max,
                                     const std::string& description,
                                     const std::string& expected = "") {
    const std::string option = reported_name(names);
    CLI::Option* added = cmd->add_option_function<std::string>(
        names,
        [=](const std::string& text) {
            store(parse_whole_number(text, option, min, max, expected));
        },
        description);
    const bool any_int =
        min == std::numeric_limits<int>::min() && max == std::numeric_limits<int>::max();
    added->type_name(
        any_int ? "INT" : "INT in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
    return added;
}

// -f, -s and -e take any frame number; the scene's range is checked later
// (resolve_frames), where the scene is known.
CLI::Option* add_frame_number_option(CLI::App* cmd, const std::string& names,
                                     std::optional<int>& frame, const std::string& description) {
    return add_whole_number_setter(
        cmd, names, [&frame](int value) { frame = value; }, std::numeric_limits<int>::min(),
        std::numeric_limits<int>::max(), description, "a frame number (a whole number)");
}

}  // namespace

CLI::Option* add_whole_number_option(CLI::App* cmd, const std::string& names, int& value, int min,
                                     int max, const std::string& description) {
    return add_whole_number_setter(
        cmd, names, [&value](int number) { value = number; }, min, max, description);
}

CLI::Option* add_whole_number_option(CLI::App* cmd, const std::string& names,
                                     std::optional<int>& value, int min, int max,
                                     const std::string& description) {
    return add_whole_number_setter(
        cmd, names, [&value](int number) { value = number; }, min, max, description);
}

CLI::Option* add_decimal_option(CLI::App* cmd, const std::string& names, double& value, double min,
                                double max, const std::string& description) {
    const std::string option = reported_name(names);
    char type[64];
    std::snprintf(type, sizeof type, "FLOAT in [%g - %g]", min, max);
    return cmd
        ->add_option_function<std::string>(
            names,
            [=, &value](const std::string& text) {
                value = parse_decimal_number(text, option, min, max);
            },
            description)
        ->type_name(type);
}

void add_frame_options(CLI::App* cmd, FrameSelection& s) {
    cmd->add_option("--frames", s.frames, "Frames to render, e.g. 1-72, 1-72:2, 1,5,10-20");
    add_frame_number_option(cmd, "-f,--frame", s.single, "One frame (Blender's -f)");
    add_frame_number_option(cmd, "-s,--start", s.start,
                            "First frame (Blender's -s); the scene's step is kept");
    add_frame_number_option(cmd, "-e,--end", s.end, "Last frame (Blender's -e)");
    add_whole_number_option(cmd, "-j,--jump", s.jump, 1, 1000000,
                            "Every Nth of the frames, with -s/-e or alone (Blender's -j)");
    cmd->add_flag("--allow-outside", s.allow_outside,
                  "Allow frames outside the scene's range (the animation is extrapolated)");
}

std::vector<int> resolve_frames(const FrameSelection& s, const OutputDesc& output) {
    const int ways = !s.frames.empty() + s.single.has_value() + (s.start || s.end || s.jump);
    if (ways > 1)
        fail_input(command_line("--frames/-f/-s/-e/-j"), "",
                   "give frames one way: --frames LIST (with its own :step), -f N, or -s/-e/-j");
    if (s.jump && !s.start && !s.end) {
        // -j alone: every Nth of the scene's frames.
        FrameSelection whole = s;
        whole.start = output.frames.front();
        return resolve_frames(whole, output);
    }
    std::vector<int> frames;
    std::string option;
    if (!s.frames.empty()) {
        option = "--frames " + s.frames;
        try {
            frames = parse_frame_ranges(s.frames);
        } catch (const Error& e) {
            fail_input(command_line(option), "", e.detail());
        }
    } else if (s.single) {
        option = "-f " + std::to_string(*s.single);
        frames = {*s.single};
    } else if (s.start || s.end) {
        const int first = s.start.value_or(output.frames.front());
        const int last = s.end.value_or(output.frames.back());
        option = "-s/-e " + std::to_string(first) + "-" + std::to_string(last);
        if (first > last)
            fail_input(command_line(option), "", "the start frame is after the end frame");
        const auto [low, high] = std::minmax_element(output.frames.begin(), output.frames.end());
        if (!s.allow_outside && (first < *low || last > *high))
            fail_input(command_line(option), "",
                       "the frames reach outside the scene's frames " + output.frames_text +
                           "; give --allow-outside to render them anyway");
        // The scene's own frames in the range, and with --allow-outside the
        // frames beyond them on the scene's grid (its first frame plus whole
        // steps), so a scene of 1-72:2 extended to 80 gives 73, 75, ...
        const long step = output.frames.size() > 1 ? output.frames[1] - output.frames[0] : 1;
        constexpr long kMostFrames = 1000000;
        if ((static_cast<long>(last) - first) / std::max(1L, step) > kMostFrames)
            fail_input(command_line(option), "", "more than a million frames");
        for (int f : output.frames)
            if (f >= first && f <= last) frames.push_back(f);
        for (long f = *low - step; f >= first; f -= step)
            if (f <= last) frames.push_back(static_cast<int>(f));
        for (long f = *high + step; f <= last; f += step)
            if (f >= first) frames.push_back(static_cast<int>(f));
        std::sort(frames.begin(), frames.end());
        if (frames.empty())
            fail_input(command_line(option), "",
                       "no frame of the scene (" + output.frames_text + ") lies in " +
                           std::to_string(first) + "-" + std::to_string(last));
        if (s.jump) {
            std::vector<int> every;
            for (size_t i = 0; i < frames.size(); i += static_cast<size_t>(*s.jump))
                every.push_back(frames[i]);
            frames = std::move(every);
        }
    } else {
        return {};
    }
    if (s.allow_outside) return frames;
    const auto [low, high] = std::minmax_element(output.frames.begin(), output.frames.end());
    for (int f : frames)
        if (f < *low || f > *high)
            fail_input(command_line(option), "",
                       "frame " + std::to_string(f) + " is outside the scene's frames " +
                           output.frames_text + " (" + range_text({*low, *high}) +
                           "); give --allow-outside to render it anyway");
    return frames;
}

void add_output_option(CLI::App* cmd, std::string& output, const std::string& description) {
    cmd->add_option("-o,--output,--out", output, description);
}

void add_threads_option(CLI::App* cmd, unsigned& threads) {
    add_whole_number_setter(
        cmd, "--threads", [&threads](int n) { threads = static_cast<unsigned>(n); }, 0, 256,
        "Worker threads (0: one per core)", "a whole number from 0 (one per core) to 256");
}

void add_quiet_flag(CLI::App* cmd, bool& quiet) {
    cmd->add_flag("-q,--quiet", quiet, "Print nothing but errors");
}

// One value per -D: a vector option would otherwise also swallow the words
// after it, so `render -D camera.fov=30 scene.yaml` lost its scene.
void add_define_option(CLI::App* cmd, std::vector<std::string>& defines) {
    cmd->add_option("-D,--define", defines, "Override a scene value: key.path=value (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
}

void reject_unknown_arguments(CLI::App* cmd) {
    const std::vector<std::string> rest = cmd->remaining();
    if (rest.empty()) return;
    const std::string& word = rest.front();
    const std::string name = word.substr(0, word.find('='));
    const std::string where = "facet " + cmd->get_name();
    if (name.size() > 1 && name[0] == '-') {
        std::vector<std::string> names;
        for (const CLI::Option* opt : cmd->get_options()) {
            for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
            for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
        }
        std::vector<std::string_view> views(names.begin(), names.end());
        fail_input(command_line(word), "",
                   "unknown option '" + name + "' for " + where + did_you_mean(name, views) + " (" +
                       where + " --help lists them)");
    }
    // `-D key={a,b}` unquoted reaches facet as several words: bash's brace
    // expansion made them.
    if (word.find('=') != std::string::npos && cmd->get_option_no_throw("-D"))
        fail_input(command_line(word), "",
                   "unexpected argument '" + word +
                       "': it looks like part of a -D value that the shell split; quote the "
                       "whole -D, e.g. -D 'objects.0.material={color: [1, 0, 0]}'");
    fail_input(command_line(word), "",
               "unexpected argument '" + word + "' for " + where + " (" + where +
                   " --help shows what it takes)");
}

void check_subcommand_name(const CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return;
    const std::string word = argv[1];
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), word) != names.end()) return;
    std::vector<std::string_view> views(names.begin(), names.end());
    fail_input(command_line(word), "",
               "unknown command '" + word + "'" + did_you_mean(word, views) +
                   " (commands: " + comma_list(names) + ")");
}

}  // namespace facet
