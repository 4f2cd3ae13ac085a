#pragma once
// Hot reload: which files a scene depends on, and whether one changed.
// Polled (a stat per file a few times a second) rather than inotify: it
// needs nothing from the system, sees network folders, and catches editors
// that save by writing a new file and renaming it over the old one.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace facet {

struct WatchList {
    std::vector<std::string> files;    // each watched whether or not it exists
    std::vector<std::string> folders;  // every visible file in them and two folders below
    friend bool operator==(const WatchList&, const WatchList&) = default;
};

// The scene file, its style files (presets it extends too, and objects'
// own), materials' textures, every mesh file, and each mesh's folder: the
// textures, material libraries and buffers a mesh names sit beside it or
// below, and are only known once loaded.
WatchList scene_watch_list(const SceneDesc& scene);

class FileWatch {
  public:
    // `skipped_folders` are never looked into (where snapshots are written:
    // writing one must not reload the scene).
    explicit FileWatch(std::vector<std::string> skipped_folders = {});

    // Watches `list` from now on. Files watched before keep the state last
    // reported, so a change made while the list was being worked out (a
    // save during a load) is still reported; new files start unchanged.
    void watch(const WatchList& list);

    // True once per change, when a watched file was created, removed,
    // written or replaced, and has then stayed the same for one more poll
    // (so a file caught half written is read again once whole).
    bool poll();

  private:
    struct Stamp {
        std::string path;
        bool exists = false;
        int64_t modified_ns = 0;
        uint64_t size = 0, inode = 0;
        friend bool operator==(const Stamp&, const Stamp&) = default;
    };
    std::vector<Stamp> stamps() const;  // sorted by path
    bool skipped(const std::filesystem::path& folder) const;

    std::vector<std::string> skipped_;  // canonical paths
    WatchList list_;
    std::vector<Stamp> accepted_;  // as last reported
    std::vector<Stamp> previous_;  // at the previous poll
};

}  // namespace facet
