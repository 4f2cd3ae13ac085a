#pragma once
// What lets several runs share one output folder (render farm nodes, two
// shells) and lets a killed run be resumed: a lock around every change to
// the folder's manifests, and a journal per running process.
#include <mutex>
#include <string>
#include <vector>

#include "output/manifest.hpp"

namespace facet {

// Held while a manifest in `folder` is read, changed and written, so that
// concurrent runs never lose each other's entries. An fcntl lock on the
// hidden file FOLDER/.facet-manifest.lock, which exists only while it is
// held: the kernel drops the lock when the holder dies, even by SIGKILL
// (the file then stays, empty and harmless, until the next holder removes
// it), and NFS carries it between hosts.
class ManifestFolderLock {
  public:
    explicit ManifestFolderLock(const std::string& folder);  // waits; throws io_failure
    ~ManifestFolderLock();
    ManifestFolderLock(const ManifestFolderLock&) = delete;
    ManifestFolderLock& operator=(const ManifestFolderLock&) = delete;

  private:
    std::string path_;
    int fd_ = -1;
};

// A running record of one run: its manifest header on the first line, then
// one line per image as its files are written, each flushed to disk, so a
// rerun knows which files a run killed with SIGKILL had completed. Named
// ".MANIFEST.HOST.PID.journal" beside the manifest it will become, and
// locked for as long as its run lives: a journal that no one holds is a
// dead run's. A finished run folds its journal into its manifest and
// removes it.
class ManifestJournal {
  public:
    ManifestJournal(const std::string& folder, const std::string& manifest_name,
                    const Manifest& header);
    ~ManifestJournal();  // closes (and unlocks); the file stays until remove()
    ManifestJournal(const ManifestJournal&) = delete;
    ManifestJournal& operator=(const ManifestJournal&) = delete;

    // One image: its frame line and files (the header's fields are ignored).
    // Safe to call from several threads: lines are written one at a time.
    void append(const Manifest& image);
    void remove();
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    int fd_ = -1;
    Manifest header_;
    std::mutex append_mutex_;
};

struct JournalFile {
    std::string path;
    std::string manifest_name;  // the manifest it is the journal of
    bool live = false;          // its run still holds it
};

// The journals in `folder` (not following into subfolders).
std::vector<JournalFile> list_journals(const std::string& folder);

// A journal's header with the frames and files of every whole line; a torn
// last line (the run died while writing it) is left out. Throws
// invalid_input when even the header is unreadable.
Manifest read_journal(const std::string& path);

}  // namespace facet
