// Exposure and tone mapping (output.exposure, output.tonemap): they change
// the images people look at (PNG, video, sheets) and never the EXR files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/color.hpp"
#include "core/display_transform.hpp"
#include "core/half.hpp"
#include "job/render_job.hpp"
#include "output/encoders.hpp"
#include "output/manifest.hpp"
#include "render/world.hpp"
#include "support.hpp"

using namespace facet;

namespace {

struct RenderedFiles {
    DecodedPng png;
    DecodedExr exr;
};

// A lit sphere on a grey card: a spread of linear values, some above 0.5
// so that doubling them clips.
RenderedFiles render_with(const test::TempDir& dir, const std::string& name,
                          const std::string& display) {
    const std::string yaml =
        "output: { size: [96, 64], formats: [png, exr], " + display +
        " }\n"
        "style: phong\n"
        "camera: { position: [0, 0, 6], target: [0, 0, 0], fov: 40 }\n"
        "lights: [{ type: directional, direction: [-1, -1, -1], intensity: 1.2 }]\n"
        "objects:\n"
        "  - { name: ball, primitive: { type: sphere, radius: 1.4 }, material: { color: [0.7, "
        "0.4, 0.2] } }\n"
        "  - { name: card, primitive: { type: cube, size: 1 }, scale: [8, 8, 0.1], translate: [0, "
        "0, -2], material: { color: [0.3, 0.3, 0.3] } }\n";
    SceneOptions scene_options;
    scene_options.style_dirs = {facet::test::styles_dir()};
    const SceneDesc scene =
        load_scene(test::write_text(dir.file(name + ".yaml"), yaml), scene_options);
    const World world = build_world(scene);
    RenderOptions options;
    options.out_dir = dir.file("out");
    options.threads = 2;
    const RenderResult result = render_scene(scene, world, options, nullptr);
    const Manifest manifest = read_manifest(result.manifest_path);
    RenderedFiles files;
    for (const ManifestFile& f : manifest.files) {
        const std::string path = manifest_file_path(result.output_dir, f.path);
        if (f.pass != "color") continue;
        if (f.format == "png") files.png = read_png(path);
        if (f.format == "exr") files.exr = read_exr(path);
    }
    return files;
}

// The 8-bit sRGB code of a linear value, as the PNG writer rounds it.
int srgb_byte(double linear) {
    return static_cast<int>(std::lround(linear_to_srgb(std::clamp(linear, 0.0, 1.0)) * 255.0));
}

}  // namespace

TEST_CASE("exposure +1 doubles the linear values of the PNG and leaves the EXR alone",
          "[display]") {
    test::TempDir dir("exposure");
    const RenderedFiles plain = render_with(dir, "plain", "exposure: 0");
    const RenderedFiles brighter = render_with(dir, "brighter", "exposure: 1");
    REQUIRE(plain.png.channels == 3);
    REQUIRE(brighter.png.channels == 3);
    // The EXR holds the scene-linear values either way.
    REQUIRE(plain.exr.channel_names == brighter.exr.channel_names);
    CHECK(plain.exr.channels == brighter.exr.channels);
    int doubled = 0, clipped = 0;
    const size_t pixels = plain.exr.channels[0].size();
    for (int c = 0; c < 3; ++c) {
        const auto at = std::find(plain.exr.channel_names.begin(), plain.exr.channel_names.end(),
                                  std::string(1, "RGB"[c]));
        REQUIRE(at != plain.exr.channel_names.end());
        const std::vector<float>& linear =
            plain.exr.channels[static_cast<size_t>(at - plain.exr.channel_names.begin())];
        for (size_t p = 0; p < pixels; ++p) {
            INFO("pixel " << p << " channel " << c << " linear " << linear[p]);
            REQUIRE(plain.png.samples[p * 3 + c] == srgb_byte(linear[p]));
            // Doubling a half float is exact: the PNG holds exactly 2x.
            REQUIRE(brighter.png.samples[p * 3 + c] == srgb_byte(2.0 * linear[p]));
            doubled += linear[p] > 0.01f && linear[p] < 0.5f;
            clipped += linear[p] > 0.5f;
        }
    }
    CHECK(doubled > 1000);  // the check saw real mid-tones
    CHECK(clipped > 10);    // and values the exposure pushed past white

    // Every tone curve changes the PNG and leaves the EXR scene-linear.
    for (const char* curve : {"aces", "filmic", "neutral", "agx"}) {
        INFO("tonemap " << curve);
        const RenderedFiles toned =
            render_with(dir, std::string("toned-") + curve, std::string("tonemap: ") + curve);
        REQUIRE(toned.exr.channel_names == plain.exr.channel_names);
        CHECK(toned.exr.channels == plain.exr.channels);
        REQUIRE(toned.png.samples.size() == plain.png.samples.size());
        CHECK(toned.png.samples != plain.png.samples);
    }
}

