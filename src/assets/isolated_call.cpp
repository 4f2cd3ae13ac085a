#include "assets/isolated_call.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/memory.hpp"

namespace facet {
namespace {

// The process's address space now, in bytes (/proc/self/statm's first
// field, in pages); 0 when it cannot be read.
uint64_t address_space_now() {
    std::ifstream statm("/proc/self/statm");
    uint64_t pages = 0;
    if (!(statm >> pages)) return 0;
    return pages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

bool write_all(int fd, const uint8_t* data, size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

// In the child: the limits, the work, and its answer on `fd`: a status
// byte (0 bytes follow, 1 an error: its exit code and message), then the
// payload. Never returns.
[[noreturn]] void child(int fd, const std::function<std::vector<uint8_t>()>& work,
                        const IsolationLimits& limits, uint64_t available) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    // What the library or the C library prints as it fails ("malloc():
    // invalid size") is not for the user: the parent says what happened.
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) ::dup2(null, STDOUT_FILENO), ::dup2(null, STDERR_FILENO);
    if (!kAddressSanitizer) {
        const uint64_t more = limits.memory_bytes ? limits.memory_bytes : available;
        const rlimit memory{address_space_now() + more, address_space_now() + more};
        ::setrlimit(RLIMIT_AS, &memory);
    }
    const rlimit cpu{limits.cpu_seconds, limits.cpu_seconds + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    ByteWriter answer;
    std::vector<uint8_t> payload;
    try {
        payload = work();
        answer.u32(0);
    } catch (const Error& e) {
        answer.u32(1);
        answer.u32(static_cast<uint32_t>(e.code()));
        answer.text(e.what());
    } catch (const std::bad_alloc&) {
        answer.u32(1);
        answer.u32(static_cast<uint32_t>(ExitCode::runtime_failure));
        answer.text("out of memory");
    } catch (const std::exception& e) {
        answer.u32(1);
        answer.u32(static_cast<uint32_t>(ExitCode::invalid_input));
        answer.text(e.what());
    }
    const std::vector<uint8_t> head = answer.take();
    const bool sent =
        write_all(fd, head.data(), head.size()) && write_all(fd, payload.data(), payload.size());
    ::_exit(sent ? 0 : 1);  // no atexit handlers: the parent's state is not the child's
}

// How a child that sent no answer ended.
std::string how_it_ended(int status, const IsolationLimits& limits) {
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        if (signal == SIGXCPU)
            return "reading it took more than " + std::to_string(limits.cpu_seconds) +
                   " s of CPU; the file is damaged or far too large";
        if (signal == SIGKILL) return "reading it was stopped (out of memory?)";
        return std::string("the reader crashed on it (") + ::strsignal(signal) +
               "): the file is damaged or not what its format says";
    }
    return "the reader ended without an answer (exit status " +
           std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
}

}  // namespace

std::vector<uint8_t> run_isolated(const std::string& what,
                                  const std::function<std::vector<uint8_t>()>& work,
                                  const IsolationLimits& limits) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return work();
    const uint64_t available = memory_available();
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return work();
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], work, limits, available);
    }
    ::close(fds[1]);
    std::vector<uint8_t> bytes;
    uint8_t buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.insert(bytes.end(), buffer, buffer + n);
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    const bool answered = WIFEXITED(status) && WEXITSTATUS(status) == 0 && bytes.size() >= 4;
    if (!answered) throw Error(ExitCode::invalid_input, what + ": " + how_it_ended(status, limits));
    ByteReader reader(bytes);
    if (reader.u32() != 0) {
        const auto code = static_cast<ExitCode>(reader.u32());
        throw Error(code, reader.text());
    }
    // The status word out, in place: a mesh's payload is not held twice.
    bytes.erase(bytes.begin(), bytes.begin() + 4);
    return bytes;
}

void ByteWriter::raw(const void* data, size_t size) {
    const auto* b = static_cast<const uint8_t*>(data);
    bytes_.insert(bytes_.end(), b, b + size);
}

void ByteWriter::u32(uint32_t value) {
    raw(&value, sizeof value);
}

void ByteWriter::f32(float value) {
    raw(&value, sizeof value);
}

void ByteWriter::text(const std::string& value) {
    u32(static_cast<uint32_t>(value.size()));
    raw(value.data(), value.size());
}

void ByteReader::check(uint64_t size) const {
    if (size > bytes_.size() - at_)
        throw Error(ExitCode::runtime_failure, "a child process's answer is cut short");
}

void ByteReader::raw(void* data, size_t size) {
    check(size);
    if (size > 0) std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
}

uint32_t ByteReader::u32() {
    uint32_t value = 0;
    raw(&value, sizeof value);
    return value;
}

float ByteReader::f32() {
    float value = 0;
    raw(&value, sizeof value);
    return value;
}

std::string ByteReader::text() {
    const uint32_t size = u32();
    check(size);
    std::string value(size, '\0');
    raw(value.data(), value.size());
    return value;
}

}  // namespace facet
