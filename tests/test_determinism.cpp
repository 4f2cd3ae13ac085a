// Determinism: the same frames give bit-identical files for any thread
// count and any frame subset (docs/architecture.md, "Why the output is bit-identical").
#include <catch2/catch.hpp>

#include <map>

#include "render_hashes.hpp"

using namespace facet;
using facet::test::render_hashes;

TEST_CASE("identical files at 1, 2 and 3 threads", "[determinism]") {
    for (const char* scene : {"tests/scenes/shapes.yaml", "scenes/turntable.yaml"}) {
        INFO(scene);
        test::TempDir a("det1"), b("det2"), c("det3");
        auto one = render_hashes(scene, 1, {1, 2, 3}, a.path());
        auto two = render_hashes(scene, 2, {1, 2, 3}, b.path());
        auto three = render_hashes(scene, 3, {1, 2, 3}, c.path());
        REQUIRE(one.size() == 12);  // 3 frames x (colour, depth) x (PNG, EXR)
        CHECK(one == two);
        CHECK(one == three);
    }
}

TEST_CASE("a frame subset renders the same files as a full run", "[determinism]") {
    test::TempDir full("full"), part("part");
    auto all = render_hashes("tests/scenes/shapes.yaml", 2, {1, 2, 3}, full.path());
    auto some = render_hashes("tests/scenes/shapes.yaml", 2, {3}, part.path());
    REQUIRE(some.size() == 4);
    for (const auto& [key, hash] : some) CHECK(all.at(key) == hash);
    // Different frames of an orbit really differ, so the comparison means something.
    CHECK(all.at("1/color/png") != all.at("2/color/png"));
}

TEST_CASE("supersampled frames are identical at 1 and 2 threads", "[determinism]") {
    test::TempDir a("ss1"), b("ss2");
    auto one = render_hashes("tests/scenes/shapes.yaml", 1, {2}, a.path(), 4);
    auto two = render_hashes("tests/scenes/shapes.yaml", 2, {2}, b.path(), 4);
    REQUIRE(one.size() == 4);
    CHECK(one == two);
}
