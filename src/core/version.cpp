#include "core/version.hpp"

#include "facet_commit.h"

namespace facet {

const BuildInfo& build_info() {
    static const BuildInfo info = [] {
        BuildInfo b;
        b.version = FACET_VERSION;
        b.commit = FACET_COMMIT;
        b.build_type = FACET_BUILD_TYPE;
        b.simd = FACET_SIMD_NAME;
#if defined(__clang__)
        b.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
        b.compiler = "gcc " __VERSION__;
#else
        b.compiler = "unknown compiler";
#endif
        // __clang_version__ may carry a trailing space and a build note.
        while (!b.compiler.empty() && b.compiler.back() == ' ') b.compiler.pop_back();
        return b;
    }();
    return info;
}

std::string version_line() {
    const BuildInfo& b = build_info();
    return "facet " + b.version + " (commit " + b.commit + ", " + b.build_type + ", " + b.simd +
           ", " + b.compiler + ")";
}

}  // namespace facet
