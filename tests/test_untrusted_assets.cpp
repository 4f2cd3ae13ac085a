// Assets nobody on the team has opened: files crafted to make facet hang,
// exhaust memory or read files outside their folder. Each case is the
// reproducer of a fault once found; facet must stop with a clear error or
// finish, within bounded time and memory. The command-line cases run under
// a CPU-time and address-space limit (run_facet_limited), so a regression
// fails the test instead of hanging the suite or the machine.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "assets/polygon_triangulation.hpp"
#include "assets/texture.hpp"
#include "core/input_file.hpp"
#include "output/atomic_file.hpp"
#include "output/deflate.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

namespace fs = std::filesystem;

// `count` copies of one triangle: every face shares all three vertices.
std::string degenerate_obj(size_t count) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    text.reserve(text.size() + 8 * count);
    for (size_t i = 0; i < count; ++i) text += "f 1 2 3\n";
    return text;
}

// `count` star polygons of `points` tips each: concave faces that make ear
// clipping search long for an ear.
std::string star_obj(int count, int points) {
    std::string text;
    for (int s = 0; s < count; ++s) {
        for (int k = 0; k < 2 * points; ++k) {
            const double angle = 2 * 3.14159265358979 * k / (2 * points);
            const double r = (k % 2) ? 0.3 : 1.0;
            text += "v " + std::to_string(r * std::cos(angle)) + " " +
                    std::to_string(r * std::sin(angle)) + " " + std::to_string(s) + "\n";
        }
        text += "f";
        for (int k = 0; k < 2 * points; ++k) {
            text += ' ';
            text += std::to_string(s * 2 * points + k + 1);
        }
        text += "\n";
    }
    return text;
}

// A PNG of nothing but its signature and header: it claims width x height
// pixels. Loaders must judge the size before they decode anything.
std::vector<uint8_t> png_header_only(uint32_t width, uint32_t height) {
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto put32 = [](std::vector<uint8_t>& out, uint32_t v) {
        for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
    };
    std::vector<uint8_t> chunk = {'I', 'H', 'D', 'R'};
    put32(chunk, width);
    put32(chunk, height);
    chunk.insert(chunk.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA
    put32(png, 13);
    png.insert(png.end(), chunk.begin(), chunk.end());
    put32(png, facet::crc32(0, chunk.data(), chunk.size()));
    return png;
}

std::string make_fifo(const std::string& path) {
    REQUIRE(::mkfifo(path.c_str(), 0600) == 0);
    return path;
}

// A triangle OBJ that uses material `m` from `mtllib`.
std::string obj_with_mtllib(const std::string& mtllib) {
    return "mtllib " + mtllib +
           "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\n"
           "f 1/1 2/2 3/3\n";
}

// A one-triangle glTF whose buffer is the file `uri`.
std::string gltf_with_buffer_uri(const std::string& path, const std::string& uri) {
    Gltf g;
    g.buffer_uri = uri;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    return g.write(path);
}

std::string render_scene_of(const std::string& folder, const std::string& mesh,
                            const std::string& extra = "") {
    return write_text(folder + "/scene.yaml", "output: { size: [64, 48], frames: 1 }\n" + extra +
                                                  "objects:\n  - mesh: " + mesh + "\n");
}

}  // namespace

// --- Quadratic loading --------------------------------------------------------

TEST_CASE("normals of a million faces on one triangle take linear work", "[untrusted]") {
    MeshPart part;
    part.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const size_t faces = 1000000;
    for (size_t i = 0; i < faces; ++i) part.indices.insert(part.indices.end(), {0, 1, 2});
    uint64_t work = 0;
    compute_normals(part, 30.0f, nullptr, &work);
    // Linear means a few steps per corner; the old pairwise fan was 10^12.
    CHECK(work <= 40 * 3 * faces);
    REQUIRE(part.normals.size() == part.positions.size());
    for (glm::vec3 n : part.normals) require_vec3(n, {0, 0, 1});
}

TEST_CASE("facet info on an OBJ of 200,000 copies of one face finishes", "[untrusted]") {
    TempDir dir("untrusted");
    const std::string obj = write_text(dir.file("d.obj"), degenerate_obj(200000));
    const RunResult r = run_facet_limited("info '" + obj + "'", 60, 4096);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("triangles"));
}

