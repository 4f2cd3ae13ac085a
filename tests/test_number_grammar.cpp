// One number grammar for everything a user types (the reliability issue,
// item 10): scene values, -D values and key times are read as the command
// line reads numbers (core/number_text.hpp): decimal, the whole text,
// finite. Before, scene values went through strtod, which took "0x10" as
// 16 and "0x1p2" as 4, while --threads 0x2 was refused.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

const char* kScene = R"(
output: { size: [32, 18], frames: "1-2" }
camera: { position: [0, 0, 5] }
objects: [ { primitive: { type: cube } } ]
)";

}  // namespace

TEST_CASE("scene and -D numbers are decimal, as command-line numbers are", "[scene][cli]") {
    TempDir dir("number-grammar");
    const std::string scene = write_text(dir.file("n.yaml"), kScene);
    for (const char* define :
         {"output.samples=0x1p2", "output.samples=0x10", "camera.fov=0x1e", "camera.fov=+30",
          "camera.fov=' 30'", "camera.fov=30k", "camera.fov=inf", "camera.fov=nan",
          "objects.0.translate=[0x1, 0, 0]"}) {
        INFO(define);
        const RunResult r = run_facet("validate " + scene + " -D \"" + define + "\"");
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("must be a number (decimal"));
    }
    for (const char* define :
         {"output.samples=4", "camera.fov=30", "camera.fov=3e1", "camera.fov=30.5",
          "camera.fov=.5e2", "objects.0.translate=[-1.5, 0, 1e-3]"}) {
        INFO(define);
        const RunResult r = run_facet("validate " + scene + " -D \"" + define + "\"");
        INFO(r.output);
        CHECK(r.exit_code == 0);
    }
}

TEST_CASE("key times are decimal numbers too", "[scene][animation]") {
    TempDir dir("number-grammar-keys");
    for (const char* key : {"0x10", "+1", "1e999", " 1"}) {
        INFO(key);
        const std::string scene =
            write_text(dir.file("k.yaml"), std::string(kScene) +
                                               "lights: [ { type: point, position: [0, 2, 2], "
                                               "intensity: { keys: { '" +
                                               key + "': 1, 24: 2 } } } ]\n");
        const RunResult r = run_facet("validate " + scene);
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("a key must be a frame number"));
    }
}

TEST_CASE("a -D list item is named by a decimal index or by its name", "[scene][cli]") {
    TempDir dir("number-grammar-index");
    const std::string scene = write_text(dir.file("n.yaml"), kScene);
    CHECK(run_facet("validate " + scene + " -D objects.0.translate=[1,0,0]").exit_code == 0);
    for (const char* index : {"+0", "0x0", " 0"}) {
        INFO(index);
        const RunResult r = run_facet("validate " + scene + " -D 'objects." + std::string(index) +
                                      ".translate=[1,0,0]'");
        INFO(r.output);
        CHECK(r.exit_code == 2);
    }
}
