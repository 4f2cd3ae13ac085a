#include "job/frame_encoder.hpp"

#include <chrono>
#include <filesystem>

#include "core/elapsed.hpp"
#include "core/sha256.hpp"
#include "job/file_metadata.hpp"
#include "job/pass_files.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"

namespace facet {
void FrameEncoder::push(EncodeJob job) {
    std::unique_lock lock(mutex_);
    space_.wait(lock, [&] { return queue_.size() < kMaxQueuedFrames || failure_; });
    if (failure_) std::rethrow_exception(failure_);
    queue_.push_back(std::move(job));
    ready_.notify_one();
}

FrameImages FrameEncoder::take_spare() {
    std::lock_guard lock(mutex_);
    if (spare_.empty()) return {};
    FrameImages images = std::move(spare_.back());
    spare_.pop_back();
    return images;
}

Manifest FrameEncoder::finish(std::exception_ptr& failure) {
    stop();
    if (!failure) failure = failure_;
    return manifest_;
}

void FrameEncoder::stop() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    ready_.notify_all();
    for (auto& worker : workers_)
        if (worker.joinable()) worker.join();
}

void FrameEncoder::run() {
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
            // The files are on disk: a rerun may trust them. Outside the
            // queue's lock, so the journal's disk sync holds up neither
            // the render thread nor the other encoder.
            ledger_.record(written);
            std::lock_guard lock(mutex_);
            if (on_written_) {
                FrameWritten report{
                    job.frame, job.camera, job.render_ms, written.frames.front().encode_ms, {}};
                for (const ManifestFile& f : written.files) report.files.push_back(f.path);
                on_written_(report);
            }
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

// Creates a folder the first time a file goes into it, and removes what
// an interrupted earlier run on this host left there half-written.
// Under the lock throughout: a second worker must not find the folder
// marked as prepared before it exists (it would write into nothing).
void FrameEncoder::prepare_folder(const std::string& folder) const {
    std::lock_guard lock(folders_mutex_);
    if (prepared_folders_.count(folder)) return;
    make_directories(folder);
    remove_stale_temporaries(folder);
    prepared_folders_.insert(folder);
}

// Encodes one frame's passes and writes its files; returns their manifest lines.
Manifest FrameEncoder::encode(const EncodeJob& job) const {
    const auto start = std::chrono::steady_clock::now();
    const OutputDesc& out = scene_.output;
    Manifest written;
    // The image's files, published together once all are written: their
    // syncs taken together and one folder sync (output/atomic_file.hpp).
    AtomicFileSet files;
    auto write = [&](const std::string& pass, const std::string& format,
                     const std::vector<uint8_t>& bytes) {
        const std::string name =
            expand(layout_.names, file_fields(scene_, job.camera, pass, job.frame, format));
        const std::filesystem::path file = std::filesystem::path(layout_.root) / name;
        prepare_folder(file.parent_path().string());
        files.write(file.string(), bytes);
        written.files.push_back({job.frame, job.camera, pass, format,
                                 path_relative_to_manifest(name, layout_.manifest_dir),
                                 sha256_hex(bytes), scene_.style.name});
    };
    const FileFacts facts{scene_.name,       job.camera,      job.frame,
                          scene_.style.name, job.images.view, job.images.projection};
    const PassFileFacts file_facts{out.depth_range.value_or(job.images.depth_view_range),
                                   png_metadata(facts), exr_metadata(facts)};
    try {
        encode_frame_files(out, layout_.frame_files, job.images, file_facts,
                           [&](const PassFile& file, const std::vector<uint8_t>& bytes) {
                               write(file.pass, file.format, bytes);
                           });
        files.publish();
    } catch (...) {
        // No file of an unfinished image stays (a full disk, say): a
        // rerun with --skip-existing renders the whole image again.
        // Those not yet published go with `files`.
        std::error_code ignored;
        for (const std::string& file : files.published()) std::filesystem::remove(file, ignored);
        throw;
    }
    written.frames.push_back({job.frame, job.camera, job.render_ms, ms_since(start), host_});
    return written;
}

}  // namespace facet
