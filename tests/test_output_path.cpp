// Output file name templates (src/output/output_path.hpp, docs/output-naming.md):
// parsing and its errors, expansion, the collision check run before
// rendering, and where manifest.json goes.
#include <catch2/catch.hpp>

#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "output/output_path.hpp"

using facet::OutputNameFields;
using facet::Placeholder;

namespace {

OutputNameFields fields(int frame, const std::string& pass = "color",
                        const std::string& ext = "png", const std::string& camera = "main",
                        const std::string& scene = "shapes") {
    return OutputNameFields{scene, camera, pass, frame, ext};
}

std::string name(const std::string& text, const OutputNameFields& f) {
    return facet::expand(facet::parse_output_template(text), f);
}

// The message parse_output_template throws, or "" if it accepts the text.
std::string parse_error(const std::string& text) {
    try {
        facet::parse_output_template(text);
    } catch (const facet::Error& e) {
        return e.what();
    }
    return "";
}

// The message check_unique_outputs throws, or "" if every file is distinct.
std::string collision(const std::string& text, const std::vector<std::string>& cameras,
                      const std::vector<std::string>& passes, const std::vector<std::string>& exts,
                      const std::vector<int>& frames) {
    try {
        facet::check_unique_outputs(facet::parse_output_template(text), "shapes", cameras, passes,
                                    exts, frames);
    } catch (const facet::Error& e) {
        return e.what();
    }
    return "";
}

std::string manifest_dir(const std::string& text, bool single_camera = true) {
    return facet::manifest_directory(facet::parse_output_template(text), fields(0), single_camera);
}

using Catch::Matchers::Contains;

}  // namespace

TEST_CASE("the default template gives the names facet has always written", "[output][naming]") {
    // The naming before templates existed: <scene>/<pass>.<frame %04d>.<ext>.
    auto old_name = [](const std::string& scene, const std::string& pass, int frame,
                       const std::string& ext) {
        char number[32];
        std::snprintf(number, sizeof number, "%04d", frame);
        return scene + "/" + pass + "." + number + "." + ext;
    };
    for (int frame : {0, 1, 42, 999, 1000, 9999, 12345, 1000000}) {
        for (const char* pass : {"color", "depth"}) {
            for (const char* ext : {"png", "exr"}) {
                CHECK(name(facet::kDefaultOutputTemplate, fields(frame, pass, ext)) ==
                      old_name("shapes", pass, frame, ext));
            }
        }
    }
    CHECK(name(facet::kDefaultOutputTemplate, fields(1)) == "shapes/color.0001.png");
}

TEST_CASE("each placeholder is replaced by its field", "[output][naming]") {
    OutputNameFields f{"spheres", "top", "depth", 7, "exr"};
    CHECK(name("{scene}", f) == "spheres");
    CHECK(name("{camera}", f) == "top");
    CHECK(name("{pass}", f) == "depth");
    CHECK(name("{frame}", f) == "0007");
    CHECK(name("{ext}", f) == "exr");
    CHECK(name("renders/{scene}/{camera}/{pass}_{frame}.{ext}", f) ==
          "renders/spheres/top/depth_0007.exr");
    // Literals are copied as they are, including dots and characters braces do not touch.
    CHECK(name("shot-1.v2/{pass}", f) == "shot-1.v2/depth");
    // A placeholder may appear more than once.
    CHECK(name("{pass}/{pass}.{frame}.{frame:1}.{ext}", f) == "depth/depth.0007.7.exr");
}

TEST_CASE("uses reports which placeholders a template has", "[output][naming]") {
    auto t = facet::parse_output_template("{scene}/f####.{ext}");
    CHECK(t.uses(Placeholder::scene));
    CHECK(t.uses(Placeholder::frame));
    CHECK(t.uses(Placeholder::ext));
    CHECK_FALSE(t.uses(Placeholder::camera));
    CHECK_FALSE(t.uses(Placeholder::pass));

    auto d = facet::parse_output_template(facet::kDefaultOutputTemplate);
    CHECK(d.uses(Placeholder::scene));
    CHECK(d.uses(Placeholder::pass));
    CHECK(d.uses(Placeholder::frame));
    CHECK(d.uses(Placeholder::ext));
    CHECK_FALSE(d.uses(Placeholder::camera));
}

