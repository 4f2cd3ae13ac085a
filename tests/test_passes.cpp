// The compositing passes (docs/passes.md): values a compositor relies on,
// computed here from the scene's geometry and checked pixel by pixel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "job/render_job.hpp"
#include "output/encoders.hpp"
#include "output/manifest.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "render_hashes.hpp"
#include "support.hpp"

using namespace facet;

namespace {

constexpr int kWidth = 200, kHeight = 100;
constexpr float kFovDegrees = 40;
// The camera looks down -Z from z = 10 at a cube of size 2 at the origin:
// its front face, at z = 1, is 9 units away and square to the view axis.
constexpr float kFaceDistance = 9;

// Pixels per scene unit on the front face.
float pixels_per_unit() {
    const float focal = 0.5f * kHeight / std::tan(glm::radians(kFovDegrees) * 0.5f);
    return focal / kFaceDistance;
}

std::string card_scene(const std::string& output, const std::string& objects) {
    return "output: { size: [" + std::to_string(kWidth) + ", " + std::to_string(kHeight) +
           "], frames: \"1-2\", " + output +
           " }\n"
           "style: unlit\n"
           "camera: { position: [0, 0, 10], target: [0, 0, 0], fov: " +
           std::to_string(kFovDegrees) +
           " }\n"
           "objects:\n" +
           objects;
}

SceneOptions with_styles() {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    return options;
}

FrameImages render_text(const test::TempDir& dir, const std::string& yaml, int frame,
                        unsigned threads = 2) {
    return test::render_yaml(dir.path(), yaml, frame, threads);
}

// The image centre is at (100, 50); q is a pixel centre relative to it, y up.
glm::vec2 from_centre(int x, int y) {
    return {static_cast<float>(x) + 0.5f - 0.5f * kWidth,
            0.5f * kHeight - (static_cast<float>(y) + 0.5f)};
}

}  // namespace

TEST_CASE("motion of a keyed translation, in pixels to the previous frame", "[passes][motion]") {
    test::TempDir dir("motion-move");
    const FrameImages images =
        render_text(dir,
                    card_scene("passes: [color, motion], formats: [exr]",
                               "  - name: card\n    primitive: { type: cube, size: 2 }\n"
                               "    translate: { keys: { 1: [0, 0, 0], 2: [0.5, 0.25, 0] } }\n"),
                    2);
    // The face moved right by 0.5 and up by 0.25: where it was is left and
    // below, by those distances in pixels.
    const glm::vec2 expected = glm::vec2(-0.5f, -0.25f) * pixels_per_unit();
    const glm::vec2 centre =
        glm::vec2(0.5f * kWidth, 0.5f * kHeight) + glm::vec2(0.5f, -0.25f) * pixels_per_unit();
    int checked = 0;
    for (int y = static_cast<int>(centre.y) - 8; y <= static_cast<int>(centre.y) + 8; ++y)
        for (int x = static_cast<int>(centre.x) - 8; x <= static_cast<int>(centre.x) + 8; ++x) {
            const glm::vec2 m = images.surface.motion.at(x, y);
            INFO("pixel " << x << ", " << y << ": " << m.x << ", " << m.y);
            CHECK(std::abs(m.x - expected.x) < 0.05f);
            CHECK(std::abs(m.y - expected.y) < 0.05f);
            ++checked;
        }
    CHECK(checked == 17 * 17);
    // The background does not move.
    CHECK(images.surface.motion.at(2, 2) == glm::vec2(0.0f));
}

