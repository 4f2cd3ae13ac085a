// The render farm workflow through the facet program: chunks and their
// partial manifests, facet merge and what it refuses, resuming with
// --skip-existing after a crash, runs sharing a folder, and the job files
// run as a scheduler would run them.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <thread>

#include "compare_support.hpp"
#include "farm_support.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"

using namespace facet;
using test::run_facet;
using test::shell_quote;

namespace {

// A render of the whole scene in one process: what a farm job must equal.
std::map<std::string, std::string> single_run(const test::TempDir& dir, const std::string& scene,
                                              const std::string& extra = "") {
    const auto r = run_facet("render " + shell_quote(scene) + " -q -o " +
                             shell_quote(dir.file("single")) + " " + extra);
    REQUIRE(r.exit_code == 0);
    return test::listed_hashes(dir.file("single/spin/manifest.json"));
}

// Writes DIR/job.yaml with `facet farm openjd spin.yaml ... OPTIONS`, run
// from DIR (11 frames in chunks of 4, into DIR/out).
void write_openjd_job(const test::TempDir& dir, const std::string& options) {
    const auto made = test::run_command(
        "cd " + shell_quote(dir.path()) + " && " + shell_quote(facet::test::facet_executable()) +
        " farm openjd spin.yaml --chunk-size 4 -o out --frames 1-11 " + options +
        " --script job.yaml 2>&1");
    INFO(made.output);
    REQUIRE(made.exit_code == 0);
}

}  // namespace

TEST_CASE("chunks rendered apart and merged equal one run, file for file", "[farm][cli]") {
    test::TempDir dir("farm-chunks");
    const std::string scene = test::write_farm_scene(dir, 10, "[96, 54]");
    const auto expected = single_run(dir, scene);
    const std::string out = shell_quote(dir.file("out"));
    for (int i = 0; i < 3; ++i) {
        const auto r = run_facet("render " + shell_quote(scene) + " -o " + out + " --chunk " +
                                 std::to_string(i) + "/3 --threads " + std::to_string(1 + i % 2));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        CHECK(r.output.find("chunk " + std::to_string(i) + "/3: frames") != std::string::npos);
    }
    // 10 frames in 3 chunks: 4, 3, 3.
    const std::string folder = dir.file("out/spin");
    CHECK(std::filesystem::exists(folder + "/manifest.part-0001-0004.json"));
    CHECK(std::filesystem::exists(folder + "/manifest.part-0005-0007.json"));
    CHECK(std::filesystem::exists(folder + "/manifest.part-0008-0010.json"));
    CHECK_FALSE(std::filesystem::exists(folder + "/manifest.json"));
    const auto part = test::read_json(folder + "/manifest.part-0005-0007.json");
    CHECK(part["job"]["frames"] == "1-10");
    CHECK(part["part"]["frames"] == "5-7");
    CHECK(part["part"]["chunk_index"] == 1);
    CHECK(part["part"]["chunk_count"] == 3);
    CHECK(part["frames"].size() == 3);
    CHECK_FALSE(part["timings"]["host"].get<std::string>().empty());
    CHECK(part["timings"]["frames"][0]["host"] == part["timings"]["host"]);

    const auto merged = run_facet("merge " + shell_quote(folder));
    INFO(merged.output);
    REQUIRE(merged.exit_code == 0);
    CHECK(merged.output.find("merged 3 partial manifests") != std::string::npos);
    CHECK(test::listed_hashes(folder + "/manifest.json") == expected);
    const auto manifest = test::read_json(folder + "/manifest.json");
    CHECK(manifest["timings"]["parts"].size() == 3);
    CHECK(manifest["job"]["frames"] == "1-10");
    CHECK_FALSE(manifest.contains("part"));
    CHECK_FALSE(std::filesystem::exists(folder + "/manifest.part-0001-0004.json"));
    CHECK(test::hidden_leftovers(folder).empty());
    // A second merge finds no parts and checks manifest.json instead.
    const auto again = run_facet("merge " + shell_quote(folder));
    CHECK(again.exit_code == 0);
    CHECK(again.output.find("checked") != std::string::npos);
}