TEST_CASE("frame padding widths", "[output][naming]") {
    CHECK(name("{frame:06}", fields(42)) == "000042");
    CHECK(name("{frame:6}", fields(42)) == "000042");
    CHECK(name("{frame:1}", fields(42)) == "42");
    CHECK(name("{frame:01}", fields(0)) == "0");
    CHECK(name("{frame:9}", fields(1)) == "000000001");
    CHECK(name("{frame}", fields(0)) == "0000");
}

TEST_CASE("frame numbers wider than the padding are written in full", "[output][naming]") {
    CHECK(name("{frame:02}", fields(100)) == "100");
    CHECK(name("{frame}", fields(123456)) == "123456");
    CHECK(name("##", fields(12345)) == "12345");
    CHECK(name("{frame:1}", fields(std::numeric_limits<int>::max())) == "2147483647");
}

TEST_CASE("negative frames pad the digits and put the sign in front", "[output][naming]") {
    CHECK(name("{frame}", fields(-1)) == "-0001");
    CHECK(name("{frame:06}", fields(-42)) == "-000042");
    CHECK(name("###", fields(-5)) == "-005");
    CHECK(name("{frame:2}", fields(-12345)) == "-12345");
    CHECK(name("{frame:1}", fields(std::numeric_limits<int>::min())) == "-2147483648");
}

TEST_CASE("a run of '#' is the frame padded to that many digits", "[output][naming]") {
    CHECK(name("#", fields(7)) == "7");
    CHECK(name("f####.{ext}", fields(7)) == "f0007.png");
    CHECK(name("{scene}/######.{ext}", fields(7)) == "shapes/000007.png");
    CHECK(name("#########", fields(7)) == "000000007");
    // Two runs separated by a literal are two frame numbers.
    CHECK(name("##_###", fields(7)) == "07_007");
}

TEST_CASE("an empty template is rejected", "[output][naming]") {
    CHECK_THAT(parse_error(""), Contains("is empty"));
}

TEST_CASE("an unknown placeholder is rejected with the closest known name", "[output][naming]") {
    std::string message = parse_error("{scene}/{fram}.{ext}");
    CHECK_THAT(message, Contains("unknown placeholder '{fram}'"));
    CHECK_THAT(message, Contains("did you mean '{frame}'"));

    CHECK_THAT(parse_error("{cam}/{frame}"), Contains("did you mean '{camera}'"));
    CHECK_THAT(parse_error("{Scene}/{frame}"), Contains("did you mean '{scene}'"));
    CHECK_THAT(parse_error("{exts}.{frame}"), Contains("did you mean '{ext}'"));
    CHECK_THAT(parse_error("{frme}.png"), Contains("did you mean '{frame}'"));
    CHECK_THAT(parse_error("{scnee}.png"), Contains("did you mean '{scene}'"));
    CHECK_THAT(parse_error("{fram:04}.png"), Contains("unknown placeholder '{fram}'"));
    CHECK_THAT(parse_error("{passes}.{frame}"), Contains("did you mean '{pass}'"));

    // Far from every name: no guess, but the list of known names.
    message = parse_error("{foo}.{frame}");
    CHECK_THAT(message, Contains("unknown placeholder '{foo}'"));
    CHECK_THAT(message, !Contains("did you mean"));
    CHECK_THAT(message, Contains("{scene}, {camera}, {pass}, {frame}, {ext}"));

    CHECK_THAT(parse_error("{}.png"), Contains("unknown placeholder '{}'"));
}

TEST_CASE("an unclosed or unopened brace is rejected", "[output][naming]") {
    CHECK_THAT(parse_error("{scene}/{pass.png"), Contains("'{pass.png' has no closing '}'"));
    // A placeholder cannot span a '/' or hold another '{'.
    CHECK_THAT(parse_error("{scene/{pass}.png"), Contains("'{scene' has no closing '}'"));
    CHECK_THAT(parse_error("{scene{pass}.png"), Contains("'{scene' has no closing '}'"));
    CHECK_THAT(parse_error("{scene}}/{frame}"), Contains("'}' at character 8 has no opening '{'"));
}

