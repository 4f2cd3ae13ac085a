#include "preview/preview_worker.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <tuple>

#include "core/display_transform.hpp"
#include "core/elapsed.hpp"
#include "core/error.hpp"
#include "core/plain_text.hpp"
#include "core/thread_pool.hpp"
#include "job/pass_files.hpp"
#include "job/render_job.hpp"
#include "job/render_memory.hpp"
#include "output/encoders.hpp"
#include "render/frame_renderer.hpp"
#include "render/framing_shapes.hpp"
#include "render/render_plan.hpp"
#include "render/world.hpp"

namespace facet {
namespace {

// One step of the progression: the scene's size over `divisor`, and
// `samples` per pixel (0: the scene's own).
struct Step {
    int divisor;
    int samples;
    const char* name;
};

constexpr Step kSteps[] = {{4, 1, "quarter"}, {1, 1, "full"}, {1, 0, "final"}};
constexpr int kMaxLiveDivisor = 8;

std::string overrides_text(const std::vector<Override>& overrides) {
    std::string text;
    for (const Override& o : overrides) text += o.path + "=" + o.value + "\n";
    return text;
}

std::string request_key(const PreviewRequest& r) {
    return overrides_text(r.overrides) + "|" + (r.camera ? r.camera->value : "") + "|" +
           std::to_string(r.frame) + "|" + std::to_string(r.camera_index) + "|" +
           std::string(pass_name(r.pass)) + "|" + (r.live ? "live" : "still") + "|" +
           std::to_string(r.files_version);
}

int resolved_frame(int frame, const SceneDesc& scene) {
    return frame == kSceneFirstFrame ? scene.output.frames.front() : frame;
}

// The pass's PNG view as a user opening the file would see it: the
// samples the file would hold, without compressing and decoding them.
PreviewImage display_image(Pass pass, const OutputDesc& out, const FrameImages& images) {
    const std::optional<PngSamples> view =
        png_view_samples(pass, out, images, out.depth_range.value_or(images.depth_view_range));
    if (!view)
        throw Error(ExitCode::invalid_input,
                    "the " + std::string(pass_name(pass)) + " pass has no image to show");
    const PngSamples& png = *view;
    const auto display_sample = [&png](size_t i) -> int {
        return png.bit_depth == 16 ? narrow_to_byte(png.sample(i)) : png.sample(i);
    };
    PreviewImage image;
    image.width = png.width;
    image.height = png.height;
    image.rgba.resize(static_cast<size_t>(png.width) * png.height * 4);
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const size_t p = static_cast<size_t>(y) * png.width + x;
            const size_t first = p * png.channels;  // the pixel's first sample
            uint8_t* d = &image.rgba[p * 4];
            for (int c = 0; c < 3; ++c)
                d[c] = static_cast<uint8_t>(display_sample(first + (png.channels >= 3 ? c : 0)));
            d[3] = 255;
            if (png.channels == 4) {
                // Straight alpha over a grey checkerboard of 8-pixel squares.
                const int checker = ((x >> 3) + (y >> 3)) & 1 ? 153 : 102;
                const int a = display_sample(first + 3);
                for (int c = 0; c < 3; ++c)
                    d[c] = static_cast<uint8_t>((d[c] * a + checker * (255 - a) + 127) / 255);
            }
        }
    return image;
}

}  // namespace

// What the worker has loaded, and the renderers of each step (they keep
// their buffers and tonal art maps between frames).
struct PreviewWorker::Loaded {
    std::string settings;  // overrides_text of the request the world was built for
    uint64_t files_version = 0;
    std::string camera;  // the camera override's value, "" for the scene's
    std::shared_ptr<const SceneDesc> scene;
    std::shared_ptr<const World> world;
    bool world_has_file_cameras = false;  // the world poses a camera: rebuild it for a moved view
    std::vector<FramingShape> framing;    // what cameras with `frame:` fit
    ThreadPool pool;
    std::map<std::tuple<int, int, Pass>,
             std::pair<std::unique_ptr<SceneDesc>, std::unique_ptr<FrameRenderer>>>
        renderers;
    explicit Loaded(unsigned threads) : pool(threads) {}
};

