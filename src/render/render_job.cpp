#include "render/render_job.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/error.hpp"
#include "core/sha256.hpp"
#include "core/thread_pool.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "output/manifest.hpp"
#include "render/frame_renderer.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Frames waiting for the encoder; more would only hold memory, since the
// encoder is then the bottleneck anyway.
constexpr size_t kMaxQueuedFrames = 2;

std::string frame_file_name(const std::string& pass, int frame, const std::string& ext) {
    char number[32];
    std::snprintf(number, sizeof number, "%04d", frame);
    return pass + "." + number + "." + ext;
}

struct EncodeJob {
    int frame;
    double render_ms;
    FrameImages images;
};

// Encodes and writes finished frames on worker threads of its own, while the
// caller renders the next frame. Each frame is encoded by one worker; the
// files' bytes depend only on the frame, so the order workers finish in
// changes nothing but the order of lines gathered for the manifest, which
// write_manifest sorts.
class Encoder {
  public:
    Encoder(const SceneDesc& scene, std::string dir, unsigned workers)
        : scene_(scene), dir_(std::move(dir)) {
        for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { run(); });
    }
    ~Encoder() { stop(); }

    void push(EncodeJob job) {
        std::unique_lock lock(mutex_);
        space_.wait(lock, [&] { return queue_.size() < kMaxQueuedFrames || failure_; });
        if (failure_) std::rethrow_exception(failure_);
        queue_.push_back(std::move(job));
        ready_.notify_one();
    }

    // Buffers of a frame already written, to render the next one into.
    FrameImages take_spare() {
        std::lock_guard lock(mutex_);
        if (spare_.empty()) return {};
        FrameImages images = std::move(spare_.back());
        spare_.pop_back();
        return images;
    }

    // Waits for all queued frames; rethrows the first encoding failure.
    Manifest finish() {
        stop();
        if (failure_) std::rethrow_exception(failure_);
        return manifest_;
    }

  private:
    void stop() {
        {
            std::lock_guard lock(mutex_);
            closed_ = true;
        }
        ready_.notify_all();
        for (auto& worker : workers_)
            if (worker.joinable()) worker.join();
    }

    void run() {
        for (;;) {
            EncodeJob job;
            {
                std::unique_lock lock(mutex_);
                ready_.wait(lock, [&] { return !queue_.empty() || closed_ || failure_; });
                if (queue_.empty() || failure_) return;
                job = std::move(queue_.front());
                queue_.pop_front();
            }
            try {
                Manifest written = encode(job);
                std::lock_guard lock(mutex_);
                manifest_.frames.insert(manifest_.frames.end(), written.frames.begin(),
                                        written.frames.end());
                manifest_.files.insert(manifest_.files.end(), written.files.begin(),
                                       written.files.end());
                spare_.push_back(std::move(job.images));
                space_.notify_one();
            } catch (...) {
                std::lock_guard lock(mutex_);
                if (!failure_) failure_ = std::current_exception();
                queue_.clear();
                space_.notify_all();
                ready_.notify_all();
                return;
            }
        }
    }

    // Encodes one frame's passes and writes its files; returns their manifest lines.
    Manifest encode(const EncodeJob& job) const {
        const auto start = Clock::now();
        const OutputDesc& out = scene_.output;
        Manifest written;
        auto write = [&](const std::string& pass, const std::string& format,
                         const std::vector<uint8_t>& bytes) {
            std::string name = frame_file_name(pass, job.frame, format);
            write_file_atomically((std::filesystem::path(dir_) / name).string(), bytes);
            written.files.push_back({job.frame, pass, format, name, sha256_hex(bytes)});
        };
        if (out.write_color && out.write_png)
            write("color", "png", encode_png_color(job.images.color, out.png_compression));
        if (out.write_color && out.write_exr)
            write("color", "exr", encode_exr_color(job.images.color));
        if (out.write_depth && out.write_png) {
            glm::vec2 range = out.depth_range.value_or(job.images.depth_view_range);
            write("depth", "png", encode_png_depth(job.images.depth, range, out.png_compression));
        }
        if (out.write_depth && out.write_exr)
            write("depth", "exr", encode_exr_depth(job.images.depth));
        written.frames.push_back({job.frame, job.render_ms, ms_since(start)});
        return written;
    }

    const SceneDesc& scene_;
    std::string dir_;
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable ready_, space_;
    std::deque<EncodeJob> queue_;
    std::vector<FrameImages> spare_;
    bool closed_ = false;
    std::exception_ptr failure_;
    Manifest manifest_;  // guarded by mutex_ until the workers have stopped
};

}  // namespace

RenderResult render_scene(const SceneDesc& scene, const World& world, const RenderOptions& options,
                          const std::function<void(const FrameProgress&)>& on_frame) {
    const std::vector<int>& frames = options.frames.empty() ? scene.output.frames : options.frames;
    RenderResult result;
    result.output_dir = (std::filesystem::path(options.out_dir) / scene.name).string();
    make_directories(result.output_dir);

    ThreadPool pool(options.threads);
    FrameRenderer renderer(scene, world, pool);
    // Encoding a 1080p frame can take longer than rendering it, so with
    // more than one thread two frames are encoded at once.
    Encoder encoder(scene, result.output_dir, pool.size() > 1 ? 2 : 1);
    size_t rendered = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        if (options.cancel && options.cancel->load()) break;
        const auto start = Clock::now();
        FrameImages images = encoder.take_spare();
        renderer.render(frames[i], images);
        const double render_ms = ms_since(start);
        encoder.push({frames[i], render_ms, std::move(images)});
        if (on_frame) on_frame({frames[i], i + 1, frames.size(), render_ms});
        rendered = i + 1;
    }
    Manifest manifest = encoder.finish();
    manifest.scene = scene.path;
    manifest.style = scene.style.name;
    manifest.width = scene.output.width;
    manifest.height = scene.output.height;
    manifest.threads = static_cast<int>(pool.size());
    result.files_written = manifest.files.size();
    result.manifest_path = (std::filesystem::path(result.output_dir) / "manifest.json").string();
    write_manifest(result.manifest_path, manifest);
    if (rendered < frames.size())
        throw Error(ExitCode::runtime_failure, "interrupted: " + std::to_string(rendered) + " of " +
                                                   std::to_string(frames.size()) +
                                                   " frames were written, and are listed in " +
                                                   result.manifest_path);
    return result;
}

}  // namespace facet
