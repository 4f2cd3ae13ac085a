#include "output/manifest_journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/host_name.hpp"
#include "output/atomic_file.hpp"

namespace facet {
namespace {

constexpr const char* kJournalSuffix = ".journal";

// Open-file-description locks (Linux): owned by the open file, not the
// process, so a second open of the same file in this process (a reader)
// neither sees its own lock as free nor releases it on close, as classic
// POSIX record locks would.
struct flock whole_file(short type) {
    struct flock lock {};
    lock.l_type = type;
    lock.l_whence = SEEK_SET;
    lock.l_start = 0;
    lock.l_len = 0;
    lock.l_pid = 0;
    return lock;
}

bool held_by_someone(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    struct flock probe = whole_file(F_WRLCK);
    const bool held = ::fcntl(fd, F_OFD_GETLK, &probe) == 0 && probe.l_type != F_UNLCK;
    ::close(fd);
    return held;
}

void write_all(int fd, const std::string& text, const std::string& path) {
    size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail_io(path, std::string("cannot write journal: ") + std::strerror(errno));
        written += static_cast<size_t>(n);
    }
}

}  // namespace

ManifestFolderLock::ManifestFolderLock(const std::string& folder)
    : path_((std::filesystem::path(folder) / ".facet-manifest.lock").string()) {
    // The file exists only while someone holds it, so folders are not left
    // with it. A run that opened it just before the holder removed it would
    // lock a file no longer in the folder: it checks, after locking, that
    // the name still leads to the file it locked, and tries again if not.
    for (;;) {
        fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd_ < 0) fail_io(path_, std::string("cannot open lock file: ") + std::strerror(errno));
        struct flock lock = whole_file(F_WRLCK);
        int locked;
        while ((locked = ::fcntl(fd_, F_OFD_SETLKW, &lock)) != 0 && errno == EINTR) {
        }
        if (locked != 0) {
            const int err = errno;
            ::close(fd_);
            fail_io(path_, std::string("cannot lock: ") + std::strerror(err));
        }
        struct stat held {
        }, named{};
        if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &named) == 0 &&
            held.st_dev == named.st_dev && held.st_ino == named.st_ino)
            return;
        ::close(fd_);
    }
}

ManifestFolderLock::~ManifestFolderLock() {
    // Removed while still held: whoever waits on this file finds it gone
    // from the folder and starts over on a new one.
    ::unlink(path_.c_str());
    ::close(fd_);
}

ManifestJournal::ManifestJournal(const std::string& folder, const std::string& manifest_name,
                                 const Manifest& header)
    : header_(header) {
    header_.frames.clear();
    header_.files.clear();
    path_ = (std::filesystem::path(folder) / ("." + manifest_name + "." + host_name() + "." +
                                              std::to_string(::getpid()) + kJournalSuffix))
                .string();
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (fd_ < 0) fail_io(path_, std::string("cannot create journal: ") + std::strerror(errno));
    struct flock lock = whole_file(F_WRLCK);
    if (::fcntl(fd_, F_OFD_SETLK, &lock) != 0) {
        const int err = errno;
        ::close(fd_);
        fail_io(path_, std::string("cannot lock journal: ") + std::strerror(err));
    }
    write_all(fd_, manifest_json(header_, false), path_);
}

ManifestJournal::~ManifestJournal() {
    if (fd_ >= 0) ::close(fd_);
}

void ManifestJournal::append(const Manifest& image) {
    Manifest line = header_;
    line.frames = image.frames;
    line.files = image.files;
    const std::string text = manifest_json(line, false);
    std::lock_guard lock(append_mutex_);
    // One write of one whole line: a reader sees it whole or torn at the
    // end, never interleaved (this process is the journal's only writer).
    write_all(fd_, text, path_);
    ::fdatasync(fd_);
}

void ManifestJournal::remove() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
}

std::vector<JournalFile> list_journals(const std::string& folder) {
    std::vector<JournalFile> journals;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        const std::string suffix = kJournalSuffix;
        const size_t json = name.find(".json.");
        if (name.size() < 2 || name[0] != '.' || json == std::string::npos ||
            name.size() <= suffix.size() ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        const std::string path = entry.path().string();
        journals.push_back({path, name.substr(1, json + 4), held_by_someone(path)});
    }
    return journals;
}

Manifest read_journal(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail_io(path, "cannot open journal");
    std::string line;
    if (!std::getline(in, line)) throw Error(ExitCode::invalid_input, path + ": empty journal");
    Manifest journal = parse_manifest(line, path);
    while (std::getline(in, line)) {
        if (in.eof()) break;  // no newline after it: torn by a crash mid-write
        try {
            const Manifest image = parse_manifest(line, path);
            journal.frames.insert(journal.frames.end(), image.frames.begin(), image.frames.end());
            journal.files.insert(journal.files.end(), image.files.begin(), image.files.end());
        } catch (const Error&) {
            break;  // a damaged line: what follows cannot be trusted either
        }
    }
    return journal;
}

}  // namespace facet
