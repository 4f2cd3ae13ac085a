#include "farm/merge.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/host_name.hpp"
#include "core/plain_text.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct NamedManifest {
    std::string name;
    Manifest manifest;
};

using ImageKey = std::pair<std::string, int>;  // camera, frame

// Frames of one camera as range text, for messages.
std::string frames_text(const std::set<ImageKey>& images, const std::string& camera) {
    std::vector<int> frames;
    for (const auto& [c, f] : images)
        if (c == camera) frames.push_back(f);
    return format_frame_ranges(frames);
}

// "frames 17-24 (camera main)", one clause per camera.
std::string describe_images(const std::set<ImageKey>& images) {
    std::set<std::string> cameras;
    for (const auto& key : images) cameras.insert(key.first);
    std::string text;
    for (const std::string& camera : cameras)
        text += (text.empty() ? "" : "; ") + std::string("frames ") + frames_text(images, camera) +
                " (camera " + camera + ")";
    return text;
}

// Every listed file is on disk with the SHA-256 recorded for it.
void check_files(const std::string& folder, const NamedManifest& m,
                 std::vector<std::string>& problems) {
    for (const ManifestFile& file : m.manifest.files) {
        const std::string problem = listed_file_problem(folder, file);
        if (!problem.empty())
            problems.push_back(file.path + ": " + problem + " (listed in " + m.name + ")");
    }
}

// The job's images that `manifest` does not list.
std::set<ImageKey> missing_images(const ManifestJob& job, const std::set<ImageKey>& listed) {
    std::set<ImageKey> missing;
    for (const std::string& camera : job.cameras)
        for (int frame : job.frames)
            if (!listed.count({camera, frame})) missing.insert({camera, frame});
    return missing;
}

// No partial manifests: manifest.json is checked as merge would check parts.
MergeReport check_manifest(const std::string& folder) {
    MergeReport report;
    report.checked_only = true;
    report.manifest_path = (fs::path(folder) / "manifest.json").string();
    NamedManifest m{"manifest.json", read_manifest(report.manifest_path)};
    check_files(folder, m, report.problems);
    std::set<ImageKey> listed;
    for (const ManifestFrame& f : m.manifest.frames) listed.insert({f.camera, f.frame});
    if (m.manifest.job) {
        const std::set<ImageKey> missing = missing_images(*m.manifest.job, listed);
        if (!missing.empty())
            report.problems.push_back("manifest.json lacks " + describe_images(missing) +
                                      " of its job");
    }
    report.frames = m.manifest.frames.size();
    report.files = m.manifest.files.size();
    return report;
}

std::vector<NamedManifest> read_parts(const std::string& folder, MergeReport& report) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (is_partial_manifest_name(entry.path().filename().string()))
            names.push_back(entry.path().filename().string());
    if (ec) fail_io(folder, "cannot list folder: " + ec.message());
    std::sort(names.begin(), names.end());
    std::vector<NamedManifest> parts;
    for (const std::string& name : names) {
        report.parts.push_back(name);
        // A manifest that is not facet's, or not valid, is an error (exit 2),
        // as in every reader, not a missing piece of the job.
        Manifest m = read_manifest((fs::path(folder) / name).string());
        if (!m.job || !m.part)
            report.problems.push_back(name + ": a partial manifest without its job and part");
        else
            parts.push_back({name, std::move(m)});
    }
    return parts;
}

// Parts of other settings or another job than the first.
void check_same_job(const std::vector<NamedManifest>& parts, MergeReport& report) {
    const NamedManifest& first = parts.front();
    std::set<std::string> builds;
    for (const NamedManifest& part : parts) {
        builds.insert(part.manifest.facet_version + " (commit " + part.manifest.facet_commit + ")");
        const std::string difference = manifest_settings_difference(first.manifest, part.manifest);
        if (!difference.empty())
            report.problems.push_back(part.name + " was rendered with other settings than " +
                                      first.name + " (" + difference + ")");
        else if (part.manifest.job->frames != first.manifest.job->frames ||
                 part.manifest.job->cameras != first.manifest.job->cameras)
            report.problems.push_back(part.name + " belongs to another job than " + first.name +
                                      " (frames " + format_frame_ranges(part.manifest.job->frames) +
                                      " there, " + format_frame_ranges(first.manifest.job->frames) +
                                      " here)");
    }
    if (builds.size() > 1) {
        report.warnings.push_back("the parts were rendered by different facet builds: " +
                                  comma_list(builds));
    }
}

