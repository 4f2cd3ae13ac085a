#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>

#include "core/error.hpp"
#include "core/number_text.hpp"

namespace facet {
namespace {

constexpr const char* kTempMark = ".facet-tmp.";

// ".frame.png.facet-tmp.HOST.PID" beside "frame.png": hidden, and saying
// who wrote it, so that a rerun can tell its own leftovers from another
// live process's file (render farm nodes share output folders).
std::string temp_name(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / ("." + p.filename().string() + kTempMark + host_name() + "." +
                               std::to_string(::getpid())))
        .string();
}

// Makes the rename itself durable: the folder's entry is on disk too.
void sync_folder(const std::string& path) {
    std::string folder = std::filesystem::path(path).parent_path().string();
    if (folder.empty()) folder = ".";
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // nothing to sync on (some file systems refuse): the file is written
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

std::string host_name() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
    std::string host = name;
    for (char& c : host)
        if (c == '/' || c == '.') c = '_';  // the mark's separator stays unambiguous
    return host;
}

void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    const std::string temp = temp_name(path);
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail_io(path, std::string("cannot create file: ") + std::strerror(errno));
    auto fail = [&](const std::string& what) {
        const int err = errno;
        if (fd >= 0) ::close(fd);
        ::unlink(temp.c_str());
        fail_io(path, what + ": " + std::strerror(err));
    };
    size_t written = 0;
    while (written < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("write failed");
        written += static_cast<size_t>(n);
    }
    // The bytes reach the disk before the name does: after a power loss the
    // path holds the old file or the whole new one, never an empty one.
    if (::fsync(fd) != 0) fail("write failed");
    const int closed = ::close(fd);
    fd = -1;
    if (closed != 0) fail("write failed");
    if (::rename(temp.c_str(), path.c_str()) != 0) fail("cannot replace file");
    sync_folder(path);
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
