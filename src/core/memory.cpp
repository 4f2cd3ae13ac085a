#include "core/memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"

namespace facet {
namespace {

// A "Name:   1234 kB" line of a /proc file, in bytes; 0 when absent.
uint64_t proc_kb(const char* file, const std::string& name) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, name.size() + 1, name + ":") != 0) continue;
        std::istringstream words(line.substr(name.size() + 1));
        uint64_t kb = 0;
        words >> kb;
        return kb * 1024;
    }
    return 0;
}

}  // namespace

uint64_t memory_available() {
    uint64_t available = proc_kb("/proc/meminfo", "MemAvailable");
    if (available == 0) available = UINT64_MAX;  // not Linux, or an old kernel: no estimate
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const uint64_t used = proc_kb("/proc/self/status", "VmSize");
        const uint64_t cap = static_cast<uint64_t>(limit.rlim_cur);
        available = std::min(available, cap > used ? cap - used : 0);
    }
    return available;
}

void check_memory(const std::string& what, const MemoryParts& parts, uint64_t available,
                  const std::string& advice) {
    uint64_t total = 0;
    for (const auto& [name, bytes] : parts) total += bytes;
    if (total <= available) return;
    std::string list;
    for (const auto& [name, bytes] : parts)
        if (bytes > 0) list += (list.empty() ? "" : ", ") + name + " " + describe_bytes(bytes);
    throw Error(ExitCode::runtime_failure, what + " needs about " + describe_bytes(total) + " (" +
                                               list + "), but only " + describe_bytes(available) +
                                               " of memory is available" +
                                               (advice.empty() ? "" : "; " + advice));
}

}  // namespace facet
