// Style presets: YAML -> StyleDesc (docs/styles.md). A style is built in
// layers: the preset it `extends:` (recursively), then its own keys, then
// -D style.* overrides and an object's own `style:` values. Each layer sets
// only the keys it names, so every value keeps the file and line it came from.
#include <algorithm>
#include <filesystem>

#include <glm/geometric.hpp>

#include "core/enum_names.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/plain_text.hpp"
#include "core/suggest.hpp"
#include "scene/scene_desc.hpp"
#include "scene/style_layers.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace fs = std::filesystem;

namespace {

// A chain of presets longer than this is a mistake, not a design.
constexpr size_t kMaxExtendsDepth = 16;

// Each model's name in style files; also what `facet validate` prints.
constexpr EnumName<HatchSpace> kHatchSpaces[] = {
    {HatchSpace::object, "object"}, {HatchSpace::uv, "uv"}, {HatchSpace::screen, "screen"}};
constexpr EnumName<HatchDirection> kHatchDirections[] = {{HatchDirection::curvature, "curvature"},
                                                         {HatchDirection::uv, "uv"},
                                                         {HatchDirection::axis, "axis"},
                                                         {HatchDirection::fixed, "fixed"}};

constexpr EnumName<ShadingModel> kShadingNames[] = {
    {ShadingModel::flat, "flat"},     {ShadingModel::gouraud, "gouraud"},
    {ShadingModel::phong, "phong"},   {ShadingModel::blinn_phong, "blinn_phong"},
    {ShadingModel::unlit, "unlit"},   {ShadingModel::depth, "depth"},
    {ShadingModel::normal, "normal"}, {ShadingModel::palette, "palette"},
    {ShadingModel::gooch, "gooch"},   {ShadingModel::toon, "toon"},
    {ShadingModel::pbr, "pbr"},
};

ShadingModel parse_shading(const Field& f) {
    std::string name = f.text();
    if (name == "blinn-phong") return ShadingModel::blinn_phong;  // the preset's spelling
    if (const std::optional<ShadingModel> model = value_of(kShadingNames, name)) return *model;
    f.fail_not_one_of(name, names_of(kShadingNames));
}

void apply_toon(const Field& f, ToonDesc& toon) {
    f.check_keys({"bands", "ramp", "softness", "specular", "rim"});
    if (f.has("bands")) {
        Field bands = f["bands"];
        toon.bands.clear();
        if (bands.size() == 0) bands.fail("give at least one band: [threshold, level or colour]");
        for (size_t i = 0; i < bands.size(); ++i) {
            Field band = bands[i];
            if (!band.is_sequence() || band.size() != 2)
                band.fail("a band is [threshold, level] or [threshold, [r, g, b]]");
            ToonBandDesc b;
            b.threshold = static_cast<float>(band[0].number(-1, 1));
            b.value = band[1].is_scalar() ? glm::vec3(static_cast<float>(band[1].number(0, 100)))
                                          : band[1].color3();
            if (!toon.bands.empty() && b.threshold <= toon.bands.back().threshold)
                band[0].fail("band thresholds must increase");
            toon.bands.push_back(b);
        }
    }
    if (f.has("ramp")) toon.ramp = f["ramp"].boolean();
    if (f.has("softness")) toon.softness = f["softness"].animated_number(0, 2);
    if (f.has("specular")) {
        Field s = f["specular"];
        s.check_keys({"color", "threshold", "shininess"});
        if (s.has("color")) toon.specular_color = s["color"].animated_color3();
        if (s.has("threshold")) toon.specular_threshold = s["threshold"].animated_number(0, 1);
        if (s.has("shininess"))
            toon.shininess = static_cast<float>(s["shininess"].number(1, 10000));
    }
    if (f.has("rim")) {
        Field r = f["rim"];
        r.check_keys({"color", "power", "threshold"});
        if (r.has("color")) toon.rim_color = r["color"].animated_color3();
        if (r.has("power")) toon.rim_power = static_cast<float>(r["power"].number(0.1, 64));
        if (r.has("threshold")) toon.rim_threshold = r["threshold"].animated_number(0, 1);
    }
}

void apply_hatching(const Field& f, std::optional<HatchingDesc>& hatching) {
    if (f.is_scalar()) {
        if (!f.boolean())
            hatching.reset();
        else if (!hatching)
            hatching = HatchingDesc{};
        return;
    }
    f.check_keys({"levels", "scale", "tile_pixels", "space", "direction", "axis", "angle",
                  "stroke_width", "ink", "strength", "white", "exposure", "pencil", "wash", "paper",
                  "seed", "blend"});
    if (!hatching) hatching = HatchingDesc{};
    HatchingDesc& h = *hatching;
    if (f.has("levels")) h.levels = f["levels"].integer(2, 32);
    if (f.has("scale")) h.scale = static_cast<float>(f["scale"].number(0.01, 1000));
    if (f.has("tile_pixels")) h.tile_pixels = static_cast<float>(f["tile_pixels"].number(4, 4096));
    if (f.has("space")) {
        h.space = f["space"].choice_of(kHatchSpaces);
    }
    if (f.has("direction")) {
        h.direction = f["direction"].choice_of(kHatchDirections);
    }
    if (f.has("axis")) {
        h.axis = f["axis"].vec3();
        if (!(glm::dot(h.axis, h.axis) > 0.0f)) f["axis"].fail("axis must not be [0, 0, 0]");
        h.axis = glm::normalize(h.axis);
    }
    if (f.has("angle")) h.angle = static_cast<float>(f["angle"].number(-360, 360));
    if (f.has("stroke_width"))
        h.stroke_width = static_cast<float>(f["stroke_width"].number(0.25, 16));
    if (f.has("ink")) h.ink = f["ink"].animated_color3();
    if (f.has("strength")) h.strength = f["strength"].animated_number(0, 1);
    if (f.has("pencil")) h.pencil = f["pencil"].boolean();
    if (f.has("white")) h.white = f["white"].animated_number(0.05, 1);
    if (f.has("exposure")) h.exposure = f["exposure"].animated_number(-10, 10);
    if (f.has("wash")) h.wash = f["wash"].animated_number(0, 1);
    if (f.has("paper")) h.paper = f["paper"].animated_color3();
    if (f.has("seed")) h.seed = f["seed"].integer(0, 1000000);
    if (f.has("blend")) h.additive = f["blend"].choice({"ink", "add"}) == "add";
}

void apply_line(const Field& f, LineDesc& line) {
    if (f.is_scalar()) {
        line.enabled = f.boolean();
        return;
    }
    f.check_keys({"enabled", "width", "color"});
    line.enabled = f.has("enabled") ? f["enabled"].boolean() : true;
    if (f.has("width")) line.width = f["width"].animated_number(0.25, 64);
    if (f.has("color")) line.color = f["color"].animated_color3();
}

void apply_outlines(const Field& f, OutlinesDesc& o) {
    if (f.is_scalar()) {
        // `outlines: false` turns off every kind (e.g. in a preset that
        // extends one with outlines); `true` turns on silhouettes and creases.
        const bool on = f.boolean();
        o.silhouette.enabled = o.crease.enabled = on;
        if (!on) o.boundary.enabled = o.intersection.enabled = false;
        return;
    }
    f.check_keys({"silhouette", "crease", "boundary", "intersection", "width", "color",
                  "crease_angle", "depth_threshold"});
    // `width` and `color` set every kind at once; a kind's own values win.
    for (LineDesc* line : {&o.silhouette, &o.crease, &o.boundary, &o.intersection}) {
        if (f.has("width")) line->width = f["width"].animated_number(0.25, 64);
        if (f.has("color")) line->color = f["color"].animated_color3();
    }
    if (f.has("silhouette")) apply_line(f["silhouette"], o.silhouette);
    if (f.has("crease")) apply_line(f["crease"], o.crease);
    if (f.has("boundary")) apply_line(f["boundary"], o.boundary);
    if (f.has("intersection")) apply_line(f["intersection"], o.intersection);
    if (f.has("crease_angle"))
        o.crease_angle = static_cast<float>(f["crease_angle"].number(1, 179));
    if (f.has("depth_threshold"))
        o.depth_threshold = static_cast<float>(f["depth_threshold"].number(0.0001, 10));
}

void apply_occlusion(const Field& f, OcclusionDesc& o) {
    if (f.is_scalar()) {
        o.enabled = f.boolean();
        return;
    }
    f.check_keys({"enabled", "radius", "strength", "samples", "resolution"});
    o.enabled = f.has("enabled") ? f["enabled"].boolean() : true;
    if (f.has("radius")) o.radius = f["radius"].animated_number(1e-6, kMaxCoordinate);
    if (f.has("strength")) o.strength = f["strength"].animated_number(0, 10);
    if (f.has("samples")) o.samples = f["samples"].integer(4, 64);
    if (f.has("resolution")) o.half_resolution = f["resolution"].choice({"half", "full"}) == "half";
}

void apply_wireframe(const Field& f, WireframeDesc& w) {
    if (f.is_scalar()) {
        w.enabled = f.boolean();
        return;
    }
    f.check_keys({"enabled", "width", "color", "hidden", "hidden_color", "fill", "fill_color",
                  "edges", "crease_angle"});
    w.enabled = f.has("enabled") ? f["enabled"].boolean() : true;
    if (f.has("width")) w.width = f["width"].animated_number(0.25, 64);
    if (f.has("color")) w.color = f["color"].animated_color3();
    if (f.has("hidden")) w.hidden = f["hidden"].boolean();
    if (f.has("hidden_color")) w.hidden_color = f["hidden_color"].animated_color3();
    if (f.has("fill")) w.fill_shading = f["fill"].choice({"shading", "color"}) == "shading";
    if (f.has("fill_color")) w.fill_color = f["fill_color"].animated_color3();
    if (f.has("edges")) w.all_edges = f["edges"].choice({"features", "all"}) == "all";
    if (f.has("crease_angle"))
        w.crease_angle = static_cast<float>(f["crease_angle"].number(0, 180));
}

bool looks_like_path(const std::string& text) {
    return text.find('/') != std::string::npos || text.ends_with(".yaml") || text.ends_with(".yml");
}

// The preset file a name or path refers to, or a failure at `field`.
std::string find_style(const Field& field, const std::string& base_dir,
                       const std::vector<std::string>& style_dirs) {
    std::string text = field.text();
    if (looks_like_path(text)) {
        fs::path p = fs::path(text).is_absolute() ? fs::path(text) : fs::path(base_dir) / text;
        const std::string problem = input_file_problem(p.string());
        if (!problem.empty()) field.fail("style file " + p.string() + ": " + problem);
        return p.lexically_normal().string();
    }
    auto presets = list_style_presets(style_dirs);
    for (const auto& [name, path] : presets)
        if (name == text) return path;
    std::vector<std::string_view> known;
    for (const auto& preset : presets) known.push_back(preset.first);
    const std::string names = comma_list(known);
    field.fail("no style preset named '" + text + "'" + did_you_mean(text, known) +
               " (available: " + (names.empty() ? "none found" : names) + ")");
}

StyleDesc load_style_chain(const std::string& path, const StyleContext& context,
                           std::vector<std::string>& visiting);

}  // namespace

