// Faults found by trying facet as a hostile user would (the reliability
// issue): each test failed before its fix.
#include <catch2/catch.hpp>

#include <functional>
#include <set>
#include <sstream>
#include <vector>

#include "asset_support.hpp"
#include "assets/texture.hpp"
#include "compare_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

uint32_t crc32_of(const std::vector<uint8_t>& bytes, size_t from) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = from; i < bytes.size(); ++i) {
        crc ^= bytes[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put_be32(std::vector<uint8_t>& out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

// A PNG signature and IHDR of width x height (8-bit RGB), and no data: a
// header alone says the size.
std::vector<uint8_t> png_header(uint32_t width, uint32_t height) {
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<uint8_t> chunk = {'I', 'H', 'D', 'R'};
    put_be32(chunk, width);
    put_be32(chunk, height);
    chunk.insert(chunk.end(), {8, 2, 0, 0, 0});
    put_be32(png, 13);
    png.insert(png.end(), chunk.begin(), chunk.end());
    put_be32(png, crc32_of(chunk, 0));
    return png;
}

}  // namespace

TEST_CASE("an image too large is refused by its size at any size, before decoding", "[texture]") {
    TempDir dir("reliability-png");
    for (uint32_t side : {17000u, 20000u, 65535u, 1000000u}) {
        INFO(side);
        const std::string path = write_bytes(dir.file("big.png"), png_header(side, side));
        require_input_error([&] { load_texture(path); },
                            "big.png: " + std::to_string(side) + "x" + std::to_string(side) +
                                " pixels (each side must be 1 to 16384)");
    }
}

TEST_CASE("float options refuse NaN and infinity", "[cli]") {
    for (const char* value : {"nan", "NaN", "inf", "-inf", "1e999", "abc", "24fps"}) {
        INFO(value);
        const RunResult r = run_facet(std::string("video /nonexistent out.mp4 --fps ") + value);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("--fps") && Contains("expected a number from 0.01 to 1000"));
    }
}

TEST_CASE("compare checks a mask image's size even when every file is identical", "[compare]") {
    TempDir dir("reliability-mask");
    const std::string a = render_shapes(dir.file("a"), "-f 1", "color", "png");
    const std::string b = render_shapes(dir.file("b"), "-f 1", "color", "png");
    write_png(dir.file("mask.png"), ColorImage(10, 10, glm::vec4(1)));
    const RunResult r = run_facet("compare '" + a + "' '" + b + "' --no-report --mask-image '" +
                                  dir.file("mask.png") + "'");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("mask.png"));
}

TEST_CASE("compare that cannot write its report does not say it passed", "[compare]") {
    TempDir dir("reliability-report");
    const std::string a = render_shapes(dir.file("a"), "-f 1", "color", "png");
    const std::string b = render_shapes(dir.file("b"), "-f 1", "color", "png");
    write_text(dir.file("a-file"), "not a folder");
    const RunResult r =
        run_facet("compare '" + a + "' '" + b + "' -o '" + dir.file("a-file") + "'");
    CHECK(r.exit_code == 4);
    CHECK_THAT(r.output, !Contains("passed"));
}

TEST_CASE("a manifest that is not facet's is exit 2 in compare, merge and video, in its own terms",
          "[compare][farm][video]") {
    TempDir dir("reliability-manifest");
    const std::string a = render_shapes(dir.file("a"), "-f 1", "color", "png");
    const std::string broken = dir.file("broken");
    std::filesystem::create_directories(broken);
    // An entry of "files" that is a list where an object belongs, and one
    // that lacks its hash.
    nlohmann::json m = read_json(a + "/manifest.json");
    for (const auto& [name, edit] :
         std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>>{
             {"array entry", [](nlohmann::json& j) { j["files"][0] = nlohmann::json::array({1}); }},
             {"no hash", [](nlohmann::json& j) { j["files"][0].erase("sha256"); }},
             {"not json", [](nlohmann::json& j) { j = "garbage"; }}}) {
        INFO(name);
        nlohmann::json edited = m;
        edit(edited);
        write_text(broken + "/manifest.json", name == "not json" ? "{ garbage" : edited.dump());
        for (const std::string& command :
             {"compare '" + a + "' '" + broken + "' --no-report", "merge '" + broken + "'",
              "video '" + broken + "' '" + dir.file("m.gif") + "'"}) {
            INFO(command);
            const RunResult r = run_facet(command);
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Contains("not a facet manifest") && !Contains("json.exception"));
            if (name == "no hash") CHECK_THAT(r.output, Contains("files[0]: 'sha256' is missing"));
        }
    }
}

TEST_CASE("merge on a file says it is not a folder", "[farm]") {
    TempDir dir("reliability-merge");
    const std::string file = write_text(dir.file("passwd"), "root:x:0:0\n");
    const RunResult r = run_facet("merge '" + file + "'");
    CHECK(r.exit_code == 4);
    CHECK_THAT(r.output, Contains("passwd: not a folder"));
    CHECK_THAT(run_facet("merge '" + dir.file("nothing") + "'").output, Contains("no such folder"));
}