PreviewWorker::PreviewWorker(std::string scene_path, SceneOptions base, unsigned threads)
    : scene_path_(std::move(scene_path)),
      base_(std::move(base)),
      threads_(threads),
      loaded_(std::make_unique<Loaded>(threads)),
      thread_([this] { run(); }) {}

PreviewWorker::~PreviewWorker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void PreviewWorker::request(const PreviewRequest& request) {
    const std::string key = request_key(request);
    {
        std::lock_guard lock(mutex_);
        // The window asks on every pass of its loop; the same view again
        // changes nothing and wakes nobody.
        if (key == requested_key_) return;
        requested_key_ = key;
        pending_ = request;
        // "The first frame" is asked for before the window knows the scene:
        // it is the view being rendered, not a new one.
        if (running_stoppable_ && request.frame != kSceneFirstFrame && key != running_key_)
            stop_.store(true);
    }
    wake_.notify_all();
}

void PreviewWorker::snapshot(const SnapshotRequest& snapshot) {
    {
        std::lock_guard lock(mutex_);
        snapshots_.push_back(snapshot);
    }
    wake_.notify_all();
}

PreviewUpdate PreviewWorker::take() {
    std::lock_guard lock(mutex_);
    PreviewUpdate out = std::move(outbox_);
    outbox_ = {};
    return out;
}

bool PreviewWorker::quit_requested() const {
    std::lock_guard lock(mutex_);
    return quit_;
}

bool PreviewWorker::busy() const {
    std::lock_guard lock(mutex_);
    return working_ || pending_ || !snapshots_.empty();
}

void PreviewWorker::publish(const std::function<void(PreviewUpdate&)>& change) {
    std::lock_guard lock(mutex_);
    change(outbox_);
}

void PreviewWorker::run() {
    PreviewRequest current;
    std::string current_key;
    bool have = false;
    int step = 0, steps = 0;
    for (;;) {
        std::vector<SnapshotRequest> snapshots;
        {
            std::unique_lock lock(mutex_);
            working_ = false;
            wake_.wait(lock, [&] {
                return quit_ || pending_ || !snapshots_.empty() || (have && step < steps);
            });
            if (quit_ && snapshots_.empty()) return;
            if (pending_ && !quit_) {
                // The window asks for "the first frame" until it knows it.
                if (pending_->frame == kSceneFirstFrame && loaded_->scene)
                    pending_->frame = loaded_->scene->output.frames.front();
                const std::string key = request_key(*pending_);
                if (!have || key != current_key) {
                    current = *pending_;
                    current_key = key;
                    have = true;
                    step = 0;
                    steps = 1;  // known once the scene is loaded
                }
                pending_.reset();
            }
            snapshots.swap(snapshots_);
            working_ = true;
        }
        // A snapshot asked for is written even when the window is closing.
        for (const SnapshotRequest& snapshot : snapshots) write_snapshot(snapshot);
        if (!have || step >= steps || quit_requested()) continue;
        const std::string error = load(current);
        publish([&](PreviewUpdate& u) { u.error = error; });
        if (!error.empty()) {
            steps = 0;
            continue;
        }
        if (current.frame == kSceneFirstFrame) {
            // Known now: a later request naming the frame is the same view.
            current.frame = loaded_->scene->output.frames.front();
            current_key = request_key(current);
        }
        const int samples = loaded_->scene->output.samples;
        steps = current.live ? 1 : samples > 1 ? 3 : 2;
        {
            std::lock_guard lock(mutex_);
            running_key_ = current_key;
            running_stoppable_ = !current.live;
            stop_.store(false);
        }
        bool finished = false;
        try {
            finished = render_step(current, step);
        } catch (const std::exception& e) {
            publish([&](PreviewUpdate& u) { u.error = e.what(); });
            steps = 0;
        }
        {
            std::lock_guard lock(mutex_);
            running_stoppable_ = false;
        }
        if (finished) ++step;  // stopped: the newer request is pending
    }
}