const char* shading_model_name(ShadingModel model) {
    return c_name_of(kShadingNames, model);
}

void apply_style_layer(const Field& f, StyleDesc& style, const StyleContext& context,
                       std::vector<std::string>& visiting) {
    f.check_keys({"name",       "description", "extends",   "shading",    "depth_range",
                  "base_color", "background",  "shadows",   "palette",    "cool",
                  "warm",       "alpha",       "beta",      "ambient",    "cels",
                  "specular",   "shininess",   "toon",      "hatching",   "outlines",
                  "wireframe",  "cel_color",   "occlusion", "hatch_below"});
    if (f.has("extends")) {
        const std::string path = find_style(f["extends"], context.base_dir, context.style_dirs);
        if (std::find(visiting.begin(), visiting.end(), path) != visiting.end())
            f["extends"].fail("extends itself through " + path);
        if (visiting.size() >= kMaxExtendsDepth)
            f["extends"].fail("more than " + std::to_string(kMaxExtendsDepth) +
                              " presets extend one another");
        const std::string name = style.name;
        const SourceLocation where = style.where;  // this layer's, not the parent's
        style = load_style_chain(path, context, visiting);
        style.chain.push_back(style.name);
        style.name = name;
        style.where = where;
        style.description.clear();  // a description speaks for its own file only
    }
    if (f.has("name")) style.name = f["name"].text();
    if (f.has("description")) style.description = f["description"].free_text();
    if (f.has("shading")) style.shading = parse_shading(f["shading"]);
    if (f.has("depth_range")) style.depth_range = f["depth_range"].distance_range();
    if (f.has("base_color")) {
        Field c = f["base_color"];
        if (c.is_scalar() && c.text() == "material")
            style.base_color.reset();
        else
            style.base_color = c.animated_color3();
    }
    if (f.has("background")) style.background = f["background"].background();
    if (f.has("shadows")) {
        Field sh = f["shadows"];
        if (sh.is_scalar() && sh.text() == "lights")
            style.shadows.reset();
        else
            style.shadows = sh.boolean();
    }
    if (f.has("palette")) {
        Field p = f["palette"];
        if (!p.is_sequence() || p.size() != 2) p.fail("must be [shadow colour, lit colour]");
        style.cool = p[0].animated_color3();
        style.warm = p[1].animated_color3();
    }
    if (f.has("cool")) style.cool = f["cool"].animated_color3();
    if (f.has("warm")) style.warm = f["warm"].animated_color3();
    if (f.has("alpha")) style.alpha = f["alpha"].animated_number(0, 10);
    if (f.has("beta")) style.beta = f["beta"].animated_number(0, 10);
    if (f.has("ambient")) style.ambient = f["ambient"].animated_number(0, 10);
    if (f.has("cels")) style.cels = f["cels"].animated_number(0, 64);
    if (f.has("cel_color"))
        style.cels_keep_hue = f["cel_color"].choice({"seed", "keep_hue"}) == "keep_hue";
    if (f.has("hatch_below")) style.hatch_below = f["hatch_below"].animated_number(0, 1);
    if (f.has("specular")) style.specular = f["specular"].animated_number(0, 100);
    if (f.has("shininess")) style.shininess = f["shininess"].animated_number(1, 100000);
    if (f.has("toon")) apply_toon(f["toon"], style.toon);
    if (f.has("hatching")) apply_hatching(f["hatching"], style.hatching);
    if (f.has("outlines")) apply_outlines(f["outlines"], style.outlines);
    if (f.has("wireframe")) apply_wireframe(f["wireframe"], style.wireframe);
    if (f.has("occlusion")) apply_occlusion(f["occlusion"], style.occlusion);
}