TEST_CASE("motion of a keyed rotation about the view axis", "[passes][motion]") {
    test::TempDir dir("motion-turn");
    const float degrees = 10;
    const FrameImages images =
        render_text(dir,
                    card_scene("passes: [color, motion], formats: [exr], samples: 4",
                               "  - name: card\n    primitive: { type: cube, size: 2 }\n"
                               "    rotate: { keys: { 1: [0, 0, 0], 2: [0, 0, 10] } }\n"),
                    2);
    // A turn by +10 degrees about +Z (counterclockwise as the camera sees
    // it): a point now at q was at q turned back by 10 degrees.
    const float a = glm::radians(-degrees);
    int checked = 0;
    float largest = 0;
    for (int y = 38; y < 62; ++y)
        for (int x = 88; x < 112; ++x) {
            const glm::vec2 q = from_centre(x, y);
            const glm::vec2 before(q.x * std::cos(a) - q.y * std::sin(a),
                                   q.x * std::sin(a) + q.y * std::cos(a));
            const glm::vec2 expected = before - q;
            const glm::vec2 m = images.surface.motion.at(x, y);
            INFO("pixel " << x << ", " << y << ": " << m.x << ", " << m.y << " expected "
                          << expected.x << ", " << expected.y);
            CHECK(std::abs(m.x - expected.x) < 0.05f);
            CHECK(std::abs(m.y - expected.y) < 0.05f);
            largest = std::max(largest, glm::length(expected));
            ++checked;
        }
    CHECK(checked == 24 * 24);
    CHECK(largest > 2.0f);  // the test sees real motion
}

TEST_CASE("motion at a frame does not depend on the frames rendered before", "[passes][motion]") {
    test::TempDir dir("motion-alone");
    const std::string yaml =
        card_scene("passes: [color, motion], formats: [exr]",
                   "  - name: card\n    primitive: { type: cube, size: 2 }\n"
                   "    translate: { keys: { 1: [0, 0, 0], 3: [1, 0, 0] } }\n");
    const SceneDesc scene =
        load_scene(test::write_text(dir.file("scene.yaml"), yaml), with_styles());
    const World world = build_world(scene);
    ThreadPool pool(2);
    FrameRenderer in_order(scene, world, pool), alone(scene, world, pool);
    FrameImages a, b;
    in_order.render(1, 0, a);
    in_order.render(2, 0, a);
    in_order.render(3, 0, a);
    alone.render(3, 0, b);
    CHECK(a.surface.motion.pixels == b.surface.motion.pixels);
    // The first frame's motion is from the frame before it, where the key
    // holds the card still.
    alone.render(1, 0, b);
    for (const glm::vec2& m : b.surface.motion.pixels) CHECK(m == glm::vec2(0.0f));
}

TEST_CASE("alpha: anti-aliased edges, straight PNG, premultiplied EXR", "[passes][alpha]") {
    test::TempDir dir("alpha-edge");
    // The card's right edge on the centre of column 120: with 2 x 2
    // samples, that column's pixels are exactly half covered.
    const int column = 120;
    const float edge = (static_cast<float>(column) + 0.5f - 0.5f * kWidth) / pixels_per_unit();
    const std::string objects =
        "  - name: card\n    primitive: { type: cube, size: 2 }\n"
        "    translate: [" +
        std::to_string(edge - 1.0f) + ", 0, 0]\n    material: { color: [0.8, 0.4, 0.2] }\n";
    const FrameImages images = render_text(
        dir,
        card_scene("passes: [color, alpha], formats: [png, exr], samples: 4, background: [0, 0, 1]",
                   objects),
        1);
    const ColorImage alpha = to_float_image(images.alpha), color = to_float_image(images.color);
    const glm::vec3 card(0.8f, 0.4f, 0.2f), blue(0, 0, 1);
    for (int y = 45; y < 55; ++y) {
        INFO("row " << y);
        CHECK(alpha.at(column - 1, y).a == 1.0f);
        CHECK(alpha.at(column, y).a == 0.5f);
        CHECK(alpha.at(column + 1, y) == glm::vec4(0.0f));
        // Premultiplied: the half-covered pixel holds half the card's colour.
        for (int c = 0; c < 3; ++c) {
            CHECK(alpha.at(column - 1, y)[c] == Approx(card[c]).margin(1e-3));
            CHECK(alpha.at(column, y)[c] == Approx(0.5f * card[c]).margin(1e-3));
            // The colour pass has the background under the other half.
            CHECK(color.at(column, y)[c] == Approx(0.5f * card[c] + 0.5f * blue[c]).margin(1e-3));
        }
        CHECK(color.at(column, y).a == 1.0f);
    }
    // The PNG is straight: the edge pixel has the card's colour at half alpha.
    const DecodedPng png = [&] {
        const std::string path = dir.file("alpha.png");
        test::write_bytes(path, encode_png_color(images.alpha, 1));
        return read_png(path);
    }();
    REQUIRE(png.channels == 4);
    const size_t edge_pixel = static_cast<size_t>(50 * kWidth + column) * 4;
    const size_t inside = static_cast<size_t>(50 * kWidth + column - 1) * 4;
    CHECK(png.samples[edge_pixel + 3] == 128);
    CHECK(png.samples[inside + 3] == 255);
    for (int c = 0; c < 3; ++c)
        CHECK(std::abs(int(png.samples[edge_pixel + c]) - int(png.samples[inside + c])) <= 1);
}

