#pragma once
// The options of commands that load a scene the way render does (render,
// validate, bench, farm), shared so that they mean the same everywhere.
#include <string>
#include <vector>

#include "cli/compare_command.hpp"
#include "cli/options.hpp"
#include "job/render_job.hpp"
#include "render/render_plan.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace CLI {
class App;
}

namespace facet {

// render: which part of the job this task renders (docs/farm.md).
struct ChunkArgs {
    std::string chunk;           // --chunk I/N
    bool from_env = false;       // --chunk-from-env
    int chunks = 0;              // --chunks N (with --chunk-from-env)
    std::string chunk_frames;    // --chunk-frames LIST
    bool skip_existing = false;  // --skip-existing
};

// render, validate and scene given a model file: the built-in turntable's
// options (docs/turntables.md), as typed; "" when not given.
struct TurntableArgs {
    std::string turns, elevation, background, ground, environment, up;
    // The first option given, "--turns" say, or "" for none.
    std::string first_given() const;
};

struct RenderArgs {
    std::string scene;
    FrameSelection frames;
    std::string size;
    std::string passes;   // e.g. "color,depth"
    std::string formats;  // e.g. "png,exr"
    std::string out = "out";
    unsigned threads = 0;
    std::string style;
    std::string cameras;  // comma-separated names, or "all"
    std::string variant;  // --variant NAME|all: the scene key `variant:`
    std::vector<std::string> defines;
    bool quiet = false;
    bool allow_asset_paths_outside = false;
    bool strict = false;  // render, validate, farm: any warning is an error (exit 2)
    bool overwrite = false;
    bool dry_run = false;                   // render: list the files, write none
    std::string video;                      // render: a movie of the colour frames too
    bool video_only = false;                // render: the movie instead of the images
    bool json = false;                      // validate: the report as JSON
    bool output_given = false;              // validate: -o was given, so its manifest is checked
    std::vector<std::string> command_line;  // as typed, for the manifest
    CompareArgs comparison;                 // render --reference DIR
    ChunkArgs chunk;                        // render: a farm task's part
    TurntableArgs turntable;                // render, validate: when `scene` is a model
};

// Command-line settings become overrides of the scene's values, so they go
// through exactly the checks the scene file's own values go through.
SceneOptions scene_options(const RenderArgs& args);

// The scene and the options that change what is rendered: --size,
// --passes, --formats, --style, -D, the frame options, --camera,
// --variant, -q, --allow-asset-paths-outside.
void add_scene_options(CLI::App* command, RenderArgs& args);

// --camera A,B: the names as given ("all" is one of them, for
// select_cameras); none when the option was not given.
std::vector<std::string> camera_names(const std::string& cameras);

// --variant NAME|all: the scene key `variant:` (an empty value is refused).
void add_variant_option(CLI::App* command, std::string& variant);

// --allow-asset-paths-outside: paths named inside meshes (mtllib, map_Kd,
// glTF URIs) stay inside the mesh's folder unless this is given
// (core/input_file.hpp).
void add_asset_paths_flag(CLI::App* command, bool& allow);

// --strict: for CI users who want any warning to fail the run.
void add_strict_flag(CLI::App* command, bool& strict);

// With --strict, the warnings (already printed) become an error naming how
// many there are and the first (invalid_input, exit 2).
void refuse_warnings(bool strict, const Warnings& warnings);

// What render checks before its first frame, in render's order: the
// outputs (names, the folder's manifest), the world (every mesh and
// texture loaded), the warnings and the memory. render, validate and farm
// all call it, so that they refuse the same inputs. The warnings are the
// scene's, the world's and `extra` (the command's own: a farm task with no
// chunk, a movie of unevenly spaced frames); they are appended to
// `collected` when given (those it holds already, from another variant's
// run, once: and not printed again), printed when `print`, and an error
// with --strict.
struct RenderCheck {
    const RenderArgs& args;
    const SceneDesc& scene;
    const RenderOptions& options;
    LoadedMeshes* model_mesh = nullptr;  // a model's turntable: the mesh its survey read
    Warnings extra;
    bool print = true;
    Warnings* collected = nullptr;
};
// A run checked: its job planned (outputs and manifest claims checked, as
// plan_job does) and its world built; the plan goes on to the render.
struct CheckedRun {
    JobPlan plan;
    World world;
    RenderPlan render_plan;  // of the world, for the memory estimate and the frames
};
CheckedRun check_render_inputs(const RenderCheck& check);

}  // namespace facet
