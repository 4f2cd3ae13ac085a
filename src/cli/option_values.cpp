#include "cli/option_values.hpp"

#include <cstdio>
#include <optional>

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/suggest.hpp"

namespace facet {
namespace {

// The items between commas, empty ones included: "a,,b" -> {"a", "", "b"}.
std::vector<std::string_view> comma_items(std::string_view text) {
    std::vector<std::string_view> items;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        items.push_back(
            text.substr(start, comma == std::string_view::npos ? comma : comma - start));
        if (comma == std::string_view::npos) return items;
        start = comma + 1;
    }
}

// The number within [min, max] that all of `text` spells, if any.
std::optional<int> whole_number_within(std::string_view text, int min, int max) {
    const std::optional<long long> value = read_whole_number(text);
    if (!value || *value < min || *value > max) return std::nullopt;
    return static_cast<int>(*value);
}

}  // namespace

SourceLocation command_line(const std::string& what) {
    return {"", 0, 0, "command line " + what};
}

void fail_option_value(const std::string& option, std::string_view value,
                       const std::string& expected, const std::string& detail) {
    std::string message = "expected " + expected + ", got '";
    message += value;
    message += '\'';
    if (!detail.empty()) message += ": " + detail;
    fail_input(command_line(option), "", message);
}

std::string whole_number_range(int min, int max) {
    return "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
}

int parse_whole_number(std::string_view text, const std::string& option, int min, int max,
                       const std::string& expected) {
    const std::optional<int> value = whole_number_within(text, min, max);
    if (!value)
        fail_option_value(option, text, expected.empty() ? whole_number_range(min, max) : expected);
    return *value;
}

double parse_decimal_number(std::string_view text, const std::string& option, double min,
                            double max) {
    const std::optional<double> value = read_finite_number(text);
    if (!value || *value < min || *value > max) {
        char expected[96];
        std::snprintf(expected, sizeof expected, "a number from %g to %g", min, max);
        fail_option_value(option, text, expected);
    }
    return *value;
}

std::pair<int, int> parse_size(std::string_view text, const std::string& option) {
    const size_t x = text.find_first_of("xX");
    std::optional<int> width, height;
    if (x != std::string_view::npos) {
        width = whole_number_within(text.substr(0, x), 1, kMaxImageSide);
        height = whole_number_within(text.substr(x + 1), 1, kMaxImageSide);
    }
    if (!width || !height)
        fail_option_value(option, text,
                          "WIDTHxHEIGHT with each side from 1 to " + std::to_string(kMaxImageSide) +
                              " (e.g. 1280x720)");
    return {*width, *height};
}

std::string parse_word(std::string_view text, const std::string& option,
                       std::span<const std::string_view> words) {
    for (std::string_view word : words)
        if (text == word) return std::string(word);
    std::string expected;
    for (size_t i = 0; i < words.size(); ++i)
        expected += std::string(i == 0                  ? ""
                                : i + 1 == words.size() ? " or "
                                                        : ", ") +
                    std::string(words[i]);
    fail_input(
        command_line(option), "",
        "expected " + expected + ", got '" + std::string(text) + "'" + did_you_mean(text, words));
}

std::vector<std::string> parse_list(std::string_view text, const std::string& option,
                                    const std::string& expected) {
    std::vector<std::string> items;
    if (text.empty()) return items;
    for (std::string_view item : comma_items(text)) {
        if (item.empty())
            fail_option_value(option, text, expected,
                              "item " + std::to_string(items.size() + 1) + " is empty");
        items.emplace_back(item);
    }
    return items;
}

std::vector<int> parse_whole_number_list(std::string_view text, const std::string& option, int min,
                                         int max, const std::string& expected) {
    if (text.empty()) fail_option_value(option, text, expected);
    std::vector<int> numbers;
    for (const std::string& item : parse_list(text, option, expected)) {
        const std::optional<int> number = whole_number_within(item, min, max);
        if (!number)
            fail_option_value(option, text, expected,
                              "'" + item + "' is not " + whole_number_range(min, max));
        numbers.push_back(*number);
    }
    return numbers;
}

}  // namespace facet
