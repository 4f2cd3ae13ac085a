// `environment:` -> EnvironmentDesc (docs/pbr.md, "Environment").
#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace {

constexpr double kMaxEnvironmentIntensity = 1e6;

// `background: true | false | { blur: 0..1 }`.
void parse_environment_background(const Field& f, EnvironmentDesc& e) {
    if (f.is_scalar()) {
        e.background = f.boolean();
        return;
    }
    f.check_keys({"blur"});
    e.background = true;
    if (f.has("blur")) e.background_blur = static_cast<float>(f["blur"].number(0, 1));
}

}  // namespace

// `environment: studio | none`, or a mapping with `file:` or `color:`
// (neither: the studio), `intensity:`, `rotation:`, `follow_camera:` and
// `background:`.
EnvironmentDesc parse_environment(const Field& f, const std::string& base_dir) {
    EnvironmentDesc e;
    e.where = f.where();
    if (f.is_scalar()) {
        const std::string name = f.choice({"studio", "none"});
        e.source = name == "none" ? EnvironmentDesc::Source::none : EnvironmentDesc::Source::studio;
        return e;
    }
    f.check_keys({"file", "color", "intensity", "rotation", "follow_camera", "background"});
    if (f.has("file") && f.has("color"))
        f["color"].fail("an environment is a file or a colour; give only one of them");
    if (f.has("file")) {
        e.source = EnvironmentDesc::Source::file;
        e.file = existing_file(f["file"], base_dir);
        e.file_at = f["file"].where();
    }
    if (f.has("color")) {
        e.source = EnvironmentDesc::Source::color;
        e.color = f["color"].color3();
    }
    if (f.has("intensity"))
        e.intensity = f["intensity"].animated_number(0, kMaxEnvironmentIntensity);
    if (f.has("rotation")) e.rotation = f["rotation"].animated_number(-36000, 36000);
    if (f.has("follow_camera")) e.follow_camera = f["follow_camera"].boolean();
    if (f.has("background")) parse_environment_background(f["background"], e);
    return e;
}

}  // namespace facet
