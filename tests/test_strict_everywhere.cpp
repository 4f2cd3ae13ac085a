// --strict covers every warning a command gives, and facet farm refuses
// what facet render would refuse (the reliability issue, item 6).
#include <catch2/catch.hpp>

#include <filesystem>

#include "farm_support.hpp"
#include "turntable_support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

// A scene whose camera has a position that its orbit makes redundant: one
// warning ("is ignored: the orbit places the camera").
std::string scene_with_warning(const TempDir& dir) {
    return write_text(dir.file("warned.yaml"), R"(
output: { size: [32, 18], frames: "1-4", passes: [color], formats: [png] }
camera: { position: [0, 0, 5], orbit: { radius: 4, turns: 1 } }
objects: [ { primitive: { type: cube } } ]
)");
}

// A binary STL file with a vertex position that is NaN: render refuses it.
std::string scene_with_nan_mesh(const TempDir& dir) {
    write_binary_stl(dir.file("nan.stl"), {{0, 0, 0}, {1, 0, 0}, {std::nanf(""), 1, 0}});
    return write_text(dir.file("nan.yaml"), R"(
output: { size: [32, 18], frames: "1-4" }
camera: { position: [0, 0, 5] }
objects: [ { mesh: nan.stl } ]
)");
}

// `facet ARGS` run in `dir`, with `env` (NAME=VALUE ...) in its environment.
std::string in(const TempDir& dir, const std::string& args, const std::string& env = "") {
    return "cd " + shell_quote(dir.path()) + " && " + env + " " + shell_quote(facet_executable()) +
           " " + args + " 2>&1";
}

}  // namespace

TEST_CASE("facet farm --strict refuses a scene with a warning, as render --strict does",
          "[farm][cli]") {
    TempDir dir("strict-farm");
    scene_with_warning(dir);
    for (const char* kind : {"slurm --chunks 2", "openjd"}) {
        INFO(kind);
        const RunResult strict = run_command(
            in(dir, std::string("farm ") + kind + " warned.yaml --strict --script job"));
        INFO(strict.output);
        CHECK(strict.exit_code == 2);
        CHECK_THAT(strict.output, Contains("--strict: 1 warning is an error") &&
                                      Contains("the orbit places the camera"));
        CHECK_FALSE(std::filesystem::exists(dir.file("job")));
        // Without --strict the warning is shown and the job written.
        const RunResult loose =
            run_command(in(dir, std::string("farm ") + kind + " warned.yaml --script job"));
        CHECK(loose.exit_code == 0);
        CHECK_THAT(loose.output, Contains("warning:") && Contains("the orbit places the camera"));
        CHECK(std::filesystem::exists(dir.file("job")));
        std::filesystem::remove(dir.file("job"));
    }
    CHECK(run_command(in(dir, "render warned.yaml --strict")).exit_code == 2);
}

TEST_CASE("facet farm refuses a mesh that render refuses, before writing the job", "[farm][cli]") {
    TempDir dir("strict-farm-mesh");
    scene_with_nan_mesh(dir);
    const RunResult render = run_command(in(dir, "render nan.yaml"));
    CHECK(render.exit_code == 2);
    CHECK_THAT(render.output, Contains("not finite"));
    for (const char* kind : {"slurm --chunks 2", "openjd"}) {
        INFO(kind);
        const RunResult farm =
            run_command(in(dir, std::string("farm ") + kind + " nan.yaml --script job"));
        INFO(farm.output);
        CHECK(farm.exit_code == 2);
        CHECK_THAT(farm.output, Contains("nan.stl") && Contains("not finite"));
        CHECK_FALSE(std::filesystem::exists(dir.file("job")));
    }
}

TEST_CASE("render --strict refuses a movie of unevenly spaced frames before rendering",
          "[video][cli]") {
    TempDir dir("strict-video");
    write_text(dir.file("even.yaml"), R"(
output: { size: [32, 18], frames: "1-4", passes: [color], formats: [png] }
camera: { position: [0, 0, 5] }
objects: [ { primitive: { type: cube } } ]
)");
    const RunResult strict =
        run_command(in(dir, "render even.yaml --frames 1,2,4 --video v.mp4 --strict -o o"));
    INFO(strict.output);
    CHECK(strict.exit_code == 2);
    CHECK_THAT(strict.output, Contains("--strict") && Contains("not evenly spaced"));
    CHECK_FALSE(std::filesystem::exists(dir.file("v.mp4")));
    CHECK_FALSE(std::filesystem::exists(dir.file("o")));
    // Without --strict: one warning, said once, and the movie.
    const RunResult loose =
        run_command(in(dir, "render even.yaml --frames 1,2,4 --video v.mp4 -o o"));
    INFO(loose.output);
    CHECK(loose.exit_code == 0);
    CHECK(count_substring(loose.output, "not evenly spaced") == 1);
    CHECK(std::filesystem::exists(dir.file("v.mp4")));
}

TEST_CASE("render --strict in a Slurm array task without a chunk option is an error",
          "[farm][cli]") {
    TempDir dir("strict-slurm-task");
    write_farm_scene(dir, 4, "[32, 18]");
    const RunResult strict =
        run_command(in(dir, "render spin.yaml --strict -o o", "SLURM_ARRAY_TASK_ID=3"));
    INFO(strict.output);
    CHECK(strict.exit_code == 2);
    CHECK_THAT(strict.output, Contains("--strict") && Contains("Slurm array task 3"));
    CHECK_FALSE(std::filesystem::exists(dir.file("o")));
    const RunResult loose = run_command(in(dir, "render spin.yaml -o o", "SLURM_ARRAY_TASK_ID=3"));
    CHECK(loose.exit_code == 0);
    CHECK_THAT(loose.output, Contains("warning:") && Contains("Slurm array task 3"));
}
