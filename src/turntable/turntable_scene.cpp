#include "turntable/turntable_scene.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/plain_text.hpp"
#include "turntable/yaml_writer.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The choices a turntable makes for a model nobody has looked at. Lengths
// are shares of the model's size (the largest side of its bounds).
constexpr double kFieldOfView = 30;       // degrees: a product shot's long lens
constexpr double kOcclusionRadius = 0.1;  // creases and contact, not the whole model
constexpr double kGroundSize = 10;        // wide enough for any shadow of the key light
constexpr double kGroundDrop = 0.001;     // below the lowest point, see write_ground
constexpr double kFloorFadeStart = 1.5;   // a floor fades out from here...
constexpr double kFloorFadeEnd = 4.5;     // ...to here, inside the ground's edge
constexpr double kBackgroundBlur = 0.8;   // the studio behind, as a soft gradient
const char* const kBackgroundGrey = "[0.2, 0.2, 0.2, 1]";

// The objects in the order the text lists them: -D may name them by index.
const char* const kObjectNames[] = {"model", "ground"};

std::string percent_of_size(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%g%%", 100 * share);
    return text;
}

// -D objects.1.material... is objects.ground.material...: the writer
// knows the items by name.
std::vector<Override> with_item_names(std::vector<Override> overrides) {
    for (Override& o : overrides) {
        const std::string prefix = "objects.";
        if (o.path.rfind(prefix, 0) != 0) continue;
        const size_t dot = o.path.find('.', prefix.size());
        const std::string item = o.path.substr(prefix.size(), dot - prefix.size());
        for (size_t i = 0; i < std::size(kObjectNames); ++i)
            if (item == std::to_string(i))
                o.path =
                    prefix + kObjectNames[i] + (dot == std::string::npos ? "" : o.path.substr(dot));
    }
    return overrides;
}

void write_header(YamlWriter& w, const ModelSurvey& s, const std::string& mesh_reference) {
    const glm::vec3 extent = s.bounds.max - s.bounds.min;
    const std::string facts =
        fs::path(mesh_reference).filename().string() + ": " + mesh_format_name(s.format) + ", " +
        std::to_string(s.triangles) + " triangles, " + yaml_rounded(extent.x) + " x " +
        yaml_rounded(extent.y) + " x " + yaml_rounded(extent.z) + " units upright";
    w.comment("facet's turntable of a model: the scene `facet render MODEL` renders, which");
    w.comment("`facet scene MODEL` writes. Rendering this file gives the same images, bit for");
    w.comment("bit, as long as its name is the model's (the name goes into the images);");
    w.comment("edit it to make the turntable your own (docs/turntables.md).");
    w.comment("");
    w.comment(facts);
    w.comment("Up: " + s.up.reason + ".");
    w.comment("");
}

void write_output(YamlWriter& w) {
    w.begin_map("output");
    w.value("size", "[1280, 720]");
    w.value("frames", "\"1-" + std::to_string(kTurntableFrames) + "\"",
            "one turn: frame 73 would be frame 1 again");
    w.value("fps", yaml_number(kTurntableFps), "three seconds");
    w.value("samples", "4", "2 x 2 samples a pixel: smooth edges");
    w.value("passes", "[color]", "--passes color,depth,... (docs/passes.md)");
    w.value("formats", "[png]", "--formats png,exr");
    w.comment("Where nothing is drawn, when the environment is not shown there:");
    w.comment("--background COLOR or transparent sets it and hides the environment.");
    w.value("background", kBackgroundGrey);
    // The other output keys, written when -D sets them (docs/scene-format.md).
    for (const char* key :
         {"exr", "normals", "exposure", "tonemap", "png_compression", "depth_range", "path"})
        w.optional_value(key);
    w.end_map();
    w.comment("");
}

void write_style(YamlWriter& w, double size) {
    w.comment("Physically based materials, as glTF means them (docs/pbr.md), lit by the");
    w.comment("environment and the key light; ambient occlusion darkens creases and the");
    w.comment("model's contact with the ground, within " + percent_of_size(kOcclusionRadius) +
              " of its size. --style NAME replaces it all.");
    w.begin_map("style");
    w.value("name", "turntable");
    w.value("extends", "pbr");
    w.begin_map("occlusion");
    w.value("radius", yaml_rounded(kOcclusionRadius * size));
    w.end_map();
    w.end_map();
    w.comment("");
}