TEST_CASE("star polygons are triangulated in bounded time", "[untrusted]") {
    TempDir dir("untrusted");
    const std::string obj = write_text(dir.file("stars.obj"), star_obj(2000, 125));
    const Mesh mesh = load_mesh(obj);
    check_sane(mesh);
    // A 250-gon becomes 248 triangles, whichever method made them.
    size_t triangles = 0;
    for (const MeshPart& p : mesh.parts) triangles += p.indices.size() / 3;
    CHECK(triangles == 2000u * 248u);
}

TEST_CASE("a hostile polygon is triangulated in O(n^2) corner tests", "[untrusted]") {
    // A star: few ears, each found after many misses, O(n^3) corner tests
    // for plain ear clipping.
    for (const int tips : {25, 125, 500}) {
        INFO(tips << " tips");
        std::vector<glm::dvec3> star;
        for (int k = 0; k < 2 * tips; ++k) {
            const double angle = std::numbers::pi * k / tips, r = (k % 2) ? 0.3 : 1.0;
            star.push_back({r * std::cos(angle), r * std::sin(angle), 0});
        }
        uint64_t work = 0;
        const auto triangles = facet::triangulate_polygon(star, &work);
        CHECK(triangles.size() == star.size() - 2);
        // The budget of 8 n^2 ear tests, then one scan of the ring per cut.
        const uint64_t n = star.size();
        CHECK(work <= 9 * n * n);
        CHECK(work > 0);
    }
}

// --- Paths inside mesh files ----------------------------------------------------

TEST_CASE("mtllib outside the OBJ's folder is refused and names the switch", "[untrusted]") {
    TempDir dir("untrusted");
    write_text(dir.file("secret.mtl"), "newmtl m\nKd 1 0 0\n");
    const std::string obj = write_text(dir.file("models/a.obj"), obj_with_mtllib("../secret.mtl"));
    require_input_error([&] { load_mesh(obj); }, "outside the asset's folder");
    require_input_error([&] { load_mesh(obj); }, "--allow-asset-paths-outside");

    AssetContext allow;
    allow.paths.allow_outside = true;
    const Mesh mesh = load_mesh(obj, allow);
    REQUIRE(!mesh.materials.empty());
    require_vec3(glm::vec3(mesh.materials.back().color), {1, 0, 0});
}

TEST_CASE("mtllib /dev/zero is refused without reading it", "[untrusted]") {
    TempDir dir("untrusted");
    const std::string obj = write_text(dir.file("a.obj"), obj_with_mtllib("/dev/zero"));
    const RunResult refused = run_facet_limited("info '" + obj + "'", 30, 2048);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Catch::Contains("/dev/zero") && Catch::Contains("outside"));
    // Even when paths outside are allowed, a device is not a material library.
    const RunResult device =
        run_facet_limited("info --allow-asset-paths-outside '" + obj + "'", 30, 2048);
    CHECK(device.exit_code == 2);
    CHECK_THAT(device.output, Catch::Contains("not a regular file (a character device)"));
}

TEST_CASE("an absolute map_Kd path cannot make /etc/passwd a texture", "[untrusted]") {
    TempDir dir("untrusted");
    write_text(dir.file("a.mtl"), "newmtl m\nmap_Kd /etc/passwd\n");
    const std::string obj = write_text(dir.file("a.obj"), obj_with_mtllib("a.mtl"));
    require_input_error([&] { load_mesh(obj); }, "material 'm': map_Kd: '/etc/passwd'");
    require_input_error([&] { load_mesh(obj); }, "outside the asset's folder");
}

TEST_CASE("a FIFO as map_Kd is refused instead of blocking", "[untrusted]") {
    TempDir dir("untrusted");
    make_fifo(dir.file("pipe.png"));
    write_text(dir.file("a.mtl"), "newmtl m\nmap_Kd pipe.png\n");
    const std::string obj = write_text(dir.file("a.obj"), obj_with_mtllib("a.mtl"));
    const RunResult r = run_facet_limited("info '" + obj + "'", 30, 2048);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("pipe.png") && Catch::Contains("(a FIFO)"));
}