namespace {

// A PNG of side x side pixels of noise (so it compresses little, as photos).
std::string noise_png(const TempDir& dir, const std::string& name, int side) {
    ColorImage image(side, side);
    uint32_t state = 12345;
    for (glm::vec4& p : image.pixels) {
        state = state * 1664525u + 1013904223u;
        p = {static_cast<float>(state >> 24) / 255.0f,
             static_cast<float>((state >> 16) & 255) / 255.0f, 0.5f, 1};
    }
    return write_png(dir.file(name), image);
}

// Peak resident kilobytes of `facet ARGS`, and its exit code.
std::pair<long, int> peak_kb(const std::string& args) {
    const RunResult r =
        run_command("/usr/bin/time -f 'PEAK %M' '" + std::string(facet::test::facet_executable()) +
                    "' " + args + " 2>&1 >/dev/null");
    const size_t at = r.output.rfind("PEAK ");
    return {at == std::string::npos ? -1 : std::stol(r.output.substr(at + 5)), r.exit_code};
}

}  // namespace

TEST_CASE("the texture budget bounds peak memory, the decoder's buffers included",
          "[texture][memory]") {
    if (!std::filesystem::exists("/usr/bin/time"))
        FACET_SKIP("/usr/bin/time is not installed (scripts/setup.sh --tests)");
    TempDir dir("reliability-budget");
    // 1800² is 17 MB of texels with mips, and stb holds two 13 MB images
    // while it decodes: within a 64 MB budget. 2600² stays 36 MB, but
    // decoding it takes 54 MB more: over.
    noise_png(dir, "fits.png", 1800);
    noise_png(dir, "over.png", 2600);
    auto scene = [&](const std::string& texture) {
        return write_text(
            dir.file("scene-" + texture + ".yaml"),
            "assets: { texture_budget_mb: 64 }\nobjects:\n  - primitive: cube\n" +
                (texture.empty() ? std::string() : "    material: { texture: " + texture + " }\n"));
    };
    const auto [baseline, base_code] = peak_kb("validate '" + scene("") + "'");
    REQUIRE(base_code == 0);
    REQUIRE(baseline > 0);
    const auto [fits, fits_code] = peak_kb("validate '" + scene("fits.png") + "'");
    CHECK(fits_code == 0);
    INFO("baseline " << baseline << " KB, with the texture " << fits << " KB");
    // AddressSanitizer's shadow memory and quarantine grow with every
    // allocation, so only a plain build's peak measures facet's own.
    if (!kAddressSanitizer) CHECK(fits - baseline <= 64 * 1024);
    const RunResult over = run_facet("validate '" + scene("over.png") + "'");
    CHECK(over.exit_code == 2);
    CHECK_THAT(over.output,
               Contains("over.png (while decoding)") && Contains("over the texture budget"));
    // The texture being decoded is not one "already loaded".
    CHECK_THAT(over.output, !Contains("already loaded: over.png"));
}

TEST_CASE("a full disk leaves the finished images listed and no file of an unfinished one",
          "[output][disk]") {
    TempDir dir("reliability-disk");
    const std::string out = dir.file("small");
    std::filesystem::create_directories(out);
    // A 180 KB file system of its own, in a mount namespace of its own:
    // room for a few frames of these four files (the depth EXR stored
    // uncompressed), not for thirty.
    const std::string inside = "mount -t tmpfs -o size=180k tmpfs " + shell_quote(out) +
                               " || exit 77; " + shell_quote(facet::test::facet_executable()) +
                               " render " + shell_quote(source_path("tests/scenes/shapes.yaml")) +
                               " --size 96x54 --frames 1-30 --allow-outside --passes color,depth "
                               "--formats png,exr -q -o " +
                               shell_quote(out) + " 2>&1; echo \"EXIT $?\"; ls -1 " +
                               shell_quote(out + "/shapes") + "; echo MANIFEST; cat " +
                               shell_quote(out + "/shapes/manifest.json");
    const RunResult r = run_command("unshare -m sh -c " + shell_quote(inside) + " 2>&1");
    if (r.exit_code == 77 || r.output.find("EXIT") == std::string::npos)
        FACET_SKIP("cannot mount a small file system here (needs root): " + r.output);
    INFO(r.output);
    CHECK_THAT(r.output, Contains("EXIT 4") && Contains("No space left on device") &&
                             Contains("images finished are listed in"));
    const size_t manifest_at = r.output.find("MANIFEST\n");
    REQUIRE(manifest_at != std::string::npos);
    const nlohmann::json manifest = nlohmann::json::parse(r.output.substr(manifest_at + 9));
    std::set<std::string> listed, on_disk;
    for (const auto& f : manifest["files"]) listed.insert(f["path"].get<std::string>());
    std::istringstream names(r.output.substr(r.output.find("EXIT 4\n") + 7,
                                             manifest_at - r.output.find("EXIT 4\n") - 7));
    for (std::string name; std::getline(names, name);)
        if (name != "manifest.json") on_disk.insert(name);
    // Some images finished, every one whole: four files each, all listed,
    // and nothing else on disk.
    CHECK(manifest["frames"].size() >= 1);
    CHECK(listed.size() == 4 * manifest["frames"].size());
    CHECK(on_disk == listed);
}
