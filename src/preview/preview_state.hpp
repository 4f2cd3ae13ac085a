#pragma once
// What the preview window shows and the panel edits: one plain record the
// window's parts share (preview_window.cpp, preview_panel.cpp).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "anim/frame_state.hpp"
#include "output/passes.hpp"
#include "preview/preview_worker.hpp"
#include "preview/tweaks.hpp"
#include "preview/view_camera.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// facet preview's command line (cli/preview_command.cpp).
struct PreviewOptions {
    std::string scene;
    SceneOptions scene_options;  // the command line's overrides and the preset folders
    // The frames the slider walks, from the scene as loaded (they follow
    // edits of its frame range); unset: the scene's own. Throws
    // facet::Error for a choice the scene cannot give.
    std::function<std::vector<int>(const OutputDesc&)> frames;
    std::string camera;  // the camera shown first, by name; "": the first
    unsigned threads = 0;
    std::string out_dir = "out";  // where snapshots go, as `facet render -o`
    bool quiet = false;
    std::vector<std::string> command_line;
};

// What the user asked for with a key or a button.
enum class PreviewAction {
    none,
    snapshot,
    print_camera,
    reset_camera,
    print_defines,
    write_style,
    revert_tweaks,
};

struct PreviewState {
    std::shared_ptr<const SceneDesc> scene;  // as last loaded; null before
    std::vector<std::string> presets;        // style preset names, for the panel
    std::vector<int> frames;                 // walked by the slider
    size_t frame_index = 0;
    bool playing = false;
    bool interacting = false;  // a camera drag or a slider held: render small and quick
    size_t camera_index = 0;
    Pass pass = Pass::color;
    std::optional<ViewCamera> view;           // the moved camera; unset: the scene's
    std::optional<CameraState> scene_camera;  // the scene's at the frame shown
    Tweaks tweaks;
    std::string style_file;  // where the panel's "Write style file" writes
    uint64_t files_version = 0;
    bool show_panel = true;
    // Shown in the window.
    std::string error;    // the last load's or render's, over the image
    std::string message;  // the last snapshot's or action's
    std::string step;     // "final, 84 ms"
};

int current_frame(const PreviewState& state);

// The worker's request for what the state shows.
PreviewRequest preview_request(const PreviewState& state);

}  // namespace facet