TEST_CASE("a symbolic link inside the folder that points out of it is outside", "[untrusted]") {
    TempDir dir("untrusted");
    write_text(dir.file("outside.mtl"), "newmtl m\nKd 0 1 0\n");
    fs::create_directories(dir.file("models"));
    fs::create_symlink(dir.file("outside.mtl"), dir.file("models/inside.mtl"));
    const std::string obj = write_text(dir.file("models/a.obj"), obj_with_mtllib("inside.mtl"));
    require_input_error([&] { load_mesh(obj); }, "outside the asset's folder");
}

TEST_CASE("glTF buffer URIs that are not files in the folder are refused", "[untrusted]") {
    TempDir dir("untrusted");
    fs::create_directories(dir.file("models/folder.bin"));
    make_fifo(dir.file("models/pipe.bin"));
    write_bytes(dir.file("outside.bin"), bytes_of(kTriangle));
    struct Case {
        std::string uri, message;
    };
    const Case cases[] = {
        {"folder.bin", "is a directory"},
        {"pipe.bin", "(a FIFO)"},
        {"../outside.bin", "outside the asset's folder"},
        {dir.file("outside.bin"), "outside the asset's folder"},
        {"missing.bin", "no such file"},
    };
    for (const Case& c : cases) {
        INFO(c.uri);
        const std::string gltf = gltf_with_buffer_uri(dir.file("models/a.gltf"), c.uri);
        require_input_error([&] { load_mesh(gltf); }, c.message);
    }
}

TEST_CASE("allowing outside paths loads a glTF buffer from the parent folder", "[untrusted]") {
    TempDir dir("untrusted");
    write_bytes(dir.file("shared.bin"), bytes_of(kTriangle));
    const std::string gltf = gltf_with_buffer_uri(dir.file("models/a.gltf"), "../shared.bin");
    require_input_error([&] { load_mesh(gltf); }, "outside the asset's folder");

    const std::string scene = render_scene_of(dir.path(), "models/a.gltf");
    CHECK(run_facet_limited("validate '" + scene + "'", 30, 2048).exit_code == 2);
    CHECK(run_facet_limited("validate --allow-asset-paths-outside '" + scene + "'", 30, 2048)
              .exit_code == 0);
    render_scene_of(dir.path(), "models/a.gltf", "assets: { allow_paths_outside: true }\n");
    CHECK(run_facet_limited("validate '" + scene + "'", 30, 2048).exit_code == 0);
}

// --- Texture budget -------------------------------------------------------------

TEST_CASE("a PNG claiming 16384 x 16384 pixels is refused before decoding", "[untrusted]") {
    TempDir dir("untrusted");
    const std::string png = write_bytes(dir.file("huge.png"), png_header_only(16384, 16384));
    TextureBudget budget(kDefaultTextureBudget);
    // 16384^2 RGBA bytes with mipmaps is about 1.3 GB, over the 1 GB default.
    require_input_error([&] { load_texture(png, &budget); }, "huge.png");
    require_input_error([&] { load_texture(png, &budget); }, "texture_budget_mb");
    CHECK(budget.used() == 0);
}

TEST_CASE("textures are charged to one budget until it runs out", "[untrusted]") {
    TempDir dir("untrusted");
    ColorImage image(64, 64);
    const std::string a = write_png(dir.file("a.png"), image);
    const std::string b = write_png(dir.file("b.png"), image);
    const std::string c = write_png(dir.file("c.png"), image);
    const uint64_t one = texture_bytes(64, 64, 8);
    // While it decodes a PNG, stb holds two images of four channels at
    // most, and the file: charged for that time, then given back.
    const uint64_t decoding = 2 * 64 * 64 * 4 + fs::file_size(a);
    TextureBudget budget(2 * one + decoding);
    load_texture(a, &budget);
    load_texture(b, &budget);
    CHECK(budget.used() == 2 * one);
    require_input_error([&] { load_texture(c, &budget); }, "c.png");
    require_input_error([&] { load_texture(c, &budget); }, "a.png");  // the largest so far
    CHECK(budget.used() == 2 * one);  // the refused texture took nothing
    // Two fit only with the room to decode the second.
    TextureBudget tight(2 * one + decoding - 1);
    load_texture(a, &tight);
    require_input_error([&] { load_texture(b, &tight); }, "b.png (while decoding)");
    CHECK(tight.used() == one);
}

