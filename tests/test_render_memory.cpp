// What rendering will hold, estimated before the first frame
// (job/render_memory.hpp): the screen-space buffers follow the frame's
// targets, so a style that keeps every sample is charged for them, and
// occlusion alone for a G-buffer of pixels only; and every pass asked for
// is counted in each frame in flight, with what the encoders and the
// motion pass hold.
#include <catch2/catch.hpp>

#include <string>

#include "job/render_memory.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

namespace {

// The bytes of the part named `name` of a small scene's estimate, 0 when
// there is none; `style` is the scene's, `output` keys added to its output.
uint64_t part_bytes(const std::string& style, const std::string& output, const std::string& name,
                    unsigned threads = 2) {
    facet::test::TempDir dir("render-memory");
    const std::string text = "output: { size: [200, 100], samples: 4, " + output +
                             " }\nstyle: " + style + "\nobjects:\n  - primitive: cube\n";
    const facet::SceneDesc scene =
        facet::test::load(facet::test::write_text(dir.file("scene.yaml"), text));
    const facet::World world = facet::build_world(scene);
    for (const auto& [part, bytes] : facet::render_memory(scene, world, threads))
        if (part == name) return bytes;
    return 0;
}

}  // namespace

TEST_CASE("the memory estimate counts the screen-space buffers the frame will have",
          "[render][memory]") {
    const uint64_t pixels = 200 * 100, samples = pixels * 4;
    const std::string part = "screen-space buffers";
    // Shading per pixel, nothing after it: none.
    CHECK(part_bytes("blinn-phong", "passes: [color]", part) == 0);
    // Occlusion alone: a G-buffer of pixels (depth, normal, object) and each
    // pixel's surface share.
    CHECK(part_bytes("{ extends: blinn-phong, occlusion: true }", "passes: [color]", part) ==
          pixels * (20 + 4));
    // Outlines: every sample's colour and depth, and a G-buffer of samples.
    CHECK(part_bytes("{ extends: blinn-phong, outlines: true }", "passes: [color]", part) ==
          samples * (20 + 20));
    // The lines pass: the samples and their strokes; with occlusion beside
    // it, the G-buffer of samples too.
    CHECK(part_bytes("blinn-phong", "passes: [color, lines]", part) == samples * (20 + 16));
    CHECK(part_bytes("{ extends: blinn-phong, occlusion: true }", "passes: [color, lines]", part) ==
          samples * (20 + 16 + 20));
    // Occlusion's own buffers: a value per G-buffer element, and its cells
    // (per 2 x 2 pixels by default).
    CHECK(part_bytes("blinn-phong", "passes: [color]", "ambient occlusion") == 0);
    CHECK(part_bytes("{ extends: blinn-phong, occlusion: true }", "passes: [color]",
                     "ambient occlusion") == pixels * 4 + pixels / 4 * 28);
    CHECK(part_bytes("{ extends: blinn-phong, occlusion: { resolution: full } }",
                     "passes: [color, lines]", "ambient occlusion") == samples * 4 + pixels * 28);
    // The output images in flight: colour and depth whatever is asked (half
    // RGBA, float), and each pass asked for besides (float normal and
    // position, two 32-bit ids, float uv, half RGBA alpha).
    CHECK(part_bytes("blinn-phong", "passes: [color]", "output images") == pixels * 12 * 5);
    CHECK(part_bytes("blinn-phong",
                     "passes: [color, depth, normal, object_id, material_id, uv, position, "
                     "alpha], formats: [png, exr]",
                     "output images") == pixels * (12 + 12 + 4 + 4 + 8 + 12 + 8) * 5);
}

TEST_CASE("the memory estimate counts the encoders' buffers and the motion pass's vertices",
          "[render][memory]") {
    const uint64_t pixels = 200 * 100;
    const std::string encoding = "encoding";
    // Each encoder (two at once with more than one thread) holds its largest
    // file. A PNG: four times its view's samples (8-bit RGB or RGBA, 16-bit
    // grey for depth).
    CHECK(part_bytes("blinn-phong", "passes: [color]", encoding) == 2 * pixels * 4 * 4);
    CHECK(part_bytes("blinn-phong", "passes: [color]", encoding, 1) == pixels * 4 * 4);
    CHECK(part_bytes("blinn-phong", "passes: [depth]", encoding) == 2 * pixels * 4 * 2);
    // An EXR written by facet (zip, zips, none): the file, at most its
    // samples; the largest of separate files here is float position.
    CHECK(part_bytes("blinn-phong", "passes: [color, depth, position], formats: [exr]", encoding) ==
          2 * pixels * 12);
    // OpenEXR's own methods can grow a file past its samples: twice.
    CHECK(part_bytes("blinn-phong", "passes: [color], formats: [exr], exr_compression: piz",
                     encoding) == 2 * pixels * 8 * 2);
    // A multi-layer EXR holds every pass at once.
    CHECK(part_bytes("blinn-phong",
                     "passes: [color, depth, normal], formats: [exr], exr: multilayer",
                     encoding) == 2 * pixels * (8 + 4 + 12));
    // The motion pass transforms the frame before as well: a second set of
    // vertex records.
    const uint64_t vertices = part_bytes("blinn-phong", "passes: [color]", "vertices");
    CHECK(vertices > 0);
    CHECK(part_bytes("blinn-phong", "passes: [color]", "previous frame's vertices") == 0);
    CHECK(part_bytes("blinn-phong", "passes: [color, motion], formats: [exr]",
                     "previous frame's vertices") == vertices);
}
