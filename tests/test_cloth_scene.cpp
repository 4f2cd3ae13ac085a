// Cloth in scenes: the flag renders the same whatever frames or threads are
// used, its settings are checked with the scene's file and key, and reviewed
// frames of scenes/flag.yaml.
#include <catch2/catch.hpp>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

SceneDesc small_flag(const std::vector<std::string>& defines = {}) {
    SceneOptions options = with_styles();
    options.overrides.push_back({"output.size", "[96, 54]", "test"});
    options.overrides.push_back({"output.samples", "1", "test"});
    for (const std::string& d : defines) {
        const size_t eq = d.find('=');
        options.overrides.push_back({d.substr(0, eq), d.substr(eq + 1), "test -D " + d});
    }
    return load(source_path("scenes/flag.yaml"), options);
}

std::vector<std::vector<glm::vec4>> render_frames(const SceneDesc& scene, const World& world,
                                                  const std::vector<int>& frames,
                                                  unsigned threads) {
    ThreadPool pool(threads);
    FrameRenderer renderer(scene, world, pool);
    std::vector<std::vector<glm::vec4>> out;
    for (int f : frames) {
        FrameImages images;
        renderer.render(f, 0, images);
        const ColorImage color = to_float_image(images.color);
        out.push_back(std::vector<glm::vec4>(color.pixels.begin(), color.pixels.end()));
    }
    return out;
}

}  // namespace

TEST_CASE("a cloth frame is the same rendered alone, in a run, or on more threads",
          "[cloth][determinism]") {
    const SceneDesc scene = small_flag();
    const World world = build_world(scene);
    const auto run = render_frames(scene, world, {38, 39, 40, 41}, 1);
    const auto alone = render_frames(scene, world, {41}, 1);
    const auto threaded = render_frames(scene, world, {40, 41}, 2);
    CHECK(run[3] == alone[0]);
    CHECK(run[2] == threaded[0]);
    CHECK(run[3] == threaded[1]);
    CHECK(run[0] != run[3]);  // the flag moves
}

TEST_CASE("cloth settings a simulation cannot use name the scene's cloth", "[cloth][scene]") {
    TempDir dir("cloth-scene");
    const std::string text =
        "objects:\n  - name: flag\n    cloth: { stiffness: 1000000000, "
        "substeps: 1 }\n";
    const std::string path = write_text(dir.file("s.yaml"), text);
    const SceneDesc scene = load(path);
    try {
        build_world(scene);
        FAIL("build_world accepted an unstable cloth");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        CHECK_THAT(std::string(e.what()), Contains(path + ":3:12"));
        CHECK_THAT(std::string(e.what()), Contains("objects.0.cloth"));
        CHECK_THAT(std::string(e.what()), Contains("stiffness"));
    }
    const std::string both = "objects:\n  - name: flag\n    primitive: plane\n    cloth: {}\n";
    const std::string message = load_error(write_text(dir.file("both.yaml"), both));
    CHECK_THAT(message, Contains("exactly one of"));
    const std::string bad_pin =
        "objects:\n  - name: flag\n    cloth: { grid: [4, 4], pin: [0, 16] }\n";
    const std::string pin_path = write_text(dir.file("pin.yaml"), bad_pin);
    check_error_at(load_error(pin_path), pin_path, line_col(bad_pin, "16"),
                   "objects.0.cloth.pin.1");
}

// clang-format off
TEST_CASE("render: flag frame 60",  "[render][cloth]") { check_render({"scenes/flag.yaml", 60, "flag-0060.png", {}, {"output.size=[320, 180]", "output.samples=1"}}); }
TEST_CASE("render: flag frame 150", "[render][cloth]") { check_render({"scenes/flag.yaml", 150, "flag-0150.png", {}, {"output.size=[320, 180]", "output.samples=1"}}); }
// clang-format on
