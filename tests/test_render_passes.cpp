// Each pass against a reviewed reference image (docs/passes.md): the
// shapes scene, anti-aliased, at frame 2 of its orbit (so the camera moves
// for the motion pass). Colour and alpha PNGs are sRGB; the data passes'
// views are plain bytes; position and motion through render_check's views.
#include <catch2/catch.hpp>

#include "render_check.hpp"

using facet::test::check_render;

// clang-format off
TEST_CASE("passes: alpha",       "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-alpha.png", {}, {"output.samples=4"}, "", "alpha"}); }
TEST_CASE("passes: depth",       "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-depth.png", {}, {"output.samples=4"}, "", "depth"}); }
TEST_CASE("passes: world normal", "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-normal-world.png", {}, {"output.samples=4"}, "", "normal"}); }
TEST_CASE("passes: camera normal", "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-normal-camera.png", {}, {"output.samples=4", "output.normals=camera"}, "", "normal"}); }
TEST_CASE("passes: object_id",   "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-object-id.png", {}, {"output.samples=4"}, "", "object_id"}); }
TEST_CASE("passes: material_id", "[render][passes]") { check_render({"tests/scenes/polyhedra.yaml", 1, "pass-material-id.png", {}, {"output.samples=4"}, "", "material_id"}); }
TEST_CASE("passes: uv",          "[render][passes]") { check_render({"tests/scenes/box_textured.yaml", 1, "pass-uv.png", {}, {"output.samples=4"}, "", "uv"}); }
TEST_CASE("passes: position",    "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-position.png", {}, {"output.samples=4"}, "", "position"}); }
TEST_CASE("passes: motion",      "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-motion.png", {}, {"output.samples=4"}, "", "motion"}); }
TEST_CASE("passes: lines of outlines", "[render][passes]") { check_render({"tests/scenes/shapes.yaml", 2, "pass-lines-outlines.png", {}, {"output.samples=4"}, "toon-outline", "lines"}); }
TEST_CASE("passes: lines of a wireframe", "[render][passes]") { check_render({"tests/scenes/polyhedra.yaml", 1, "pass-lines-wireframe.png", {}, {"output.samples=4"}, "wireframe", "lines"}); }
// clang-format on
