#include "cli/model_commands.hpp"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "assets/mesh_format.hpp"
#include "cli/option_values.hpp"
#include "output/atomic_file.hpp"
#include "turntable/model_turntable.hpp"

namespace facet {
namespace {

const char* const kGroup = "Turntable of a model (when the file is a mesh, docs/turntables.md)";

// The ranges the scene gives camera.orbit's values (scene/scene_parser.cpp).
constexpr double kMaxTurns = 1000;
constexpr double kMaxElevation = 89.9;

// A number option kept as typed, for the override it becomes, after the
// check every number on the command line gets.
CLI::Option* add_number_text(CLI::App* cmd, const std::string& name, std::string& text,
                             double limit, const std::string& type,
                             const std::string& description) {
    return cmd
        ->add_option_function<std::string>(
            name,
            [=, &text](const std::string& value) {
                parse_decimal_number(value, name, -limit, limit);
                text = value;
            },
            description)
        ->type_name(type)
        ->group(kGroup);
}

// A text option kept as typed, refused at once when empty: an empty value
// is no choice, and taking it as "not given" would hide a script's
// missing variable behind the default.
CLI::Option* add_text(CLI::App* cmd, const std::string& name, std::string& text,
                      const std::string& type, const std::string& description) {
    return cmd
        ->add_option_function<std::string>(
            name,
            [=, &text](const std::string& value) {
                if (value.empty())
                    fail_input(command_line(name + " ''"), "",
                               "expected " + type + ", got an empty value");
                text = value;
            },
            description)
        ->type_name(type)
        ->group(kGroup);
}

TurntableOptions turntable_options(const TurntableArgs& args) {
    TurntableOptions options;
    options.turns = args.turns;
    options.elevation = args.elevation;
    options.background = args.background;
    options.environment = args.environment;
    if (!args.ground.empty()) options.ground = parse_choice(args.ground, "--ground", kGroundKinds);
    if (!args.up.empty()) options.up = parse_choice(args.up, "--up", kUpAxes);
    return options;
}

TurntableRequest turntable_request(const RenderArgs& args, const SceneOptions& options) {
    return {args.scene, turntable_options(args.turntable), options, args.allow_asset_paths_outside,
            args.threads};
}

// Said on stderr: the model became a turntable, which way up and why.
void report_model(const std::string& path, const ModelSurvey& survey) {
    std::fprintf(stderr, "facet: %s: a model (%s): facet's turntable of it; up: %s\n", path.c_str(),
                 mesh_format_name(survey.format).c_str(), survey.up.reason.c_str());
}

}  // namespace

std::string TurntableArgs::first_given() const {
    const std::pair<const std::string*, const char*> options[] = {
        {&turns, "--turns"},   {&elevation, "--elevation"},     {&background, "--background"},
        {&ground, "--ground"}, {&environment, "--environment"}, {&up, "--up"}};
    for (const auto& [value, name] : options)
        if (!value->empty()) return name;
    return "";
}

void add_turntable_options(CLI::App* cmd, TurntableArgs& args) {
    add_number_text(cmd, "--turns", args.turns, kMaxTurns, "N",
                    "Turns of the camera over the frames (default 1; negative: clockwise); "
                    "-D camera.orbit.turns=N");
    add_number_text(cmd, "--elevation", args.elevation, kMaxElevation, "DEG",
                    "Degrees the camera looks down from (default 20); "
                    "-D camera.orbit.elevation=DEG");
    add_text(cmd, "--background", args.background, "transparent|gradient|COLOR",
             "transparent, gradient (the studio blurred, the default) or a colour "
             "('#rrggbb', [r,g,b]); -D output.background=... "
             "-D environment.background=false");
    add_text(cmd, "--ground", args.ground, "shadow|floor|none",
             "shadow (only the shadow and occlusion show, the default), floor (a grey "
             "floor) or none");
    add_text(cmd, "--environment", args.environment, "FILE",
             "Light it with this .hdr or .exr (default: the built-in studio); "
             "-D environment.file=FILE");
    add_text(cmd, "--up", args.up, "y|z",
             "The model's up axis, y or z (default: glTF, OBJ and the others y; STL and "
             "PLY z when they stand on a flat base at their lowest z)");
}

SceneDesc load_scene_or_model(const RenderArgs& args, SceneOptions& options, LoadedMeshes* loaded) {
    if (scene_input_kind(args.scene) != SceneInputKind::mesh) {
        const std::string option = args.turntable.first_given();
        if (!option.empty())
            fail_input(command_line(option), "",
                       "builds the turntable of a model (a mesh file), and " + args.scene +
                           " is not one: set the scene's own values, or give -D");
        return load_scene(args.scene, options);
    }
    Turntable turntable = load_turntable(turntable_request(args, options));
    options.overrides = turntable.overrides;
    if (loaded) *loaded = std::move(turntable.meshes);
    if (!args.quiet) report_model(args.scene, turntable.survey);
    return std::move(turntable.scene);
}

CLI::App* add_scene_command(CLI::App& app, SceneFileArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "scene", "Write facet's turntable of a model as a commented scene file (YAML)");
    RenderArgs& model = args.model;
    cmd->add_option("model", model.scene,
                    "Mesh file: .glb, .gltf, .obj, .stl, .ply, .fbx, .dae or .3ds")
        ->required();
    add_output_option(cmd, args.output,
                      "The scene file to write (name it after the model: its name goes into "
                      "the images); default: print it");
    cmd->add_option("--size", model.size, "Image size WIDTHxHEIGHT, e.g. 1280x720");
    cmd->add_option("--style", model.style, "Style preset name or file");
    cmd->add_option("--passes", model.passes, "Passes to write, comma-separated");
    cmd->add_option("--formats", model.formats, "File formats: png, exr or png,exr");
    add_variant_option(cmd, model.variant);
    add_define_option(cmd, model.defines);
    cmd->get_option("-D")->description(
        "Set a value the file has, key.path=value, written in with the option as its comment "
        "(repeatable)");
    add_quiet_flag(cmd, model.quiet);
    add_asset_paths_flag(cmd, model.allow_asset_paths_outside);
    add_turntable_options(cmd, model.turntable);
    return cmd;
}

int scene_command(const SceneFileArgs& args) {
    const RenderArgs& model = args.model;
    const SceneInputKind kind = scene_input_kind(model.scene);
    if (kind == SceneInputKind::scene)
        fail_input({model.scene, 0, 0, ""}, "",
                   "a scene already: facet scene writes the turntable scene of a model (a mesh "
                   "file: " +
                       mesh_formats_read() + ")");
    if (kind == SceneInputKind::neither) load_scene(model.scene, {});  // says what it is not
    std::string folder = std::filesystem::path(args.output).parent_path().string();
    if (folder.empty()) folder = ".";
    const TurntableRequest request = turntable_request(model, scene_options(model));
    // Printed, the text may be saved anywhere: its paths are absolute then.
    const TurntableFile file = turntable_scene_file(request, args.output.empty() ? "" : folder);
    if (!model.quiet) report_model(model.scene, file.survey);
    if (args.output.empty()) {
        std::fwrite(file.text.data(), 1, file.text.size(), stdout);
        return 0;
    }
    make_directories(folder);
    write_file_atomically(args.output, file.text);
    if (!model.quiet)
        std::printf("wrote %s: `facet render %s` renders the turntable\n", args.output.c_str(),
                    args.output.c_str());
    return 0;
}

}  // namespace facet