TEST_CASE("chunks of frames listed one by one, and more chunks than frames", "[farm][cli]") {
    test::TempDir dir("farm-list");
    const std::string scene = test::write_farm_scene(dir, 10, "[64, 36]");
    const std::string base = "render " + shell_quote(scene) + " -o " +
                             shell_quote(dir.file("out")) + " --frames 1,2,5,9 ";
    for (int i = 0; i < 6; ++i) {
        const auto r = run_facet(base + "--chunk " + std::to_string(i) + "/6");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        if (i >= 4) CHECK(r.output.find("nothing to do") != std::string::npos);
    }
    CHECK(std::filesystem::exists(dir.file("out/spin/manifest.part-0009-0009.json")));
    const auto merged = run_facet("merge " + shell_quote(dir.file("out/spin")));
    INFO(merged.output);
    CHECK(merged.exit_code == 0);
    CHECK(test::read_json(dir.file("out/spin/manifest.json"))["frames"].size() == 4);

    const auto bad = run_facet(base + "--chunk 6/6");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("numbered from 0") != std::string::npos);
    const auto two = run_facet(base + "--chunk 0/2 --chunk-frames 1");
    CHECK(two.exit_code == 2);
    const auto outside = run_facet(base + "--chunk-frames 3");
    CHECK(outside.exit_code == 2);
    CHECK(outside.output.find("frame 3 is not one of the job's frames (1,2,5,9)") !=
          std::string::npos);
    const auto reference = run_facet(base + "--chunk 0/2 --reference " + shell_quote(dir.path()));
    CHECK(reference.exit_code == 2);
    CHECK(reference.output.find("after facet merge") != std::string::npos);
}

TEST_CASE("merge refuses gaps, duplicates, damaged files and stray parts with exit code 3",
          "[farm][cli]") {
    test::TempDir dir("farm-merge");
    const std::string scene = test::write_farm_scene(dir, 8, "[64, 36]");
    const std::string folder = dir.file("out/spin");
    auto render_chunk = [&](int i) {
        const auto r =
            run_facet("render " + shell_quote(scene) + " -q -o " + shell_quote(dir.file("out")) +
                      " --chunk " + std::to_string(i) + "/4");
        REQUIRE(r.exit_code == 0);
    };
    for (int i : {0, 1, 3}) render_chunk(i);
    auto merge = [&] { return run_facet("merge " + shell_quote(folder)); };

    auto r = merge();
    INFO(r.output);
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("no partial manifest covers frames 5,6 (camera main)") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(folder + "/manifest.json"));

    render_chunk(2);
    // A part copied under another name lists its frames twice.
    std::filesystem::copy_file(folder + "/manifest.part-0003-0004.json",
                               folder + "/manifest.part-0003-0003.json");
    r = merge();
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("frame 3 (camera main) is listed more than once") != std::string::npos);
    std::filesystem::remove(folder + "/manifest.part-0003-0003.json");

    // A file changed after it was written.
    test::write_text(folder + "/color.0006.png", "not the rendered image");
    r = merge();
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("color.0006.png: its SHA-256 is not the one recorded: the file changed "
                        "after it was written (listed in manifest.part-0005-0006.json)") !=
          std::string::npos);
    std::filesystem::remove(folder + "/color.0006.png");
    r = merge();
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("color.0006.png: missing") != std::string::npos);

    // A part that stopped early (its manifest lists fewer frames than asked).
    render_chunk(2);
    auto part = test::read_json(folder + "/manifest.part-0007-0008.json");
    part["frames"].erase(1);
    test::write_text(folder + "/manifest.part-0007-0008.json", part.dump(2));
    r = merge();
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("manifest.part-0007-0008.json is incomplete: it lacks frames 8") !=
          std::string::npos);
    render_chunk(3);

    // A part of another job (other settings) in the folder: refused when
    // rendered, and when merged if it was put there by hand.
    const auto other = run_facet("render " + shell_quote(scene) + " -q -o " +
                                 shell_quote(dir.file("out")) + " --chunk 0/4 --style toon");
    CHECK(other.exit_code == 2);
    CHECK(other.output.find("other settings") != std::string::npos);
    auto stray = test::read_json(folder + "/manifest.part-0001-0002.json");
    stray["style"] = "toon";
    test::write_text(folder + "/manifest.part-0009-0010.json", stray.dump(2));
    r = merge();
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("manifest.part-0009-0010.json was rendered with other settings") !=
          std::string::npos);
    std::filesystem::remove(folder + "/manifest.part-0009-0010.json");

    r = merge();
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(test::listed_hashes(folder + "/manifest.json") == single_run(dir, scene));

    const auto empty = run_facet("merge " + shell_quote(dir.path()));
    CHECK(empty.exit_code == 2);
    CHECK(empty.output.find("neither partial manifests") != std::string::npos);
}

TEST_CASE("a cut into other chunks is refused unless --overwrite", "[farm][cli]") {
    test::TempDir dir("farm-recut");
    const std::string scene = test::write_farm_scene(dir, 6, "[64, 36]");
    const std::string base =
        "render " + shell_quote(scene) + " -q -o " + shell_quote(dir.file("out")) + " --chunk ";
    REQUIRE(run_facet(base + "0/2").exit_code == 0);
    const auto r = run_facet(base + "0/3");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("the job was cut into other parts there") != std::string::npos);
    REQUIRE(run_facet(base + "0/3 --overwrite").exit_code == 0);
    CHECK_FALSE(std::filesystem::exists(dir.file("out/spin/manifest.part-0001-0003.json")));
    CHECK(std::filesystem::exists(dir.file("out/spin/manifest.part-0001-0002.json")));
}

