// glTF alpha modes (render/alpha_coverage.hpp): MASK cuts out where the
// alpha falls below the cutoff, BLEND keeps a share of samples equal to its
// alpha, so the surface behind shows through in proportion once samples
// are resolved. Checked on the rendered, linear colour.
#include <catch2/catch.hpp>

#include "asset_support.hpp"
#include "core/half.hpp"
#include "real_asset_support.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

// A white quad (x, y in -1..1 at z = 0.5) with `material`, UVs 0..1, in
// front of a red quad at z = 0 that fills more of the view.
std::string layered_file(const TempDir& dir, const json& material, const std::string& name,
                         const std::string& texture = "") {
    Gltf g;
    auto quad = [&](float half, float z, int material_index) {
        return g.mesh(
            {{"attributes",
              {{"POSITION",
                g.floats({-half, -half, z, half, -half, z, half, half, z, -half, half, z}, "VEC3")},
               {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
               {"TEXCOORD_0", g.floats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2")}}},
             {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123)},
             {"material", material_index}});
    };
    g.doc["materials"] =
        json::array({material, {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}});
    if (!texture.empty()) {
        g.doc["images"] = json::array({{{"uri", texture}}});
        g.doc["textures"] = json::array({{{"source", 0}}});
    }
    const int front = g.node({{"mesh", quad(1, 0.5f, 0)}});
    const int back = g.node({{"mesh", quad(3, 0, 1)}});
    g.scene({front, back});
    return g.write(dir.file(name));
}

ColorImage render(const TempDir& dir, const std::string& file, int samples, int threads = 1) {
    const SceneDesc scene = load(write_text(
        dir.file("alpha.yaml"),
        "output: { size: [64, 64], frames: \"1\", samples: " + std::to_string(samples) +
            " }\nstyle: unlit\ncamera: { position: [0, 0, 4], target: [0, 0, 0], fov: 40 }\n"
            "objects:\n  - mesh: " +
            file + "\n"));
    if (threads == 1) return to_float_image(render_frame(scene, 1).color);
    const World world = build_world(scene);
    ThreadPool pool(threads);
    FrameRenderer renderer(scene, world, pool);
    FrameImages images;
    renderer.render(1, 0, images);
    return to_float_image(images.color);
}

json white(double alpha, const std::string& mode, double cutoff = 0.5) {
    return {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, alpha}}}},
            {"alphaMode", mode},
            {"alphaCutoff", cutoff}};
}

}  // namespace

TEST_CASE("alphaMode MASK keeps the samples whose alpha reaches the cutoff", "[gltf][alpha]") {
    TempDir dir("alpha");
    // The centre pixel shows the white quad, or the red one behind it.
    auto centre = [&](double alpha, double cutoff) {
        return glm::vec3(
            render(dir, layered_file(dir, white(alpha, "MASK", cutoff), "mask.gltf"), 1)
                .at(32, 32));
    };
    CHECK(centre(0.6, 0.5) == glm::vec3(1, 1, 1));
    CHECK(centre(0.4, 0.5) == glm::vec3(1, 0, 0));
    CHECK(centre(0.4, 0.3) == glm::vec3(1, 1, 1));
    // OPAQUE ignores alpha.
    CHECK(glm::vec3(
              render(dir, layered_file(dir, white(0.1, "OPAQUE"), "opaque.gltf"), 1).at(32, 32)) ==
          glm::vec3(1, 1, 1));
}

TEST_CASE("alphaMode MASK cuts a texture's transparent squares out", "[gltf][alpha]") {
    TempDir dir("alpha");
    // 2 x 2 checker: opaque at the bottom-left and top-right texels.
    ColorImage checker(2, 2);
    checker.at(0, 0) = {1, 1, 1, 0};
    checker.at(1, 0) = {1, 1, 1, 1};
    checker.at(0, 1) = {1, 1, 1, 1};
    checker.at(1, 1) = {1, 1, 1, 0};
    write_png(dir.file("checker.png"), checker);
    json material = white(1, "MASK");
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const ColorImage image = render(dir, layered_file(dir, material, "cut.gltf", "checker.png"), 1);
    // The quad spans about pixels 14..49; sample the middle of each quarter.
    const int low = 22, high = 41;
    int white_quarters = 0;
    for (int y : {low, high})
        for (int x : {low, high}) white_quarters += image.at(x, y).g > 0.5f ? 1 : 0;
    CHECK(white_quarters == 2);
    CHECK((image.at(low, low).g > 0.5f) != (image.at(high, low).g > 0.5f));
    CHECK((image.at(low, low).g > 0.5f) == (image.at(high, high).g > 0.5f));
}

TEST_CASE("alphaMode BLEND shows the surface behind in proportion", "[gltf][alpha]") {
    TempDir dir("alpha");
    // 16 samples: each pixel holds one whole 4 x 4 pattern, so the resolved
    // green (white over red) is the alpha, to a sixteenth.
    for (double alpha : {0.25, 0.5, 0.75}) {
        INFO("alpha " << alpha);
        const ColorImage image =
            render(dir, layered_file(dir, white(alpha, "BLEND"), "blend.gltf"), 16);
        CHECK(image.at(32, 32).g == Approx(alpha).margin(1.0 / 32));
        CHECK(image.at(32, 32).r == Approx(1).margin(1e-3));
        CHECK(image.at(20, 40).g == Approx(alpha).margin(1.0 / 32));
    }
    // One sample per pixel: the pattern itself, half the pixels of a block.
    const ColorImage one = render(dir, layered_file(dir, white(0.5, "BLEND"), "blend.gltf"), 1);
    int shown = 0;
    for (int y = 28; y < 36; ++y)
        for (int x = 28; x < 36; ++x) shown += one.at(x, y).g > 0.5f ? 1 : 0;
    CHECK(shown == 32);
    // The same bytes on any number of threads.
    const std::string file = layered_file(dir, white(0.4, "BLEND"), "blend.gltf");
    const ColorImage a = render(dir, file, 4, 1), b = render(dir, file, 4, 2);
    CHECK(a.pixels == b.pixels);
}

TEST_CASE("bad alpha modes are errors naming the material", "[gltf][alpha][errors]") {
    TempDir dir("alpha");
    require_input_error([&] { load_gltf(layered_file(dir, white(1, "GLASS"), "glass.gltf")); },
                        "alphaMode must be OPAQUE, MASK or BLEND");
    require_input_error([&] { load_gltf(layered_file(dir, white(1, "MASK", 2), "cutoff.gltf")); },
                        "alphaCutoff");
}
