// manifest.json writing, reading and merging (docs/scene-format.md, "manifest.json"), and the
// atomic file writer everything in output/ goes through.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <set>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"
#include "support.hpp"

using facet::Manifest;
using facet::ManifestFile;
using facet::ManifestFrame;
using facet::test::read_file;
using facet::test::require_error;
using facet::test::TempDir;
using facet::test::write_text;
namespace fs = std::filesystem;

namespace {

// A manifest for `frames` of `scene`, one colour PNG per frame, with a digest
// that encodes the tag so that replaced entries can be told apart.
Manifest make_manifest(const std::string& scene, std::vector<int> frames, const std::string& tag,
                       int width = 64, int height = 48) {
    Manifest m;
    m.scene = scene;
    m.style = "flat";
    m.width = width;
    m.height = height;
    m.threads = 2;
    for (int f : frames) {
        m.frames.push_back({f, "main", 10.0 + f, 1.0 + f});
        m.files.push_back({f, "main", "color", "png", "color." + std::to_string(f) + ".png",
                           tag + std::to_string(f)});
    }
    return m;
}

std::vector<int> frame_numbers(const Manifest& m) {
    std::vector<int> out;
    for (const auto& f : m.frames) out.push_back(f.frame);
    return out;
}

std::vector<int> file_frames(const Manifest& m) {
    std::vector<int> out;
    for (const auto& f : m.files) out.push_back(f.frame);
    return out;
}

// Names of the entries of a folder, temporary files included.
std::vector<std::string> entries(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

bool has_temp_files(const std::string& dir) {
    for (const auto& name : entries(dir))
        if (name.find(".facet-tmp.") != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("a manifest reads back as it was written", "[manifest]") {
    TempDir dir("manifest");
    std::string path = dir.file("manifest.json");
    Manifest m;
    m.scene = "scenes/turntable.yaml";
    m.style = "gouraud";
    m.width = 320;
    m.height = 240;
    m.threads = 3;
    m.frames = {{1, "main", 12.5, 0.25}, {2, "side", 0.1, 3.0}};
    m.files = {{1, "main", "color", "png", "color.0001.png", std::string(64, 'a')},
               {1, "main", "depth", "exr", "depth.0001.exr", std::string(64, 'b')},
               {2, "side", "color", "png", "color.0002.png", std::string(64, 'c')}};
    facet::write_manifest(path, m);

    Manifest r = facet::read_manifest(path);
    CHECK(r.scene == m.scene);
    CHECK(r.style == m.style);
    CHECK(r.width == 320);
    CHECK(r.height == 240);
    CHECK(r.threads == 3);
    REQUIRE(r.frames.size() == 2);
    CHECK(r.frames[0].frame == 1);
    CHECK(r.frames[0].camera == "main");
    CHECK(r.frames[1].camera == "side");
    CHECK(r.frames[0].render_ms == 12.5);
    CHECK(r.frames[0].encode_ms == 0.25);
    CHECK(r.frames[1].frame == 2);
    CHECK(r.frames[1].render_ms == Approx(0.1));
    CHECK(r.frames[1].encode_ms == 3.0);
    REQUIRE(r.files.size() == 3);
    for (size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        CHECK(r.files[i].frame == m.files[i].frame);
        CHECK(r.files[i].pass == m.files[i].pass);
        CHECK(r.files[i].format == m.files[i].format);
        CHECK(r.files[i].path == m.files[i].path);
        CHECK(r.files[i].sha256 == m.files[i].sha256);
    }
}

TEST_CASE("the manifest file has the documented JSON layout", "[manifest]") {
    TempDir dir("manifest");
    std::string path = dir.file("manifest.json");
    facet::write_manifest(path, make_manifest("a.yaml", {2, 1}, "x"));

    nlohmann::json j = nlohmann::json::parse(read_file(path));
    CHECK(j.at("scene") == "a.yaml");
    CHECK(j.at("style") == "flat");
    CHECK(j.at("size") == nlohmann::json::array({64, 48}));
    REQUIRE(j.at("frames").is_array());
    REQUIRE(j.at("frames").size() == 2);
    // Entries are written in frame order whatever order they came in.
    CHECK(j["frames"][0].at("frame") == 1);
    CHECK(j["frames"][1].at("frame") == 2);
    CHECK(j.at("manifest_version") == 2);
    CHECK(j["timings"]["frames"][0].at("render_ms") == 11.0);
    CHECK(j["timings"]["frames"][0].at("encode_ms") == 2.0);
    CHECK(j["timings"].at("threads") == 2);
    REQUIRE(j.at("files").size() == 2);
    for (const auto& f : j["files"]) {
        CHECK(f.at("frame").is_number_integer());
        CHECK(f.at("pass") == "color");
        CHECK(f.at("format") == "png");
        CHECK(f.at("path").is_string());
        CHECK(f.at("sha256").is_string());
    }
    CHECK(j["files"][0].at("path") == "color.1.png");
}

TEST_CASE("manifests for pieces of a sequence merge into one", "[manifest]") {
    TempDir dir("manifest");
    std::string path = dir.file("manifest.json");

    SECTION("frames 1-2 then 3-4 keep all four") {
        facet::write_manifest(path, make_manifest("a.yaml", {1, 2}, "first"));
        facet::write_manifest(path, make_manifest("a.yaml", {3, 4}, "second"));
        Manifest r = facet::read_manifest(path);
        CHECK(frame_numbers(r) == std::vector<int>{1, 2, 3, 4});
        CHECK(file_frames(r) == std::vector<int>{1, 2, 3, 4});
        CHECK(r.files[0].sha256 == "first1");
        CHECK(r.files[3].sha256 == "second4");
    }
    SECTION("pieces written out of order end sorted") {
        facet::write_manifest(path, make_manifest("a.yaml", {3, 4}, "late"));
        facet::write_manifest(path, make_manifest("a.yaml", {1, 2}, "early"));
        Manifest r = facet::read_manifest(path);
        CHECK(frame_numbers(r) == std::vector<int>{1, 2, 3, 4});
        CHECK(file_frames(r) == std::vector<int>{1, 2, 3, 4});
    }
    SECTION("a frame rendered again replaces its old entries") {
        facet::write_manifest(path, make_manifest("a.yaml", {1, 2, 3}, "old"));
        facet::write_manifest(path, make_manifest("a.yaml", {2}, "new"));
        Manifest r = facet::read_manifest(path);
        CHECK(frame_numbers(r) == std::vector<int>{1, 2, 3});
        REQUIRE(r.files.size() == 3);
        CHECK(r.files[0].sha256 == "old1");
        CHECK(r.files[1].sha256 == "new2");
        CHECK(r.files[2].sha256 == "old3");
        CHECK(r.frames[1].render_ms == 12.0);
    }
    SECTION("the newest run's style and thread count are recorded") {
        facet::write_manifest(path, make_manifest("a.yaml", {1}, "old"));
        Manifest second = make_manifest("a.yaml", {2}, "new");
        second.threads = 7;
        facet::write_manifest(path, second);
        CHECK(facet::read_manifest(path).threads == 7);
    }
}

TEST_CASE("a manifest of another scene or size replaces the old one", "[manifest]") {
    TempDir dir("manifest");
    std::string path = dir.file("manifest.json");
    facet::write_manifest(path, make_manifest("a.yaml", {1, 2}, "a"));

    SECTION("different scene") {
        facet::write_manifest(path, make_manifest("b.yaml", {3, 4}, "b"));
        Manifest r = facet::read_manifest(path);
        CHECK(r.scene == "b.yaml");
        CHECK(frame_numbers(r) == std::vector<int>{3, 4});
        CHECK(file_frames(r) == std::vector<int>{3, 4});
    }
    SECTION("different size") {
        facet::write_manifest(path, make_manifest("a.yaml", {3}, "small", 32, 24));
        Manifest r = facet::read_manifest(path);
        CHECK(r.width == 32);
        CHECK(frame_numbers(r) == std::vector<int>{3});
    }
    SECTION("an unreadable old manifest") {
        write_text(path, "{ this is not json");
        facet::write_manifest(path, make_manifest("a.yaml", {5}, "c"));
        CHECK(frame_numbers(facet::read_manifest(path)) == std::vector<int>{5});
    }
    CHECK_FALSE(has_temp_files(dir.path()));
}

TEST_CASE("reading something that is not a manifest fails cleanly", "[manifest]") {
    TempDir dir("manifest");
    SECTION("missing file is an I/O failure naming it") {
        std::string path = dir.file("nope.json");
        require_error([&] { facet::read_manifest(path); }, facet::ExitCode::io_failure, path);
    }
    SECTION("JSON without the manifest's keys is invalid input") {
        std::string path = write_text(dir.file("other.json"), R"({"scene": "a.yaml"})");
        require_error([&] { facet::read_manifest(path); }, facet::ExitCode::invalid_input, path);
    }
}

TEST_CASE("write_file_atomically writes and replaces whole files", "[atomic_file]") {
    TempDir dir("atomic");
    std::string path = dir.file("data.bin");

    SECTION("a new file gets exactly the bytes, zeros included") {
        std::vector<uint8_t> bytes = {0, 1, 2, 0, 255, 0};
        facet::write_file_atomically(path, bytes);
        std::string back = read_file(path);
        CHECK(std::vector<uint8_t>(back.begin(), back.end()) == bytes);
        CHECK(entries(dir.path()) == std::vector<std::string>{"data.bin"});
    }
    SECTION("an existing file is replaced, not appended to or partly overwritten") {
        write_text(path, std::string(1000, 'x'));
        facet::write_file_atomically(path, std::string("short"));
        CHECK(read_file(path) == "short");
        facet::write_file_atomically(path, std::string("second version"));
        CHECK(read_file(path) == "second version");
        CHECK(entries(dir.path()) == std::vector<std::string>{"data.bin"});
    }
    SECTION("an empty file") {
        facet::write_file_atomically(path, std::string());
        CHECK(fs::exists(path));
        CHECK(fs::file_size(path) == 0);
    }
    SECTION("readers holding the old file keep seeing the old contents") {
        // Replacing by rename leaves an open old file intact, unlike rewriting in place.
        write_text(path, "old contents");
        std::ifstream old(path, std::ios::binary);
        facet::write_file_atomically(path, std::string("new"));
        std::string seen((std::istreambuf_iterator<char>(old)), std::istreambuf_iterator<char>());
        CHECK(seen == "old contents");
        CHECK(read_file(path) == "new");
    }
    SECTION("a missing folder is an I/O failure that leaves nothing behind") {
        std::string bad = dir.file("no/such/folder/file.bin");
        require_error([&] { facet::write_file_atomically(bad, std::string("x")); },
                      facet::ExitCode::io_failure, bad);
        CHECK(entries(dir.path()).empty());
    }
    CHECK_FALSE(has_temp_files(dir.path()));
}

TEST_CASE("an atomic file set shows its files only once published, all together", "[atomic_file]") {
    TempDir dir("atomic-set");
    const std::string a = dir.file("a.bin"), b = dir.file("b.bin");
    const std::vector<uint8_t> bytes_a = {1, 2, 3}, bytes_b = {0, 255};
    SECTION("nothing under the names before publish, every file after") {
        facet::AtomicFileSet files;
        files.write(a, bytes_a);
        files.write(b, bytes_b);
        CHECK_FALSE(fs::exists(a));
        CHECK_FALSE(fs::exists(b));
        files.publish();
        CHECK(read_file(a) == "\x01\x02\x03");
        CHECK(read_file(b) == std::string("\x00\xff", 2));
        CHECK(files.published() == std::vector<std::string>{a, b});
        CHECK(entries(dir.path()) == std::vector<std::string>{"a.bin", "b.bin"});
    }
    SECTION("a set given up before publish leaves nothing, and an old file as it was") {
        write_text(a, "old");
        {
            facet::AtomicFileSet files;
            files.write(a, bytes_a);
            files.write(b, bytes_b);
        }
        CHECK(read_file(a) == "old");
        CHECK(entries(dir.path()) == std::vector<std::string>{"a.bin"});
    }
    SECTION("a name that cannot be replaced fails naming it; what was published is listed") {
        const std::string folder = dir.file("taken");
        facet::make_directories(folder);
        write_text(folder + "/inside", "x");  // a folder that is not empty: rename refuses it
        facet::AtomicFileSet files;
        files.write(a, bytes_a);
        files.write(folder, bytes_b);
        require_error([&] { files.publish(); }, facet::ExitCode::io_failure, folder);
        CHECK(files.published() == std::vector<std::string>{a});
        CHECK_FALSE(has_temp_files(dir.path()));
    }
}

namespace {

// System calls that fail where a test says (the set's seam, FileCalls):
// the Nth open, the Nth sync of a file, or the sync of a folder.
struct Faults {
    int fail_open = -1, fail_file_sync = -1;
    bool fail_folder_sync = false;
    int opens = 0, file_syncs = 0;
    std::set<int> folders;  // open descriptors of folders
};
Faults g_faults;  // the test's own: a plain function pointer captures nothing

int faulty_open(const char* path, int flags, mode_t mode) {
    if (g_faults.opens++ == g_faults.fail_open) {
        errno = ENOSPC;
        return -1;
    }
    const int fd = ::open(path, flags, mode);
    if (fd >= 0 && (flags & O_DIRECTORY)) g_faults.folders.insert(fd);
    return fd;
}
int faulty_fsync(int fd) {
    if (g_faults.folders.count(fd) ? g_faults.fail_folder_sync
                                   : g_faults.file_syncs++ == g_faults.fail_file_sync) {
        errno = EIO;
        return -1;
    }
    return ::fsync(fd);
}
int faulty_close(int fd) {
    g_faults.folders.erase(fd);
    return ::close(fd);
}
const facet::FileCalls kFaultyCalls{faulty_open,  ::write,  faulty_fsync,
                                    faulty_close, ::rename, ::unlink};

}  // namespace

TEST_CASE("an atomic file set publishes all of its files or none when a system call fails",
          "[atomic_file]") {
    TempDir dir("atomic-faults");
    const std::string a = dir.file("a.bin"), b = dir.file("b.bin");
    write_text(a, "old");
    g_faults = {};
    SECTION("a failed sync of the second file: nothing is published, the old file stays") {
        g_faults.fail_file_sync = 1;
        facet::AtomicFileSet files(kFaultyCalls);
        files.write(a, {1});
        files.write(b, {2});
        require_error([&] { files.publish(); }, facet::ExitCode::io_failure, b);
        CHECK(files.published().empty());
        CHECK(read_file(a) == "old");
        CHECK_FALSE(fs::exists(b));
    }
    SECTION("a path written twice: the second bytes win, and one temporary is used") {
        facet::AtomicFileSet files(kFaultyCalls);
        files.write(a, {1, 1});
        files.write(a, {2});
        files.publish();
        CHECK(read_file(a) == "\x02");
        CHECK(files.published() == std::vector<std::string>{a});
    }
    SECTION("a path written twice whose second open fails leaves no temporary behind") {
        g_faults.fail_open = 1;
        facet::AtomicFileSet files(kFaultyCalls);
        files.write(a, {1});
        require_error([&] { files.write(a, {2}); }, facet::ExitCode::io_failure, a);
        CHECK_FALSE(has_temp_files(dir.path()));
        CHECK(read_file(a) == "old");
    }
    SECTION("EIO on the folder's sync is an I/O failure naming the folder, after the renames") {
        g_faults.fail_folder_sync = true;
        facet::AtomicFileSet files(kFaultyCalls);
        files.write(a, {1});
        files.write(b, {2});
        require_error([&] { files.publish(); }, facet::ExitCode::io_failure, dir.path());
        CHECK(read_file(a) == "\x01");
        CHECK(read_file(b) == "\x02");
    }
    CHECK_FALSE(has_temp_files(dir.path()));
}

TEST_CASE("make_directories creates nested folders and accepts existing ones", "[atomic_file]") {
    TempDir dir("atomic");
    std::string nested = dir.file("a/b/c");
    facet::make_directories(nested);
    CHECK(fs::is_directory(nested));
    facet::make_directories(nested);  // again: no error
    CHECK(fs::is_directory(nested));

    // A plain file in the way is an I/O failure.
    std::string blocker = write_text(dir.file("file"), "x");
    CHECK_THROWS_AS(facet::make_directories(blocker + "/sub"), facet::Error);
}
