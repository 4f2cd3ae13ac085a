#include "farm/shell_word.hpp"

#include <cstdio>

#include "core/plain_text.hpp"

namespace facet {
namespace {

// `text` as bash's $'...' word: every byte that is not printable ASCII,
// and ' and \, as an escape, so the word stays on one line whatever it holds.
std::string ansi_c_quoted(const std::string& text) {
    std::string quoted = "$'";
    for (unsigned char c : text) {
        if (c == '\'' || c == '\\') {
            quoted += '\\';
            quoted += static_cast<char>(c);
        } else if (c < 0x20 || c >= 0x7f) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\x%02x", c);
            quoted += escape;
        } else {
            quoted += static_cast<char>(c);
        }
    }
    return quoted + "'";
}

}  // namespace

std::string shell_quoted(const std::string& text) {
    if (line_breaking_character(text)) return ansi_c_quoted(text);
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string shell_word(const std::string& text) {
    const std::string safe =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%";
    if (!text.empty() && text.find_first_not_of(safe) == std::string::npos) return text;
    return shell_quoted(text);
}

}  // namespace facet
