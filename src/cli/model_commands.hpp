#pragma once
// A model file where a scene is expected (docs/turntables.md): the
// turntable's options of render and validate, a mesh read as facet's
// built-in turntable around it, and `facet scene MODEL`, which writes that
// turntable as a scene file to grow into.
#include <string>

#include "assets/mesh.hpp"
#include "cli/render_args.hpp"
#include "scene/scene_desc.hpp"

namespace CLI {
class App;
}

namespace facet {

// --turns, --elevation, --background, --ground, --environment and --up,
// under their own heading in the help.
void add_turntable_options(CLI::App* command, TurntableArgs& args);

// The scene `args.scene` names: a scene file as load_scene reads it, or
// the turntable of a mesh file, whose options' overrides are then put
// before the user's in `options` (the manifest lists them). Says on stderr
// (unless args.quiet) which way up a model was taken and why. `loaded`,
// when given, receives the model's mesh as the survey read it, for
// build_world to take instead of reading the file again.
SceneDesc load_scene_or_model(const RenderArgs& args, SceneOptions& options,
                              LoadedMeshes* loaded = nullptr);

// `facet scene MODEL [options] [-o FILE]`.
struct SceneFileArgs {
    RenderArgs model;    // the model as `scene`, and the options render takes for it
    std::string output;  // the YAML file to write; "" prints it
};
CLI::App* add_scene_command(CLI::App& app, SceneFileArgs& args);
int scene_command(const SceneFileArgs& args);

}  // namespace facet
