#include "output/run_ledger.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct FolderManifest {
    std::string name;
    Manifest manifest;
};

// manifest.json and the partial manifests in the folder. One that is not
// facet's, or that facet cannot read, is someone's file that a render
// would replace: an error (exit 2), whatever --overwrite says.
std::vector<FolderManifest> folder_manifests(const std::string& folder) {
    std::vector<FolderManifest> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (name != "manifest.json" && !is_partial_manifest_name(name)) continue;
        try {
            found.push_back({name, read_manifest(entry.path().string())});
        } catch (const Error& e) {
            throw Error(ExitCode::invalid_input,
                        std::string(e.what()) +
                            "; facet does not replace a file it cannot read as its own "
                            "manifest: move it away, or give another -o");
        }
    }
    std::sort(found.begin(), found.end(),
              [](const auto& a, const auto& b) { return a.name < b.name; });
    return found;
}

bool overlap(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> common;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    return !common.empty();
}

// The manifests in the way of this run; each with the reason.
std::vector<std::pair<std::string, std::string>> conflicts(
    const LedgerRequest& request, const std::vector<FolderManifest>& manifests) {
    std::vector<std::pair<std::string, std::string>> found;
    if (request.overwrite) return found;
    for (const FolderManifest& other : manifests) {
        const std::string difference = manifest_settings_difference(other.manifest, request.header);
        if (!difference.empty()) {
            found.push_back(
                {other.name, "was written by a run with other settings (" + difference + ")"});
            continue;
        }
        const auto& part = request.header.part;
        if (part && other.name != request.manifest_name && other.manifest.part &&
            overlap(other.manifest.part->frames, part->frames))
            found.push_back({other.name,
                             "holds some of this part's frames: the job was cut into other "
                             "parts there (remove the partial manifests, or give --overwrite)"});
    }
    return found;
}

void check_live_runs(const LedgerRequest& request, const std::vector<JournalFile>& journals) {
    for (const JournalFile& journal : journals) {
        if (!journal.live) continue;
        Manifest other;
        try {
            other = read_journal(journal.path);
        } catch (const Error&) {
            continue;
        }
        const std::string difference = manifest_settings_difference(other, request.header);
        if (!difference.empty())
            throw Error(ExitCode::invalid_input,
                        request.folder + ": another facet run (" + other.host +
                            ") is writing there with other settings (" + difference +
                            "); wait for it, or give another -o");
    }
}

void check_claims(const LedgerRequest& request, const std::vector<FolderManifest>& manifests,
                  const std::vector<JournalFile>& journals) {
    check_live_runs(request, journals);
    const auto found = conflicts(request, manifests);
    if (found.empty()) return;
    const std::string path = (fs::path(request.folder) / found.front().first).string();
    std::string hint = "give --overwrite to start a new manifest there, or another -o";
    throw Error(ExitCode::invalid_input, path + " " + found.front().second + "; " + hint);
}

}  // namespace

void check_manifest_claims(const LedgerRequest& request) {
    check_claims(request, folder_manifests(request.folder), list_journals(request.folder));
}

RunLedger::RunLedger(LedgerRequest request) : request_(std::move(request)) {
    ManifestFolderLock lock(request_.folder);
    // Read once, under the lock: checked, then the records to skip by.
    const std::vector<FolderManifest> manifests = folder_manifests(request_.folder);
    const std::vector<JournalFile> journals = list_journals(request_.folder);
    check_claims(request_, manifests, journals);
    std::vector<Manifest> sources;
    for (const FolderManifest& m : manifests) {
        const bool same = manifest_settings_difference(m.manifest, request_.header).empty();
        // --overwrite: a partial manifest of other settings, or of another
        // cut of the job, describes files this run replaces.
        if (request_.overwrite && is_partial_manifest_name(m.name) &&
            m.name != request_.manifest_name) {
            const bool other_cut = request_.header.part && m.manifest.part &&
                                   m.manifest.part->frames != request_.header.part->frames;
            if (!same || other_cut) {
                std::error_code ignored;
                fs::remove(fs::path(request_.folder) / m.name, ignored);
                continue;
            }
        }
        if (same) sources.push_back(m.manifest);
    }
    for (const JournalFile& journal : journals) {
        try {
            Manifest recorded = read_journal(journal.path);
            if (manifest_settings_difference(recorded, request_.header).empty())
                sources.push_back(std::move(recorded));
        } catch (const Error&) {
        }
    }
    for (const Manifest& source : sources) {
        for (const ManifestFrame& f : source.frames) recorded_[{f.camera, f.frame}].frame = f;
        for (const ManifestFile& f : source.files) {
            auto& files = recorded_[{f.camera, f.frame}].files;
            auto same_path = [&](const ManifestFile& g) { return g.path == f.path; };
            files.erase(std::remove_if(files.begin(), files.end(), same_path), files.end());
            files.push_back(f);
        }
    }
    journal_ =
        std::make_unique<ManifestJournal>(request_.folder, request_.manifest_name, request_.header);
}

std::optional<RecordedImage> RunLedger::verified(int frame, const std::string& camera,
                                                 const std::vector<std::string>& paths) const {
    const auto it = recorded_.find({camera, frame});
    if (it == recorded_.end()) return std::nullopt;
    RecordedImage image;
    image.frame = it->second.frame;
    image.frame.frame = frame;
    image.frame.camera = camera;
    for (const std::string& path : paths) {
        const auto file = std::find_if(it->second.files.begin(), it->second.files.end(),
                                       [&](const ManifestFile& f) { return f.path == path; });
        // Missing, changed or unreadable: rendered again.
        if (file == it->second.files.end() || !listed_file_problem(request_.folder, *file).empty())
            return std::nullopt;
        image.files.push_back(*file);
    }
    return image;
}

std::string RunLedger::finish(Manifest manifest) {
    ManifestFolderLock lock(request_.folder);
    const std::string path = (fs::path(request_.folder) / request_.manifest_name).string();
    write_manifest(path, std::move(manifest), !request_.overwrite);
    journal_->remove();
    for (const JournalFile& journal : list_journals(request_.folder))
        if (!journal.live && journal.manifest_name == request_.manifest_name) {
            std::error_code ignored;
            fs::remove(journal.path, ignored);
        }
    return path;
}

}  // namespace facet
