#include "turntable/yaml_writer.hpp"

#include <algorithm>
#include <charconv>

namespace facet {
namespace {

constexpr int kIndentStep = 2;
// Notes start in this column when the line is shorter, so they line up.
constexpr size_t kNoteColumn = 32;

// An override's value as the scene text must hold it to read as -D reads
// it: a leading '#' is a colour there, not a comment (scene/yaml_field.cpp),
// and a value over several lines is kept as text on one.
std::string value_text(const std::string& value) {
    const size_t first = value.find_first_not_of(' ');
    if (first != std::string::npos && value[first] == '#') return yaml_quoted(value.substr(first));
    if (value.find_first_of("\r\n") != std::string::npos) return yaml_quoted(value);
    return value;
}

// Comment text on one line: a line break in a file name or a -D value
// would end the comment and turn the rest into scene keys.
std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

}  // namespace

std::string yaml_number(double value) {
    if (value == 0) return "0";  // and not "-0"
    char text[64];
    const auto end = std::to_chars(text, text + sizeof text, static_cast<float>(value)).ptr;
    return std::string(text, end);
}

std::string yaml_rounded(double value, int digits) {
    if (value == 0) return "0";
    char text[64];
    const auto end =
        std::to_chars(text, text + sizeof text, value, std::chars_format::general, digits).ptr;
    return std::string(text, end);
}

std::string yaml_vector(const std::vector<double>& values, int digits) {
    std::string text = "[";
    for (size_t i = 0; i < values.size(); ++i) {
        if (i > 0) text += ", ";
        text += digits > 0 ? yaml_rounded(values[i], digits) : yaml_number(values[i]);
    }
    return text + "]";
}

YamlWriter::YamlWriter(std::vector<Override> overrides)
    : overrides_(std::move(overrides)), used_(overrides_.size(), false) {}

std::string YamlWriter::path_of(const std::string& key) const {
    return levels_.empty() ? key : levels_.back().path + "." + key;
}

bool YamlWriter::has_key(const std::string& path) const {
    return std::find(keys_.begin(), keys_.end(), path) != keys_.end();
}

const Override* YamlWriter::override_of(const std::string& path) {
    const Override* last = nullptr;
    for (size_t i = 0; i < overrides_.size(); ++i)
        if (overrides_[i].path == path) {
            used_[i] = true;
            last = &overrides_[i];
        }
    return last;
}

void YamlWriter::write_line(int depth, const std::string& text, const std::string& note) {
    std::string line(static_cast<size_t>(depth), ' ');
    if (item_first_line_) {
        line.replace(line.size() - kIndentStep, kIndentStep, "- ");
        item_first_line_ = false;
    }
    line += text;
    if (!note.empty()) {
        line.resize(std::max(line.size() + 2, kNoteColumn), ' ');
        line += "# " + one_line(note);
    }
    text_ += line + "\n";
}

void YamlWriter::comment(const std::string& text) {
    if (skipping()) return;
    if (text.empty()) {
        text_ += "\n";
        return;
    }
    text_ += std::string(static_cast<size_t>(indent()), ' ') + "# " + one_line(text) + "\n";
}

void YamlWriter::value(const std::string& key, const std::string& yaml, const std::string& note) {
    const std::string path = path_of(key);
    keys_.push_back(path);
    if (skipping()) return;
    if (const Override* o = override_of(path))
        write_line(indent(), key + ": " + value_text(o->value), o->origin);
    else
        write_line(indent(), key + ": " + yaml, note);
}

void YamlWriter::optional_value(const std::string& key) {
    const std::string path = path_of(key);
    keys_.push_back(path);
    if (skipping()) return;
    if (const Override* o = override_of(path))
        write_line(indent(), key + ": " + value_text(o->value), o->origin);
}

void YamlWriter::begin_map(const std::string& key, const std::string& note) {
    const std::string path = path_of(key);
    keys_.push_back(path);
    const bool skipped = skipping();
    const Override* whole = skipped ? nullptr : override_of(path);
    if (whole)
        write_line(indent(), key + ": " + value_text(whole->value), whole->origin);
    else if (!skipped)
        write_line(indent(), key + ":", note);
    levels_.push_back({path, indent() + kIndentStep, skipped || whole != nullptr});
}

void YamlWriter::end_map() {
    levels_.pop_back();
}

void YamlWriter::begin_list(const std::string& key) {
    if (!skipping()) write_line(indent(), key + ":", "");
    levels_.push_back({path_of(key), indent() + kIndentStep, skipping()});
}

void YamlWriter::begin_item(const std::string& name) {
    // Items are addressed by name, as -D addresses them.
    levels_.push_back({path_of(name), indent() + kIndentStep, skipping()});
    item_first_line_ = !skipping();
    value("name", name);
}

void YamlWriter::end_item() {
    levels_.pop_back();
}

void YamlWriter::end_list() {
    levels_.pop_back();
}

bool YamlWriter::has_override_under(const std::string& path) const {
    const std::string prefix = path_of(path) + ".";
    for (const Override& o : overrides_)
        if (o.path.rfind(prefix, 0) == 0) return true;
    return false;
}

std::vector<Override> YamlWriter::unused() const {
    std::vector<Override> out;
    for (size_t i = 0; i < overrides_.size(); ++i)
        if (!used_[i]) out.push_back(overrides_[i]);
    return out;
}

}  // namespace facet
