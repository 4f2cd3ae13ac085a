#pragma once
// The preview's rendering thread. The window hands it the view it wants
// (request) and takes back images as they come (take); it never waits for
// a render. The worker loads the scene through load_scene with the
// preview's overrides and renders with the frame renderer `facet render`
// uses, in steps (docs/preview.md): a quarter-size image, then full size,
// then the scene's anti-aliased samples, starting again whenever a newer
// request arrives between steps.
#include <atomic>
#include <climits>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "anim/frame_state.hpp"
#include "output/passes.hpp"
#include "preview/file_watch.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// PreviewRequest::frame before the scene is loaded: its first frame.
inline constexpr int kSceneFirstFrame = INT_MIN;

struct PreviewRequest {
    // The scene's settings: the command line's overrides, then the
    // preview's tweaks. A change reloads the scene and its meshes.
    std::vector<Override> overrides;
    // The moved view camera (preview/view_camera.hpp); a change reloads the
    // scene file only.
    std::optional<Override> camera;
    int frame = 0;
    size_t camera_index = 0;
    Pass pass = Pass::color;  // shown; any pass, whatever the scene writes
    // Live (playing, or a camera or slider being dragged): one step only,
    // at the size that renders within `live_budget_ms`.
    bool live = false;
    double live_budget_ms = 1000.0 / 24;
    uint64_t files_version = 0;  // bumped when a watched file changes: reload
};

// One step's image, ready to show.
struct PreviewImage {
    int width = 0, height = 0;  // of `rgba`; the window scales it to the scene's size
    // 8-bit RGBA: the pixels the pass's PNG file would hold (alpha laid
    // over a checkerboard, depth's 16 bits cut to 8).
    std::vector<uint8_t> rgba;
    int frame = 0;
    std::string step;  // "quarter", "full", "final", or "live 1/2" ...
    double render_ms = 0;
    bool last_step = false;     // nothing more is coming for this request
    CameraState camera;         // the camera it was rendered with
    bool camera_moved = false;  // with the view camera, not the scene's
};

// Writes the view's frame as `facet render` writes it (render_scene).
struct SnapshotRequest {
    PreviewRequest view;
    std::string out_dir;
    std::vector<std::string> command_line;  // for the manifest
};

// A step rendered: what the image was (the window shows only the newest).
struct PreviewStep {
    std::string step;
    int width = 0, height = 0, frame = 0;
    double render_ms = 0;
};

// A snapshot's outcome, for the status line and standard error.
struct PreviewMessage {
    std::string text;
    bool failed = false;  // printed even with -q
};

// What came in since the last take().
struct PreviewUpdate {
    std::optional<PreviewImage> image;  // the newest
    std::vector<PreviewStep> steps;     // every step rendered, in order
    // After each successful load: the scene as loaded, and what to watch.
    std::shared_ptr<const SceneDesc> scene;
    std::optional<WatchList> watch;
    // After a load or render: the error, or "" when the last one worked.
    std::optional<std::string> error;
    std::vector<PreviewMessage> messages;  // snapshots written or failed
};

class PreviewWorker {
  public:
    PreviewWorker(std::string scene_path, SceneOptions base, unsigned threads);
    ~PreviewWorker();  // after the step in progress and the snapshots asked for
    PreviewWorker(const PreviewWorker&) = delete;
    PreviewWorker& operator=(const PreviewWorker&) = delete;

    // Replaces any request not yet started; a request equal to the current
    // one changes nothing.
    void request(const PreviewRequest& request);
    void snapshot(const SnapshotRequest& snapshot);
    PreviewUpdate take();
    // Rendering or loading, or something queued.
    bool busy() const;

  private:
    struct Loaded;
    void run();
    std::string load(const PreviewRequest& request);
    bool render_step(const PreviewRequest& request, int step);  // false: stopped
    void write_snapshot(const SnapshotRequest& snapshot);
    void publish(const std::function<void(PreviewUpdate&)>& change);
    bool quit_requested() const;

    const std::string scene_path_;
    const SceneOptions base_;
    const unsigned threads_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<PreviewRequest> pending_;
    std::string requested_key_;  // of the last request taken in
    std::vector<SnapshotRequest> snapshots_;
    bool working_ = false;
    bool quit_ = false;
    // The request the step in progress renders, and whether a newer one
    // stops it: a still view's steps do, so the window answers at once; a
    // live step is short and finishes, or a drag would never show one.
    std::string running_key_;
    bool running_stoppable_ = false;
    std::atomic<bool> stop_{false};
    PreviewUpdate outbox_;

    // The worker thread's own.
    std::unique_ptr<Loaded> loaded_;
    int live_divisor_ = 2;  // live: the image is the scene's size over this

    std::thread thread_;  // last: starts once everything above exists
};

}  // namespace facet