TEST_CASE("background: transparent makes the colour pass the alpha pass", "[passes][alpha]") {
    test::TempDir dir("alpha-transparent");
    const std::string objects = "  - name: card\n    primitive: { type: sphere, radius: 1.2 }\n";
    const FrameImages images = render_text(
        dir, card_scene("passes: [color, alpha], samples: 4, background: transparent", objects), 1);
    CHECK(to_float_image(images.color).pixels == to_float_image(images.alpha).pixels);
    const ColorImage color = to_float_image(images.color);
    CHECK(color.at(1, 1) == glm::vec4(0.0f));
    CHECK(color.at(100, 50).a == 1.0f);
    int partial = 0;  // the sphere's anti-aliased rim
    for (const glm::vec4& p : color.pixels) partial += p.a > 0.0f && p.a < 1.0f;
    CHECK(partial > 20);
}

TEST_CASE("ids: exact integers per object and material, named in the manifest", "[passes][ids]") {
    test::TempDir dir("ids");
    const std::string objects =
        "  - name: left\n    primitive: { type: cube, size: 1 }\n    translate: [-2.5, 0, 0]\n"
        "  - name: middle\n    primitive: { type: sphere, radius: 0.6 }\n"
        "  - name: right\n    primitive: { type: cube, size: 1 }\n    translate: [2.5, 0, 0]\n"
        "    rotate: { keys: { 1: [0, 0, 0], 2: [0, 45, 0] } }\n";
    const std::string scene_path = test::write_text(
        dir.file("scene.yaml"),
        card_scene("passes: [color, object_id, material_id], formats: [png, exr], samples: 4",
                   objects));
    const SceneDesc scene = load_scene(scene_path, with_styles());
    const World world = build_world(scene);
    RenderOptions options;
    options.out_dir = dir.file("out");
    options.threads = 2;
    const RenderResult result = render_scene(scene, world, options, nullptr);
    const Manifest manifest = read_manifest(result.manifest_path);
    std::map<std::string, std::string> path_of;
    for (const ManifestFile& f : manifest.files)
        path_of[std::to_string(f.frame) + f.pass + f.format] =
            manifest_file_path(result.output_dir, f.path);

    // The manifest names every id.
    std::map<std::pair<std::string, uint32_t>, std::string> names;
    for (const ManifestId& id : manifest.ids) names[{id.pass, id.id}] = id.name;
    CHECK(names.at({"object_id", 1}) == "left");
    CHECK(names.at({"object_id", 2}) == "middle");
    CHECK(names.at({"object_id", 3}) == "right");
    CHECK(names.at({"material_id", 2}) == "middle:0");

    const float ppu = pixels_per_unit();
    auto pixel_of = [&](float world_x) {
        return static_cast<int>(0.5f * kWidth + world_x * ppu * kFaceDistance / 9.5f);
    };
    for (int frame : {1, 2}) {
        INFO("frame " << frame);
        const DecodedExr objects_exr = read_exr(path_of.at(std::to_string(frame) + "object_idexr"));
        const DecodedExr materials_exr =
            read_exr(path_of.at(std::to_string(frame) + "material_idexr"));
        REQUIRE(objects_exr.channel_names == std::vector<std::string>{"object_id.id"});
        REQUIRE(materials_exr.channel_names == std::vector<std::string>{"material_id.id"});
        auto id_at = [&](const DecodedExr& exr, int x, int y) {
            return exr.channels[0][static_cast<size_t>(y) * kWidth + x];
        };
        CHECK(id_at(objects_exr, pixel_of(-2.5f), 50) == 1.0f);
        CHECK(id_at(objects_exr, pixel_of(0.0f), 50) == 2.0f);
        CHECK(id_at(objects_exr, pixel_of(2.5f), 50) == 3.0f);
        CHECK(id_at(objects_exr, 2, 2) == 0.0f);
        CHECK(id_at(materials_exr, pixel_of(0.0f), 50) == 2.0f);
        // Never a blend: every value is one of the ids.
        for (float v : objects_exr.channels[0]) CHECK((v == 0 || v == 1 || v == 2 || v == 3));
    }
    // The same objects keep their colours in the PNG view from frame to frame.
    CHECK(id_view_color(1) != id_view_color(2));
    CHECK(id_view_color(0) == std::array<uint8_t, 3>{0, 0, 0});
}

