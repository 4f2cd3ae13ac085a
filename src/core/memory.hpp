#pragma once
// How much memory this process may still take: what the kernel says is
// available (MemAvailable in /proc/meminfo), lowered by an address-space
// limit (ulimit -v, RLIMIT_AS) when one is set. Loaders and the renderer
// check their estimates against it before they allocate, so that a scene
// too big for the machine stops with a clear error instead of meeting the
// out-of-memory killer.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace facet {

uint64_t memory_available();

// Whether this build has AddressSanitizer, which reserves terabytes of
// address space up front: no address-space limit (RLIMIT_AS, ulimit -v)
// can be set for it or its children.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// Named parts of an estimate, for messages: {"frame buffers", bytes}, ...
using MemoryParts = std::vector<std::pair<std::string, uint64_t>>;

// Throws facet::Error (runtime_failure) "WHAT needs about N (parts...), but
// only M is available; ADVICE" when the parts add up to more than
// `available`.
void check_memory(const std::string& what, const MemoryParts& parts, uint64_t available,
                  const std::string& advice = "");

}  // namespace facet
