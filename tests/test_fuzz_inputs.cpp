// The fuzz harnesses' inputs replayed in the normal suite: every crash or
// hang a fuzzer ever found (tests/fuzz/regressions/TARGET/) and the checked-in
// corpus (tests/fuzz/corpus/TARGET/). Each must load or be refused with a
// facet::Error; under scripts/test.sh --sanitize they also run under ASan
// and UBSan, which abort on any report.
#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz/fuzz_targets.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;

// Replays the files of tests/fuzz/KIND/TARGET; returns how many there were.
size_t replay(const std::string& kind, const std::string& target) {
    const fs::path folder = fs::path(FACET_SOURCE_DIR) / "tests/fuzz" / kind / target;
    size_t count = 0;
    if (!fs::is_directory(folder)) return 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        INFO(entry.path().string());
        CHECK_NOTHROW(facet::fuzz::run_target(target, bytes.data(), bytes.size()));
        ++count;
    }
    return count;
}

}  // namespace

TEST_CASE("fuzz regression inputs load or are refused cleanly", "[fuzz]") {
    for (const char* target : {"scene", "obj", "gltf", "texture"}) {
        INFO(target);
        CHECK(replay("regressions", target) > 0);
    }
}

TEST_CASE("the checked-in fuzz corpora load or are refused cleanly", "[fuzz]") {
    for (const char* target : {"scene", "obj", "gltf", "texture"}) {
        INFO(target);
        CHECK(replay("corpus", target) > 0);
    }
}

TEST_CASE("an unknown fuzz target is reported", "[fuzz]") {
    const uint8_t byte = 0;
    CHECK_FALSE(facet::fuzz::run_target("bogus", &byte, 1));
}
