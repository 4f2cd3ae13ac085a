#pragma once
// Writes a commented YAML scene in block style, key by key, and puts the
// value of an override in place of the written one wherever an override
// names that key: `facet scene MODEL --turns 2` writes `turns: 2` where the
// built-in scene has `turns: 1`, with the option that set it as a comment.
// Reading the text written with overrides gives the scene that reading it
// without them and applying them as `-D` would give.
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace facet {

class YamlWriter {
  public:
    // `overrides`: their paths are dotted keys with list items by name
    // (objects.ground.visible); the last one of a path wins, as with -D.
    explicit YamlWriter(std::vector<Override> overrides);

    // A comment line at the current depth ("" for an empty line).
    void comment(const std::string& text);
    // `key: value  # comment`; the override of that key's value instead.
    void value(const std::string& key, const std::string& yaml, const std::string& note = "");
    // A key written only when an override gives it a value.
    void optional_value(const std::string& key);
    // A mapping under `key`; its keys follow until end_map. An override of
    // the whole mapping replaces it (its keys are then left out).
    void begin_map(const std::string& key, const std::string& note = "");
    void end_map();
    // A list of mappings under `key`, and its items, each known by its `name`.
    void begin_list(const std::string& key);
    void begin_item(const std::string& name);
    void end_item();
    void end_list();

    // Whether an override names a key under `path` (a mapping the text
    // writes only when something sets a key in it).
    bool has_override_under(const std::string& path) const;
    // Whether the text has `path` (dotted, list items by name): a key or
    // mapping written so far, or a key it writes when an override sets it.
    bool has_key(const std::string& path) const;

    const std::string& text() const { return text_; }
    // The overrides whose keys the text does not have.
    std::vector<Override> unused() const;

  private:
    struct Level {
        std::string path;  // dotted, from the top
        int indent;        // of the keys inside
        bool skipped;      // an override replaced this mapping
    };
    std::string path_of(const std::string& key) const;
    const Override* override_of(const std::string& path);
    void write_line(int indent, const std::string& text, const std::string& note);
    bool skipping() const { return !levels_.empty() && levels_.back().skipped; }
    int indent() const { return levels_.empty() ? 0 : levels_.back().indent; }

    std::vector<Override> overrides_;
    std::vector<bool> used_;
    std::vector<Level> levels_;
    std::vector<std::string> keys_;  // has_key: every path value, optional_value, begin_map saw
    bool item_first_line_ = false;   // the next key opens a list item ("- ")
    std::string text_;
};

// A number as a scene writes it: the shortest text that reads back as the
// same float, and 0 for -0.
std::string yaml_number(double value);
// A length nobody needs to the last digit (a ground's size, a radius):
// `digits` significant ones.
std::string yaml_rounded(double value, int digits = 3);
// "[x, y, z]": each as yaml_number writes it, or rounded to `digits`.
std::string yaml_vector(const std::vector<double>& values, int digits = 0);

}  // namespace facet
