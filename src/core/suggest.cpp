#include "core/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace facet {

size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

namespace {

std::string lower_case(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::string closest_name(std::string_view typed, std::span<const std::string_view> known) {
    const std::string lower = lower_case(typed);
    if (lower.size() >= 2)
        for (std::string_view name : known) {
            const std::string candidate = lower_case(name);
            if (name != typed && (candidate.starts_with(lower) || lower.starts_with(candidate)))
                return std::string(name);
        }
    // A suggestion further away than this would only confuse ("foo" -> "ext").
    size_t best = std::max<size_t>(2, lower.size() / 2) + 1;
    std::string closest;
    for (std::string_view name : known) {
        const size_t distance = edit_distance(lower, lower_case(name));
        if (name != typed && distance < best) {
            best = distance;
            closest = std::string(name);
        }
    }
    return closest;
}

std::string did_you_mean(std::string_view typed, std::span<const std::string_view> known) {
    const std::string closest = closest_name(typed, known);
    return closest.empty() ? "" : "; did you mean '" + closest + "'?";
}

}  // namespace facet
