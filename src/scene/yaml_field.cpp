#include "scene/yaml_field.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <yaml-cpp/depthguard.h>
#include <sstream>

#include "core/color.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/plain_text.hpp"
#include "core/sha256.hpp"
#include "core/suggest.hpp"
#include "scene/scene_desc.hpp"

namespace facet {
namespace {

// Two lowercase hexadecimal digits.
std::string hex_byte(unsigned value) {
    const char* digits = "0123456789abcdef";
    return {digits[(value >> 4) & 15], digits[value & 15]};
}

std::string join_path(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

bool parse_hex_color(const std::string& text, glm::vec4& out) {
    if (text.size() != 7 && text.size() != 9) return false;
    if (text[0] != '#') return false;
    float channels[4] = {0, 0, 0, 1};
    for (size_t i = 1, c = 0; i < text.size(); i += 2, ++c) {
        const std::string byte = text.substr(i, 2);
        if (!std::isxdigit(static_cast<unsigned char>(byte[0])) ||
            !std::isxdigit(static_cast<unsigned char>(byte[1])))
            return false;
        channels[c] = static_cast<float>(std::stoi(byte, nullptr, 16)) / 255.0f;
    }
    // Colour pickers give sRGB; shading is linear (docs/scene-format.md). Alpha is linear.
    out = {srgb_to_linear(channels[0]), srgb_to_linear(channels[1]), srgb_to_linear(channels[2]),
           channels[3]};
    return true;
}

std::shared_ptr<YamlDocument> parse(const std::string& text, const std::string& name) {
    auto doc = std::make_shared<YamlDocument>();
    doc->file = name;
    doc->sha256 = sha256_hex(text.data(), text.size());
    try {
        doc->root = YAML::Load(text);
    } catch (const YAML::DeepRecursion& e) {
        // yaml-cpp stops at 2000 nested parser calls, several per level.
        SourceLocation where{name, e.mark.line + 1, e.mark.column + 1, ""};
        throw Error(ExitCode::invalid_input, where, "",
                    "nested too deeply (limit about " + std::to_string(kMaxYamlNesting) +
                        " levels of [ ], { } or indented blocks)");
    } catch (const YAML::Exception& e) {
        SourceLocation where{name, e.mark.line + 1, e.mark.column + 1, ""};
        throw Error(ExitCode::invalid_input, where, "", "YAML syntax error: " + e.msg);
    }
    return doc;
}

}  // namespace

std::shared_ptr<YamlDocument> read_yaml_file(const std::string& path) {
    const std::vector<uint8_t> bytes = read_input_file(path, "YAML", kMaxYamlFileBytes);
    return parse(std::string(bytes.begin(), bytes.end()), path);
}

std::shared_ptr<YamlDocument> read_yaml_text(const std::string& text, const std::string& name) {
    return parse(text, name);
}

Field root_field(const std::shared_ptr<YamlDocument>& doc) {
    return Field(doc, doc->root, "");
}

Field::Field(std::shared_ptr<const YamlDocument> doc, YAML::Node node, std::string path)
    : doc_(std::move(doc)), node_(std::move(node)), path_(std::move(path)) {}

SourceLocation Field::where() const {
    // A value set from the command line is reported as the command line.
    for (const auto& [path, origin] : doc_->overridden) {
        if (path_ == path || path_.rfind(path + ".", 0) == 0) return {"", 0, 0, origin};
    }
    SourceLocation loc{doc_->file, 0, 0, ""};
    if (node_) {
        YAML::Mark mark = node_.Mark();
        if (!mark.is_null()) {
            loc.line = mark.line + 1;
            loc.column = mark.column + 1;
        }
    }
    return loc;
}

void Field::fail(const std::string& message) const {
    fail_input(where(), path_.empty() ? "" : path_, message);
}

std::string Field::scalar_for_message() const {
    if (!node_ || node_.IsNull()) return "nothing";
    if (node_.IsScalar()) return "'" + text_for_message(node_.Scalar()) + "'";
    if (node_.IsSequence()) return "a list";
    return "a mapping";
}

void Field::expect_map() const {
    if (!node_.IsMap()) fail("must be a mapping of keys to values, got " + scalar_for_message());
}

void Field::check_keys(std::span<const char* const> allowed) const {
    expect_map();
    std::set<std::string> seen;
    for (auto it = node_.begin(); it != node_.end(); ++it) {
        std::string key = it->first.Scalar();
        // yaml-cpp accepts repeated keys and lookups find the first, so a
        // later `fov: 40` under `fov: 30` would be silently ignored. YAML
        // itself forbids repeats.
        if (!seen.insert(key).second)
            Field(doc_, it->first, join_path(path_, key)).fail("key given more than once");
        bool known = false;
        for (const char* name : allowed) known = known || key == name;
        if (!known) {
            const std::vector<std::string_view> names(allowed.begin(), allowed.end());
            Field key_field(doc_, it->first, join_path(path_, key));
            key_field.fail("unknown key" + did_you_mean(key, names) +
                           " (expected one of: " + comma_list(names) + ")");
        }
    }
}

bool Field::has(const std::string& key) const {
    return node_.IsMap() && node_[key] && !node_[key].IsNull();
}

Field Field::operator[](const std::string& key) const {
    expect_map();
    return Field(doc_, node_[key], join_path(path_, key));
}

Field Field::require(const std::string& key) const {
    if (!has(key)) fail("missing required key '" + key + "'");
    return (*this)[key];
}

std::vector<std::string> Field::keys() const {
    expect_map();
    std::vector<std::string> out;
    for (auto it = node_.begin(); it != node_.end(); ++it) out.push_back(it->first.Scalar());
    return out;
}

Field Field::key(const std::string& name) const {
    expect_map();
    for (auto it = node_.begin(); it != node_.end(); ++it)
        if (it->first.Scalar() == name) return Field(doc_, it->first, join_path(path_, name));
    return (*this)[name];
}

size_t Field::size() const {
    if (!node_.IsSequence()) fail("must be a list, got " + scalar_for_message());
    return node_.size();
}

Field Field::operator[](size_t index) const {
    return Field(doc_, node_[index], join_path(path_, std::to_string(index)));
}

std::string Field::free_text() const {
    if (!node_.IsScalar()) {
        // "-D output.path={scene}/x" reaches YAML as a flow mapping; say how
        // to write text that starts with a brace.
        const auto given = doc_->overridden.find(path_);
        if (given != doc_->overridden.end() && node_.IsMap())
            fail(
                "must be a text value, got a mapping: YAML reads a value that starts with '{' "
                "as one; quote it as YAML text: -D '" +
                path_ +
                "=\"...\"', e.g. -D "
                "'output.path=\"{scene}/{pass}.{frame}.{ext}\"'");
        fail("must be a text value, got " + scalar_for_message());
    }
    return node_.Scalar();
}

std::string Field::text() const {
    std::string value = free_text();
    // Names and paths reach file names, manifests and job files, where a
    // line break would end a line (a command, a comment, a YAML key).
    if (const auto problem = line_breaking_character(value))
        fail("holds " + *problem + ", which no name or path may hold, got '" +
             text_for_message(value) + "'");
    return value;
}

double Field::number(double min, double max) const {
    if (!node_.IsScalar()) fail("must be a number, got " + scalar_for_message());
    const std::string& s = node_.Scalar();
    // Read as the command line reads numbers (core/number_text.hpp): the
    // whole text, decimal, finite; no hexadecimal, no '+', no spaces.
    const std::optional<double> read = read_finite_number(s);
    if (!read)
        fail("must be a number (decimal, as 2.5 or 1e-3), got '" + text_for_message(s) + "'");
    const double value = *read;
    if (value < min || value > max) {
        std::ostringstream range;
        range << "must be between " << min << " and " << max << ", got " << s;
        fail(range.str());
    }
    return value;
}

int Field::integer(int min, int max) const {
    double value = number(min, max);
    if (value != std::floor(value)) fail("must be a whole number, got " + node_.Scalar());
    return static_cast<int>(value);
}

bool Field::boolean() const {
    if (node_.IsScalar()) {
        const std::string& s = node_.Scalar();
        if (s == "true" || s == "yes" || s == "on") return true;
        if (s == "false" || s == "no" || s == "off") return false;
    }
    fail("must be true or false, got " + scalar_for_message());
}

std::vector<double> Field::numbers(size_t min_count, size_t max_count) const {
    if (!node_.IsSequence() || node_.size() < min_count || node_.size() > max_count) {
        std::string count = min_count == max_count
                                ? std::to_string(min_count)
                                : std::to_string(min_count) + " or " + std::to_string(max_count);
        fail("must be a list of " + count + " numbers, got " + scalar_for_message() +
             (node_.IsSequence() ? " of " + std::to_string(node_.size()) : ""));
    }
    std::vector<double> out;
    for (size_t i = 0; i < node_.size(); ++i) out.push_back((*this)[i].number(-1e30, 1e30));
    return out;
}

glm::vec2 Field::vec2() const {
    auto v = numbers(2, 2);
    return {v[0], v[1]};
}

glm::vec3 Field::vec3() const {
    auto v = numbers(3, 3);
    return {v[0], v[1], v[2]};
}

glm::vec2 Field::distance_range() const {
    glm::vec2 range = vec2();
    if (!(range.x >= 0 && range.y > range.x)) fail("must be [near, far] with 0 <= near < far");
    return range;
}

glm::vec4 Field::color4() const {
    glm::vec4 out;
    if (node_.IsScalar() && parse_hex_color(node_.Scalar(), out)) return out;
    if (node_.IsScalar())
        fail("must be a colour: [r, g, b], [r, g, b, a] or '#rrggbb', got '" + node_.Scalar() +
             "'");
    auto v = numbers(3, 4);
    for (size_t i = 0; i < v.size(); ++i)
        if (v[i] < 0) (*this)[i].fail("colour components must be >= 0");
    return {v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0};
}

glm::vec4 Field::background() const {
    if (node_.IsScalar() && node_.Scalar() == "transparent") return glm::vec4(0.0f);
    return color4();
}

glm::vec3 Field::color3() const {
    if (node_.IsSequence() && node_.size() != 3) numbers(3, 3);  // reports the count
    if (node_.IsScalar() && node_.Scalar().size() == 9) fail("must be an RGB colour '#rrggbb'");
    return glm::vec3(color4());
}

std::string Field::choice(std::initializer_list<const char*> words) const {
    std::string value = text();
    for (const char* word : words)
        if (value == word) return value;
    fail_not_one_of(value, std::vector<std::string_view>(words.begin(), words.end()));
}

void Field::fail_not_one_of(const std::string& value,
                            const std::vector<std::string_view>& words) const {
    fail("got '" + value + "'" + did_you_mean(value, words) +
         " (must be one of: " + comma_list(words) + ")");
}

std::vector<std::string> Field::choices(std::initializer_list<const char*> words) const {
    std::vector<std::string> out;
    if (node_.IsScalar()) return {choice(words)};
    for (size_t i = 0; i < size(); ++i) out.push_back((*this)[i].choice(words));
    return out;
}

namespace {

// The item of a list that a -D path part names: by index ("0"), or by the
// value of the items' `name` key ("knot"), so paths survive reordering.
long list_item_index(const YAML::Node& list, const std::string& part, const SourceLocation& origin,
                     const std::string& parent, const std::string& walked) {
    const std::optional<long long> index = read_whole_number(part);
    const bool numeric = index.has_value();
    if (numeric && *index >= 0 && static_cast<unsigned long long>(*index) < list.size())
        return static_cast<long>(*index);
    std::vector<std::string> names;
    for (size_t i = 0; i < list.size(); ++i) {
        const YAML::Node item = list[i];
        if (!item.IsMap() || !item["name"] || !item["name"].IsScalar()) continue;
        if (!numeric && item["name"].Scalar() == part) return static_cast<long>(i);
        names.push_back(item["name"].Scalar());
    }
    std::string message = "'" + parent + "' is a list of " + std::to_string(list.size()) +
                          " items; use an index from 0 to " + std::to_string(list.size() - 1);
    if (!names.empty()) {
        std::vector<std::string_view> views(names.begin(), names.end());
        const std::string list_text = comma_list(names);
        message = "'" + parent + "' has no item " + (numeric ? part : "named '" + part + "'") +
                  (numeric ? "" : did_you_mean(part, views)) + " (use an index from 0 to " +
                  std::to_string(list.size() - 1) + " or a name: " + list_text + ")";
    }
    fail_input(origin, walked, message);
}

}  // namespace

std::string yaml_quoted(const std::string& text) {
    YAML::Emitter out;
    out << YAML::DoubleQuoted << text;
    // yaml-cpp escapes C0 controls but writes U+0085, U+2028 and U+2029
    // (and the other C1 controls) as they are, and YAML 1.1 readers such
    // as PyYAML take the first three as line breaks: escaped here, inside
    // the double quotes, where "\uXXXX" is read back as the character.
    const std::string emitted = out.c_str();
    std::string safe;
    for (size_t i = 0; i < emitted.size(); ++i) {
        const auto byte = [&](size_t k) { return static_cast<unsigned char>(emitted[k]); };
        if (byte(i) == 0xc2 && i + 1 < emitted.size() && byte(i + 1) >= 0x80 &&
            byte(i + 1) <= 0x9f) {
            safe += "\\u00" + hex_byte(byte(i + 1));
            ++i;
        } else if (byte(i) == 0xe2 && i + 2 < emitted.size() && byte(i + 1) == 0x80 &&
                   (byte(i + 2) == 0xa8 || byte(i + 2) == 0xa9)) {
            safe += "\\u20" + hex_byte(byte(i + 2) & 0x3f);  // E2 80 A8 is U+2028
            i += 2;
        } else {
            safe += emitted[i];
        }
    }
    return safe;
}

Override parse_define(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        fail_input(SourceLocation{"", 0, 0, "command line -D " + text}, "",
                   "expected key.path=value, e.g. camera.fov=30");
    return {text.substr(0, eq), text.substr(eq + 1), "command line -D " + text};
}

void apply_overrides(YamlDocument& doc, const std::vector<Override>& overrides) {
    for (const Override& ov : overrides) {
        SourceLocation origin{"", 0, 0, ov.origin};
        if (ov.path.empty()) fail_input(origin, "", "the key path is empty");
        YAML::Node value;
        try {
            // On the command line '#rrggbb' is a colour, not a YAML comment
            // (which would make the value null and the override vanish).
            size_t first = ov.value.find_first_not_of(' ');
            if (first != std::string::npos && ov.value[first] == '#')
                value = YAML::Node(ov.value.substr(first));
            else
                value = YAML::Load(ov.value);
        } catch (const YAML::Exception& e) {
            fail_input(origin, ov.path,
                       "value is not valid YAML: " + e.msg +
                           " (a list or mapping must reach facet as one word: quote the whole "
                           "-D, e.g. -D 'objects.0.material={color: [1, 0, 0]}', since a shell "
                           "splits {a,b} into words)");
        }
        {
            // "a: b" is a YAML mapping; a user who typed it almost always meant text.
            const size_t first = ov.value.find_first_not_of(' ');
            if (value.IsMap() && (first == std::string::npos || ov.value[first] != '{'))
                fail_input(origin, ov.path,
                           "YAML reads '" + ov.value +
                               "' as a mapping (a colon followed by a space); for text, quote "
                               "it: -D '" +
                               ov.path + "=\"" + ov.value +
                               "\"'; for a mapping, write it in braces: {key: value}");
        }
        if (!doc.root || doc.root.IsNull()) doc.root = YAML::Node(YAML::NodeType::Map);
        YAML::Node current = doc.root;
        std::string walked;
        size_t start = 0;
        for (;;) {
            size_t dot = ov.path.find('.', start);
            std::string part =
                ov.path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
            const std::string parent = walked;
            walked = join_path(walked, part);
            if (part.empty()) fail_input(origin, ov.path, "the key path has an empty part");
            bool last = dot == std::string::npos;
            if (current.IsSequence()) {
                if (current.size() == 0)
                    fail_input(origin, walked,
                               "'" + parent + "' is an empty list; there is no item " + part);
                const long index = list_item_index(current, part, origin, parent, walked);
                // Fields are looked up by index: record the path that way, so
                // errors in the value name the command line, not the file.
                walked = join_path(parent, std::to_string(index));
                if (last) {
                    current[static_cast<size_t>(index)] = value;
                    break;
                }
                YAML::Node next = current[static_cast<size_t>(index)];
                current.reset(next);  // rebind, do not assign through the reference
            } else {
                if (current.IsScalar())
                    fail_input(origin, walked, "cannot set a key inside a plain value");
                if (last) {
                    current[part] = value;
                    break;
                }
                if (!current[part] || current[part].IsNull() || current[part].IsScalar())
                    current[part] = YAML::Node(YAML::NodeType::Map);
                YAML::Node next = current[part];
                current.reset(next);
            }
            start = dot + 1;
        }
        doc.overridden[walked] = ov.origin;
    }
}

std::string existing_file(const Field& field, const std::string& base_dir) {
    std::filesystem::path path(field.text());
    if (!path.is_absolute()) path = std::filesystem::path(base_dir) / path;
    const std::string resolved = path.lexically_normal().string();
    const std::string problem = input_file_problem(resolved);
    if (!problem.empty())
        field.fail(
            "cannot read '" +
            text_for_message(std::filesystem::absolute(resolved).lexically_normal().string(), 200) +
            "': " + problem + "; a file is needed here");
    return resolved;
}

}  // namespace facet
