#pragma once
// Text that stays on one line wherever facet writes it (job files,
// manifests, messages), and values quoted in messages. One rule for every
// reader: bash and Slurm end a line at '\n'; YAML 1.1 readers such as
// PyYAML and libyaml (what openjd-model loads templates with) also at
// '\r', U+0085, U+2028 and U+2029 (YAML 1.1, section 5.4), and refuse the
// other C0 and C1 control characters and text that is not UTF-8.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace facet {

// The first character of `text` that some reader of a text file takes as
// the end of a line or refuses: a C0 control (tab and newline included),
// DEL, a C1 control (U+0080-U+009F, U+0085 among them), U+2028, U+2029,
// or a byte that does not start valid UTF-8. Its name ("a newline", "U+2028
// (a line separator)", "a control character (\x1b)", "bytes that are not
// UTF-8"), or nothing when the text is plain.
std::optional<std::string> line_breaking_character(std::string_view text);

// `text` for a message: what line_breaking_character finds written as an
// escape (\n, \t, \xNN, \u2028), everything else as it is, and cut after
// `max_chars` bytes with "... (N bytes)" so that a 5 MB value does not make
// a 5 MB message.
std::string text_for_message(std::string_view text, size_t max_chars = 80);

// A message from a library, with every word (a run without spaces) longer
// than `max_chars` cut as text_for_message cuts a value: a library may
// quote a 5 MB data: URI whole.
std::string with_long_words_cut(std::string_view text, size_t max_chars = 80);

// "1 file", "3 files": a count and the word that goes with it.
std::string count_of(size_t n, const char* singular, const char* plural);

// "a, b, c": the names of `items` for a message, each `name(item)` (a
// string, a string_view or a C string), in order.
template <typename Items, typename Name = std::identity>
std::string comma_list(const Items& items, Name name = {}) {
    std::string list;
    for (const auto& item : items) {
        if (!list.empty()) list += ", ";
        list += std::string_view(name(item));
    }
    return list;
}

}  // namespace facet