TEST_CASE("lines: the strokes alone, to composite over the colour without them",
          "[passes][lines]") {
    // toon-outline is toon with outlines: toon's colour with the lines pass
    // over it must be toon-outline's colour (one sample per pixel, where
    // outlines are composited per pixel too).
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    options.overrides.push_back({"output.passes", "[color, lines]", "test"});
    options.overrides.push_back({"style", "toon-outline", "test"});
    const SceneDesc outlined = load_scene(test::source_path("tests/scenes/shapes.yaml"), options);
    options.overrides.back().value = "toon";
    const SceneDesc plain = load_scene(test::source_path("tests/scenes/shapes.yaml"), options);
    ThreadPool pool(2);
    const World world = build_world(outlined);
    FrameRenderer a(outlined, world, pool), b(plain, world, pool);
    FrameImages with_lines, without;
    a.render(2, 0, with_lines);
    b.render(2, 0, without);
    const ColorImage lines = to_float_image(with_lines.lines);
    const ColorImage expected_base = to_float_image(without.color);
    const ColorImage actual = to_float_image(with_lines.color);
    int stroked = 0;
    for (size_t i = 0; i < lines.pixels.size(); ++i) {
        const glm::vec4 l = lines.pixels[i];
        const glm::vec3 over = glm::vec3(l) + glm::vec3(expected_base.pixels[i]) * (1.0f - l.a);
        for (int c = 0; c < 3; ++c) REQUIRE(actual.pixels[i][c] == Approx(over[c]).margin(2e-3));
        stroked += l.a > 0.5f;
    }
    CHECK(stroked > 500);  // the silhouettes of five shapes and the floor
}

TEST_CASE("every pass is identical at 1 and 3 threads and for a frame subset",
          "[passes][determinism]") {
    const std::string all =
        "[color, alpha, depth, normal, object_id, material_id, uv, position, motion, lines]";
    test::TempDir a("pass-det1"), b("pass-det3"), c("pass-det-part");
    const auto one = test::render_hashes("tests/scenes/shapes.yaml", 1, {1, 2, 3}, a.path(), 4, all,
                                         "toon-outline");
    const auto three = test::render_hashes("tests/scenes/shapes.yaml", 3, {1, 2, 3}, b.path(), 4,
                                           all, "toon-outline");
    const auto part =
        test::render_hashes("tests/scenes/shapes.yaml", 2, {3}, c.path(), 4, all, "toon-outline");
    // Ten passes: eight with a PNG view, all ten as EXR.
    REQUIRE(one.size() == 3 * 18);
    CHECK(one == three);
    for (const auto& [key, hash] : part) CHECK(one.at(key) == hash);
    CHECK(one.at("2/motion/exr") != one.at("3/motion/exr"));
}

namespace {

const std::string kEveryPass =
    "color,alpha,depth,normal,object_id,material_id,uv,position,motion,lines";

// Renders frame 2 of tests/scenes/shapes.yaml with every pass into `folder`,
// as EXR, with the given extra options.
void render_every_pass(const std::string& folder, const std::string& options) {
    REQUIRE(test::run_facet("render '" + test::source_path("tests/scenes/shapes.yaml") +
                            "' -f 2 --style toon-outline --formats exr --passes " + kEveryPass +
                            " " + options + " -o " + folder)
                .exit_code == 0);
}

}  // namespace

