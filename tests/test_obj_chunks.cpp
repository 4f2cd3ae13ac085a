// Wavefront OBJ files big enough to be read in parallel chunks
// (src/assets/obj_parse.cpp): the mesh is bit-identical for any thread
// count, relative indices and materials carry across chunk boundaries, and
// errors far into the file name their line and column.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "core/input_file.hpp"
#include "core/parallel_sort.hpp"
#include "core/thread_pool.hpp"

using namespace facet::test;

namespace {

// Enough lines for several 1 MB chunks, and more than the 4 MB from which
// the loader reads in parallel.
constexpr int kStrips = 60000;

// Strip i: three vertices at x = i, a texture coordinate and a normal for
// some, and faces that name them in every form OBJ has: absolute and
// relative, v, v/vt, v//vn and v/vt/vn, triangles and quads, with CRLF
// and comments mixed in (a comment after a face's corners is refused, as
// other readers do), and a material change every 997 strips.
std::string strips_obj() {
    std::string text = "mtllib strips.mtl\n# strips\n";
    text.reserve(size_t(kStrips) * 120);
    int vertices = 0;
    for (int i = 0; i < kStrips; ++i) {
        const std::string x = std::to_string(i);
        text += "v " + x + " 0 0\nv " + x + " 1.5 0\r\nv " + x + ".0 0 -2.25e0\n";
        text += "vt 0." + std::to_string(i % 10) + " 1\nvn 1 0 0\n";
        vertices += 3;
        if (i % 997 == 0) text += std::string("usemtl ") + (i % 2 ? "odd" : "even") + "\n";
        switch (i % 4) {
            case 0:
                text += "f -3 -2 -1\n";
                break;
            case 1:
                text += "f -3/-1 -2/-1 -1/-1\n# a comment\n";
                break;
            case 2:
                text += "f " + std::to_string(vertices - 2) + "//" + std::to_string(i + 1) + " " +
                        std::to_string(vertices - 1) + "//-1 " + std::to_string(vertices) +
                        "//-1\n";
                break;
            default:  // a quad with the strip before: two triangles
                text += "f -6/-1/-1 -3/-1/-1 -1/-1/-1 -4/-1/-1\n";
                break;
        }
    }
    return text;
}

struct StripsFile {
    TempDir dir{"obj-chunks"};
    std::string path;
    StripsFile() {
        write_text(dir.file("strips.mtl"), "newmtl even\nKd 1 0 0\nnewmtl odd\nKd 0 0 1\n");
        path = write_text(dir.file("strips.obj"), strips_obj());
    }
};

facet::Mesh load_with_threads(const std::string& path, unsigned threads) {
    facet::AssetContext context;
    context.threads = threads;
    return facet::load_obj(path, context);
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void require_identical(const facet::Mesh& a, const facet::Mesh& b) {
    REQUIRE(a.parts.size() == b.parts.size());
    for (size_t p = 0; p < a.parts.size(); ++p) {
        INFO("part " << p);
        CHECK(a.parts[p].material == b.parts[p].material);
        CHECK(same_bytes(a.parts[p].positions, b.parts[p].positions));
        CHECK(same_bytes(a.parts[p].normals, b.parts[p].normals));
        CHECK(same_bytes(a.parts[p].uvs, b.parts[p].uvs));
        CHECK(same_bytes(a.parts[p].indices, b.parts[p].indices));
    }
    CHECK(a.warnings.size() == b.warnings.size());
}

}  // namespace

TEST_CASE("OBJ read in chunks is bit-identical on any number of threads", "[assets][obj]") {
    const StripsFile file;
    const facet::Mesh one = load_with_threads(file.path, 1);
    check_sane(one);
    // Three strips in four are a triangle, the fourth a quad.
    CHECK(one.triangle_count() == size_t(kStrips) / 4 * 5);
    for (unsigned threads : {2u, 3u, 0u}) {
        DYNAMIC_SECTION(threads << " threads") {
            require_identical(one, load_with_threads(file.path, threads));
        }
    }
}

TEST_CASE("OBJ chunks resolve relative indices and materials across their seams", "[assets][obj]") {
    const StripsFile file;
    const facet::Mesh mesh = load_with_threads(file.path, 2);
    std::map<std::string, size_t> by_material;
    std::set<float> strips;
    for (const auto& part : mesh.parts) {
        by_material[material_of(mesh, part).name] += part.triangle_count();
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            const glm::vec3 a = corner(part, t, 0), b = corner(part, t, 1), c = corner(part, t, 2);
            // A triangle of one strip lies in the plane x = i; a quad's
            // triangles join strip i - 1 to strip i.
            const float low = std::min({a.x, b.x, c.x}), high = std::max({a.x, b.x, c.x});
            INFO("triangle " << t << " at x " << low << ".." << high);
            CHECK((high == low || high == low + 1));
            strips.insert(high);
        }
    }
    CHECK(strips.size() == size_t(kStrips));
    CHECK(*strips.rbegin() == float(kStrips - 1));
    // usemtl every 997 strips: even, odd, even...; the file has no default faces.
    CHECK(by_material.size() == 2);
    CHECK(by_material["even"] + by_material["odd"] == mesh.triangle_count());
    CHECK(by_material["even"] > by_material["odd"]);
}

