// Render tests for lights and shadows: each line renders one frame and
// compares it with a reviewed reference in tests/baselines (render_check.hpp).
#include <catch2/catch.hpp>

#include "render_check.hpp"

using facet::test::check_render;

// clang-format off
TEST_CASE("render: polyhedra with sun and point-light shadows", "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 1, "polyhedra-shadows.png", {}, {"output.size=[480, 270]", "output.samples=1"}}); }
TEST_CASE("render: spot point sun and ambient lights",          "[render][shadow]") { check_render({"tests/scenes/shadow_lights.yaml", 1, "shadow-lights.png"}); }
// The seed-001 display modes, as presets.
TEST_CASE("render: polyhedra mode wireframe",     "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 20, "mode-wireframe.png", {}, {"output.size=[320, 180]", "output.samples=1"}, "wireframe"}); }
TEST_CASE("render: polyhedra mode intersections", "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 20, "mode-intersections.png", {}, {"output.size=[320, 180]", "output.samples=1"}, "intersections"}); }
TEST_CASE("render: polyhedra mode lit",           "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 20, "mode-lit.png", {}, {"output.size=[320, 180]", "output.samples=1"}, "lit"}); }
TEST_CASE("render: polyhedra mode lit-shadows",   "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 20, "mode-lit-shadows.png", {}, {"output.size=[320, 180]", "output.samples=1"}, "lit-shadows"}); }
// clang-format on
