#include "core/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace facet {

std::optional<long long> read_whole_number(std::string_view text) {
    long long value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
    return value;
}

std::optional<double> read_finite_number(std::string_view text) {
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::string format_number(double value, int significant_digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", significant_digits, value);
    return text;
}

}  // namespace facet
