// The samples of the PNG views (output/png_views.cpp, render/pass_files.cpp):
// facet preview shows them without compressing them into a file, so they
// must be, byte for byte, what decoding that file gives back.
#include <catch2/catch.hpp>

#include <limits>
#include <optional>

#include "core/thread_pool.hpp"
#include "job/pass_files.hpp"
#include "output/encoders.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "support.hpp"

using namespace facet;

namespace {

constexpr Pass kViewedPasses[] = {Pass::color,     Pass::alpha,       Pass::depth, Pass::normal,
                                  Pass::object_id, Pass::material_id, Pass::uv,    Pass::lines};

// The shapes scene, small, with every viewed pass and anti-aliased edges over
// a transparent background (so the colour view is RGBA with partial alpha),
// shown with `exposure` and `tonemap`.
SceneDesc shapes_scene(const std::string& exposure, const std::string& tonemap) {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    options.overrides = {
        {"output.size", "[96, 72]", "test"},
        {"output.samples", "4", "test"},
        {"output.background", "transparent", "test"},
        {"output.passes", "[color, alpha, depth, normal, object_id, material_id, uv, lines]",
         "test"},
        {"output.exposure", exposure, "test"},
        {"output.tonemap", tonemap, "test"},
        {"style", "toon-outline", "test"},  // outlines: a lines pass with strokes
    };
    return load_scene(test::source_path("tests/scenes/shapes.yaml"), options);
}

FrameImages render_frame(const SceneDesc& scene) {
    const World world = build_world(scene);
    ThreadPool pool(2);
    FrameRenderer renderer(scene, world, pool);
    FrameImages images;
    renderer.render(2, 0, images);
    return images;
}

// A decoded PNG's samples laid out as the file's rows hold them: one byte
// each at 8 bits, two (most significant first) at 16.
std::vector<uint8_t> file_layout(const DecodedPng& png) {
    std::vector<uint8_t> bytes;
    for (const uint16_t s : png.samples) {
        if (png.bit_depth == 16) bytes.push_back(static_cast<uint8_t>(s >> 8));
        bytes.push_back(static_cast<uint8_t>(s));
    }
    return bytes;
}

}  // namespace

TEST_CASE("every pass's PNG view samples are what decoding its PNG gives", "[output][png]") {
    // The display transform skipped, and applied.
    const auto [exposure, tonemap] =
        GENERATE(table<std::string, std::string>({{"0", "none"}, {"1.5", "aces"}}));
    INFO("exposure " << exposure << ", tonemap " << tonemap);
    const SceneDesc scene = shapes_scene(exposure, tonemap);
    const FrameImages images = render_frame(scene);
    const PassFileFacts facts{images.depth_view_range, {{"Software", "facet"}}, {}};
    for (const Pass pass : kViewedPasses) {
        INFO("pass " << pass_name(pass));
        const std::optional<PngSamples> view =
            png_view_samples(pass, scene.output, images, facts.depth_range);
        REQUIRE(view);
        const DecodedPng png = decode_png(encode_png_view(pass, scene.output, images, facts),
                                          std::string(pass_name(pass)));
        CHECK(view->width == png.width);
        CHECK(view->height == png.height);
        CHECK(view->channels == png.channels);
        CHECK(view->bit_depth == png.bit_depth);
        CHECK(view->bytes == file_layout(png));
        size_t differing = 0;  // sample() widens them as decode_png does
        for (size_t i = 0; i < png.samples.size(); ++i)
            differing += view->sample(i) != png.samples[i];
        CHECK(differing == 0);
        // The passes are the kinds the test claims to cover.
        if (pass == Pass::color || pass == Pass::alpha) CHECK(png.channels == 4);
        if (pass == Pass::depth) CHECK((png.channels == 1 && png.bit_depth == 16));
        if (pass == Pass::object_id) CHECK(png.channels == 3);
    }
}

TEST_CASE("position and motion have no PNG view samples", "[output][png]") {
    const OutputDesc out;
    const FrameImages images{};  // never read: there is no view to make
    CHECK_FALSE(png_view_samples(Pass::position, out, images, {1, 2}));
    CHECK_FALSE(png_view_samples(Pass::motion, out, images, {1, 2}));
    CHECK(encode_png_view(Pass::motion, out, images, {}).empty());
}

TEST_CASE("the depth view maps every value as documented, eight at a time and one at a time",
          "[output][png]") {
    // docs/scene-format.md: near -> 65535, far -> 0, linear between,
    // clamped; the background (+inf) 0. NaN and -inf are no depth a render
    // gives, but must come out as something fixed: 0 and 0.
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec2 range(2.0f, 10.0f);
    const std::vector<std::pair<float, uint16_t>> cases = {
        {inf, 0},   {-inf, 0},     {nan, 0},       {2.0f, 65535}, {10.0f, 0},       {1.0f, 65535},
        {50.0f, 0}, {6.0f, 32768}, {-0.0f, 65535}, {9.99999f, 0}, {2.00001f, 65535}};
    // Eleven columns: eight in lanes, three one at a time; each row shifts
    // the cases by one, so every case is met at every column.
    const int width = 11, height = static_cast<int>(cases.size());
    DepthImage depth(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            depth.at(x, y) = cases[static_cast<size_t>(x + y) % cases.size()].first;
    const PngSamples samples = png_depth_samples(depth, range);
    REQUIRE(samples.bit_depth == 16);
    REQUIRE(samples.channels == 1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto& [value, expected] = cases[static_cast<size_t>(x + y) % cases.size()];
            INFO("depth " << value << " at column " << x);
            CHECK(samples.sample(static_cast<size_t>(y) * width + x) == expected);
        }
}
