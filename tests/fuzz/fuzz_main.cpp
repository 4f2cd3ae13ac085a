// libFuzzer's entry point for one harness; FACET_FUZZ_TARGET names it
// (tests/fuzz/CMakeLists.txt builds one executable per harness).
#include <cstdlib>

#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!facet::fuzz::run_target(FACET_FUZZ_TARGET, data, size)) std::abort();
    return 0;
}