TEST_CASE("the Slurm script's tasks and merge, run as Slurm runs them, complete the job",
          "[farm][cli][jobs]") {
    test::TempDir dir("farm-slurm-script");
    const std::string scene = test::write_farm_scene(dir, 9, "[64, 36]");
    const std::string in_dir = "cd " + shell_quote(dir.path()) + " && ";
    const auto made = test::run_command(in_dir + shell_quote(facet::test::facet_executable()) +
                                        " farm slurm spin.yaml --chunks 4 -o out -D "
                                        "'objects.0.material.color=[0.2, 0.5, 0.9]' --cpus 2 "
                                        "--frames 2-9 --script job.sh 2>&1");
    INFO(made.output);
    REQUIRE(made.exit_code == 0);
    const std::string script = test::read_file(dir.file("job.sh"));
    CHECK(script.find("#SBATCH --cpus-per-task=2") != std::string::npos);
    CHECK(script.find("-D 'objects.0.material.color=[0.2, 0.5, 0.9]' --threads 2 --frames 2-9") !=
          std::string::npos);
    CHECK(test::run_command("bash -n " + shell_quote(dir.file("job.sh"))).exit_code == 0);
    // Each array task as Slurm starts it: from another folder (the script
    // changes to its own), with its task id and the job's task count.
    for (int task = 0; task < 4; ++task) {
        const auto r = test::run_command(
            "cd / && FACET_FARM_STEP=render SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
            " SLURM_ARRAY_TASK_COUNT=4 bash " + shell_quote(dir.file("job.sh")) + " 2>&1");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        CHECK(r.output.find("chunk " + std::to_string(task) +
                            "/4 from --chunk-from-env "
                            "(SLURM_ARRAY_TASK_ID=" +
                            std::to_string(task) + ", --chunks 4)") != std::string::npos);
    }
    const auto merged = test::run_command("cd / && FACET_FARM_STEP=merge bash " +
                                          shell_quote(dir.file("job.sh")) + " 2>&1");
    INFO(merged.output);
    REQUIRE(merged.exit_code == 0);
    CHECK(test::listed_hashes(dir.file("out/spin/manifest.json")) ==
          single_run(dir, scene, "--frames 2-9 -D 'objects.0.material.color=[0.2, 0.5, 0.9]'"));
}

// tests/farm/run_openjd.py is the tests' own runner: it runs the steps and
// chunks of the templates facet writes, as a scheduler would, and refuses
// anything else. It is not an OpenJD implementation; the next test checks
// the template against OpenJD's own model where its CLI is installed.
TEST_CASE("the OpenJD template, run step by step by the tests' runner, completes the job",
          "[farm][cli][jobs]") {
    test::TempDir dir("farm-openjd");
    const std::string scene = test::write_farm_scene(dir, 11, "[64, 36]");
    write_openjd_job(dir, "--style toon");
    // Every task runs in a session folder of its own: the paths are absolute.
    const std::string text = test::read_file(dir.file("job.yaml"));
    CHECK(text.find("\"" + dir.file("spin.yaml") + "\"") != std::string::npos);
    CHECK(text.find("\"" + dir.file("out") + "\"") != std::string::npos);
    const auto r =
        test::run_command("python3 " + shell_quote(test::source_path("tests/farm/run_openjd.py")) +
                          " " + shell_quote(dir.file("job.yaml")) + " 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    // 11 frames in chunks of 4: 1-4, 5-8, 9-11.
    CHECK(r.output.find("--chunk-frames 9-11") != std::string::npos);
    CHECK(r.output.find("merged 3 partial manifests") != std::string::npos);
    CHECK(test::listed_hashes(dir.file("out/spin/manifest.json")) ==
          single_run(dir, scene, "--style toon"));
}

// OpenJD's own validator (openjd-cli, from PyPI; Debian has no package).
TEST_CASE("the OpenJD template passes openjd check", "[farm][cli][jobs]") {
    if (!test::have_command("openjd"))
        FACET_SKIP(
            "openjd is missing (pip install openjd-cli); the template is checked by "
            "tests/farm/run_openjd.py only");
    test::TempDir dir("farm-openjd-check");
    test::write_farm_scene(dir, 11, "[64, 36]");
    write_openjd_job(dir, "");
    const auto check =
        test::run_command("openjd check " + shell_quote(dir.file("job.yaml")) + " 2>&1");
    INFO(check.output);
    CHECK(check.exit_code == 0);
}