TEST_CASE("OBJ errors far into a chunked file name their line and column", "[assets][obj]") {
    TempDir dir("obj-chunks");
    std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 600000; ++i) body += "f 1 2 3\n";  // lines 4 .. 600003: 4.8 MB
    struct Case {
        const char* name;
        std::string line;  // line 600004
        const char* message;
    };
    const std::vector<Case> cases = {
        {"a word in a vertex", "v 1 nan 0\n", "bad.obj:600004:5: 'nan' is not a finite number"},
        {"a zero index", "f 1 0 2\n", "bad.obj:600004:5: '0' is not a vertex reference"},
        {"a vertex past the end", "f 1 2 9\n", "bad.obj:600004:7: '9' refers to vertex 9"},
        {"a relative index before the first", "f -1 -2 -4\n",
         "bad.obj:600004:9: '-4' counts back past the first vertex"},
        {"a coordinate too large for a float", "v 1e39 0 0\n",
         "bad.obj:600004:3: '1e39' is too large for a float"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const std::string path = write_text(dir.file("bad.obj"), body + c.line + "f 1 2 3\n");
            require_input_error([&] { load_with_threads(path, 2); }, c.message);
        }
    }
}

TEST_CASE("OBJ notes what it reads but does not draw, naming the first place", "[assets][obj]") {
    TempDir dir("obj");
    const std::string path =
        write_text(dir.file("notes.obj"),
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
                   "f 1 2\nf 1//1 2//7 3//1\nf 1/1/1 2/9/1 3/1/1\nf 1/1 2/1 3/-5\nf 3\n");
    const facet::Mesh mesh = facet::load_obj(path);
    CHECK(mesh.triangle_count() == 3);
    std::vector<std::string> text;
    for (const auto& w : mesh.warnings) text.push_back(w.describe());
    REQUIRE(text.size() == 3);
    CHECK_THAT(text[0], Catch::StartsWith(path + ":6:1: a face of fewer than three corners"));
    CHECK_THAT(text[0], Catch::Contains("(and 1 more)"));
    CHECK_THAT(text[1], Catch::StartsWith(path + ":8:9: '2/9/1' names a texture coordinate"));
    CHECK_THAT(text[1], Catch::Contains("(and 1 more)"));
    CHECK_THAT(text[2], Catch::StartsWith(path + ":7:8: '2//7' names a normal"));
}

TEST_CASE("OBJ numbers: what other readers make of odd words", "[assets][obj]") {
    TempDir dir("obj");
    // "+1" is 1, "-" and "1e" are no numbers (0), a number below the
    // smallest float is 0, a CR alone ends a line (old Mac files), and a
    // NUL ends a line's data.
    const std::string path = write_text(
        dir.file("odd.obj"), std::string("v +1 - 1e\rv 1e-60 2 0\rv 0 0 3 # comment\r\nv 5 5 5") +
                                 '\0' + " 9\nf 1 2 3\n");
    const facet::Mesh mesh = facet::load_obj(path);
    REQUIRE(mesh.triangle_count() == 1);
    const auto& part = mesh.parts[0];
    CHECK(corner(part, 0, 0) == glm::vec3(1, 0, 0));
    CHECK(corner(part, 0, 1) == glm::vec3(0, 2, 0));
    CHECK(corner(part, 0, 2) == glm::vec3(0, 0, 3));
}

