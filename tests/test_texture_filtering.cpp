// Anisotropic texture filtering (Texture::sample of a footprint,
// docs/scene-format.md, `output.texture_filter`): a checker seen at a 75°
// slant against a reference worked out here, 64 points a pixel of the
// checker's closed form, box-filtered; the footprint's lookups against
// their definition; trilinear kept to the bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/texture.hpp"
#include "core/color.hpp"
#include "gltf_quad_support.hpp"
#include "render_check.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

constexpr int kSide = 192;       // the image's pixels a side
constexpr int kSquares = 32;     // the checker's squares along u and v
constexpr int kTexels = 512;     // the texture's texels a side
constexpr double kSlant = 75.0;  // degrees between the view and the quad's normal
constexpr double kFov = 50.0, kDistance = 1.7;

// The checker as a texture: black and white squares, 16 texels each.
std::vector<uint8_t> checker_png() {
    std::vector<uint8_t> grey(static_cast<size_t>(kTexels) * kTexels);
    const int texels_per_square = kTexels / kSquares;
    for (int y = 0; y < kTexels; ++y)
        for (int x = 0; x < kTexels; ++x)
            grey[static_cast<size_t>(y) * kTexels + x] =
                ((x / texels_per_square + y / texels_per_square) % 2) ? 255 : 0;
    return png_of(kTexels, kTexels, 1, grey);
}

glm::dvec3 camera_position() {
    const double a = glm::radians(kSlant);
    return {kDistance * std::sin(a), 0.0, kDistance * std::cos(a)};
}

// The scene: gltf_quad_support's quad (u = (x + 1) / 2, v = (1 - y) / 2),
// unlit, seen from the side at kSlant, with the filter given.
std::string slanted_scene(const std::string& mesh, const std::string& filter) {
    const glm::dvec3 eye = camera_position();
    return "output: { size: [" + std::to_string(kSide) + ", " + std::to_string(kSide) +
           "], tonemap: none, background: [0.5, 0, 0, 1], texture_filter: " + filter +
           " }\nstyle: unlit\nlights: []\ncamera: { position: [" + std::to_string(eye.x) + ", 0, " +
           std::to_string(eye.z) + "], target: [0, 0, 0], fov: " + std::to_string(kFov) +
           " }\nobjects:\n  - name: quad\n    mesh: " + mesh + "\n";
}

// The reference at one pixel: the mean of the checker's closed form at
// 8 x 8 points spread evenly over the pixel, the camera's rays cut with the
// quad's plane z = 0. Negative where a point misses the quad.
double reference_pixel(int px, int py) {
    const glm::dvec3 eye = camera_position();
    const glm::dvec3 forward = glm::normalize(-eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double half = std::tan(glm::radians(kFov) / 2.0);
    double sum = 0.0;
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            const double sx = (px + (i + 0.5) / 8.0) / kSide * 2.0 - 1.0;
            const double sy = 1.0 - (py + (j + 0.5) / 8.0) / kSide * 2.0;
            const glm::dvec3 ray = forward + right * (sx * half) + up * (sy * half);
            const double t = -eye.z / ray.z;
            const glm::dvec3 p = eye + ray * t;
            if (!(std::fabs(p.x) < 1.0 && std::fabs(p.y) < 1.0)) return -1.0;
            const double u = (p.x + 1.0) / 2.0, v = (1.0 - p.y) / 2.0;
            const int cell = static_cast<int>(std::floor(u * kSquares)) +
                             static_cast<int>(std::floor(v * kSquares));
            sum += cell % 2 ? 1.0 : 0.0;
        }
    return sum / 64.0;
}

struct Measured {
    double mean_error = 0.0;  // mean |image - reference| over the quad's pixels
    double contrast = 0.0, reference_contrast = 0.0;  // standard deviations there
};

Measured measure(const FrameImages& images) {
    double error = 0.0, n = 0.0, s = 0.0, s2 = 0.0, r = 0.0, r2 = 0.0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const double reference = reference_pixel(x, y);
            if (reference < 0.0) continue;
            // The checker's white is sRGB 255: linear 1.
            const double got = to_float(images.color.at(x, y)).g;
            error += std::fabs(got - reference);
            s += got, s2 += got * got, r += reference, r2 += reference * reference, n += 1.0;
        }
    REQUIRE(n > 1000.0);
    return {error / n, std::sqrt(s2 / n - (s / n) * (s / n)),
            std::sqrt(r2 / n - (r / n) * (r / n))};
}

}  // namespace

TEST_CASE(
    "texture filtering: a checker at a 75 degree slant is nearer its box-filtered "
    "reference anisotropic than trilinear",
    "[render][texture]") {
    TempDir dir("texture-filtering");
    Gltf g;
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(checker_png())}}};
    g.doc["textures"] = {{{"source", 0}}};
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const std::string mesh = g.write(dir.file("checker.gltf"));
    const FrameImages anisotropic =
        render_yaml(dir.file("a"), slanted_scene(mesh, "anisotropic"), 1, 2);
    const FrameImages trilinear =
        render_yaml(dir.file("t"), slanted_scene(mesh, "trilinear"), 1, 2);
    const Measured a = measure(anisotropic), t = measure(trilinear);
    INFO("mean error: anisotropic " << a.mean_error << ", trilinear " << t.mean_error
                                    << "; contrast: anisotropic " << a.contrast << ", trilinear "
                                    << t.contrast << ", reference " << a.reference_contrast);
    CHECK(a.mean_error <= 0.5 * t.mean_error);
    CHECK(a.contrast >= 0.8 * a.reference_contrast);
    CHECK(t.contrast < a.contrast);  // trilinear blurs it: the measure can tell
}

namespace {

Texture ramp_texture() {
    // 64 x 64, the value rising along x: its levels are ramps too.
    std::vector<glm::vec4> texels;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) texels.emplace_back((x + 0.5f) / 64.0f, 0.0f, 0.0f, 1.0f);
    return Texture::from_linear(64, 64, texels, Texture::Format::half);
}

}  // namespace

TEST_CASE(
    "texture filtering: a footprint's lookups are spread along its longer axis, at the "
    "shorter one's level",
    "[texture]") {
    Texture t = ramp_texture();
    // 8 texels long along u, 2 wide: 4 lookups at level 1, at offsets of
    // -3/8, -1/8, 1/8 and 3/8 of the axis.
    const TextureFootprint f{{0.5f, 0.5f}, {8.0f / 64.0f, 0.0f}, 8.0f, 2.0f};
    glm::vec4 expected(0.0f);
    for (const float along : {-0.375f, -0.125f, 0.125f, 0.375f})
        expected += t.sample(f.uv + f.major_axis * along, 1.0f);
    expected *= 0.25f;
    CHECK(t.sample(f) == expected);
    // Capped at max_anisotropy, the level follows the longer axis over the cap.
    t.sampler.max_anisotropy = 2;
    const glm::vec4 capped = 0.5f * (t.sample(f.uv - f.major_axis * 0.25f, 2.0f) +
                                     t.sample(f.uv + f.major_axis * 0.25f, 2.0f));
    CHECK(t.sample(f) == capped);
    // Trilinear (max_anisotropy 1) and a round footprint are sample(uv, log2 major).
    t.sampler.max_anisotropy = 1;
    CHECK(t.sample(f) == t.sample(f.uv, 3.0f));
    t.sampler.max_anisotropy = 16;
    const TextureFootprint round{{0.3f, 0.6f}, {0.0f, 4.0f / 64.0f}, 4.0f, 4.0f};
    CHECK(t.sample(round) == t.sample(round.uv, 2.0f));
}
