#pragma once
// "Did you mean" hints: the one edit distance of the project, and the
// closest known name to what a user typed (scene keys, output-template
// placeholders, command-line words, enum values).
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace facet {

// Levenshtein distance: insertions, deletions and substitutions, each 1.
size_t edit_distance(std::string_view a, std::string_view b);

// The known name the user probably meant, or "" when none is close enough
// to help. Case is ignored. A known name that starts with what was typed
// ("cam" -> "camera"), or that the typed word starts with, wins when the
// typed word has at least two characters; otherwise the nearest name within
// `max(2, length / 2)` edits.
std::string closest_name(std::string_view typed, std::span<const std::string_view> known);

// "; did you mean 'x'?" or "" (for appending to a message).
std::string did_you_mean(std::string_view typed, std::span<const std::string_view> known);

}  // namespace facet