namespace {

// A grid of n x n quads folded up and down at every other column (a crease
// at each), with a seam down the middle: the vertices of column n / 2 are
// repeated, with other texture coordinates, so that only the weld by
// position joins the two sides. Enough vertices for many ranges, and
// enough split corners to sort on several threads.
facet::MeshPart folded_grid(int n) {
    facet::MeshPart part;
    auto vertex = [&](int x, int y, float u) {
        part.positions.push_back({float(x), float(y), (x % 2) * 1.5f});
        part.uvs.push_back({u, float(y) / float(n)});
        part.colors.push_back({float(x % 7) / 7, float(y % 5) / 5, 0.5f});
    };
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) vertex(x, y, float(x) / float(n));
    const uint32_t seam = static_cast<uint32_t>(part.positions.size());
    for (int y = 0; y <= n; ++y) vertex(n / 2, y, 2.0f);
    auto at = [&](int x, int y) {
        if (x == n / 2 && y % 3 == 0) return seam + static_cast<uint32_t>(y);
        return static_cast<uint32_t>(y * (n + 1) + x);
    };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = at(x, y), b = at(x + 1, y), c = at(x, y + 1), d = at(x + 1, y + 1);
            part.indices.insert(part.indices.end(), {a, b, d, a, d, c});
        }
    part.normals.assign(part.positions.size(), glm::vec3(0));
    return part;
}

}  // namespace

TEST_CASE("Normals computed on a pool are those computed on one thread", "[assets][normals]") {
    const facet::MeshPart grid = folded_grid(300);
    facet::MeshPart part = grid;
    uint64_t work = 0;
    std::vector<uint32_t> source;
    facet::compute_normals(part, 30.0f, &source, &work);
    // Every fold splits its column of vertices in two.
    CHECK(part.positions.size() > grid.positions.size() * 3 / 2);
    for (unsigned threads : {2u, 3u, 4u}) {
        DYNAMIC_SECTION(threads << " threads") {
            facet::MeshPart pooled = grid;
            uint64_t pooled_work = 0;
            std::vector<uint32_t> pooled_source;
            facet::ThreadPool pool(threads);
            facet::compute_normals(pooled, 30.0f, &pooled_source, &pooled_work, &pool);
            CHECK(same_bytes(part.positions, pooled.positions));
            CHECK(same_bytes(part.normals, pooled.normals));
            CHECK(same_bytes(part.uvs, pooled.uvs));
            CHECK(same_bytes(part.colors, pooled.colors));
            CHECK(same_bytes(part.indices, pooled.indices));
            CHECK(source == pooled_source);
            CHECK(work == pooled_work);
        }
    }
}

TEST_CASE("Normals split a vertex once per normal, numbered in order of first use",
          "[assets][normals]") {
    const facet::MeshPart grid = folded_grid(120);
    facet::MeshPart part = grid;
    std::vector<uint32_t> source;
    facet::ThreadPool pool(3);
    facet::compute_normals(part, 30.0f, &source, nullptr, &pool);
    REQUIRE(part.indices.size() == grid.indices.size());
    // Corners of one old vertex with the same normal bits share a new one,
    // others do not, and new vertices appear in corner order.
    std::map<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>, uint32_t> vertex_of;
    uint32_t next = 0;
    for (size_t c = 0; c < part.indices.size(); ++c) {
        const uint32_t v = part.indices[c];
        const glm::vec3 n = part.normals[v];
        uint32_t bits[3];
        std::memcpy(bits, &n, sizeof bits);
        const auto key = std::tuple(grid.indices[c], bits[0], bits[1], bits[2]);
        const auto [it, added] = vertex_of.emplace(key, next);
        if (added) ++next;
        INFO("corner " << c);
        REQUIRE(v == it->second);
        REQUIRE(source[v] == grid.indices[c]);
    }
    CHECK(next == part.positions.size());
}

