#pragma once
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// Writes the bytes to a temporary file beside `path` (".NAME.facet-tmp.HOST.PID"),
// syncs it to disk, renames it over `path` and syncs the folder, so readers
// see the old file or the new one, never half of one, even after a power
// loss. Throws facet::Error (io_failure) naming the path.
void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes);
void write_file_atomically(const std::string& path, const std::string& text);

// Files written atomically together, as write_file_atomically writes one,
// with the waits for the disk taken together: each file's bytes go to its
// temporary at write() and start for the disk, and publish() syncs them
// all, then renames each over its path and syncs each folder once (one
// folder sync per image of a render instead of one per file, and the
// files' syncs after their writeback has begun: docs/performance.md).
// Each pending file holds an open descriptor until publish(). Temporaries
// not published are removed when the set goes.
// The system calls a set makes, in one record so that a test can make any
// of them fail (a full disk, EIO on a sync, a rename refused) and check
// that the set publishes all of its files or none. system_file_calls()
// are the real ones.
struct FileCalls {
    int (*open)(const char* path, int flags, mode_t mode);
    ssize_t (*write)(int fd, const void* bytes, size_t count);
    int (*fsync)(int fd);
    int (*close)(int fd);
    int (*rename)(const char* from, const char* to);
    int (*unlink)(const char* path);
};
const FileCalls& system_file_calls();

class AtomicFileSet {
  public:
    explicit AtomicFileSet(const FileCalls& calls = system_file_calls()) : calls_(calls) {}
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;
    ~AtomicFileSet();

    // Throws facet::Error (io_failure) naming the path. A path written
    // again replaces its earlier bytes.
    void write(const std::string& path, const std::vector<uint8_t>& bytes);
    // After it returns, every file written is on disk under its path.
    // Throws facet::Error (io_failure) naming the path, and the set is then
    // empty: a failed sync publishes nothing; a failed rename leaves the
    // files renamed before it (durably), which published() lists.
    void publish();
    const std::vector<std::string>& published() const { return published_; }

  private:
    void discard();  // closes and removes every temporary not yet published
    void sync_folder(const std::string& folder) const;

    struct Pending {
        std::string path, temp;
        int fd;
    };
    const FileCalls& calls_;
    std::vector<Pending> pending_;
    std::vector<std::string> published_;
};

// Creates the folder and its parents; throws io_failure if that fails.
void make_directories(const std::string& path);

// Removes the temporary files an earlier run on this host left in `folder`
// when it was killed mid-write (their process is gone); returns how many.
// Another live process's temporaries, and other hosts', are left alone.
size_t remove_stale_temporaries(const std::string& folder);

}  // namespace facet
