#pragma once
// The values options take: numbers, sizes and comma-separated lists, read
// one way (core/number_text.hpp: all of the text, no spaces, no guessing)
// and refused one way, with an error that names the option, says what it
// takes and quotes what it got (invalid_input, exit code 2):
//   command line --size: expected WIDTHxHEIGHT with each side from 1 to
//   16384 (e.g. 1280x720), got '12abc'
// Grammars of their own (--frames lists, --chunk I/N, -t kind.key=value)
// read their numbers with the same primitives.
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/enum_names.hpp"
#include "core/error.hpp"

namespace facet {

// Where a value given on the command line is reported: "command line WHAT".
SourceLocation command_line(const std::string& what);

// The one error of a value an option cannot take. `detail`, when given,
// says which part of the value is wrong ("item 2 is empty").
[[noreturn]] void fail_option_value(const std::string& option, std::string_view value,
                                    const std::string& expected, const std::string& detail = "");

// "a whole number from MIN to MAX", what parse_whole_number expects by default.
std::string whole_number_range(int min, int max);

// A whole number from `min` to `max`. `expected` replaces the default
// description in the error (e.g. "a whole number from 0 (one per core) to 256").
int parse_whole_number(std::string_view text, const std::string& option, int min, int max,
                       const std::string& expected = "");

// A finite number from `min` to `max` (NaN and infinity are refused).
double parse_decimal_number(std::string_view text, const std::string& option, double min,
                            double max);

// "1280x720" (or "1280X720") -> {1280, 720}, each side from 1 to kMaxImageSide.
std::pair<int, int> parse_size(std::string_view text, const std::string& option);

// One of `words`, exactly: "command line --ground: expected shadow, floor
// or none, got 'flor'; did you mean 'floor'?".
std::string parse_word(std::string_view text, const std::string& option,
                       std::span<const std::string_view> words);

// The value whose name `text` is, from the enum's one table; else the error
// parse_word gives.
template <typename E, size_t N>
E parse_choice(std::string_view text, const std::string& option, const EnumName<E> (&table)[N]) {
    return *value_of(table, parse_word(text, option, names_of(table)));
}

// Comma-separated items, each kept as typed (names may hold spaces):
// "front,side" -> {"front", "side"}. "" is the option not given: no items.
// An empty item ("a,,b", "a,", ",") is refused, not dropped: it is a typo.
std::vector<std::string> parse_list(std::string_view text, const std::string& option,
                                    const std::string& expected);

// Comma-separated whole numbers, each from `min` to `max`, at least one
// ("1,2,4"). `expected` describes the whole list in the error.
std::vector<int> parse_whole_number_list(std::string_view text, const std::string& option, int min,
                                         int max, const std::string& expected);

}  // namespace facet
