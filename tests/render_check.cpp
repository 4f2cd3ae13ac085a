#include "render_check.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/color.hpp"
#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "job/pass_files.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "support.hpp"

namespace facet::test {
namespace fs = std::filesystem;

FrameImages render_images(const SceneDesc& scene, int frame, unsigned threads, ShadingPaths paths) {
    const World world = build_world(scene);
    ThreadPool pool(threads);
    FrameRenderer renderer(scene, world, pool, paths);
    FrameImages images;
    renderer.render(frame, 0, images);
    return images;
}

FrameImages render_yaml(const std::string& folder, const std::string& yaml, int frame,
                        unsigned threads, ShadingPaths paths) {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    const std::string path = write_text((fs::path(folder) / "scene.yaml").string(), yaml);
    return render_images(load_scene(path, options), frame, threads, paths);
}

namespace {

// The pass's picture: its PNG view, or for the float-only passes one made
// here. Position: each axis from [-4, 4] m to [0, 1]; motion: 0.5 plus
// the vector over 32 pixels, in red and green.
std::vector<uint8_t> pass_png(const std::string& pass, const FrameImages& images) {
    const int width = images.color.width, height = images.color.height;
    ColorImage view(width, height);
    if (pass == "position" || pass == "motion") {
        for (size_t i = 0; i < view.pixels.size(); ++i) {
            const glm::vec3 v = pass == "position"
                                    ? images.surface.position.pixels[i] / 8.0f + 0.5f
                                    : glm::vec3(images.surface.motion.pixels[i] / 32.0f + 0.5f, 0);
            // Linear values meant as display values: undo the sRGB curve.
            for (int a = 0; a < 3; ++a)
                view.pixels[i][a] = srgb_to_linear(std::clamp(v[a], 0.0f, 1.0f));
            view.pixels[i].a = 1;
        }
        return encode_png_color(view, 6);
    }
    OutputDesc out;
    out.passes = {};
    out.passes.add(*pass_from_name(pass));
    out.png_compression = 6;
    std::vector<uint8_t> png;
    encode_frame_files(out, frame_files(out), images, {images.depth_view_range, {}, {}},
                       [&](const PassFile&, const std::vector<uint8_t>& bytes) { png = bytes; });
    return png;
}

}  // namespace

ColorImage render_color(const SceneDesc& scene, int frame, unsigned threads) {
    return to_float_image(render_images(scene, frame, threads).color);
}

void check_render(const RenderCase& c) {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    if (!c.style.empty()) options.overrides.push_back({"style", c.style, "test style"});
    for (const auto& d : c.defines) {
        size_t eq = d.find('=');
        options.overrides.push_back({d.substr(0, eq), d.substr(eq + 1), "test -D " + d});
    }
    if (c.pass != "color") {
        options.overrides.push_back({"output.passes", "[" + c.pass + "]", "test pass"});
        options.overrides.push_back({"output.formats", "[png, exr]", "test pass"});
    }
    SceneDesc scene = load_scene(source_path(c.scene), options);
    const FrameImages images = render_images(scene, c.frame, 2);
    check_against_baseline(pass_png(c.pass, images), c.reference, c.tolerance);
}

void check_against_baseline(const std::vector<uint8_t>& png, const std::string& reference,
                            const Tolerance& tolerance) {
    const fs::path out_dir = fs::path("render-test-output");
    fs::create_directories(out_dir);
    const std::string actual_path = (out_dir / reference).string();
    write_file_atomically(actual_path, png);
    const std::string reference_path =
        (fs::path(facet::test::baselines_dir()) / reference).string();

    const char* update = std::getenv("FACET_UPDATE_BASELINES");
    if ((update && std::string(update) == "1") || !fs::exists(reference_path)) {
        fs::copy_file(actual_path, reference_path, fs::copy_options::overwrite_existing);
        FAIL("wrote a new reference " << reference_path
                                      << ": look at it, then commit it if it is right");
    }

    DecodedPng actual = read_png(actual_path);
    DecodedPng expected = read_png(reference_path);
    REQUIRE(actual.width == expected.width);
    REQUIRE(actual.height == expected.height);
    // RGB and RGBA files compare equal when the RGBA one is opaque.
    auto sample = [](const DecodedPng& png, size_t pixel, int channel) {
        return channel < png.channels ? int(png.samples[pixel * png.channels + channel]) : 255;
    };
    const int channels = std::max(actual.channels, expected.channels);
    const size_t pixels = static_cast<size_t>(actual.width) * actual.height;
    double sum = 0;
    size_t outliers = 0;
    std::vector<uint8_t> diff(pixels * 4, 255);
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int ch = 0; ch < channels; ++ch)
            worst = std::max(worst, std::abs(sample(actual, p, ch) - sample(expected, p, ch)));
        sum += worst;
        if (worst > 24) ++outliers;
        uint8_t v = static_cast<uint8_t>(std::min(255, worst * 8));
        diff[4 * p] = v;
        diff[4 * p + 1] = diff[4 * p + 2] = 0;
    }
    const double mean = sum / static_cast<double>(pixels);
    const double outlier_fraction = static_cast<double>(outliers) / static_cast<double>(pixels);
    if (mean > tolerance.mean || outlier_fraction > tolerance.outliers) {
        ColorImage diff_image(actual.width, actual.height);
        for (size_t p = 0; p < pixels; ++p) diff_image.pixels[p] = {diff[4 * p] / 255.0f, 0, 0, 1};
        write_file_atomically((out_dir / ("diff-" + reference)).string(),
                              encode_png_color(diff_image, 1));
    }
    INFO(reference << ": mean difference " << mean << " (allowed " << tolerance.mean
                   << "), outliers " << outlier_fraction << " (allowed " << tolerance.outliers
                   << "); actual image in " << fs::absolute(actual_path).string());
    CHECK(mean <= tolerance.mean);
    CHECK(outlier_fraction <= tolerance.outliers);
}

glm::vec4 pixel_at(const FrameImages& images, const HalfColorImage& image, glm::vec3 p) {
    const glm::vec4 clip = images.projection * images.view * glm::vec4(p, 1.0f);
    const float x = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(image.width);
    const float y = (0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(image.height);
    return to_float(image.at(static_cast<int>(x), static_cast<int>(y)));
}

}  // namespace facet::test