namespace {

StyleDesc load_style_chain(const std::string& path, const StyleContext& context,
                           std::vector<std::string>& visiting) {
    auto doc = read_yaml_file(path);
    Field root = root_field(doc);
    if (root.is_null()) root.fail("the style file is empty");
    StyleDesc style;
    style.name = fs::path(path).stem().string();
    style.where = root.where();
    visiting.push_back(path);
    StyleContext own = context;
    own.base_dir = fs::path(path).parent_path().string();
    apply_style_layer(root, style, own, visiting);
    style.files.push_back(path);
    visiting.pop_back();
    return style;
}

}  // namespace

StyleDesc load_style_file(const std::string& path, const std::vector<std::string>& style_dirs) {
    std::vector<std::string> visiting;
    return load_style_chain(path, {style_dirs, fs::path(path).parent_path().string()}, visiting);
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

StyleDesc parse_style_field(const Field& field, const StyleContext& context) {
    std::vector<std::string> visiting;
    if (field.is_map()) {
        StyleDesc style;
        style.name = "inline";
        style.where = field.where();
        apply_style_layer(field, style, context, visiting);
        return style;
    }
    return load_style_chain(find_style(field, context.base_dir, context.style_dirs), context,
                            visiting);
}

namespace {

// Keys of `top` over those of `base`; mappings merge key by key, as the
// style layers apply (a child's `toon: {bands: 3}` keeps the parent's
// other toon keys), and anything else is replaced whole.
YAML::Node merged(const YAML::Node& base, const YAML::Node& top) {
    if (!base.IsMap() || !top.IsMap()) return YAML::Clone(top);
    YAML::Node out = YAML::Clone(base);
    for (auto it = top.begin(); it != top.end(); ++it) {
        const std::string key = it->first.Scalar();
        out[key] = out[key] ? merged(out[key], it->second) : YAML::Clone(it->second);
    }
    return out;
}

}  // namespace

std::string resolved_style_yaml(const std::string& path,
                                const std::vector<std::string>& style_dirs) {
    const StyleDesc checked = load_style_file(path, style_dirs);  // every error, with its place
    std::vector<std::shared_ptr<YamlDocument>> layers;
    std::vector<std::string> names;
    for (std::string file = path;;) {
        auto doc = read_yaml_file(file);
        layers.push_back(doc);
        names.push_back(fs::path(file).stem().string());
        const Field root = root_field(doc);
        if (!root.has("extends")) break;
        file = find_style(root["extends"], fs::path(file).parent_path().string(), style_dirs);
    }
    YAML::Node result(YAML::NodeType::Map);
    for (auto it = layers.rbegin(); it != layers.rend(); ++it) result = merged(result, (*it)->root);
    result.remove("extends");
    YAML::Emitter out;
    out << result;
    std::string chain;
    for (const std::string& n : names) chain += (chain.empty() ? "" : " <- ") + n;
    return "# " + checked.name + ": " + chain +
           "\n# every layer applied; keys not listed take the defaults of docs/styles.md\n" +
           out.c_str() + "\n";
}

std::string style_yaml_with_overrides(const std::string& file, const std::string& key,
                                      const std::vector<Override>& overrides) {
    auto doc = read_yaml_file(file);
    const YAML::Node style = key.empty() ? doc->root : doc->root[key];
    // The overrides' paths start with "style.", as the scene reader's style
    // layer has them.
    auto layer = read_yaml_text("style: {}", "preview");
    if (style && style.IsMap()) layer->root["style"] = YAML::Clone(style);
    apply_overrides(*layer, overrides);
    YAML::Emitter out;
    out << layer->root["style"];
    return std::string(out.c_str()) + "\n";
}

}  // namespace facet
