#pragma once
// A YAML node together with its dotted key path and the file it came from,
// so that every conversion can report exactly where a bad value is.
// Internal to the scene module (the only yaml-cpp user).
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/enum_names.hpp"
#include "core/error.hpp"
#include "scene/animated.hpp"

namespace facet {

struct YamlDocument {
    std::string file;
    std::string sha256;  // of exactly the text that was parsed
    YAML::Node root;
    // Key paths whose values came from the command line, with how the user wrote them.
    std::map<std::string, std::string> overridden;
};

// Parses a YAML file; syntax errors become facet::Error with line and column.
std::shared_ptr<YamlDocument> read_yaml_file(const std::string& path);
std::shared_ptr<YamlDocument> read_yaml_text(const std::string& text, const std::string& name);

class Field {
  public:
    Field(std::shared_ptr<const YamlDocument> doc, YAML::Node node, std::string path);

    const std::string& path() const { return path_; }
    SourceLocation where() const;
    [[noreturn]] void fail(const std::string& message) const;

    bool is_map() const { return node_.IsMap(); }
    bool is_sequence() const { return node_.IsSequence(); }
    bool is_scalar() const { return node_.IsScalar(); }
    bool is_null() const { return !node_ || node_.IsNull(); }

    // Mapping access. Every key of the mapping must be in `allowed`.
    void expect_map() const;
    void check_keys(std::initializer_list<const char*> allowed) const {
        check_keys(std::span<const char* const>(allowed.begin(), allowed.size()));
    }
    void check_keys(std::span<const char* const> allowed) const;
    bool has(const std::string& key) const;
    Field operator[](const std::string& key) const;  // key must exist (see has)
    Field require(const std::string& key) const;     // fails at this mapping if missing
    std::vector<std::string> keys() const;
    // The key `name` itself rather than its value, for errors about the key.
    Field key(const std::string& name) const;

    // Sequence access.
    size_t size() const;
    Field operator[](size_t index) const;

    // Conversions; each fails with the key and the allowed range.
    // A name, path or word: one line, no control characters
    // (core/plain_text.hpp), as every text that can reach a file name, a
    // manifest or a job file must be.
    std::string text() const;
    // Text for people only (a preset's description): any characters.
    std::string free_text() const;
    double number(double min, double max) const;
    int integer(int min, int max) const;
    bool boolean() const;
    glm::vec2 vec2() const;
    glm::vec3 vec3() const;
    glm::vec3 color3() const;          // [r, g, b] linear, or "#rrggbb" sRGB
    glm::vec2 distance_range() const;  // [near, far] with 0 <= near < far
    glm::vec4 color4() const;          // [r, g, b, a] or [r, g, b] or "#rrggbb[aa]"
    glm::vec4 background() const;      // a color4, or `transparent`: [0, 0, 0, 0]
    // One of the given words.
    std::string choice(std::initializer_list<const char*> words) const;
    // The value whose name the text is, from the enum's one table
    // (core/enum_names.hpp).
    template <typename E, size_t N>
    E choice_of(const EnumName<E> (&table)[N]) const {
        const std::string value = text();
        if (const std::optional<E> named = value_of(table, value)) return *named;
        fail_not_one_of(value, names_of(table));
    }
    // "got 'x'; did you mean 'y'? (one of: ...)": the one message for a
    // word outside its set.
    [[noreturn]] void fail_not_one_of(const std::string& value,
                                      const std::vector<std::string_view>& words) const;
    // A list of words from the given set.
    std::vector<std::string> choices(std::initializer_list<const char*> words) const;

    // A constant or a keyframe track (`{keys: {frame: value, ...}, ...}`,
    // track_parser.cpp); every key's value is checked like the constant.
    Animated<float> animated_number(double min, double max) const;
    Animated<glm::vec3> animated_vec3() const;
    Animated<glm::vec3> animated_color3() const;
    Animated<glm::vec3> animated_direction() const;  // never [0, 0, 0]
    // A number for all three axes or [x, y, z]; never zero on an axis.
    Animated<glm::vec3> animated_scale() const;
    // Euler degrees; a track may choose `rotation: shortest | angles`.
    Animated<glm::vec3> animated_rotation() const;
    // True when the value is written as a keyframe track.
    bool is_track() const { return node_.IsMap() && node_["keys"]; }

  private:
    std::vector<double> numbers(size_t min_count, size_t max_count) const;
    std::string scalar_for_message() const;

    std::shared_ptr<const YamlDocument> doc_;
    YAML::Node node_;
    std::string path_;
};

Field root_field(const std::shared_ptr<YamlDocument>& doc);

// The file a path value names, resolved against `base_dir` (the scene's or
// style's folder); fails at the value when it is not a readable file.
std::string existing_file(const Field& field, const std::string& base_dir);

// Applies command-line overrides to the document, remembering their origin.
struct Override;
void apply_overrides(YamlDocument& doc, const std::vector<Override>& overrides);

}  // namespace facet
