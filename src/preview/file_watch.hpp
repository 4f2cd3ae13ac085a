#pragma once
// Hot reload: which files a scene depends on, and whether one changed.
// Polled (a stat per file a few times a second) rather than inotify: it
// needs nothing from the system, sees network folders, and catches editors
// that save by writing a new file and renaming it over the old one.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace facet {

struct WatchList {
    std::vector<std::string> files;    // each watched whether or not it exists
    std::vector<std::string> folders;  // every visible file in them and two folders below
};

// The scene file, its style files (presets it extends too, and objects'
// own), every mesh file, and each mesh's folder: the textures, material
// libraries and buffers a mesh names sit beside it or below, and are only
// known once loaded.
WatchList scene_watch_list(const SceneDesc& scene);

class FileWatch {
  public:
    // Starts watching `list`, taking its current state as unchanged.
    void watch(WatchList list);

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
    std::vector<Stamp> stamps() const;

    WatchList list_;
    std::vector<Stamp> accepted_;  // as last reported
    std::vector<Stamp> previous_;  // at the previous poll
};

}  // namespace facet