void write_lighting(YamlWriter& w) {
    w.comment("The light all round: facet's studio (a grey cove, soft boxes at the front");
    w.comment("left, right and behind), shown behind the model too, blurred into a neutral");
    w.comment("gradient. --environment FILE lights it with an .hdr or .exr image instead.");
    w.begin_map("environment");
    w.optional_value("file");
    w.value("follow_camera", "true", "turns with the camera: the studio stays put in the image");
    w.begin_map("background");
    w.value("blur", yaml_number(kBackgroundBlur));
    w.end_map();
    w.end_map();
    w.comment("");
    w.comment("No `lights:`: facet's default key light, above and to the left of the");
    w.comment("camera, goes round with it and casts the shadow (at half strength under the");
    w.comment("studio). A `lights:` list of your own replaces it.");
    w.comment("");
}

void write_camera(YamlWriter& w) {
    w.comment("The camera circles the model over the frames, looking at its centre from");
    w.comment("the distance where, seen from anywhere on the circle, it fills the frame");
    w.comment("and never leaves it.");
    w.begin_map("camera");
    w.value("fov", yaml_number(kFieldOfView), "degrees, vertical");
    w.begin_map("frame");
    w.value("objects", "[model]");
    w.value("fit", "geometry", "its vertices, from 72 places round the circle");
    w.end_map();
    w.begin_map("orbit");
    w.value("elevation", yaml_number(kTurntableDefaults.elevation),
            "degrees above its centre: --elevation DEG");
    w.value("turns", yaml_number(kTurntableDefaults.turns), "--turns N");
    w.end_map();
    w.end_map();
    w.comment("");
}

void write_model(YamlWriter& w, const ModelSurvey& s, const std::string& mesh_reference) {
    const glm::vec3 low = s.bounds.min, high = s.bounds.max;
    w.begin_item(kObjectNames[0]);
    w.value("mesh", yaml_quoted(mesh_reference));
    if (s.up.axis == UpAxis::z)
        w.value("rotate", "[-90, 0, 0]", "Z-up: its Z turned to facet's Y (--up y)");
    else
        w.value("rotate", "[0, 0, 0]", "Y-up, as facet's world (--up z turns Z to Y)");
    w.value("translate",
            yaml_vector({-(low.x + high.x) / 2.0, -double(low.y), -(low.z + high.z) / 2.0}),
            "on its lowest point, centred");
    if (s.animations > 0) {
        char note[120];
        std::snprintf(note, sizeof note, "the file's %d animation%s (%g s), looping", s.animations,
                      s.animations == 1 ? "" : "s", s.animation_seconds);
        w.value("animation", "all", note);
    }
    w.end_item();
}

void write_ground(YamlWriter& w, double size) {
    w.comment("The ground: only the model's shadow and occlusion show on it, over the");
    w.comment("background (--ground floor: a grey floor fading away; --ground none: no");
    w.comment("ground). A hair below the model, so that a flat base does not flicker");
    w.comment("through it.");
    w.begin_item(kObjectNames[1]);
    w.begin_map("primitive");
    w.value("type", "plane");
    w.value("size", yaml_rounded(kGroundSize * size));
    w.end_map();
    w.value("translate", yaml_vector({0, -kGroundDrop * size, 0}, 3));
    w.value("cast_shadows", "false");
    w.optional_value("visible");
    w.begin_map("material");
    w.value("shadow_catcher", "true", "false: --ground floor");
    w.value("color", "[0.5, 0.5, 0.5]", "the floor's");
    w.value("roughness", "0.8");
    w.value("fade", yaml_vector({kFloorFadeStart * size, kFloorFadeEnd * size}, 3));
    w.end_map();
    w.end_item();
}

// The model's variants (KHR_materials_variants), listed when it has any;
// the key that chooses them is written when --variant or -D gives it.
void write_variant(YamlWriter& w, const ModelSurvey& s) {
    if (s.mesh && !s.mesh->variants.empty()) {
        const std::string names = comma_list(
            s.mesh->variants, [](const std::string& name) { return text_for_message(name); });
        w.comment("");
        w.comment("The model's variants: " + names + ". `variant: NAME` draws one (--variant");
        w.comment("NAME); `variant: all` renders each into a folder of its own.");
    }
    w.optional_value("variant");
}

}  // namespace