// Loads the scene (and its meshes, unless only the camera moved) for the
// request; "" when it worked, else the error as the user reads it.
std::string PreviewWorker::load(const PreviewRequest& request) {
    Loaded& loaded = *loaded_;
    const std::string settings = overrides_text(request.overrides);
    const std::string camera = request.camera ? request.camera->value : "";
    const bool same_inputs = loaded.world && loaded.settings == settings &&
                             loaded.files_version == request.files_version;
    if (same_inputs && loaded.camera == camera) return "";
    std::optional<WatchList> watch;  // of the scene read, even if its world then fails
    try {
        SceneOptions options = base_;
        options.overrides.insert(options.overrides.end(), request.overrides.begin(),
                                 request.overrides.end());
        if (request.camera) options.overrides.push_back(*request.camera);
        SceneDesc read = load_scene(scene_path_, options);
        watch = scene_watch_list(read);
        // Only the camera moved: the world stays, and the cameras just read
        // go into the scene it was built from. The file may have changed on
        // disk since (a save the watch has not reported yet); the world
        // must stay with the objects it was built for. A camera taken from
        // a glTF file is posed by the world, which is then built again.
        const bool camera_only = same_inputs && !loaded.world_has_file_cameras &&
                                 read.cameras.size() == loaded.scene->cameras.size();
        std::shared_ptr<const SceneDesc> scene;
        std::shared_ptr<const World> world = loaded.world;
        if (camera_only) {
            SceneDesc spliced = *loaded.scene;
            spliced.cameras = std::move(read.cameras);
            scene = std::make_shared<const SceneDesc>(std::move(spliced));
        } else {
            scene = std::make_shared<const SceneDesc>(std::move(read));
            world = std::make_shared<const World>(build_world(*scene, loaded.pool.size()));
        }
        // As render does: a size or sample count the machine cannot hold is
        // an error to show, not a crash.
        check_render_memory(*scene, *world, plan_render(*scene, *world), loaded.pool.size());
        loaded.renderers.clear();
        loaded.scene = scene;
        loaded.world = world;
        loaded.settings = settings;
        loaded.files_version = request.files_version;
        loaded.camera = camera;
        // What `frame:` fits depends on the meshes, not on where the camera
        // is (an animated mesh is posed over every frame for it): made again
        // only with the world, or when a framing camera comes back.
        if (!camera_only || loaded.framing.empty()) loaded.framing = framing_shapes(*scene, *world);
        if (!camera_only)
            loaded.world_has_file_cameras =
                std::any_of(world->file_cameras.begin(), world->file_cameras.end(),
                            [](const FileCamera& c) { return c.rig != nullptr; });
        publish([&](PreviewUpdate& u) {
            u.scene = scene;
            u.watch = scene_watch_list(*scene);
        });
        return "";
    } catch (const std::exception& e) {
        // Editing the file the error is in must reload: it may be a file
        // the last good scene did not name (a new mesh, a style it could
        // not reach), or the first load may have failed.
        WatchList list = watch          ? *watch
                         : loaded.scene ? scene_watch_list(*loaded.scene)
                                        : WatchList{};
        list.files.push_back(scene_path_);
        if (const auto* error = dynamic_cast<const Error*>(&e))
            if (!error->where().file.empty()) list.files.push_back(error->where().file);
        publish([&](PreviewUpdate& u) { u.watch = list; });
        return e.what();
    }
}

