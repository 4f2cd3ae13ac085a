// Resuming with --skip-existing after a crash, runs sharing one output
// folder, and the exit code of an interrupted run.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "compare_support.hpp"
#include "core/host_name.hpp"
#include "farm_support.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"

using namespace facet;
using test::run_facet;
using test::shell_quote;

namespace {

// A process id no process has now, for a temporary "left by a dead run".
int dead_pid() {
    for (int pid = 4000000; pid > 1000; --pid)
        if (::kill(pid, 0) != 0 && errno == ESRCH) return pid;
    return 999999;
}

size_t journal_lines(const std::string& folder) {
    size_t lines = 0;
    std::error_code ec;  // the folder may not exist yet
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() > 8 && name.substr(name.size() - 8) == ".journal") {
            std::ifstream in(entry.path());
            std::string line;
            while (std::getline(in, line)) ++lines;
        }
    }
    return lines;
}

// Starts facet in the background; returns its process id.
int start_facet(const std::string& args, const std::string& log) {
    const auto r = test::run_command(std::string("'") + facet::test::facet_executable() + "' " +
                                     args + " > " + shell_quote(log) + " 2>&1 & echo $!");
    return std::stoi(r.output);
}

int wait_for(int pid) {
    // Not our child (the shell's): poll until it is gone.
    while (::kill(pid, 0) == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return 0;
}

}  // namespace

TEST_CASE("skip-existing after a crash renders only what is missing or damaged",
          "[farm][cli][resume]") {
    test::TempDir dir("farm-skip");
    const std::string scene = test::write_farm_scene(dir, 8, "[96, 54]");
    const std::string folder = dir.file("out/spin");
    const std::string render =
        "render " + shell_quote(scene) + " -o " + shell_quote(dir.file("out")) + " ";
    REQUIRE(run_facet(render + "-q").exit_code == 0);
    const std::map<std::string, std::string> expected =
        test::listed_hashes(folder + "/manifest.json");

    // The state a run killed after six images leaves: no manifest, its
    // journal (a dead run's: nobody holds it) with a torn last line, a
    // temporary file, and then someone truncates an image.
    Manifest written = read_manifest(folder + "/manifest.json");
    std::filesystem::remove(folder + "/manifest.json");
    {
        Manifest header = written;
        header.frames.clear();
        header.files.clear();
        ManifestJournal journal(folder, "manifest.json", header);
        for (int frame = 1; frame <= 6; ++frame) {
            Manifest image;
            for (const auto& f : written.frames)
                if (f.frame == frame) image.frames.push_back(f);
            for (const auto& f : written.files)
                if (f.frame == frame) image.files.push_back(f);
            journal.append(image);
        }
    }
    std::string journal_path;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".journal") journal_path = entry.path().string();
    REQUIRE_FALSE(journal_path.empty());
    std::ofstream(journal_path, std::ios::app) << R"({"scene": "torn)";
    std::filesystem::remove(folder + "/color.0007.png");  // frame 7: never finished
    test::write_text(
        folder + "/.color.0007.png.facet-tmp." + host_name() + "." + std::to_string(dead_pid()),
        "half an image");
    std::filesystem::resize_file(folder + "/depth.0003.exr", 100);  // damaged

    const auto r = run_facet(render + "--skip-existing --threads 2");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("5 images are already written") != std::string::npos);
    // One line per image written in a log: frames 3, 7 and 8 only.
    CHECK(test::count_substring(r.output, "rendered in") == 3);
    for (const char* frame : {"frame 3 ", "frame 7 ", "frame 8 "})
        CHECK(r.output.find(frame) != std::string::npos);
    CHECK(r.output.find("frame 1 ") == std::string::npos);
    CHECK(test::listed_hashes(folder + "/manifest.json") == expected);
    CHECK(test::hidden_leftovers(folder).empty());
    for (const auto& [path, hash] : expected)
        CHECK(test::sha256_of_file(folder + "/" + path) == hash);

    // Without --skip-existing, everything is rendered again.
    const auto all = run_facet(render + "--threads 2");
    CHECK(test::count_substring(all.output, "rendered in") == 8);
}

TEST_CASE("killed with SIGKILL mid-run, a rerun renders only the rest, bit for bit",
          "[farm][cli][resume]") {
    test::TempDir dir("farm-kill");
    const std::string scene = test::write_farm_scene(dir, 40, "[640, 360]");
    const std::string folder = dir.file("out/spin");
    const std::string render =
        "render " + shell_quote(scene) + " -o " + shell_quote(dir.file("out")) + " --threads 1 ";
    const int pid = start_facet(render + "-q", dir.file("log"));
    // Kill once the journal records a few images: whatever the machine's speed.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (journal_lines(folder) < 5 && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ::kill(pid, SIGKILL);
    wait_for(pid);
    const size_t recorded = journal_lines(folder) - 1;  // the header is a line
    REQUIRE(recorded >= 4);
    REQUIRE(recorded < 40);
    CHECK_FALSE(std::filesystem::exists(folder + "/manifest.json"));

    const auto r = run_facet(render + "--skip-existing");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(test::count_substring(r.output, "rendered in") == 40 - recorded);
    CHECK(test::hidden_leftovers(folder).empty());
    const auto whole = run_facet("render " + shell_quote(scene) + " -q --threads 2 -o " +
                                 shell_quote(dir.file("whole")));
    REQUIRE(whole.exit_code == 0);
    CHECK(test::listed_hashes(folder + "/manifest.json") ==
          test::listed_hashes(dir.file("whole/spin/manifest.json")));
}

TEST_CASE("two runs writing into one folder keep every entry, other settings are refused",
          "[farm][cli][concurrent]") {
    test::TempDir dir("farm-shared");
    // Enough frames that both runs are still writing when the third starts:
    // with 12 each (0.1 s of work) one full suite saw them finish first.
    const std::string scene = test::write_farm_scene(dir, 240, "[320, 180]");
    const std::string folder = dir.file("out/spin");
    const std::string render =
        "render " + shell_quote(scene) + " -q -o " + shell_quote(dir.file("out")) + " --threads 1 ";
    const int a = start_facet(render + "--frames 1-120", dir.file("a.log"));
    const int b = start_facet(render + "--frames 121-240", dir.file("b.log"));
    // While they run, a run of other settings is turned away.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (journal_lines(folder) < 2 && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const auto other = run_facet(render + "--frames 1-2 --style toon --overwrite");
    wait_for(a);
    wait_for(b);
    INFO(other.output);
    CHECK(other.exit_code == 2);
    CHECK(other.output.find("another facet run") != std::string::npos);
    INFO(test::read_file(dir.file("a.log")) + test::read_file(dir.file("b.log")));
    const auto manifest = test::read_json(folder + "/manifest.json");
    CHECK(manifest["frames"].size() == 240);
    CHECK(manifest["files"].size() == 960);
    CHECK(test::hidden_leftovers(folder).empty());
    const auto check = run_facet("merge " + shell_quote(folder));
    CHECK(check.exit_code == 0);
}
