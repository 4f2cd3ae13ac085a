// Ctrl-C (SIGINT) stops a render cleanly: the frames already rendered are
// written whole and listed in the manifest, and no temporary file is left.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "output/manifest.hpp"
#include "support.hpp"

using namespace facet;

TEST_CASE("an interrupted render leaves whole files and a matching manifest", "[cli][interrupt]") {
    test::TempDir dir("interrupt");
    std::string scene = test::write_text(dir.file("long.yaml"), R"(
output: { size: [640, 360], frames: "1-2000", passes: [color, depth], formats: [png, exr] }
camera: { orbit: { radius: 4 } }
lights: [ { type: directional, direction: [-1, -1, -1] } ]
objects: [ { primitive: { type: sphere, segments: 128, rings: 64 } } ]
)");
    // SIGINT once, as soon as the first frame's last file is written, well
    // before 2000 frames are done. (`timeout` would signal the whole
    // process group as well, i.e. twice, and the second interrupt is meant
    // to end facet at once.)
    const std::string first = dir.file("out/long/depth.0001.exr");
    std::string command = "'";
    command += facet::test::facet_executable();
    command += "' render '" + scene + "' --out '" + dir.file("out") + "' --quiet 2>&1 & pid=$!; ";
    command += "for i in $(seq 600); do [ -e '" + first + "' ] && break; sleep 0.1; done; ";
    command += "kill -INT $pid; wait $pid; echo \"exit=$?.\"";
    FILE* pipe = ::popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string output;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    ::pclose(pipe);
    INFO(output);
    REQUIRE(output.find("exit=5.") != std::string::npos);  // interrupted, resumable
    CHECK(output.find("interrupted") != std::string::npos);

    const std::filesystem::path folder = dir.file("out/long");
    const Manifest manifest = read_manifest((folder / "manifest.json").string());
    const size_t frames = manifest.frames.size();
    CHECK(frames >= 1);
    CHECK(frames < 2000);
    REQUIRE(manifest.files.size() == 4 * frames);
    // Every file listed is whole: on disk with the SHA-256 recorded for it.
    for (const ManifestFile& file : manifest.files) {
        INFO(file.path);
        CHECK(listed_file_problem(folder.string(), file).empty());
    }
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        CHECK(name.find(".facet-tmp.") == std::string::npos);
        if (name != "manifest.json" && name != ".facet-manifest.lock") ++files;
    }
    CHECK(files == 4 * frames);
}
