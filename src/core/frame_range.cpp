#include "core/frame_range.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "core/number_text.hpp"

namespace facet {
namespace {

// A frame list longer than this is almost certainly a typo (e.g. 1-1000000).
constexpr long long kMaxFrames = 1000000;

// Spaces around a number are part of the frame list's grammar ("1 - 3").
int parse_int(std::string_view text, const std::string& whole) {
    auto trimmed = text;
    while (!trimmed.empty() && trimmed.front() == ' ') trimmed.remove_prefix(1);
    while (!trimmed.empty() && trimmed.back() == ' ') trimmed.remove_suffix(1);
    const std::optional<long long> value = read_whole_number(trimmed);
    if (!value || *value < std::numeric_limits<int>::min() ||
        *value > std::numeric_limits<int>::max())
        throw Error(ExitCode::invalid_input, "'" + std::string(text) + "' in frame range '" +
                                                 whole + "' is not a whole number");
    return static_cast<int>(*value);
}

}  // namespace

std::vector<int> parse_frame_ranges(const std::string& text) {
    if (text.find_first_not_of(" ,") == std::string::npos)
        throw Error(ExitCode::invalid_input, "frame range is empty");
    std::vector<int> frames;
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        std::string_view part(text.data() + start,
                              (comma == std::string::npos ? text.size() : comma) - start);
        start = comma == std::string::npos ? text.size() + 1 : comma + 1;
        if (part.find_first_not_of(' ') == std::string_view::npos)
            throw Error(ExitCode::invalid_input, "frame range '" + text + "' has an empty item");

        int step = 1;
        if (size_t colon = part.find(':'); colon != std::string_view::npos) {
            step = parse_int(part.substr(colon + 1), text);
            part = part.substr(0, colon);
            if (step < 1)
                throw Error(ExitCode::invalid_input,
                            "step in frame range '" + text + "' must be >= 1");
        }
        // A '-' after the first character separates the bounds (the first may be a sign).
        size_t dash = part.find('-', part.find_first_not_of(' ') + 1);
        int first = 0, last = 0;
        if (dash == std::string_view::npos) {
            first = last = parse_int(part, text);
        } else {
            first = parse_int(part.substr(0, dash), text);
            last = parse_int(part.substr(dash + 1), text);
        }
        if (last < first)
            throw Error(ExitCode::invalid_input,
                        "frame range '" + std::string(part) + "' ends before it starts");
        if ((static_cast<long long>(last) - first) / step + frames.size() >= kMaxFrames)
            throw Error(ExitCode::invalid_input, "frame range '" + text + "' has more than " +
                                                     std::to_string(kMaxFrames) + " frames");
        for (long long f = first; f <= last; f += step) frames.push_back(static_cast<int>(f));
    }
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

std::string format_frame_ranges(const std::vector<int>& frames) {
    std::string text;
    auto item = [&](const std::string& part) {
        if (!text.empty()) text += ',';
        text += part;
    };
    size_t i = 0;
    while (i < frames.size()) {
        // The longest run from i with the step of its first two frames.
        size_t end = i + 1;
        if (i + 2 < frames.size()) {
            const long long step = static_cast<long long>(frames[i + 1]) - frames[i];
            while (end < frames.size() &&
                   static_cast<long long>(frames[end]) - frames[end - 1] == step)
                ++end;
            if (end - i >= 3) {
                std::string range =
                    std::to_string(frames[i]) + "-" + std::to_string(frames[end - 1]);
                if (step != 1) {
                    range += ':';
                    range += std::to_string(step);
                }
                item(range);
                i = end;
                continue;
            }
        }
        item(std::to_string(frames[i]));
        ++i;
    }
    return text;
}

}  // namespace facet
