#pragma once
// The encoder of a render job (job/render_job.cpp): finished frames are
// encoded and written on worker threads of its own while the caller renders
// the next frame. Each frame is encoded by one worker; the files' bytes
// depend only on the frame, so the order workers finish in changes nothing
// but the order of lines gathered for the manifest, which write_manifest
// sorts. The queue's and the workers' counts are here once, for the job and
// its memory estimate (job/render_memory.cpp).
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "job/output_layout.hpp"
#include "job/render_job.hpp"
#include "output/manifest.hpp"
#include "output/run_ledger.hpp"
#include "render/frame_renderer.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// Frames waiting for the encoder; more would only hold memory, since the
// encoder is then the bottleneck anyway.
constexpr size_t kMaxQueuedFrames = 2;

// The encoder's workers for a job on `threads` threads: one, or two at once.
inline unsigned encoder_workers(unsigned threads) {
    return threads > 1 ? 2 : 1;
}

// The frames whose images a job holds at once: the one being rendered, the
// queued ones and those being encoded.
inline uint64_t frames_in_flight(unsigned threads) {
    return 1 + kMaxQueuedFrames + encoder_workers(threads);
}

// One rendered frame for the encoder.
struct EncodeJob {
    int frame;
    std::string camera;
    double render_ms;
    FrameImages images;
};

class FrameEncoder {
  public:
    FrameEncoder(const SceneDesc& scene, const OutputLayout& layout, unsigned workers,
                 RunLedger& ledger, std::string host,
                 std::function<void(const FrameWritten&)> on_written)
        : scene_(scene),
          layout_(layout),
          ledger_(ledger),
          host_(std::move(host)),
          on_written_(std::move(on_written)) {
        for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { run(); });
    }
    ~FrameEncoder() { stop(); }

    // Queues a frame, waiting while kMaxQueuedFrames wait already; throws
    // the first encoding failure.
    void push(EncodeJob job);

    // Buffers of a frame already written, to render the next one into.
    FrameImages take_spare();

    // Waits for all queued frames: the frames written, and the first
    // encoding failure, if any (the frames queued after it are dropped).
    Manifest finish(std::exception_ptr& failure);

  private:
    void stop();
    void run();
    // Creates a folder the first time a file goes into it, and removes what
    // an interrupted earlier run on this host left there half-written.
    void prepare_folder(const std::string& folder) const;
    // Encodes one frame's passes and writes its files; returns their manifest lines.
    Manifest encode(const EncodeJob& job) const;

    const SceneDesc& scene_;
    const OutputLayout& layout_;
    RunLedger& ledger_;  // its journal serialises its own appends
    std::string host_;
    std::function<void(const FrameWritten&)> on_written_;  // called under mutex_
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable ready_, space_;
    std::deque<EncodeJob> queue_;
    std::vector<FrameImages> spare_;
    mutable std::mutex folders_mutex_;
    mutable std::set<std::string> prepared_folders_;
    bool closed_ = false;
    std::exception_ptr failure_;
    Manifest manifest_;  // guarded by mutex_ until the workers have stopped
};

}  // namespace facet