TEST_CASE("parallel_sort sorts as std::sort does on any number of threads", "[core][sort]") {
    // Few distinct keys, so that runs hold long stretches of equal keys
    // that only the index tells apart.
    std::vector<std::pair<uint32_t, uint32_t>> items;
    uint32_t state = 12345;
    for (uint32_t i = 0; i < 200000; ++i) {
        state = state * 1664525u + 1013904223u;
        items.push_back({state >> 28, i});
    }
    std::vector<std::pair<uint32_t, uint32_t>> expected = items;
    std::sort(expected.begin(), expected.end());
    for (unsigned threads : {1u, 2u, 3u, 4u, 5u}) {
        DYNAMIC_SECTION(threads << " threads") {
            std::vector<std::pair<uint32_t, uint32_t>> sorted = items;
            facet::ThreadPool pool(threads);
            facet::parallel_sort(sorted, std::less<>(), &pool);
            CHECK(sorted == expected);
        }
    }
}

namespace {

// The folded grid as an OBJ file without normals (facet computes them),
// its seam written as texture coordinates of its own: some 9 MB, read in
// parallel.
std::string folded_grid_obj(const std::string& line_end) {
    const facet::MeshPart grid = folded_grid(600);
    std::string text;
    text.reserve(grid.indices.size() * 20);
    char line[96];
    for (size_t v = 0; v < grid.positions.size(); ++v) {
        const glm::vec3 p = grid.positions[v];
        const glm::vec2 uv = grid.uvs[v];
        text += std::string(line, std::snprintf(line, sizeof line, "v %g %g %g", p.x, p.y, p.z));
        text += line_end;
        text += std::string(line, std::snprintf(line, sizeof line, "vt %g %g", uv.x, uv.y));
        text += line_end;
    }
    for (size_t t = 0; t < grid.indices.size(); t += 3) {
        const uint32_t a = grid.indices[t] + 1, b = grid.indices[t + 1] + 1,
                       c = grid.indices[t + 2] + 1;
        // The seam's vertices are positions of their own, at the places of
        // the grid's: only the weld by position joins them.
        text += std::string(
            line, std::snprintf(line, sizeof line, "f %u/%u %u/%u %u/%u", a, a, b, b, c, c));
        text += line_end;
    }
    return text;
}

}  // namespace

TEST_CASE("OBJ normals, seams and creases are bit-identical on any number of threads",
          "[assets][obj]") {
    TempDir dir("obj-chunks");
    const std::string path = write_text(dir.file("folded.obj"), folded_grid_obj("\n"));
    const facet::Mesh one = load_with_threads(path, 1);
    check_sane(one);
    for (unsigned threads : {2u, 3u, 0u}) {
        DYNAMIC_SECTION(threads << " threads") {
            require_identical(one, load_with_threads(path, threads));
        }
    }
    // Lone CRs (old Mac files) make the reader clean the whole text first.
    SECTION("CR line ends") {
        const std::string cr = write_text(dir.file("folded-cr.obj"), folded_grid_obj("\r"));
        require_identical(one, load_with_threads(cr, 2));
    }
}

TEST_CASE("A file read by ranges says when it no longer holds a range", "[assets][obj]") {
    TempDir dir("obj-chunks");
    const std::string path = write_text(dir.file("short.obj"), "v 0 0 0\n");
    const facet::InputFileReader file(path, "OBJ");
    REQUIRE(file.size() == 8);
    char bytes[16];
    file.read_at(0, bytes, 8);
    CHECK(std::string(bytes, 8) == "v 0 0 0\n");
    // As when the file is cut short between the first pass and the second.
    require_error([&] { file.read_at(4, bytes, 8); }, facet::ExitCode::io_failure,
                  "was cut short while it was read");
}

TEST_CASE("OBJ line, point and free-form elements are named as not drawn", "[assets][obj]") {
    TempDir dir("obj");
    const std::string path = write_text(dir.file("elements.obj"),
                                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\np 3\nl 2 3\n"
                                        "cstype bspline\ncurv 0 1 1 2\nend\n");
    const facet::Mesh mesh = facet::load_obj(path);
    CHECK(mesh.triangle_count() == 1);
    std::vector<std::string> text;
    for (const auto& w : mesh.warnings) text.push_back(w.describe());
    REQUIRE(text.size() == 2);
    CHECK_THAT(text[0], Catch::StartsWith(path + ":5:1: line ('l') and point ('p') elements"));
    CHECK_THAT(text[0], Catch::Contains("(and 2 more)"));
    CHECK_THAT(text[1], Catch::StartsWith(path + ":9:1: free-form curves and surfaces"));
}
