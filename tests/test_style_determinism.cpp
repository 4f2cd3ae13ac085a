// Styles with post passes (outlines, hatching, hidden wireframe edges) give
// the same pixels for any thread count.
#include <catch2/catch.hpp>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

TEST_CASE("styled renders are identical for 1, 2 and 3 threads", "[style][determinism]") {
    const char* looks[] = {"toon-outline", "hatching",  "pencil",
                           "palette",      "blueprint", "intersections"};
    for (const char* look : looks) {
        INFO("style " << look);
        SceneOptions options = with_styles();
        options.overrides.push_back({"style", look, "test"});
        options.overrides.push_back({"output.size", "[160, 120]", "test"});
        options.overrides.push_back({"output.samples", "4", "test"});
        if (std::string(look) == "blueprint")
            options.overrides.push_back({"style.wireframe.hidden", "true", "test"});
        const SceneDesc scene = load(source_path("tests/scenes/shapes.yaml"), options);
        const World world = build_world(scene);
        std::vector<std::vector<glm::vec4>> images;
        for (unsigned threads : {1u, 2u, 3u}) {
            ThreadPool pool(threads);
            FrameRenderer renderer(scene, world, pool);
            FrameImages out;
            renderer.render(2, 0, out);
            const ColorImage color = to_float_image(out.color);
            images.push_back(std::vector<glm::vec4>(color.pixels.begin(), color.pixels.end()));
        }
        CHECK(images[0] == images[1]);
        CHECK(images[0] == images[2]);
    }
}