// Each of the job's images listed exactly once, by a part that was asked
// to render it.
void check_coverage(const std::vector<NamedManifest>& parts, MergeReport& report) {
    const ManifestJob& job = *parts.front().manifest.job;
    std::map<ImageKey, std::vector<std::string>> listed_by;
    for (const NamedManifest& part : parts) {
        std::set<ImageKey> listed;
        for (const ManifestFrame& f : part.manifest.frames) {
            listed_by[{f.camera, f.frame}].push_back(part.name);
            listed.insert({f.camera, f.frame});
        }
        // A part that stopped early (interrupted, killed, out of time).
        const ManifestJob asked{part.manifest.part->frames, job.cameras};
        const std::set<ImageKey> unfinished = missing_images(asked, listed);
        if (!unfinished.empty())
            report.problems.push_back(part.name + " is incomplete: it lacks " +
                                      describe_images(unfinished) +
                                      " (rerun its chunk; --skip-existing keeps what is done)");
    }
    std::set<ImageKey> in_job;
    for (const std::string& camera : job.cameras)
        for (int frame : job.frames) in_job.insert({camera, frame});
    std::set<ImageKey> covered;
    for (const NamedManifest& part : parts)
        for (int frame : part.manifest.part->frames)
            for (const std::string& camera : job.cameras) covered.insert({camera, frame});
    std::set<ImageKey> never_asked;
    for (const ImageKey& key : in_job)
        if (!covered.count(key)) never_asked.insert(key);
    if (!never_asked.empty())
        report.problems.push_back("no partial manifest covers " + describe_images(never_asked) +
                                  ": a chunk has not run, or its manifest is missing");
    for (const auto& [key, names] : listed_by) {
        if (!in_job.count(key))
            report.problems.push_back(names.front() + " lists frame " + std::to_string(key.second) +
                                      " (camera " + key.first + "), which is not part of the job");
        if (names.size() > 1) {
            report.problems.push_back("frame " + std::to_string(key.second) + " (camera " +
                                      key.first +
                                      ") is listed more than once: " + comma_list(names));
        }
    }
}

Manifest combined(const std::vector<NamedManifest>& parts, const MergeRequest& request) {
    Manifest merged = parts.front().manifest;
    merged.part.reset();
    merged.frames.clear();
    merged.files.clear();
    merged.command_line = request.command_line;
    merged.host = host_name();
    for (const NamedManifest& part : parts) {
        const Manifest& m = part.manifest;
        merged.frames.insert(merged.frames.end(), m.frames.begin(), m.frames.end());
        merged.files.insert(merged.files.end(), m.files.begin(), m.files.end());
        merged.parts.push_back({part.name, m.host, m.facet_commit, m.threads, m.command_line});
        merged.threads = std::max(merged.threads, m.threads);
    }
    return merged;
}

}  // namespace

MergeReport merge_partial_manifests(const MergeRequest& request) {
    const std::string& folder = request.folder;
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw Error(
            ExitCode::io_failure,
            folder + (fs::exists(folder, ec) ? ": not a folder (give the run's OUT/SCENE folder)"
                                             : ": no such folder"));
    ManifestFolderLock lock(folder);  // no render adds a part while this reads them
    MergeReport report;
    std::vector<NamedManifest> parts = read_parts(folder, report);
    if (report.parts.empty()) {
        if (fs::exists(fs::path(folder) / "manifest.json", ec)) return check_manifest(folder);
        throw Error(ExitCode::invalid_input,
                    folder +
                        " holds neither partial manifests (manifest.part-*.json) nor "
                        "manifest.json: give the folder the render wrote them to, e.g. "
                        "OUT/SCENE");
    }
    if (parts.empty()) return report;
    check_same_job(parts, report);
    check_coverage(parts, report);
    for (const NamedManifest& part : parts) check_files(folder, part, report.problems);
    Manifest merged = combined(parts, request);
    report.frames = merged.frames.size();
    report.files = merged.files.size();
    if (!report.problems.empty()) return report;
    report.manifest_path = (fs::path(folder) / "manifest.json").string();
    write_manifest(report.manifest_path, std::move(merged), true);
    if (!request.keep_parts)
        for (const NamedManifest& part : parts) fs::remove(fs::path(folder) / part.name, ec);
    return report;
}

}  // namespace facet
