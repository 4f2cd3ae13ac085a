#pragma once
// Frame range lists: "1-120", "1-120:2", "1,5,10-20" (inclusive ranges).
#include <string>
#include <vector>

namespace facet {

// Parses a range list into ascending, distinct frame numbers. Throws
// facet::Error (invalid_input, no place: the caller knows it) saying what is wrong.
std::vector<int> parse_frame_ranges(const std::string& text);

}  // namespace facet
