// --passes and --formats choose the files a render writes, and bad values
// are reported against the command line with exit code 2.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

#include "support.hpp"

using namespace facet;

namespace {

const char* kScene = R"(
output: { size: [32, 24], frames: "1-2", passes: [color], formats: [png] }
objects: [ { primitive: cube } ]
)";

std::set<std::string> files_in(const std::string& folder) {
    std::set<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        names.insert(e.path().filename().string());
    return names;
}

}  // namespace

TEST_CASE("the passes and formats options pick the files written", "[cli]") {
    test::TempDir dir("passes");
    std::string scene = test::write_text(dir.file("s.yaml"), kScene);
    auto run = test::run_facet("render '" + scene + "' --out '" + dir.file("a") +
                               "' --passes depth --formats exr,png -q");
    REQUIRE(run.exit_code == 0);
    CHECK(files_in(dir.file("a/s")) == std::set<std::string>{"depth.0001.exr", "depth.0001.png",
                                                             "depth.0002.exr", "depth.0002.png",
                                                             "manifest.json"});
    run = test::run_facet("render '" + scene + "' --out '" + dir.file("b") + "' -q");
    REQUIRE(run.exit_code == 0);
    CHECK(files_in(dir.file("b/s")) ==
          std::set<std::string>{"color.0001.png", "color.0002.png", "manifest.json"});
}

TEST_CASE("bad passes and formats options are usage errors", "[cli]") {
    test::TempDir dir("badpasses");
    std::string scene = test::write_text(dir.file("s.yaml"), kScene);
    auto run =
        test::run_facet("render '" + scene + "' --out '" + dir.file("o") + "' --passes colour");
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("command line --passes colour"));
    run = test::run_facet("render '" + scene + "' --out '" + dir.file("o") + "' --formats tiff");
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("must be one of: png, exr"));
    CHECK(files_in(dir.file("o")).empty());
}
