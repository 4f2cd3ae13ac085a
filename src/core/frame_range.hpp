#pragma once
// Frame range lists: "1-120", "1-120:2", "1,5,10-20" (inclusive ranges).
#include <string>
#include <vector>

namespace facet {

// Parses a range list into ascending, distinct frame numbers. Throws
// facet::Error (invalid_input, no place: the caller knows it) saying what is wrong.
std::vector<int> parse_frame_ranges(const std::string& text);

// The shortest-reading list that parse_frame_ranges turns back into
// `frames` (ascending, distinct): "1-48", "1-47:2", "1,5,10-20". Runs of
// three or more frames with one step become a range. "" for no frames.
std::string format_frame_ranges(const std::vector<int>& frames);

}  // namespace facet
