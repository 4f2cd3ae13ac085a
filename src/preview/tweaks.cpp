#include "preview/tweaks.hpp"

#include <charconv>
#include <filesystem>

#include "core/error.hpp"
#include "farm/shell_word.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (;;) {
        const size_t dot = path.find('.', start);
        parts.push_back(path.substr(start, dot == std::string::npos ? dot : dot - start));
        if (dot == std::string::npos) return parts;
        start = dot + 1;
    }
}

// How the style file names the style it extends: a preset's name when it
// is found in the preset folders, else the file's absolute path.
std::string extends_name(const std::string& file, const std::vector<std::string>& style_dirs) {
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(fs::path(file).parent_path(), ec);
    for (const std::string& dir : style_dirs)
        if (fs::weakly_canonical(dir, ec) == folder) return fs::path(file).stem().string();
    return fs::weakly_canonical(file, ec).string();
}

}  // namespace

std::string yaml_number(float value) {
    if (value == 0.0f) value = 0.0f;  // no "-0"
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string yaml_vector(const glm::vec3& v) {
    // Appended piece by piece: gcc 12 warns falsely (-Wrestrict) about
    // "literal" + a temporary string.
    std::string text = "[";
    text += yaml_number(v.x);
    text += ", ";
    text += yaml_number(v.y);
    text += ", ";
    text += yaml_number(v.z);
    return text + "]";
}

std::string yaml_value(const TweakValue& value) {
    if (const float* f = std::get_if<float>(&value)) return yaml_number(*f);
    if (const int* i = std::get_if<int>(&value)) return std::to_string(*i);
    if (const glm::vec3* v = std::get_if<glm::vec3>(&value)) return yaml_vector(*v);
    return yaml_quoted(std::get<std::string>(value));
}

std::vector<Override> tweak_overrides(const Tweaks& tweaks) {
    std::vector<Override> out;
    // The preset first: style.* values are a layer over whichever preset it is.
    if (auto it = tweaks.find("style"); it != tweaks.end())
        out.push_back({"style", yaml_value(it->second), "preview panel: style"});
    for (const auto& [path, value] : tweaks)
        if (path != "style") out.push_back({path, yaml_value(value), "preview panel: " + path});
    return out;
}

std::string define_arguments(const std::vector<Override>& overrides) {
    std::string out;
    for (const Override& o : overrides) {
        if (!out.empty()) out += " ";
        out += "-D ";
        out += shell_quoted(o.path + "=" + o.value);
    }
    return out;
}

namespace {

bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

// The light and wind values: scene values, not a style's, listed so that
// nothing changed in the panel is silently left out of the file.
std::string scene_values_comment(const Tweaks& tweaks) {
    std::string lines;
    for (const auto& [path, value] : tweaks)
        if (path != "style" && path.rfind("style.", 0) != 0)
            lines += "#   -D " + path + "=" + yaml_value(value) + "\n";
    return lines.empty() ? ""
                         : "# Scene values, not part of a style (give them with -D):\n" + lines;
}

// The style.* values nested as a style file nests them. Paths arrive
// sorted, so keys that share a parent are neighbours: each line opens
// only the parents the previous line did not.
std::string nested_style_keys(const Tweaks& tweaks) {
    std::string text;
    std::vector<std::string> open;
    for (const auto& [path, value] : tweaks) {
        if (path.rfind("style.", 0) != 0) continue;
        const std::vector<std::string> parts = split_path(path.substr(6));
        size_t shared = 0;
        while (shared < open.size() && shared + 1 < parts.size() && open[shared] == parts[shared])
            ++shared;
        open.resize(shared);
        for (size_t i = shared; i + 1 < parts.size(); ++i) {
            text += std::string(2 * i, ' ') + parts[i] + ":\n";
            open.push_back(parts[i]);
        }
        text += std::string(2 * (parts.size() - 1), ' ') + parts.back() + ": " + yaml_value(value) +
                "\n";
    }
    return text;
}

std::vector<Override> style_overrides(const Tweaks& tweaks) {
    std::vector<Override> out;
    for (const Override& o : tweak_overrides(tweaks))
        if (o.path.rfind("style.", 0) == 0) out.push_back(o);
    return out;
}

}  // namespace

std::string style_file_yaml(const SceneDesc& scene, const Tweaks& tweaks,
                            const std::vector<std::string>& style_dirs, const std::string& target) {
    const std::string header = "# Written by facet preview from the scene " + scene.path + ".\n";
    // The preset files read for the scene's style, its own file last; an
    // inline style (a mapping in the scene file) has only the presets it extends.
    const std::vector<std::string>& chain = scene.style.files;
    const bool inline_style =
        !scene.style.where.file.empty() && same_file(scene.style.where.file, scene.path);
    const size_t parents = inline_style || chain.empty() ? chain.size() : chain.size() - 1;
    for (size_t i = 0; i < parents; ++i)
        if (same_file(target, chain[i]))
            fail_input({}, "",
                       target +
                           " is a preset the scene's style extends; write the look "
                           "to a file of its own");
    const auto preset = tweaks.find("style");
    if (preset == tweaks.end()) {
        // The scene's inline style written out, or its own style file
        // written again: its own keys stay, with the panel's values over
        // them (a file extending itself would not load).
        if (inline_style)
            return header +
                   style_yaml_with_overrides(scene.path, "style", style_overrides(tweaks)) +
                   scene_values_comment(tweaks);
        if (!chain.empty() && same_file(target, chain.back()))
            return header + style_yaml_with_overrides(chain.back(), "", style_overrides(tweaks)) +
                   scene_values_comment(tweaks);
    }
    std::string extends;
    if (preset != tweaks.end()) {
        extends = std::get<std::string>(preset->second);
        for (const auto& [name, path] : list_style_presets(style_dirs))
            if (name == extends && same_file(target, path))
                fail_input({}, "",
                           target + " is the preset '" + name +
                               "' itself; write the look to a file of its own");
    } else if (!chain.empty()) {
        extends = extends_name(chain.back(), style_dirs);
    }
    return header + (extends.empty() ? "" : "extends: " + extends + "\n") +
           nested_style_keys(tweaks) + scene_values_comment(tweaks);
}

}  // namespace facet