TEST_CASE("tone curves keep black, rise monotonically and roll off below white", "[display]") {
    for (Tonemap curve : {Tonemap::aces, Tonemap::filmic, Tonemap::neutral, Tonemap::agx}) {
        INFO(name_of(kTonemaps, curve));
        const DisplayTransform t{0, curve};
        CHECK(display_color({0, 0, 0, 1}, t) == glm::vec4(0, 0, 0, 1));
        float previous = 0;
        for (float x = 0.001f; x < 64.0f; x *= 1.05f) {
            const float y = display_color({x, x, x, 1}, t).r;
            CHECK(y >= previous);
            CHECK(y <= 1.0f);
            previous = y;
        }
        // Highlights that `none` clips keep distinct values.
        CHECK(display_color({2, 2, 2, 1}, t).r < display_color({4, 4, 4, 1}, t).r);
        CHECK(display_color({1, 1, 1, 1}, t).r < 1.0f);
        // Grey stays grey.
        const glm::vec4 grey = display_color({0.18f, 0.18f, 0.18f, 1}, t);
        CHECK(grey.r == grey.g);
        CHECK(grey.g == grey.b);
        // The curve applies to the straight colour: an edge pixel half
        // covered gets half the surface's displayed colour, alpha kept.
        const glm::vec4 full = display_color({0.9f, 0.5f, 0.1f, 1}, t);
        const glm::vec4 half = display_color({0.45f, 0.25f, 0.05f, 0.5f}, t);
        for (int c = 0; c < 3; ++c) CHECK(half[c] == Approx(0.5f * full[c]).epsilon(1e-5));
        CHECK(half.a == 0.5f);
    }
    // none with no exposure is the identity; a transparent pixel stays so.
    const DisplayTransform identity;
    CHECK(display_color({3, 0.5f, 0.25f, 1}, identity) == glm::vec4(3, 0.5f, 0.25f, 1));
    CHECK(display_color({0, 0, 0, 0}, DisplayTransform{2, Tonemap::aces}) == glm::vec4(0));
}

// The one conversion of every 8-bit display image (PNG, sheet JPEG, movie
// frames, the preview).
TEST_CASE("display bytes: linear to 8-bit sRGB, and 16-bit samples to 8 bits", "[display][color]") {
    CHECK(facet::display_byte(0.0) == 0);
    CHECK(facet::display_byte(1.0) == 255);
    CHECK(facet::display_byte(0.5) == 188);       // sRGB(0.5) = 0.7354 -> 187.5...
    CHECK(facet::display_byte(0.0031308) == 10);  // the curve's linear segment ends here
    CHECK(facet::display_byte(-1.0) == 0);
    CHECK(facet::display_byte(std::nan("")) == 0);
    CHECK(facet::display_byte(INFINITY) == 255);
    CHECK(facet::display_byte(7.5) == 255);
    // Every code is reached and the mapping never goes down.
    int previous = -1, codes = 0;
    for (int i = 0; i <= 100000; ++i) {
        const int b = facet::display_byte(i / 100000.0);
        CHECK(b >= previous);
        codes += b != previous;
        previous = b;
    }
    CHECK(codes == 256);

    CHECK(facet::narrow_to_byte(0) == 0);
    CHECK(facet::narrow_to_byte(65535) == 255);
    CHECK(facet::narrow_to_byte(128) == 0);  // 0.498 of a code
    CHECK(facet::narrow_to_byte(129) == 1);  // 0.502
    CHECK(facet::narrow_to_byte(257) == 1);
    for (int b = 0; b < 256; ++b) CHECK(facet::narrow_to_byte(static_cast<uint16_t>(b * 257)) == b);
}

