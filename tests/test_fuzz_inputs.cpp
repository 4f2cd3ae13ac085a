// The fuzz harnesses' inputs replayed in the normal suite: every crash or
// hang a fuzzer ever found (tests/fuzz/regressions/TARGET/) and the checked-in
// corpus (tests/fuzz/corpus/TARGET/). Each must load or be refused with a
// facet::Error; under scripts/test.sh --sanitize they also run under ASan
// and UBSan, which abort on any report.
#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz/fuzz_targets.hpp"
#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;

// Replays the files of tests/fuzz/KIND/TARGET; returns how many there were.
size_t replay(const std::string& kind, const std::string& target) {
    const fs::path folder = fs::path(facet::test::source_dir()) / "tests/fuzz" / kind / target;
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
    for (const char* target :
         {"scene", "obj", "gltf", "texture", "environment", "ply", "assimp", "manifest"}) {
        INFO(target);
        CHECK(replay("regressions", target) > 0);
    }
}

TEST_CASE("the checked-in fuzz corpora load or are refused cleanly", "[fuzz]") {
    for (const char* target : {"scene", "obj", "gltf", "texture", "environment", "ply", "assimp",
                               "manifest", "override"}) {
        INFO(target);
        CHECK(replay("corpus", target) > 0);
    }
}

// Seeds a reader refuses would start the fuzzer from the error paths only.
TEST_CASE("the manifest and -D seeds are inputs facet accepts", "[fuzz]") {
    const fs::path corpus = fs::path(facet::test::source_dir()) / "tests/fuzz/corpus";
    const facet::Manifest whole =
        facet::read_manifest((corpus / "manifest/two-frames.json").string());
    CHECK(whole.frames.size() == 2);
    CHECK(whole.files.size() == 8);
    const facet::Manifest journal =
        facet::read_journal((corpus / "manifest/journal.json").string());
    CHECK(journal.frames.size() == 2);
    CHECK(journal.files.size() == 8);
    CHECK(facet::manifest_settings_difference(whole, journal).empty());
    for (const auto& entry : fs::directory_iterator(corpus / "override")) {
        INFO(entry.path().string());
        std::ifstream in(entry.path());
        facet::SceneOptions options;
        options.style_dirs = {facet::test::styles_dir()};
        for (std::string line; std::getline(in, line);)
            options.overrides.push_back(facet::parse_define(line));
        CHECK(options.overrides.size() >= 2);
        CHECK_NOTHROW(facet::load_scene(facet::test::override_scene(), options));
    }
}

TEST_CASE("a manifest number out of its field's range is refused, naming the field", "[fuzz]") {
    const fs::path found = fs::path(facet::test::source_dir()) /
                           "tests/fuzz/regressions/manifest/float-frame-1e62.json";
    facet::test::require_input_error([&] { facet::read_manifest(found.string()); },
                                     "'frame' must be a whole number in range");
    facet::test::TempDir dir("manifest-range");
    for (const char* size : {"[64.5, 48]", "[3000000000, 48]", "[-1e400, 1]"}) {
        INFO(size);
        std::string text = facet::test::read_file(
            (fs::path(facet::test::source_dir()) / "tests/fuzz/corpus/manifest/two-frames.json")
                .string());
        const size_t at = text.find("\"size\": [");
        text.replace(at, text.find(']', at) - at + 1, std::string("\"size\": ") + size);
        const std::string path = facet::test::write_text(dir.file("m.json"), text);
        CHECK_THROWS_AS(facet::read_manifest(path), facet::Error);
    }
}

TEST_CASE("an unknown fuzz target is reported", "[fuzz]") {
    const uint8_t byte = 0;
    CHECK_FALSE(facet::fuzz::run_target("bogus", &byte, 1));
}
