#include "core/plain_text.hpp"

#include <cstdint>
#include <cstdio>

namespace facet {
namespace {

// One character of UTF-8 text: its code point and length in bytes, or
// length 0 where the bytes at `at` are not UTF-8 (a stray continuation
// byte, a truncated sequence, an overlong form, a surrogate, or a value
// past U+10FFFF).
struct Decoded {
    uint32_t code_point = 0;
    size_t length = 0;
};

Decoded decode(std::string_view text, size_t at) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) return {lead, 1};
    size_t length = 0;
    uint32_t cp = 0, least = 0;
    if ((lead & 0xe0) == 0xc0) {
        length = 2, cp = lead & 0x1f, least = 0x80;
    } else if ((lead & 0xf0) == 0xe0) {
        length = 3, cp = lead & 0x0f, least = 0x800;
    } else if ((lead & 0xf8) == 0xf0) {
        length = 4, cp = lead & 0x07, least = 0x10000;
    } else {
        return {};
    }
    if (at + length > text.size()) return {};
    for (size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xc0) != 0x80) return {};
        cp = (cp << 6) | (byte(at + i) & 0x3f);
    }
    if (cp < least || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {};
    return {cp, length};
}

std::string hex_escape(const char* format, uint32_t value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, format, static_cast<unsigned>(value));
    return buffer;
}

// What is wrong with the character at `at` (decoded as `d`), or "".
std::string problem_of(const Decoded& d) {
    if (d.length == 0) return "bytes that are not UTF-8";
    const uint32_t cp = d.code_point;
    if (cp == '\n') return "a newline";
    if (cp == '\r') return "a carriage return";
    if (cp == '\t') return "a tab";
    if (cp < 0x20 || cp == 0x7f) return "a control character (" + hex_escape("\\x%02x", cp) + ")";
    if (cp == 0x85) return "U+0085 (a next-line character)";
    if (cp >= 0x80 && cp <= 0x9f) return "a control character (U+" + hex_escape("%04X", cp) + ")";
    if (cp == 0x2028) return "U+2028 (a line separator)";
    if (cp == 0x2029) return "U+2029 (a paragraph separator)";
    if (cp == 0xfffe || cp == 0xffff) return "U+" + hex_escape("%04X", cp) + " (not a character)";
    return "";
}

// The escape a message shows for a character problem_of names.
std::string escape_of(std::string_view text, size_t at, const Decoded& d) {
    if (d.length == 0) return hex_escape("\\x%02x", static_cast<unsigned char>(text[at]));
    switch (d.code_point) {
        case '\n':
            return "\\n";
        case '\r':
            return "\\r";
        case '\t':
            return "\\t";
        default:
            break;
    }
    if (d.code_point < 0x80) return hex_escape("\\x%02x", d.code_point);
    return hex_escape("\\u%04x", d.code_point);
}

}  // namespace

std::optional<std::string> line_breaking_character(std::string_view text) {
    for (size_t at = 0; at < text.size();) {
        const Decoded d = decode(text, at);
        if (std::string problem = problem_of(d); !problem.empty()) return problem;
        at += d.length;
    }
    return std::nullopt;
}

std::string text_for_message(std::string_view text, size_t max_chars) {
    std::string out;
    size_t at = 0;
    while (at < text.size() && at < max_chars) {
        const Decoded d = decode(text, at);
        if (problem_of(d).empty()) {
            out.append(text.substr(at, d.length));
            at += d.length;
        } else {
            out += escape_of(text, at, d);
            at += d.length == 0 ? 1 : d.length;
        }
    }
    if (at < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

std::string with_long_words_cut(std::string_view text, size_t max_chars) {
    std::string out;
    size_t at = 0;
    while (at < text.size()) {
        const size_t space = text.find_first_of(" \n", at);
        const size_t end = space == std::string_view::npos ? text.size() : space;
        const std::string_view word = text.substr(at, end - at);
        out += word.size() > max_chars ? text_for_message(word, max_chars) : std::string(word);
        if (end < text.size()) out += text[end];
        at = end + 1;
    }
    return out;
}

std::string count_of(size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace facet