TEST_CASE("neutral is Khronos PBR Neutral: base colours pass, highlights compress in hue",
          "[display]") {
    const DisplayTransform neutral{0, Tonemap::neutral};
    const auto shown = [&](glm::vec3 c) { return glm::vec3(display_color({c, 1}, neutral)); };
    // Below the compression (largest channel < 0.76 after the offset) only
    // the offset moves a colour: 0.04 once its darkest channel reaches 0.08,
    // x - 6.25 x^2 below that (0.04 -> 0.03).
    CHECK(shown({0.5f, 0.5f, 0.5f}).r == Approx(0.46f).epsilon(1e-6));
    CHECK(shown({0.04f, 0.04f, 0.04f}).r == Approx(0.01f).epsilon(1e-5));
    const glm::vec3 base = shown({0.7f, 0.3f, 0.1f});
    CHECK(base.r == Approx(0.66f).epsilon(1e-6));
    CHECK(base.g == Approx(0.26f).epsilon(1e-6));
    CHECK(base.b == Approx(0.06f).epsilon(1e-6));
    // Grey 2 (1.96 after the offset): the peak goes to 1 - 0.24^2 / 1.44 =
    // 0.96, and grey has nothing to desaturate.
    CHECK(shown({2, 2, 2}).r == Approx(0.96f).epsilon(1e-5));
    // A bright colour keeps its order of channels and moves toward white.
    const glm::vec3 bright = shown({4.0f, 2.0f, 1.0f});
    CHECK(bright.r > bright.g);
    CHECK(bright.g > bright.b);
    CHECK(bright.r < 1.0f);
    CHECK(bright.b / bright.r > 1.0f / 4.0f);  // desaturated
    CHECK(name_of(kTonemaps, Tonemap::neutral) == "neutral");
    CHECK(value_of(kTonemaps, "neutral") == Tonemap::neutral);
}

namespace {

// HSV hue in turns, for checking that a colour keeps its hue roughly.
double hue_turns(glm::vec3 c) {
    const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    const double chroma = hi - lo;
    double sixths = hi == c.r   ? (c.g - c.b) / chroma
                    : hi == c.g ? (c.b - c.r) / chroma + 2
                                : (c.r - c.g) / chroma + 4;
    if (sixths < 0) sixths += 6;
    return sixths / 6;
}

double saturation(glm::vec3 c) {
    const float hi = std::max({c.r, c.g, c.b});
    return hi > 0 ? (hi - std::min({c.r, c.g, c.b})) / hi : 0.0;
}

}  // namespace

TEST_CASE("agx is Blender 4's AgX: grey to its pivot, bright colours to white", "[display]") {
    const DisplayTransform agx{0, Tonemap::agx};
    const auto shown = [&](glm::vec3 c) { return glm::vec3(display_color({c, 1}, agx)); };
    CHECK(shown({0, 0, 0}) == glm::vec3(0));
    // Middle grey: every matrix maps white to white, the log encoding puts
    // 0.18 at the curve's pivot x = 10/16.5, and the curve gives the pivot's
    // y = 0.18^(1/2.4); decoded with 2.4 that is 0.18 again, and encoded with
    // 1/2.4 for the display, 0.18^(1/2.4) = exp(ln 0.18 / 2.4) = 0.48944.
    // That is the code Blender writes (byte 124.8 -> 125). The polynomial
    // fit many engines use ("AgX minimal") gives 0.4967 there instead.
    const glm::vec3 grey = shown({0.18f, 0.18f, 0.18f});
    CHECK(linear_to_srgb(grey.r) == Approx(0.48944).margin(1e-4));
    CHECK(display_byte(grey.r) == 125);
    // The curve's ends: -10 stops below middle grey and darker are black;
    // +6.5 stops above is the curve's (1, 1), white.
    CHECK(shown(glm::vec3(0.18f * std::exp2(-10.5f))).r == 0.0f);
    CHECK(shown(glm::vec3(0.18f * std::exp2(6.5f))).r == Approx(1.0f).margin(1e-4));
    // Brighter, never darker, from 1e-4 to 1e3, for grey and for colours
    // (luminance of the shown colour; 1e-6 is float rounding near white).
    for (const glm::vec3 colour :
         {glm::vec3(1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1),
          glm::vec3(1, 0.2f, 0.05f), glm::vec3(0.1f, 0.3f, 1.0f)}) {
        INFO("colour " << colour.r << " " << colour.g << " " << colour.b);
        float previous = 0;
        for (float k = 1e-4f; k <= 1e3f; k *= 1.05f) {
            const glm::vec3 c = shown(colour * k);
            const float y = rec709_luminance(c.r, c.g, c.b);
            INFO("scale " << k);
            CHECK(y >= previous - 1e-6f);
            CHECK(std::max({c.r, c.g, c.b}) <= 1.0f);
            CHECK(std::min({c.r, c.g, c.b}) >= 0.0f);
            previous = y;
        }
    }
    // A saturated orange made ever brighter: it keeps the order of its
    // channels and roughly its hue while it pales, and ends white.
    const glm::vec3 orange(1.0f, 0.2f, 0.05f);
    double previous_saturation = 1.0;
    for (const float k : {1.0f, 4.0f, 16.0f, 64.0f}) {
        INFO("scale " << k);
        const glm::vec3 c = shown(orange * k);
        CHECK(c.r >= c.g);
        CHECK(c.g >= c.b);
        if (k <= 16.0f) CHECK(std::abs(hue_turns(c) - hue_turns(orange)) < 0.05);
        CHECK(saturation(c) < previous_saturation);
        previous_saturation = saturation(c);
    }
    // Pure red, in display codes: from a separate double-precision
    // transcription of the same steps (Python), which this float code
    // matches to 0.01 of a code.
    const glm::vec3 red = shown({1, 0, 0});
    CHECK(linear_to_srgb(red.r) * 255 == Approx(220.82).margin(0.1));
    CHECK(linear_to_srgb(red.g) * 255 == Approx(67.45).margin(0.1));
    CHECK(linear_to_srgb(red.b) * 255 == Approx(45.35).margin(0.1));
    const glm::vec3 blinding = shown(orange * 1000.0f);
    CHECK(std::min({blinding.r, blinding.g, blinding.b}) > 0.999f);
    CHECK(name_of(kTonemaps, Tonemap::agx) == "agx");
    CHECK(value_of(kTonemaps, "agx") == Tonemap::agx);
}