TEST_CASE("a bad frame padding is rejected", "[output][naming]") {
    CHECK_THAT(parse_error("{frame:0}.png"), Contains("bad frame padding '{frame:0}'"));
    CHECK_THAT(parse_error("{frame:00}.png"), Contains("bad frame padding '{frame:00}'"));
    CHECK_THAT(parse_error("{frame:x}.png"), Contains("bad frame padding '{frame:x}'"));
    CHECK_THAT(parse_error("{frame:}.png"), Contains("bad frame padding '{frame:}'"));
    CHECK_THAT(parse_error("{frame:10}.png"), Contains("bad frame padding '{frame:10}'"));
    CHECK_THAT(parse_error("{frame:-4}.png"), Contains("bad frame padding '{frame:-4}'"));
    CHECK_THAT(parse_error("{frame: 4}.png"), Contains("bad frame padding '{frame: 4}'"));
    CHECK_THAT(parse_error("{frame:99999999999}.png"),
               Contains("bad frame padding '{frame:99999999999}'"));
    CHECK_THAT(parse_error("##########.png"), Contains("bad frame padding '##########'"));
    CHECK_THAT(parse_error("{frame:0}.png"), Contains("from 1 to 9"));
    CHECK(parse_error("{frame:4}.png").empty());
    // Only {frame} takes a width.
    CHECK_THAT(parse_error("{pass:04}.png"),
               Contains("'{pass:04}' has a padding width, but only {frame} takes one"));
}

TEST_CASE("paths that leave the output folder are rejected", "[output][naming]") {
    CHECK_THAT(parse_error("/tmp/{scene}/{frame}.png"), Contains("'/tmp/{scene}/{frame}.png'"));
    CHECK_THAT(parse_error("/tmp/{scene}/{frame}.png"), Contains("absolute path"));
    CHECK_THAT(parse_error("../{scene}/{frame}.png"), Contains("'..' would leave the output"));
    CHECK_THAT(parse_error("{scene}/../../{frame}.png"), Contains("'..'"));
    CHECK_THAT(parse_error("{scene}/.."), Contains("'..'"));
    CHECK_THAT(parse_error("./{scene}/{frame}.png"), Contains("'.' path component"));
    // Dots inside a name are only dots.
    CHECK(parse_error("..{frame}.png").empty());
    CHECK(parse_error("{scene}/...png").empty());
    CHECK(parse_error("{scene}/.hidden/{frame}.png").empty());
}

TEST_CASE("a template must end in a file name and have no empty component", "[output][naming]") {
    CHECK_THAT(parse_error("{scene}/"), Contains("ends in '/'"));
    CHECK_THAT(parse_error("{scene}/{pass}/"), Contains("'{scene}/{pass}/'"));
    CHECK_THAT(parse_error("a//{frame}.png"), Contains("empty path component ('//')"));
    CHECK_THAT(parse_error("a//{frame}.png"), Contains("'a//{frame}.png'"));
}

TEST_CASE("values that would break the path apart are rejected on expansion", "[output][naming]") {
    auto t = facet::parse_output_template("{scene}/{camera}/{frame}.{ext}");
    CHECK_THROWS_WITH(facet::expand(t, fields(1, "color", "png", "../up")),
                      Contains("{camera} is '../up', which contains '/'"));
    CHECK_THROWS_WITH(facet::expand(t, fields(1, "color", "png", "..")),
                      Contains("expands to 'shapes/../0001.png'"));
    CHECK_THROWS_WITH(facet::expand(t, fields(1, "color", "png", "")),
                      Contains("expands to 'shapes//0001.png'"));
    // A field the template does not use is never looked at.
    CHECK(name("{scene}/{frame}.{ext}", fields(1, "a/b", "png", "..")) == "shapes/0001.png");
}

