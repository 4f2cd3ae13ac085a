#pragma once
// Numbers a person typed (command-line values, environment variables,
// frame lists, placeholder widths), read one way: the whole text is the
// number, in the same notation whatever the process's locale. Nothing is
// skipped or guessed, so " 4", "+4", "4k", "0x10" and "1,5" are not numbers,
// "010" is ten (not eight, as base-detecting readers take it), and a number
// too large for its type is refused instead of wrapping or saturating.
#include <optional>
#include <string>
#include <string_view>

namespace facet {

// An optional '-' and decimal digits, all of `text`, within long long.
std::optional<long long> read_whole_number(std::string_view text);

// A decimal number as std::from_chars reads it ("2", "-0.5", ".5", "1e-3"),
// all of `text`; NaN, infinity and numbers beyond double's range are refused.
std::optional<double> read_finite_number(std::string_view text);

// A number for a message, as printf's %g writes it with that many
// significant digits ("0.5", "1e+07", "65504").
std::string format_number(double value, int significant_digits = 6);

}  // namespace facet
