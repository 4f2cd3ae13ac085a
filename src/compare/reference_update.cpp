#include "compare/reference_update.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/sha256.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

bool named_by(UpdateMode mode, const FileResult& r) {
    switch (mode) {
        case UpdateMode::failed:
            return (r.status == FileStatus::compared && r.outcome == Outcome::fail) ||
                   r.status == FileStatus::size_mismatch;
        case UpdateMode::missing:
            return r.status == FileStatus::extra;
        // A NEW file that cannot be decoded never becomes a reference.
        case UpdateMode::all:
            return !r.new_path.empty() && r.status != FileStatus::identical &&
                   r.status != FileStatus::unreadable;
    }
    return false;
}

std::string manifest_path(const std::string& dir) {
    return (fs::path(dir) / "manifest.json").string();
}

}  // namespace

void prepare_reference_folder(const std::string& ref_dir, const std::string& new_dir) {
    std::error_code ec;
    if (fs::is_regular_file(manifest_path(ref_dir), ec)) return;
    Manifest header = read_manifest(manifest_path(new_dir));
    header.frames.clear();
    header.files.clear();
    make_directories(ref_dir);
    write_manifest(manifest_path(ref_dir), header);
}

UpdateResult update_reference(const CompareReport& report, const std::string& ref_dir,
                              const std::string& new_dir, UpdateMode mode) {
    UpdateResult result;
    const Manifest produced = read_manifest(manifest_path(new_dir));
    Manifest reference = read_manifest(manifest_path(ref_dir));
    using Key = std::tuple<std::string, std::string, int, std::string>;
    std::map<Key, const ManifestFile*> produced_files;
    for (const ManifestFile& f : produced.files)
        produced_files[{f.camera, f.pass, f.frame, f.format}] = &f;
    std::set<std::pair<std::string, int>> known_frames;
    for (const ManifestFrame& f : reference.frames) known_frames.insert({f.camera, f.frame});

    // Each file is written atomically; if one fails, the manifest is still
    // written for those already copied, so it always states what is on disk.
    std::exception_ptr failure;
    for (const FileResult& r : report.files) {
        if (!named_by(mode, r)) {
            if (r.outcome == Outcome::fail && r.status != FileStatus::missing)
                ++result.unresolved_failures;
            continue;
        }
        const Key key{r.key.camera, r.key.pass, r.key.frame, r.key.format};
        const auto found = produced_files.find(key);
        if (found == produced_files.end()) continue;
        ManifestFile entry = *found->second;
        try {
            // The bytes are hashed as copied, so the manifest states what is on disk.
            const std::vector<uint8_t> bytes = read_input_file(r.new_path, "new image");
            const fs::path target = fs::path(ref_dir) / entry.path;
            make_directories(target.parent_path().string());
            write_file_atomically(target.string(), bytes);
            entry.sha256 = sha256_hex(bytes);
        } catch (...) {
            failure = std::current_exception();
            break;
        }
        bool replaced = false;
        for (ManifestFile& old : reference.files)
            if (std::tie(old.camera, old.pass, old.frame, old.format) ==
                std::tie(entry.camera, entry.pass, entry.frame, entry.format)) {
                std::error_code ignored;  // a stale file left behind is harmless
                if (old.path != entry.path) fs::remove(fs::path(ref_dir) / old.path, ignored);
                old = entry;
                replaced = true;
            }
        if (!replaced) reference.files.push_back(entry);
        if (known_frames.insert({entry.camera, entry.frame}).second)
            for (const ManifestFrame& f : produced.frames)
                if (f.camera == entry.camera && f.frame == entry.frame)
                    reference.frames.push_back(f);
        result.written.push_back(r.key.label());
    }
    // "missing" in the report is a file the reference has and NEW lacks:
    // no mode deletes a reference, so it stays a failure.
    for (const FileResult& r : report.files)
        if (r.status == FileStatus::missing) ++result.unresolved_failures;
    // Rewritten files now come from NEW's settings: the header says so.
    if (mode != UpdateMode::missing && !result.written.empty()) {
        Manifest header = produced;
        header.frames = std::move(reference.frames);
        header.files = std::move(reference.files);
        reference = std::move(header);
    }
    write_manifest(manifest_path(ref_dir), reference, false);
    if (failure) std::rethrow_exception(failure);
    return result;
}

}  // namespace facet