TEST_CASE("a complete template writes every combination to its own file", "[output][naming]") {
    std::vector<int> frames = {-1, 0, 1, 2, 10, 100, 1000, 10000};
    CHECK(collision("{scene}/{camera}/{pass}.{frame}.{ext}", {"main", "top"}, {"color", "depth"},
                    {"png", "exr"}, frames) == "");
    CHECK(collision(facet::kDefaultOutputTemplate, {"main"}, {"color", "depth"}, {"png", "exr"},
                    frames) == "");
    // Padding narrower than the numbers does not make two frames the same.
    CHECK(collision("{frame:02}.png", {"main"}, {"color"}, {"png"}, {1, 10, 100, 1000}) == "");
    CHECK(collision("{frame:1}.png", {"main"}, {"color"}, {"png"}, {-1, 1, 11, -11}) == "");
    // A frame listed twice is the same file, not a collision.
    CHECK(collision(facet::kDefaultOutputTemplate, {"main"}, {"color"}, {"png"}, {1, 1}) == "");
    // Nothing rendered, nothing to collide.
    CHECK(collision("out.png", {"main"}, {"color"}, {"png"}, {}) == "");
    // One of everything: a template of literals only is fine.
    CHECK(collision("out.png", {"main"}, {"color"}, {"png"}, {1}) == "");
}

TEST_CASE("a template without a frame number collides over several frames", "[output][naming]") {
    std::string message = collision("{scene}/{pass}.{ext}", {"main"}, {"color"}, {"png"}, {1, 2});
    CHECK_THAT(message, Contains("writes 'shapes/color.png' for both"));
    CHECK_THAT(message, Contains("frame 1, camera 'main', pass 'color', ext 'png'"));
    CHECK_THAT(message, Contains("frame 2, camera 'main', pass 'color', ext 'png'"));
    CHECK_THAT(message, Contains("add {frame} or ####"));
    // One frame needs no frame number.
    CHECK(collision("{scene}/{pass}.{ext}", {"main"}, {"color"}, {"png"}, {5}) == "");
}

TEST_CASE("a template without {pass} collides when writing colour and depth", "[output][naming]") {
    std::string message =
        collision("{scene}/{frame}.{ext}", {"main"}, {"color", "depth"}, {"exr"}, {1, 2});
    CHECK_THAT(message, Contains("writes 'shapes/0001.exr'"));
    CHECK_THAT(message, Contains("pass 'color'"));
    CHECK_THAT(message, Contains("pass 'depth'"));
    CHECK_THAT(message, Contains("add {pass}"));
    CHECK(collision("{scene}/{frame}.{ext}", {"main"}, {"color"}, {"exr"}, {1, 2}) == "");
}

TEST_CASE("a template without {ext} collides when writing png and exr", "[output][naming]") {
    std::string message =
        collision("{scene}/{pass}.{frame}", {"main"}, {"color"}, {"png", "exr"}, {1});
    CHECK_THAT(message, Contains("writes 'shapes/color.0001'"));
    CHECK_THAT(message, Contains("ext 'png'"));
    CHECK_THAT(message, Contains("ext 'exr'"));
    CHECK_THAT(message, Contains("add {ext}"));
    CHECK(collision("{scene}/{pass}.{frame}", {"main"}, {"color"}, {"png"}, {1}) == "");
}

TEST_CASE("a template without {camera} collides when rendering two cameras", "[output][naming]") {
    std::string message =
        collision(facet::kDefaultOutputTemplate, {"main", "top"}, {"color"}, {"png"}, {1});
    CHECK_THAT(message, Contains("writes 'shapes/color.0001.png'"));
    CHECK_THAT(message, Contains("camera 'main'"));
    CHECK_THAT(message, Contains("camera 'top'"));
    CHECK_THAT(message, Contains("add {camera}"));
    CHECK(collision("{camera}/{pass}.{frame}.{ext}", {"main", "top"}, {"color"}, {"png"}, {1}) ==
          "");
}

TEST_CASE("placeholders that run together can collide through real string equality",
          "[output][naming]") {
    // "a1" + "1" and "a" + "11" are both "a11".
    std::string message =
        collision("{camera}{frame:1}.png", {"a1", "a"}, {"color"}, {"png"}, {1, 11});
    CHECK_THAT(message, Contains("writes 'a11.png'"));
    CHECK_THAT(message, Contains("separate them"));
    CHECK(collision("{camera}_{frame:1}.png", {"a1", "a"}, {"color"}, {"png"}, {1, 11}) == "");
}

