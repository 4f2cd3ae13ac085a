// Render tests: each line renders one frame and compares it with a reviewed
// reference in tests/baselines (see render_check.hpp for the thresholds).
#include <catch2/catch.hpp>

#include "render_check.hpp"

using facet::test::check_render;

// clang-format off
TEST_CASE("render: demo turntable",       "[render]") { check_render({"scenes/turntable.yaml", 10, "turntable-0010.png", {}, {"output.size=[480, 270]"}}); }
// The PBR sampler: metals and dielectrics over a roughness range, normal and
// occlusion maps (with the file's tangents and with made ones), a
// metal-rough map, under the studio and three lights.
TEST_CASE("render: demo pbr sampler",    "[render][pbr]") { check_render({"scenes/pbr.yaml", 13, "pbr-0013.png", {}, {"output.size=[480, 270]"}}); }
TEST_CASE("render: shapes blinn-phong",   "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-blinn-phong.png"}); }
TEST_CASE("render: shapes phong",         "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-phong.png", {}, {}, "phong"}); }
TEST_CASE("render: shapes gouraud",       "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-gouraud.png", {}, {}, "gouraud"}); }
TEST_CASE("render: shapes flat",          "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-flat.png", {}, {}, "flat"}); }
TEST_CASE("render: shapes depth view",    "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-depth.png", {}, {}, "depth"}); }
TEST_CASE("render: shapes normals",       "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-normals.png", {}, {}, "normals"}); }
TEST_CASE("render: floor through near",   "[render]") { check_render({"tests/scenes/near_floor.yaml", 1, "near-floor.png"}); }
TEST_CASE("render: OBJ spider textured",  "[render]") { check_render({"tests/scenes/spider.yaml", 1, "spider.png"}); }
TEST_CASE("render: glTF box textured",    "[render]") { check_render({"tests/scenes/box_textured.yaml", 1, "box-textured.png"}); }
TEST_CASE("render: glTF texture transform", "[render]") { check_render({"tests/scenes/texture_transform.yaml", 1, "texture-transform.png"}); }
TEST_CASE("render: double-sided tubes",   "[render]") { check_render({"tests/scenes/double_sided.yaml", 1, "double-sided.png"}); }
TEST_CASE("render: shapes 4 samples",     "[render]") { check_render({"tests/scenes/shapes.yaml", 2, "shapes-aa4.png", {}, {"output.samples=4"}}); }
TEST_CASE("render: polyhedra",            "[render]") { check_render({"tests/scenes/polyhedra.yaml", 1, "polyhedra.png"}); }
TEST_CASE("render: glTF skin animation",  "[render]") { check_render({"scenes/tentacles.yaml", 30, "tentacles-0030.png", {}, {"output.size=[320, 180]", "output.samples=1"}}); }
TEST_CASE("render: eased product spin",   "[render]") { check_render({"scenes/product-spin.yaml", 30, "product-spin-0030.png", {}, {"output.size=[240, 180]", "output.samples=1"}}); }
TEST_CASE("render: spline fly-around",    "[render]") { check_render({"scenes/flyaround.yaml", 50, "flyaround-0050.png", {}, {"output.size=[320, 180]", "output.samples=1"}}); }
// clang-format on