TEST_CASE("multi-layer EXR: every pass as layers, each as in the pass's own file",
          "[passes][exr]") {
    test::TempDir dir("multilayer");
    render_every_pass(dir.file("layered"), "-D output.exr=multilayer");
    render_every_pass(dir.file("separate"), "");
    const Manifest layered = read_manifest(dir.file("layered/shapes/manifest.json"));
    REQUIRE(layered.files.size() == 1);
    CHECK(layered.files[0].pass == "multilayer");
    const std::string file = dir.file("layered/shapes/multilayer.0002.exr");

    // Our own reader: the channels Nuke and Blender read, in the file's
    // (sorted) order, each with the same samples as the pass's own file.
    const DecodedExr exr = read_exr(file);
    const std::vector<std::string> expected = {"A",
                                               "B",
                                               "G",
                                               "N.X",
                                               "N.Y",
                                               "N.Z",
                                               "P.X",
                                               "P.Y",
                                               "P.Z",
                                               "R",
                                               "Z",
                                               "alpha.A",
                                               "alpha.B",
                                               "alpha.G",
                                               "alpha.R",
                                               "lines.A",
                                               "lines.B",
                                               "lines.G",
                                               "lines.R",
                                               "material_id.id",
                                               "motion.X",
                                               "motion.Y",
                                               "object_id.id",
                                               "uv.U",
                                               "uv.V"};
    CHECK(exr.channel_names == expected);
    const std::map<std::string, std::string> separate_channel = {
        {"R", "color:R"},
        {"Z", "depth:Z"},
        {"N.Y", "normal:N.Y"},
        {"P.Z", "position:P.Z"},
        {"alpha.A", "alpha:A"},
        {"lines.R", "lines:R"},
        {"motion.X", "motion:motion.X"},
        {"object_id.id", "object_id:object_id.id"},
        {"uv.V", "uv:uv.V"}};
    for (const auto& [layered_name, where] : separate_channel) {
        INFO(layered_name);
        const std::string pass = where.substr(0, where.find(':'));
        const std::string channel = where.substr(where.find(':') + 1);
        const DecodedExr own = read_exr(dir.file("separate/shapes/" + pass + ".0002.exr"));
        const auto at = [](const DecodedExr& e, const std::string& name) {
            return e.channels[static_cast<size_t>(
                std::find(e.channel_names.begin(), e.channel_names.end(), name) -
                e.channel_names.begin())];
        };
        REQUIRE(std::find(own.channel_names.begin(), own.channel_names.end(), channel) !=
                own.channel_names.end());
        CHECK(at(exr, layered_name) == at(own, channel));
    }
}

// OpenImageIO, as compositing tools would open the file.
TEST_CASE("multi-layer EXR: OpenImageIO reads every layer", "[passes][exr]") {
    if (!test::have_command("oiiotool"))
        FACET_SKIP("oiiotool is missing (scripts/setup.sh --tests installs openimageio-tools)");
    test::TempDir dir("multilayer-oiio");
    render_every_pass(dir.file("layered"), "-D output.exr=multilayer");
    const std::string file = dir.file("layered/shapes/multilayer.0002.exr");
    const test::RunResult info = test::run_command("oiiotool --info -v '" + file + "' 2>&1");
    REQUIRE(info.exit_code == 0);
    CHECK_THAT(info.output, Catch::Contains("320 x  240, 25 channel"));
    CHECK_THAT(
        info.output,
        Catch::Contains("channel list: R (half), G (half), B (half), A (half), Z (float), "
                        "N.X (float), N.Y (float), N.Z (float), P.X (float), P.Y (float), "
                        "P.Z (float), alpha.R (half), alpha.G (half), alpha.B (half), "
                        "alpha.A (half), lines.R (half), lines.G (half), lines.B (half), "
                        "lines.A (half), material_id.id (uint), motion.X (float), "
                        "motion.Y (float), object_id.id (uint), uv.U (float), uv.V (float)"));
}