bool PreviewWorker::render_step(const PreviewRequest& request, int step) {
    Loaded& loaded = *loaded_;
    const SceneDesc& scene = *loaded.scene;
    Step s = kSteps[step];
    if (request.live) s = {live_divisor_, 1, "live"};
    const int samples = s.samples == 0 ? scene.output.samples : s.samples;
    auto& [level_scene, renderer] = loaded.renderers[{s.divisor, samples, request.pass}];
    if (!renderer) {
        // The same scene at this step's size and samples, making the pass shown.
        level_scene = std::make_unique<SceneDesc>(scene);
        OutputDesc& out = level_scene->output;
        out.width = std::max(1, (scene.output.width + s.divisor - 1) / s.divisor);
        out.height = std::max(1, (scene.output.height + s.divisor - 1) / s.divisor);
        out.samples = samples;
        out.passes.add(request.pass);
        renderer = std::make_unique<FrameRenderer>(*level_scene, *loaded.world, loaded.pool);
    }
    const auto start = std::chrono::steady_clock::now();
    FrameImages images;
    const size_t camera = std::min(request.camera_index, scene.cameras.size() - 1);
    const int frame = resolved_frame(request.frame, scene);
    renderer->render(frame, camera, images,
                     [this] { return stop_.load(std::memory_order_relaxed); });
    if (stop_.load()) return false;
    const double render_ms = ms_since(start);
    PreviewImage image = display_image(request.pass, level_scene->output, images);
    image.frame = frame;
    image.render_ms = render_ms;
    image.camera_moved = request.camera.has_value();
    image.camera = evaluate_frame(scene, loaded.world->object_bounds, frame, camera,
                                  FrameAssets{loaded.framing, loaded.world->file_cameras,
                                              loaded.world->object_lights})
                       .camera;
    image.step = s.name;
    if (request.live) {
        image.step += " 1/" + std::to_string(s.divisor);
        // Keep within the budget: halving the size quarters the pixels, so
        // go up a size only when a quarter of the time would still fit.
        const double budget = request.live_budget_ms;
        if (render_ms > budget && live_divisor_ < kMaxLiveDivisor)
            live_divisor_ *= 2;
        else if (render_ms * 4 < budget * 0.8 && live_divisor_ > 1)
            live_divisor_ /= 2;
    }
    image.last_step = request.live || step == (scene.output.samples > 1 ? 2 : 1);
    publish([&](PreviewUpdate& u) {
        u.steps.push_back({image.step, image.width, image.height, image.frame, image.render_ms});
        u.image = std::move(image);
    });
    return true;
}

void PreviewWorker::write_snapshot(const SnapshotRequest& snapshot) {
    const std::string error = load(snapshot.view);
    if (!error.empty()) {
        publish([&](PreviewUpdate& u) {
            u.messages.push_back({"snapshot not written: " + error, true});
        });
        return;
    }
    const SceneDesc& scene = *loaded_->scene;
    RenderOptions options;
    const int frame = resolved_frame(snapshot.view.frame, scene);
    options.frames = {frame};
    options.cameras = {
        scene.cameras[std::min(snapshot.view.camera_index, scene.cameras.size() - 1)].name};
    options.threads = threads_;
    options.out_dir = snapshot.out_dir;
    // Each snapshot is a run of its own settings (the camera moves between
    // them): it starts a new manifest rather than being refused.
    options.overwrite = true;
    options.provenance.command_line = snapshot.command_line;
    options.provenance.overrides = base_.overrides;
    for (const Override& o : snapshot.view.overrides) options.provenance.overrides.push_back(o);
    if (snapshot.view.camera) options.provenance.overrides.push_back(*snapshot.view.camera);
    std::vector<std::string> files;
    try {
        const RenderResult result = render_scene(
            scene, *loaded_->world, options, [](const FrameProgress&) {},
            [&](const FrameWritten& w) {
                for (const std::string& f : w.files) files.push_back(f);
            });
        const std::string list = comma_list(files);
        publish([&](PreviewUpdate& u) {
            u.messages.push_back({"snapshot of frame " + std::to_string(frame) + ": wrote " + list +
                                  " in " + result.output_dir});
        });
    } catch (const std::exception& e) {
        publish([&](PreviewUpdate& u) {
            u.messages.push_back({std::string("snapshot not written: ") + e.what(), true});
        });
    }
}

}  // namespace facet
