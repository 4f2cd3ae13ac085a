#pragma once
// What facet build this is, for --version, manifests and image metadata.
#include <string>

namespace facet {

struct BuildInfo {
    std::string version;     // "0.1.0" (CMake's project version)
    std::string commit;      // `git describe` of the source at build time, or "unknown"
    std::string build_type;  // "Release", "Sanitize", ...
    std::string simd;        // "avx2" or "baseline"
    std::string compiler;    // "gcc 12.2.0", "clang 14.0.6"
};

const BuildInfo& build_info();

// "facet 0.1.0 (commit 301e8ec, Release, avx2, gcc 12.2.0)".
std::string version_line();

}  // namespace facet
