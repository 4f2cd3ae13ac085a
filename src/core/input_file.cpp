#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::string kind_of(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// Whether `inner` is `outer` or lies below it; both absolute and normal.
bool is_within(const fs::path& inner, const fs::path& outer) {
    auto i = inner.begin();
    for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
        if (o->empty()) continue;  // a trailing separator
        if (i == inner.end() || *i != *o) return false;
    }
    return true;
}

}  // namespace

std::string describe_bytes(uint64_t bytes) {
    char text[64];
    const double b = static_cast<double>(bytes);
    if (bytes >= (uint64_t(1) << 30))
        std::snprintf(text, sizeof text, "%.1f GB", b / double(uint64_t(1) << 30));
    else if (bytes >= (uint64_t(1) << 20))
        std::snprintf(text, sizeof text, "%.1f MB", b / double(1 << 20));
    else if (bytes >= 1024)
        std::snprintf(text, sizeof text, "%.1f KB", b / 1024.0);
    else
        std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
}

std::string input_file_problem(const std::string& path, uint64_t max_bytes) {
    if (path.empty()) return "no file named (empty path)";
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        switch (errno) {
            case ENOENT: {
                struct stat link {};
                if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
                    return "is a symbolic link to nothing";
                return "no such file";
            }
            case ELOOP:
                return "symbolic link loop";
            case EACCES:
                return "permission denied";
            case ENOTDIR:
                return "a folder on its path is a file";
            case ENAMETOOLONG:
                return "the path is too long";
            default:
                return std::strerror(errno);
        }
    }
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (!S_ISREG(st.st_mode)) return "is not a regular file (" + kind_of(st.st_mode) + ")";
    if (max_bytes > 0 && static_cast<uint64_t>(st.st_size) > max_bytes)
        return "is " + describe_bytes(static_cast<uint64_t>(st.st_size)) + ", over the limit of " +
               describe_bytes(max_bytes);
    if (::access(path.c_str(), R_OK) != 0) return "permission denied";
    return "";
}

void require_input_file(const std::string& path, const std::string& what, uint64_t max_bytes) {
    const std::string problem = input_file_problem(path, max_bytes);
    if (!problem.empty())
        throw Error(ExitCode::invalid_input, path + ": cannot read " + what + ": " + problem);
}

std::vector<uint8_t> read_input_file(const std::string& path, const std::string& what,
                                     uint64_t max_bytes) {
    require_input_file(path, what, max_bytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ExitCode::io_failure, path + ": cannot open " + what);
    // Read in blocks, the first the size the file had when it was checked:
    // a byte at a time through istreambuf_iterator took 0.1 s for 90 MB,
    // and the growing vector held twice the file at times. The file may
    // have grown or shrunk since.
    std::error_code size_error;
    const uintmax_t checked_size = fs::file_size(path, size_error);
    std::vector<uint8_t> bytes;
    size_t block = size_error ? size_t(1) << 20 : static_cast<size_t>(checked_size) + 1;
    for (;;) {
        const size_t used = bytes.size();
        bytes.resize(used + block);
        in.read(reinterpret_cast<char*>(bytes.data() + used), static_cast<std::streamsize>(block));
        bytes.resize(used + static_cast<size_t>(in.gcount()));
        if (!in || (max_bytes > 0 && bytes.size() > max_bytes)) break;
        block = size_t(1) << 20;
    }
    if (in.bad()) throw Error(ExitCode::io_failure, path + ": read error in " + what);
    // The file may have grown since it was checked.
    if (max_bytes > 0 && bytes.size() > max_bytes)
        throw Error(
            ExitCode::invalid_input,
            path + ": cannot read " + what + ": over the limit of " + describe_bytes(max_bytes));
    return bytes;
}

InputFileReader::InputFileReader(const std::string& path, const std::string& what)
    : path_(path), what_(what) {
    require_input_file(path, what);
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0)
        throw Error(ExitCode::io_failure,
                    path + ": cannot open " + what + ": " + std::strerror(errno));
    // The path may name another file by now: the open one is checked.
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd_);
        throw Error(ExitCode::invalid_input,
                    path + ": cannot read " + what + ": is not a regular file");
    }
    size_ = static_cast<uint64_t>(st.st_size);
}

InputFileReader::~InputFileReader() {
    ::close(fd_);
}

void InputFileReader::read_at(uint64_t offset, char* out, size_t count) const {
    while (count > 0) {
        const ssize_t got = ::pread(fd_, out, count, static_cast<off_t>(offset));
        if (got < 0 && errno == EINTR) continue;
        if (got < 0)
            throw Error(ExitCode::io_failure,
                        path_ + ": read error in " + what_ + ": " + std::strerror(errno));
        if (got == 0)
            throw Error(ExitCode::io_failure,
                        path_ + ": " + what_ + " was cut short while it was read");
        out += got;
        offset += static_cast<uint64_t>(got);
        count -= static_cast<size_t>(got);
    }
}

std::string resolve_asset_reference(const std::string& asset, const std::string& where,
                                    const std::string& reference, const AssetPathPolicy& policy) {
    auto refuse = [&](const std::string& why) {
        throw Error(ExitCode::invalid_input, asset + ": " + where + ": '" + reference + "' " + why);
    };
    if (reference.empty()) refuse("is an empty path");
    if (reference.find('\0') != std::string::npos) refuse("contains a NUL byte");
    std::error_code ec;
    const fs::path folder = fs::absolute(fs::path(asset), ec).lexically_normal().parent_path();
    const fs::path given(reference);
    const fs::path path = (given.is_absolute() ? given : folder / given).lexically_normal();
    if (ec) refuse("cannot be resolved: " + ec.message());
    if (!policy.allow_outside) {
        // Symbolic links are followed on both sides: a link inside the
        // folder that points out of it is outside.
        const fs::path real_folder = fs::weakly_canonical(folder, ec);
        const fs::path real_path = fs::weakly_canonical(path, ec);
        if (ec || !is_within(real_path, real_folder))
            refuse("is outside the asset's folder " + folder.string() +
                   " (--allow-asset-paths-outside, or assets.allow_paths_outside: true in the "
                   "scene, allows it)");
    }
    const std::string problem = input_file_problem(path.string(), policy.max_file_bytes);
    if (!problem.empty()) refuse("(" + path.string() + ") " + problem);
    return path.string();
}

}  // namespace facet
