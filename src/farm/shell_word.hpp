#pragma once
// Text as words for a POSIX shell: job scripts (farm) and the -D arguments
// facet preview prints for pasting.
#include <string>

namespace facet {

// `text` in single quotes, each ' written as '\'' : one word, nothing
// expanded. Text that holds a line break or another control character
// (core/plain_text.hpp) is written as bash's $'...' with escapes instead,
// so that the word never spans lines.
std::string shell_quoted(const std::string& text);

// `text` as one word: unchanged when it is plainly safe, else shell_quoted.
std::string shell_word(const std::string& text);

}  // namespace facet