TEST_CASE("the scene's texture budget stops a render with a clear error", "[untrusted]") {
    TempDir dir("untrusted");
    write_bytes(dir.file("huge.png"), png_header_only(8192, 8192));
    write_text(dir.file("a.mtl"), "newmtl m\nmap_Kd huge.png\n");
    write_text(dir.file("a.obj"), obj_with_mtllib("a.mtl"));
    const std::string scene =
        render_scene_of(dir.path(), "a.obj", "assets: { texture_budget_mb: 64 }\n");
    const RunResult r = run_facet_limited("validate '" + scene + "'", 30, 2048);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("huge.png") && Catch::Contains("8192"));
}

// --- Messages that say what is wrong ----------------------------------------------

TEST_CASE("a mesh path that is no file says what it is", "[untrusted]") {
    TempDir dir("untrusted");
    fs::create_directories(dir.file("folder.obj"));
    make_fifo(dir.file("pipe.obj"));
    fs::create_symlink(dir.file("loop-b.obj"), dir.file("loop-a.obj"));
    fs::create_symlink(dir.file("loop-a.obj"), dir.file("loop-b.obj"));
    const std::pair<std::string, std::string> cases[] = {
        {"folder.obj", "is a directory"},
        {"pipe.obj", "is not a regular file (a FIFO)"},
        {"loop-a.obj", "symbolic link loop"},
        {"missing.obj", "no such file"},
    };
    for (const auto& [mesh, message] : cases) {
        INFO(mesh);
        const RunResult r =
            run_facet_limited("validate '" + render_scene_of(dir.path(), mesh) + "'", 30, 2048);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Catch::Contains(mesh) && Catch::Contains(message));
    }
}

TEST_CASE("deeply nested YAML is reported as such", "[untrusted]") {
    TempDir dir("untrusted");
    const std::string scene =
        write_text(dir.file("deep.yaml"), "objects: " + std::string(100000, '[') + "\n");
    const RunResult r = run_facet_limited("validate '" + scene + "'", 30, 2048);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("deep.yaml") && Catch::Contains("nested too deeply"));
}

TEST_CASE("a directory given as the scene says so", "[untrusted]") {
    TempDir dir("untrusted");
    const RunResult r = run_facet_limited("validate '" + dir.path() + "'", 30, 2048);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("is a directory"));
}

// --- Memory and half-written files -------------------------------------------------

TEST_CASE("a render too big for the memory limit stops before it starts", "[untrusted]") {
    // The limit is an address-space limit, which AddressSanitizer's shadow
    // memory rules out; the default build runs this case.
    if (kAddressSanitizer) FACET_SKIP("the address-space limit cannot hold under AddressSanitizer");
    TempDir dir("untrusted");
    const std::string scene = write_text(dir.file("big.yaml"),
                                         "output: { size: [8000, 8000], frames: 1, samples: 4 }\n"
                                         "style: toon-outline\nobjects:\n  - primitive: sphere\n");
    const RunResult r =
        run_facet_limited("render '" + scene + "' --out '" + dir.file("out") + "'", 60, 1024);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Catch::Contains("needs about") && Catch::Contains("available"));
    CHECK(!fs::exists(dir.file("out")));
}

TEST_CASE("temporaries of dead runs on this host are removed, others kept", "[untrusted]") {
    TempDir dir("untrusted");
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    // A pid that is not running: fork a child and wait for it to end.
    const pid_t dead = ::fork();
    if (dead == 0) ::_exit(0);
    ::waitpid(dead, nullptr, 0);
    const std::string stale = write_text(
        dir.file(".a.png.facet-tmp." + std::string(host) + "." + std::to_string(dead)), "x");
    const std::string live = write_text(
        dir.file(".b.png.facet-tmp." + std::string(host) + "." + std::to_string(::getpid())), "x");
    const std::string other_host =
        write_text(dir.file(".c.png.facet-tmp.some-other-host." + std::to_string(dead)), "x");
    const std::string unrelated = write_text(dir.file("notes.facet-tmp.txt"), "x");
    CHECK(remove_stale_temporaries(dir.path()) == 1);
    CHECK(!fs::exists(stale));
    CHECK(fs::exists(live));
    CHECK(fs::exists(other_host));
    CHECK(fs::exists(unrelated));
}
