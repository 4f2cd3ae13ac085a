// What rendering will hold, estimated before the first frame
// (job/render_memory.hpp), against what a render really holds: the peak
// resident memory of `facet render` at full size, less the same scene's at
// a tiny size (the program, the world, the textures: what the estimate of
// the frames does not cover), must lie within 0.45 to 1.4 times the
// estimate's growth between the two sizes. The estimate counts every frame
// the job may hold at once; when the encoder keeps up, fewer are held
// (0.6 to 0.8 of it for colour alone, run to run), hence the low bound. Measured by the kernel
// (/usr/bin/time's maximum resident set size), so the test knows nothing
// of the estimate's constants: a buffer added to a frame and not to the
// estimate, or an estimate of a buffer no frame holds, moves the ratio.
#include <catch2/catch.hpp>

#include <string>

#include "core/memory.hpp"
#include "job/render_memory.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

namespace {

struct Case {
    const char* name;
    std::string output;  // keys added to the scene's output
    std::string style;
};

// The scene: a sphere over a floor, six frames, so the encoder's queue
// fills as it would in a long run.
std::string scene_text(const Case& c, const std::string& size) {
    return "output: { size: " + size + ", frames: \"1-6\", " + c.output + " }\nstyle: " + c.style +
           "\ncamera: { position: [0, 1, 4], target: [0, 0, 0] }\n"
           "objects:\n  - primitive: sphere\n"
           "  - { primitive: { type: plane, size: 10 }, translate: [0, -1, 0] }\n";
}

uint64_t estimate(const std::string& path) {
    const facet::SceneDesc scene = facet::test::load(path);
    const facet::World world = facet::build_world(scene);
    uint64_t total = 0;
    for (const auto& [part, bytes] :
         facet::render_memory(scene, world, facet::plan_render(scene, world), 2))
        total += bytes;
    return total;
}

// The peak resident bytes of rendering `path` on two threads.
uint64_t peak(const std::string& path, const std::string& out) {
    const facet::test::RunResult r = facet::test::run_command(
        "/usr/bin/time -f '%M' '" + facet::test::facet_executable() + "' render '" + path +
        "' -o '" + out + "' --threads 2 -q --overwrite 2>&1 >/dev/null | tail -n 1");
    REQUIRE(r.exit_code == 0);
    return std::stoull(r.output) * 1024;
}

}  // namespace

TEST_CASE("the memory estimate is within 0.45 to 1.4 times what a render really holds",
          "[render][memory]") {
    if (facet::kAddressSanitizer)
        FACET_SKIP("AddressSanitizer's shadow memory and redzones are not the program's");
    if (!facet::test::have_command("/usr/bin/time"))
        FACET_SKIP("/usr/bin/time (Debian package time) is not installed");
    const Case cases[] = {
        {"colour alone", "passes: [color]", "blinn-phong"},
        {"samples kept: outlines, occlusion and the lines pass",
         "samples: 4, passes: [color, lines], formats: [png, exr]",
         "{ extends: blinn-phong, outlines: true, occlusion: true }"},
        {"every pass, PNG and EXR",
         "passes: [color, alpha, depth, normal, object_id, material_id, uv, position, motion], "
         "formats: [png, exr]",
         "pbr"},
    };
    facet::test::TempDir dir("render-memory");
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string large =
            facet::test::write_text(dir.file("large.yaml"), scene_text(c, "[1920, 1080]"));
        const std::string small =
            facet::test::write_text(dir.file("small.yaml"), scene_text(c, "[32, 18]"));
        const double estimated = static_cast<double>(estimate(large) - estimate(small));
        const double measured = static_cast<double>(peak(large, dir.file("out"))) -
                                static_cast<double>(peak(small, dir.file("out")));
        INFO("estimated " << estimated / 1048576 << " MiB, measured " << measured / 1048576
                          << " MiB: " << measured / estimated);
        CHECK(measured >= 0.45 * estimated);
        CHECK(measured <= 1.4 * estimated);
    }
}

namespace {

// The estimate's shadow-map part for one spot light of `outer_angle` (a
// number, or a track) at `resolution` texels a side.
uint64_t spot_shadow_bytes(const std::string& outer_angle, int resolution) {
    facet::test::TempDir dir("memory-spot");
    const std::string path = facet::test::write_text(
        dir.file("spot.yaml"),
        "output: { size: [64, 36], frames: \"1-10\" }\n"
        "camera: { position: [0, 1, 4], target: [0, 0, 0] }\n"
        "lights:\n  - { type: spot, position: [0, 3, 0], direction: [0, -1, 0], outer_angle: " +
            outer_angle + ", shadows: true, shadow_resolution: " + std::to_string(resolution) +
            " }\n"
            "objects:\n  - primitive: sphere\n"
            "  - { primitive: { type: plane, size: 10 }, translate: [0, -1, 0] }\n");
    const facet::SceneDesc scene = facet::test::load(path);
    const facet::World world = facet::build_world(scene);
    for (const auto& [part, bytes] :
         facet::render_memory(scene, world, facet::plan_render(scene, world), 2))
        if (part == "shadow maps") return bytes;
    FAIL("no shadow maps part");
    return 0;
}

}  // namespace

TEST_CASE("the shadow estimate counts six faces for a spot that is, or widens to, a cube map",
          "[render][memory]") {
    // A spot wider than 60 degrees is drawn into a cube map (render/shadow_stage.cpp):
    // its texels grow six times as fast with the resolution as a narrow one's.
    auto growth = [](const std::string& angle) {
        return spot_shadow_bytes(angle, 1024) - spot_shadow_bytes(angle, 512);
    };
    const uint64_t narrow = growth("50");
    REQUIRE(narrow > 0);
    CHECK(growth("80") == 6 * narrow);
    CHECK(growth("{ keys: { 1: 50, 10: 80 } }") == 6 * narrow);
    CHECK(growth("{ keys: { 1: 30, 10: 60 } }") == narrow);
}