std::string path_from_scene(const std::string& scene_dir, const std::string& file) {
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(fs::absolute(file, ec), ec);
    if (scene_dir.empty()) return target.string();  // text with no folder of its own
    const fs::path folder = fs::weakly_canonical(fs::absolute(scene_dir, ec), ec);
    // Relative within one top folder (a checkout, a home), so the two move
    // together; absolute across top folders, where ../../.. says nothing.
    auto top = [](const fs::path& p) {
        auto it = p.begin();
        return it != p.end() && ++it != p.end() ? *it : fs::path();
    };
    const fs::path relative = target.lexically_relative(folder);
    if (relative.empty() || top(target) != top(folder)) return target.string();
    return relative.generic_string();
}

std::vector<Override> turntable_overrides(const TurntableOptions& options,
                                          const std::string& scene_dir) {
    std::vector<Override> out;
    auto add = [&](const std::string& key, const std::string& value, const std::string& option) {
        out.push_back({key, value, "command line " + option});
    };
    if (!options.turns.empty()) add(kTurnsKey, options.turns, "--turns " + options.turns);
    if (!options.elevation.empty())
        add(kElevationKey, options.elevation, "--elevation " + options.elevation);
    if (!options.background.empty() && options.background != kTurntableDefaults.background) {
        const std::string option = "--background " + options.background;
        add(kBackgroundKey, options.background, option);
        add(kEnvironmentShownKey, "false", option);
    }
    if (options.ground == GroundKind::floor) add(kGroundCatcherKey, "false", "--ground floor");
    if (options.ground == GroundKind::none) add(kGroundVisibleKey, "false", "--ground none");
    if (!options.environment.empty())
        add(kEnvironmentFileKey, yaml_quoted(path_from_scene(scene_dir, options.environment)),
            "--environment " + options.environment);
    return out;
}

std::vector<std::pair<std::string, std::string>> turntable_option_record(
    const TurntableOptions& options, const ModelSurvey& survey) {
    auto given = [](const std::string& value, const std::string& otherwise) {
        return value.empty() ? otherwise : value;
    };
    return {
        {"turns", given(options.turns, yaml_number(kTurntableDefaults.turns))},
        {"elevation", given(options.elevation, yaml_number(kTurntableDefaults.elevation))},
        {"background", given(options.background, std::string(kTurntableDefaults.background))},
        {"ground",
         std::string(name_of(kGroundKinds, options.ground.value_or(kTurntableDefaults.ground)))},
        {"environment", given(options.environment, std::string(kTurntableDefaults.environment))},
        {"up", std::string(name_of(kUpAxes, survey.up.axis))},
        {"up_from", options.up           ? "--up"
                    : survey.up.detected ? "the model's shape"
                                         : "the format's convention"}};
}

std::string turntable_scene_yaml(const ModelSurvey& survey, const std::string& mesh_reference,
                                 const std::vector<Override>& written_in,
                                 std::vector<Override>& unused) {
    YamlWriter w(with_item_names(written_in));
    const double size = survey.size();
    write_header(w, survey, mesh_reference);
    write_output(w);
    write_style(w, size);
    write_lighting(w);
    write_camera(w);
    w.begin_list("objects");
    write_model(w, survey, mesh_reference);
    write_ground(w, size);
    w.end_list();
    write_variant(w, survey);
    // Limits on the files the model names (--allow-asset-paths-outside).
    if (w.has_override_under("assets")) {
        w.comment("");
        w.begin_map("assets");
        for (const char* key : {"allow_paths_outside", "max_file_mb", "texture_budget_mb"})
            w.optional_value(key);
        w.end_map();
    }
    // Each key an option sets is one the text has (written, or written
    // when set): else an option would be refused as a -D of an unknown key.
    for (const char* key : kOptionKeys)
        if (!w.has_key(key))
            throw std::logic_error(std::string("the turntable's text lacks ") + key);
    unused = w.unused();
    return w.text();
}

}  // namespace facet