TEST_CASE("an output file may not overwrite manifest.json", "[output][naming]") {
    CHECK_THAT(collision("{scene}/manifest.json", {"main"}, {"color"}, {"png"}, {1}),
               Contains("writes 'shapes/manifest.json'"));
    CHECK_THAT(collision("{scene}/manifest.json", {"main"}, {"color"}, {"png"}, {1}),
               Contains("overwrite the run's manifest"));
    // In another folder than the manifest's, the name is free.
    CHECK(collision("{scene}/{pass}/manifest.json", {"main"}, {"color"}, {"png"}, {1}) == "");
}

TEST_CASE("the collision check handles 100k frames", "[output][naming]") {
    std::vector<int> frames;
    for (int f = 1; f <= 100000; ++f) frames.push_back(f);
    CHECK(collision(facet::kDefaultOutputTemplate, {"main"}, {"color", "depth"}, {"png", "exr"},
                    frames) == "");
    // Without a frame number, the second frame already collides.
    std::string message = collision("{pass}.{ext}", {"main"}, {"color"}, {"png"}, frames);
    CHECK_THAT(message, Contains("frame 1,"));
    CHECK_THAT(message, Contains("frame 2,"));
    // A collision found only after all 100k names of the first camera are in
    // the set: camera "a1" frame 1 and camera "a" frame 11 are both "a11".
    message = collision("{camera}{frame:1}.png", {"a", "a1"}, {"color"}, {"png"}, frames);
    CHECK_THAT(message, Contains("writes 'a11.png' for both frame 11, camera 'a'"));
    CHECK_THAT(message, Contains("and frame 1, camera 'a1'"));
}

TEST_CASE("manifest.json goes in the leading folders that do not change within a run",
          "[output][naming]") {
    CHECK(manifest_dir(facet::kDefaultOutputTemplate) == "shapes");
    CHECK(manifest_dir("renders/{scene}/{camera}/f####.{ext}", true) == "renders/shapes/main");
    CHECK(manifest_dir("renders/{scene}/{camera}/f####.{ext}", false) == "renders/shapes");
    CHECK(manifest_dir("{pass}/{frame}.{ext}") == "");
    // The file name never counts, even when it is fixed.
    CHECK(manifest_dir("{scene}.png") == "");
    CHECK(manifest_dir("a/b/{scene}-x/{pass}/{frame}/{ext}") == "a/b/shapes-x");
    // The run stops at the first component that changes.
    CHECK(manifest_dir("{scene}/{pass}/{scene}/{frame}.{ext}") == "shapes");
    CHECK(manifest_dir("{scene}_{camera}/{frame}.{ext}", true) == "shapes_main");
    CHECK(manifest_dir("{scene}_{camera}/{frame}.{ext}", false) == "");
}

TEST_CASE("output paths are made relative to the manifest folder", "[output][naming]") {
    auto t = facet::parse_output_template("renders/{scene}/{camera}/{pass}/f####.{ext}");
    OutputNameFields f = fields(12, "depth", "exr", "top");
    std::string dir = facet::manifest_directory(t, f, true);
    std::string path = facet::expand(t, f);
    CHECK(dir == "renders/shapes/top");
    CHECK(path == "renders/shapes/top/depth/f0012.exr");
    CHECK(facet::path_relative_to_manifest(path, dir) == "depth/f0012.exr");

    // The default: the manifest sits beside the files, as before.
    auto d = facet::parse_output_template(facet::kDefaultOutputTemplate);
    CHECK(facet::path_relative_to_manifest(facet::expand(d, fields(1)),
                                           facet::manifest_directory(d, fields(1), true)) ==
          "color.0001.png");

    CHECK(facet::path_relative_to_manifest("color/0001.png", "") == "color/0001.png");
    // Whole components only: "shapes2" is not inside "shapes".
    CHECK_THROWS_WITH(facet::path_relative_to_manifest("shapes2/a.png", "shapes"),
                      Contains("'shapes2/a.png' is not inside the manifest's folder 'shapes'"));
    CHECK_THROWS_AS(facet::path_relative_to_manifest("shapes", "shapes"), facet::Error);
}
