// Render tests for lights and shadows: each line renders one frame and
// compares it with a reviewed reference in tests/baselines (render_check.hpp).
#include <catch2/catch.hpp>

#include "render_check.hpp"

using facet::test::check_render;

// clang-format off
TEST_CASE("render: polyhedra with sun and point-light shadows", "[render][shadow]") { check_render({"scenes/polyhedra.yaml", 1, "polyhedra-shadows.png", {}, {"output.size=[480, 270]", "output.samples=1"}}); }
TEST_CASE("render: spot point sun and ambient lights",          "[render][shadow]") { check_render({"tests/scenes/shadow_lights.yaml", 1, "shadow-lights.png"}); }
// clang-format on
