#include "cli/options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include <CLI/CLI.hpp>

#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/suggest.hpp"

namespace facet {
namespace {

std::string range_text(const std::vector<int>& frames) {
    if (frames.empty()) return "none";
    return std::to_string(frames.front()) + "-" + std::to_string(frames.back());
}

}  // namespace

SourceLocation command_line(const std::string& what) {
    return {"", 0, 0, "command line " + what};
}

void add_frame_options(CLI::App* cmd, FrameSelection& s) {
    cmd->add_option("--frames", s.frames, "Frames to render, e.g. 1-72, 1-72:2, 1,5,10-20");
    cmd->add_option("-f,--frame", s.single, "One frame (Blender's -f)");
    cmd->add_option("-s,--start", s.start, "First frame (Blender's -s); the scene's step is kept");
    cmd->add_option("-e,--end", s.end, "Last frame (Blender's -e)");
    cmd->add_option("-j,--jump", s.jump,
                    "Every Nth of the frames, with -s/-e or alone (Blender's -j)")
        ->check(CLI::Range(1, 1000000));
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
    cmd->add_option("--threads", threads, "Worker threads (0: one per core)")
        ->check(CLI::Range(0u, 256u));
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
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    fail_input(
        command_line(word), "",
        "unknown command '" + word + "'" + did_you_mean(word, views) + " (commands: " + list + ")");
}

std::string count_of(size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

CLI::Validator finite_range(double min, double max) {
    char range[96];
    std::snprintf(range, sizeof range, "a number from %g to %g", min, max);
    const std::string expected = range;
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            double value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error != std::errc() || stop != end || !std::isfinite(value) || value < min ||
                value > max)
                return "expected " + expected + ", got '" + text + "'";
            return "";
        },
        "FLOAT in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

}  // namespace facet
