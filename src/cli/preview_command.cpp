#include "cli/preview_command.hpp"

#include <optional>

#include <CLI/CLI.hpp>

#include "cli/options.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "job/render_job.hpp"
#include "preview/preview.hpp"

namespace facet {

CLI::App* add_preview_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "preview", "Open a window that re-renders the scene whenever it or its files change");
    add_scene_options(cmd, args);
    add_output_option(cmd, args.out, "Output folder for snapshots (files go to OUTPUT/SCENE/)");
    add_threads_option(cmd, args.threads);
    return cmd;
}

int preview_command(const RenderArgs& args) {
    require_display();
    // A scene that does not load opens the window with its error, to be
    // fixed while it is open; a scene file that is not there is a typo.
    require_input_file(args.scene, "scene");
    PreviewOptions options;
    options.scene = args.scene;
    options.scene_options = scene_options(args);
    // Resolved against each loaded scene, as render resolves them.
    const FrameSelection frames = args.frames;
    options.frames = [frames](const OutputDesc& output) { return resolve_frames(frames, output); };
    const std::vector<std::string> cameras = camera_names(args.cameras);
    if (cameras.size() > 1 || args.cameras == "all")
        fail_input(command_line("--camera " + args.cameras), "",
                   "the preview shows one camera at a time (the panel switches): give one name");
    if (args.variant == kAllVariants)
        fail_input(command_line("--variant all"), "",
                   "the preview shows one variant at a time: give one name");
    if (!cameras.empty()) {
        options.camera = cameras.front();
        // A name the scene lacks is refused as render refuses it. A scene
        // that does not load yet is checked by the window, which shows why.
        std::optional<SceneDesc> scene;
        try {
            scene = load_scene(args.scene, options.scene_options);
        } catch (const Error&) {
        }
        if (scene) select_cameras(*scene, cameras);
    }
    options.threads = args.threads;
    options.out_dir = args.out;
    options.quiet = args.quiet;
    options.command_line = args.command_line;
    return run_preview(options);
}

}  // namespace facet
