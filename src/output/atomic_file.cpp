#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/host_name.hpp"
#include "core/number_text.hpp"

namespace facet {
namespace {

constexpr const char* kTempMark = ".facet-tmp.";

// ".frame.png.facet-tmp.HOST.PID" beside "frame.png": hidden, and saying
// who wrote it, so that a rerun can tell its own leftovers from another
// live process's file (render farm nodes share output folders).
std::string temp_name(const std::string& path) {
    const std::filesystem::path p(path);
    std::string name = ".";  // appended piece by piece: GCC 12 misreads "." + string (-Wrestrict)
    name += p.filename().string();
    name += kTempMark;
    name += host_name();
    name += ".";
    name += std::to_string(::getpid());
    return (p.parent_path() / name).string();
}

std::string folder_of(const std::string& path) {
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return folder.empty() ? std::string(".") : folder;
}

int open_file(const char* path, int flags, mode_t mode) {
    return ::open(path, flags, mode);
}

}  // namespace

const FileCalls& system_file_calls() {
    static const FileCalls calls{open_file, ::write, ::fsync, ::close, ::rename, ::unlink};
    return calls;
}

// Makes renames into the folder durable: its entries are on disk too. A
// folder that cannot be opened or synced (some file systems refuse) is
// left as it is; a failing disk is an I/O failure.
void AtomicFileSet::sync_folder(const std::string& folder) const {
    const int fd = calls_.open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC, 0);
    if (fd < 0) return;
    const bool failed = calls_.fsync(fd) != 0 && errno == EIO;
    calls_.close(fd);
    if (failed) fail_io(folder, "cannot sync folder: " + std::string(std::strerror(EIO)));
}

void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    AtomicFileSet file;
    file.write(path, bytes);
    file.publish();
}

AtomicFileSet::~AtomicFileSet() {
    discard();
}

void AtomicFileSet::discard() {
    for (const Pending& p : pending_) {
        if (p.fd >= 0) calls_.close(p.fd);
        calls_.unlink(p.temp.c_str());
    }
    pending_.clear();
}

void AtomicFileSet::write(const std::string& path, const std::vector<uint8_t>& bytes) {
    // A path written again replaces its earlier bytes: its temporary goes
    // first, so that a failure below leaves nothing of it behind.
    const auto again = std::find_if(pending_.begin(), pending_.end(),
                                    [&](const Pending& p) { return p.path == path; });
    if (again != pending_.end()) {
        calls_.close(again->fd);
        calls_.unlink(again->temp.c_str());
        pending_.erase(again);
    }
    pending_.reserve(pending_.size() + 1);  // no allocation failure once the file is open
    const std::string temp = temp_name(path);
    const int fd = calls_.open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail_io(path, std::string("cannot create file: ") + std::strerror(errno));
    size_t written = 0;
    while (written < bytes.size()) {
        ssize_t n = calls_.write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int err = n < 0 ? errno : EIO;
            calls_.close(fd);
            calls_.unlink(temp.c_str());
            fail_io(path, std::string("write failed: ") + std::strerror(err));
        }
        written += static_cast<size_t>(n);
    }
#ifdef __linux__
    // Start the bytes for the disk now, so that publish() mostly waits for
    // the file system's journal, not for the data. Only a hint: publish() syncs.
    ::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
#endif
    pending_.push_back({path, temp, fd});
}

void AtomicFileSet::publish() {
    // The bytes reach the disk before the names do: after a power loss a
    // path holds the old file or the whole new one, never an empty one.
    for (Pending& p : pending_) {
        const bool synced = calls_.fsync(p.fd) == 0;
        const int sync_error = errno;
        const bool closed = calls_.close(p.fd) == 0;
        const int close_error = errno;
        p.fd = -1;
        if (synced && closed) continue;
        // None of the set is published, and it cannot be published later:
        // a failed sync may have dropped the bytes it did not write.
        const std::string path = p.path;
        discard();
        fail_io(path,
                std::string("write failed: ") + std::strerror(synced ? close_error : sync_error));
    }
    std::set<std::string> folders;
    auto sync_folders = [&] {
        for (const std::string& folder : folders) sync_folder(folder);
    };
    while (!pending_.empty()) {
        const Pending p = pending_.front();
        pending_.erase(pending_.begin());
        if (calls_.rename(p.temp.c_str(), p.path.c_str()) != 0) {
            const int err = errno;
            calls_.unlink(p.temp.c_str());
            discard();
            sync_folders();  // what was published stays, durably
            fail_io(p.path, std::string("cannot replace file: ") + std::strerror(err));
        }
        published_.push_back(p.path);
        folders.insert(folder_of(p.path));
    }
    sync_folders();
}

void write_file_atomically(const std::string& path, const std::string& text) {
    write_file_atomically(path, std::vector<uint8_t>(text.begin(), text.end()));
}

void make_directories(const std::string& path) {
    std::error_code ec;
    std::filesystem::create_directories(path, ec);
    if (ec) fail_io(path, "cannot create folder: " + ec.message());
}

size_t remove_stale_temporaries(const std::string& folder) {
    const std::string mark = kTempMark + host_name() + ".";
    size_t removed = 0;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        const size_t at = name.rfind(mark);
        if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
        const std::string pid_text = name.substr(at + mark.size());
        // Digits naming a process id, or not one of facet's temporaries.
        const std::optional<long long> pid = read_whole_number(pid_text);
        if (!pid || *pid <= 0 || *pid > std::numeric_limits<pid_t>::max()) continue;
        // A live process of this host (this one included) may still be writing it.
        if (*pid == ::getpid() || ::kill(static_cast<pid_t>(*pid), 0) == 0 || errno != ESRCH)
            continue;
        std::error_code remove_ec;
        if (std::filesystem::remove(entry.path(), remove_ec)) ++removed;
    }
    return removed;
}

}  // namespace facet
