// Style presets: YAML -> StyleDesc (docs/styles.md).
#include <algorithm>
#include <filesystem>

#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace fs = std::filesystem;

namespace {

ShadingModel parse_shading(const Field& f) {
    std::string name = f.choice(
        {"flat", "gouraud", "phong", "blinn_phong", "blinn-phong", "unlit", "depth", "normal"});
    if (name == "flat") return ShadingModel::flat;
    if (name == "gouraud") return ShadingModel::gouraud;
    if (name == "phong") return ShadingModel::phong;
    if (name == "unlit") return ShadingModel::unlit;
    if (name == "depth") return ShadingModel::depth;
    if (name == "normal") return ShadingModel::normal;
    return ShadingModel::blinn_phong;
}

StyleDesc parse_style_mapping(const Field& f, const std::string& name) {
    StyleDesc style;
    style.name = name;
    style.where = f.where();
    f.check_keys({"name", "description", "shading", "depth_range"});
    if (f.has("name")) style.name = f["name"].text();
    if (f.has("description")) style.description = f["description"].text();
    if (f.has("shading")) style.shading = parse_shading(f["shading"]);
    if (f.has("depth_range")) style.depth_range = f["depth_range"].distance_range();
    return style;
}

bool looks_like_path(const std::string& text) {
    return text.find('/') != std::string::npos || text.ends_with(".yaml") || text.ends_with(".yml");
}

}  // namespace

const char* shading_model_name(ShadingModel model) {
    switch (model) {
        case ShadingModel::flat:
            return "flat";
        case ShadingModel::gouraud:
            return "gouraud";
        case ShadingModel::phong:
            return "phong";
        case ShadingModel::blinn_phong:
            return "blinn_phong";
        case ShadingModel::unlit:
            return "unlit";
        case ShadingModel::depth:
            return "depth";
        case ShadingModel::normal:
            return "normal";
    }
    return "?";
}

StyleDesc load_style_file(const std::string& path) {
    auto doc = read_yaml_file(path);
    Field root = root_field(doc);
    if (root.is_null()) root.fail("the style file is empty");
    return parse_style_mapping(root, fs::path(path).stem().string());
}

std::vector<std::pair<std::string, std::string>> list_style_presets(
    const std::vector<std::string>& style_dirs) {
    std::vector<std::pair<std::string, std::string>> found;
    for (const auto& dir : style_dirs) {
        std::error_code ec;
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(dir, ec))
            if (entry.path().extension() == ".yaml") files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        for (const auto& file : files) {
            std::string name = file.stem().string();
            bool seen = std::any_of(found.begin(), found.end(),
                                    [&](const auto& p) { return p.first == name; });
            if (!seen) found.emplace_back(name, file.string());
        }
    }
    return found;
}

// `style:` in a scene: a preset name, a path to a preset file, or a mapping.
StyleDesc parse_style_field(const Field& field, const std::string& base_dir,
                            const std::vector<std::string>& style_dirs) {
    if (field.is_map()) return parse_style_mapping(field, "inline");
    std::string text = field.text();
    if (looks_like_path(text)) {
        fs::path p = fs::path(text).is_absolute() ? fs::path(text) : fs::path(base_dir) / text;
        std::error_code ec;
        if (!fs::is_regular_file(p, ec)) field.fail("style file not found: " + p.string());
        return load_style_file(p.lexically_normal().string());
    }
    auto presets = list_style_presets(style_dirs);
    for (const auto& [name, path] : presets)
        if (name == text) return load_style_file(path);
    std::string names;
    for (const auto& preset : presets) names += (names.empty() ? "" : ", ") + preset.first;
    field.fail("no style preset named '" + text +
               "' (available: " + (names.empty() ? "none found" : names) + ")");
}

}  // namespace facet
