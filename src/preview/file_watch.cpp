#include "preview/file_watch.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

namespace facet {
namespace {

namespace fs = std::filesystem;

// Textures usually sit in a folder or two below their mesh; a mesh in a
// huge folder tree costs a bounded number of stats per poll.
constexpr int kMaxFolderDepth = 2;
constexpr size_t kMaxFolderEntries = 4000;

void add_unique(std::vector<std::string>& list, const std::string& item) {
    if (!item.empty() && std::find(list.begin(), list.end(), item) == list.end())
        list.push_back(item);
}

// Editors' swap and backup files (".scene.yaml.swp", "scene.yaml~") and
// facet's own temporaries change while nothing the scene reads does.
bool ignored_name(const std::string& name) {
    return name.empty() || name.front() == '.' || name.back() == '~' || name.ends_with(".swp") ||
           name.ends_with(".tmp");
}

}  // namespace

WatchList scene_watch_list(const SceneDesc& scene) {
    WatchList list;
    add_unique(list.files, scene.path);
    for (const std::string& file : scene.style.files) add_unique(list.files, file);
    for (const ObjectDesc& object : scene.objects) {
        if (object.style)
            for (const std::string& file : object.style->files) add_unique(list.files, file);
        for (const std::string& map : object.material.map_paths()) add_unique(list.files, map);
        if (object.mesh.empty()) continue;
        add_unique(list.files, object.mesh);
        const std::string folder = fs::path(object.mesh).parent_path().string();
        add_unique(list.folders, folder.empty() ? "." : folder);
    }
    for (const CameraDesc& camera : scene.cameras) add_unique(list.files, camera.from);
    return list;
}

FileWatch::FileWatch(std::vector<std::string> skipped_folders) {
    for (const std::string& folder : skipped_folders) {
        std::error_code ec;
        skipped_.push_back(fs::weakly_canonical(folder, ec).string());
    }
}

void FileWatch::watch(const WatchList& list) {
    if (list == list_ && !previous_.empty()) return;
    list_ = list;
    std::vector<Stamp> now = stamps();
    std::vector<Stamp> accepted = now;
    for (Stamp& stamp : accepted) {
        auto known =
            std::lower_bound(accepted_.begin(), accepted_.end(), stamp.path,
                             [](const Stamp& s, const std::string& path) { return s.path < path; });
        if (known != accepted_.end() && known->path == stamp.path) stamp = *known;
    }
    accepted_ = std::move(accepted);
    previous_ = std::move(now);
}

bool FileWatch::poll() {
    std::vector<Stamp> now = stamps();
    const bool settled = now == previous_;
    previous_ = now;
    if (!settled || now == accepted_) return false;
    accepted_ = std::move(now);
    return true;
}

bool FileWatch::skipped(const fs::path& folder) const {
    if (skipped_.empty()) return false;
    std::error_code ec;
    const std::string path = fs::weakly_canonical(folder, ec).string();
    return std::find(skipped_.begin(), skipped_.end(), path) != skipped_.end();
}

std::vector<FileWatch::Stamp> FileWatch::stamps() const {
    std::vector<std::string> paths = list_.files;
    for (const std::string& folder : list_.folders) {
        std::error_code ec;
        size_t seen = 0;
        for (auto it = fs::recursive_directory_iterator(folder, ec);
             !ec && it != fs::recursive_directory_iterator() && ++seen <= kMaxFolderEntries;
             it.increment(ec)) {
            const bool hidden = ignored_name(it->path().filename().string());
            std::error_code type_error;
            if (it->is_directory(type_error)) {
                if (hidden || it.depth() + 1 > kMaxFolderDepth || skipped(it->path()))
                    it.disable_recursion_pending();
            } else if (!hidden && it->is_regular_file(type_error)) {
                paths.push_back(it->path().string());
            }
        }
    }
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    std::vector<Stamp> out;
    out.reserve(paths.size());
    for (const std::string& path : paths) {
        Stamp stamp{path};
        struct stat info {};
        if (::stat(path.c_str(), &info) == 0) {
            stamp.exists = true;
            stamp.modified_ns =
                static_cast<int64_t>(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec;
            stamp.size = static_cast<uint64_t>(info.st_size);
            stamp.inode = static_cast<uint64_t>(info.st_ino);
        }
        out.push_back(std::move(stamp));
    }
    return out;
}

}  // namespace facet