TEST_CASE(
    "every tone curve is monotonic from 0 to +infinity: a brighter input never gives a darker "
    "pixel, and infinity is the curve's white",
    "[display]") {
    const float inf = std::numeric_limits<float>::infinity();
    // Greys, and colours of several hues and saturations, each scaled from
    // 1e-6 to 3e38 in steps of a quarter stop, then infinity.
    const std::vector<glm::vec3> colours = {{1, 1, 1},        {1, 0, 0},       {0, 1, 0},
                                            {0, 0, 1},        {1, 0.5f, 0.1f}, {0.2f, 0.9f, 0.6f},
                                            {0.05f, 0.1f, 1}, {1, 1, 0},       {0.7f, 0.7f, 0.65f}};
    std::vector<float> scales;
    for (float s = 1e-6f; s < 3e38f; s *= 1.189207f) scales.push_back(s);
    scales.push_back(inf);
    for (Tonemap curve :
         {Tonemap::none, Tonemap::aces, Tonemap::filmic, Tonemap::neutral, Tonemap::agx})
        for (float exposure : {0.0f, 10.0f}) {
            const DisplayTransform t{exposure, curve};
            for (const glm::vec3& colour : colours) {
                INFO(name_of(kTonemaps, curve) << " exposure " << exposure << " colour " << colour.r
                                               << "," << colour.g << "," << colour.b);
                float previous = -1.0f;
                for (float s : scales) {
                    // An infinite channel times 0 is NaN, not a colour: the
                    // zero channels of an infinite colour stay zero.
                    const glm::vec3 c =
                        s == inf ? glm::vec3(colour.r > 0 ? inf : 0, colour.g > 0 ? inf : 0,
                                             colour.b > 0 ? inf : 0)
                                 : colour * s;
                    const glm::vec4 shown = display_color({c, 1}, t);
                    INFO("scale " << s << " -> " << shown.r << "," << shown.g << "," << shown.b);
                    REQUIRE_FALSE(std::isnan(shown.r + shown.g + shown.b));
                    // What the 8-bit file shows, by luminance: never darker.
                    const float luminance = 0.2126f * display_byte(shown.r) +
                                            0.7152f * display_byte(shown.g) +
                                            0.0722f * display_byte(shown.b);
                    REQUIRE(luminance >= previous);
                    previous = luminance;
                }
                // Infinity is as bright as the curve goes.
                CHECK(previous >= 0.2126f * 255 * (colour.r > 0) + 0.7152f * 255 * (colour.g > 0) +
                                      0.0722f * 255 * (colour.b > 0) - 1.0f);
            }
        }
}

TEST_CASE("a colour past the half-float range is shown as white, not black", "[display]") {
    // The frame's colour is stored as half floats, saturated at 65504.
    for (Tonemap curve : {Tonemap::aces, Tonemap::filmic, Tonemap::neutral, Tonemap::agx}) {
        INFO(name_of(kTonemaps, curve));
        HalfColorImage image(2, 1);
        image.at(0, 0) = to_half(glm::vec4(7e4f, 7e4f, 7e4f, 1));
        image.at(1, 0) = to_half(glm::vec4(std::numeric_limits<float>::infinity(), 1.6e9f, 1, 1));
        const HalfColorImage shown = apply_display_transform(image, {0, curve});
        for (int x = 0; x < 2; ++x) {
            const glm::vec4 c = to_float(shown.at(x, 0));
            CHECK(display_byte(c.r) == 255);
            CHECK(display_byte(c.g) >= 250);
        }
    }
}
