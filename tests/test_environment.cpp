// Environment lighting for the physically based shading model
// (shade/environment_map.hpp, docs/pbr.md "Environment lighting: the
// prefiltered maps"): uniform environments are exact, the octahedral maps
// continue across their folds, a small bright patch stays where it is,
// spreads with roughness and keeps its energy, the studio is deterministic
// and lit as documented, the files are read by content with messages that
// name them, and the maps have the same bits for any thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/exact_trig.hpp"
#include "core/half.hpp"
#include "output/encoders.hpp"
#include "render/environment_file.hpp"
#include "shade/environment_map.hpp"
#include "support.hpp"

using namespace facet;

namespace {

constexpr double kPi = 3.14159265358979323846;

// n points spread evenly over the sphere (a Fibonacci lattice): each
// stands for 4 pi / n steradians.
std::vector<glm::vec3> sphere_points(int n) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
        const double phi = i * 2.399963229728653;  // the golden angle
        points.emplace_back(r * std::cos(phi), z, r * std::sin(phi));
    }
    return points;
}

// An equirect image whose texels hold radiance(direction at the texel's centre).
pbr::EquirectRadiance make_image(int width, int height,
                                 const std::function<glm::vec3(const glm::dvec3&)>& radiance) {
    pbr::EquirectRadiance image{width, height, std::vector<float>(size_t(width) * height * 3)};
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const glm::vec3 l =
                radiance(pbr::equirect_direction((column + 0.5) / width, (row + 0.5) / height));
            for (int c = 0; c < 3; ++c) image.rgb[(size_t(row) * width + column) * 3 + c] = l[c];
        }
    return image;
}

// The integral of f over the sphere, by the points of sphere_points.
double integrate_sphere(const std::function<double(const glm::vec3&)>& f, int n) {
    double sum = 0.0;
    for (const glm::vec3& d : sphere_points(n)) sum += f(d);
    return sum * 4.0 * kPi / n;
}

// Whether two environments hold the same bits: coefficients and every
// level's texels.
bool same_bits(const pbr::PrefilteredEnvironment& a, const pbr::PrefilteredEnvironment& b) {
    if (std::memcmp(&a.sh(), &b.sh(), sizeof(pbr::RadianceSh)) != 0) return false;
    for (int k = 0; k < pbr::kEnvironmentLevels; ++k) {
        const pbr::OctahedralMap &la = a.level(k), &lb = b.level(k);
        if (la.size() != lb.size()) return false;
        for (int row = -1; row <= la.size(); ++row)
            for (int column = -1; column <= la.size(); ++column)
                if (std::memcmp(&la.texel(column, row), &lb.texel(column, row), sizeof(glm::vec3)))
                    return false;
    }
    return true;
}

// The right-handed rotation by 90 degrees about +Y: +X to -Z, +Z to +X.
glm::vec3 turn_90(const glm::vec3& d) {
    return {d.z, d.y, -d.x};
}

}  // namespace

TEST_CASE("environment: atan2_turns agrees with atan2 in every quadrant", "[environment][shade]") {
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const double y = std::sin(0.37 * i) * (1 + i % 7), x = std::cos(0.53 * i) * (1 + i % 5);
        const double error = std::abs(atan2_turns(y, x) * 2.0 * kPi - std::atan2(y, x));
        worst = std::max(worst, std::min(error, std::abs(error - 2.0 * kPi)));
    }
    CHECK(worst < 1e-14);
    CHECK(atan2_turns(0.0, -1.0) == Approx(0.5));
    CHECK(atan2_turns(-1.0, 0.0) == Approx(-0.25));
    CHECK(atan2_turns(0.0, 0.0) == 0.0);
}

TEST_CASE("environment: a uniform environment returns its radiance everywhere (white furnace)",
          "[environment][shade]") {
    const glm::vec3 radiance(0.25f, 0.5f, 1.0f);
    const pbr::SharedEnvironment env = pbr::uniform_environment(radiance);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> roughnesses = {0.0f,  0.02f, 1.0f / 7.0f, 0.3f, 0.5f,
                                            0.99f, 1.0f,  -1.0f,       2.0f, nan};
    std::vector<glm::vec3> directions = sphere_points(500);
    directions.push_back({0, 0, 0});
    directions.push_back({nan, 1, 0});
    directions.push_back({std::numeric_limits<float>::infinity(), 0, 0});
    int exact = 0, lookups = 0;
    for (const glm::vec3& d : directions)
        for (float r : roughnesses) {
            lookups += 2;
            exact += env->specular(d, r) == radiance;
            exact += env->radiance(d, r) == radiance;
        }
    CHECK(exact == lookups);
    const pbr::SharedEnvironment white = pbr::uniform_environment(glm::vec3(1.0f));
    double worst = 0.0;
    for (const glm::vec3& n : sphere_points(500)) {
        const glm::vec3 e = env->diffuse(n);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(e[c] / radiance[c] - 1.0));
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(white->diffuse(n)[c] - 1.0));
    }
    CHECK(worst < 1e-5);  // far inside the white furnace's 1 %
}

TEST_CASE("environment: a constant image prefilters to its constant", "[environment][shade]") {
    const glm::vec3 radiance(0.3f, 1.5f, 4.0f);
    const pbr::SharedEnvironment env =
        pbr::build_environment(make_image(64, 32, [&](const glm::dvec3&) { return radiance; }), 2);
    double worst_specular = 0.0, worst_diffuse = 0.0;
    for (const glm::vec3& d : sphere_points(300))
        for (int k = 0; k <= 14; ++k) {
            const glm::vec3 s = env->specular(d, k / 14.0f);
            const glm::vec3 e = env->diffuse(d);
            for (int c = 0; c < 3; ++c) {
                worst_specular = std::max(worst_specular, std::abs(s[c] / radiance[c] - 1.0));
                worst_diffuse = std::max(worst_diffuse, std::abs(e[c] / radiance[c] - 1.0));
            }
        }
    CHECK(worst_specular < 1e-5);
    CHECK(worst_diffuse < 2e-3);  // texel-centre directions of a 64 x 32 image
}

TEST_CASE("environment: octahedral maps round-trip and continue across their folds",
          "[environment][shade]") {
    // Every texel centre maps back onto itself.
    pbr::OctahedralMap map(64);
    double worst_round_trip = 0.0;
    for (int row = 0; row < 64; ++row)
        for (int column = 0; column < 64; ++column) {
            const glm::vec2 p = pbr::octahedral_encode(glm::vec3(map.texel_direction(column, row)));
            worst_round_trip =
                std::max({worst_round_trip, std::abs(p.x - ((column + 0.5) / 32.0 - 1.0)),
                          std::abs(p.y - ((row + 0.5) / 32.0 - 1.0))});
        }
    CHECK(worst_round_trip < 1e-6);
    CHECK(glm::length(pbr::octahedral_decode({0.0, 0.0}) - glm::dvec3(0, 1, 0)) < 1e-12);
    CHECK(glm::length(pbr::octahedral_decode({1.0, 1.0}) - glm::dvec3(0, -1, 0)) < 1e-12);
    CHECK(glm::length(pbr::octahedral_decode({0.0, -1.0}) - glm::dvec3(0, 0, -1)) < 1e-12);

    // A smooth function of the direction, filtered bilinearly, is followed
    // closely everywhere, the lower hemisphere's folds (the square's edges)
    // included. The worst error is where the mapping bends, 0.9 % here.
    const auto smooth = [](const glm::dvec3& d) {
        return 1.0 + 0.5 * d.x + 0.3 * d.y - 0.2 * d.z + 0.25 * d.x * d.z;
    };
    for (int row = 0; row < 64; ++row)
        for (int column = 0; column < 64; ++column)
            map.set_texel(column, row, glm::vec3(float(smooth(map.texel_direction(column, row)))));
    map.fill_border();
    double worst = 0.0;
    for (const glm::vec3& d : sphere_points(40000))
        worst = std::max(worst,
                         std::abs(map.sample(pbr::octahedral_encode(d)).x - smooth(glm::dvec3(d))));
    CHECK(worst < 0.0125);
    // A point on an edge and its mirror image about the edge's midpoint are
    // one direction, so they read the same value: the border holds the
    // texels across the fold.
    double worst_mirror = 0.0;
    for (int i = 0; i <= 100; ++i) {
        const float t = -1.0f + 0.02f * i;
        const std::pair<glm::vec2, glm::vec2> pairs[] = {{{1.0f, t}, {1.0f, -t}},
                                                         {{-1.0f, t}, {-1.0f, -t}},
                                                         {{t, 1.0f}, {-t, 1.0f}},
                                                         {{t, -1.0f}, {-t, -1.0f}}};
        for (const auto& [a, b] : pairs) {
            CHECK(glm::length(pbr::octahedral_decode(a) - pbr::octahedral_decode(b)) < 1e-6);
            worst_mirror =
                std::max(worst_mirror, double(std::abs(map.sample(a).x - map.sample(b).x)));
        }
    }
    CHECK(worst_mirror < 1e-6);
    // Just either side of a fold, the two sides agree.
    for (const double y : {-0.2, -0.6, -0.95}) {
        for (const glm::vec3 across : {glm::vec3(1e-4f, 0, 0), glm::vec3(0, 0, 1e-4f)}) {
            const glm::vec3 base = across.x != 0.0f ? glm::vec3(0.0f, float(y), 0.5f)
                                                    : glm::vec3(0.5f, float(y), 0.0f);
            CHECK(map.sample(pbr::octahedral_encode(glm::normalize(base - across))).x ==
                  Approx(map.sample(pbr::octahedral_encode(glm::normalize(base + across))).x)
                      .epsilon(1e-3));
        }
    }
    // Points outside the square, or NaN, read the border instead of memory
    // beyond it.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const glm::vec2 p : {glm::vec2(5, -5), glm::vec2(nan, 0), glm::vec2(-1.01f, 1.01f)})
        CHECK(std::isfinite(map.sample(p).x));
}

TEST_CASE("environment: a small bright patch stays put, spreads with roughness, keeps its energy",
          "[environment][shade]") {
    constexpr int kWidth = 256, kHeight = 128;
    constexpr float kPatch = 100.0f;
    // 6 x 6 texels around column 176, row 48: above the horizon, to the right.
    const auto in_patch = [](int column, int row) {
        return column >= 173 && column < 179 && row >= 45 && row < 51;
    };
    pbr::EquirectRadiance image{kWidth, kHeight, std::vector<float>(kWidth * kHeight * 3, 0.0f)};
    double patch_energy = 0.0;  // radiance times solid angle
    for (int row = 0; row < kHeight; ++row)
        for (int column = 0; column < kWidth; ++column)
            if (in_patch(column, row)) {
                for (int c = 0; c < 3; ++c) image.rgb[(row * kWidth + column) * 3 + c] = kPatch;
                patch_energy += kPatch * pbr::equirect_texel_solid_angle(kWidth, kHeight, row);
            }
    const glm::vec3 centre(pbr::equirect_direction(176.0 / kWidth, 48.0 / kHeight));
    const pbr::SharedEnvironment env = pbr::build_environment(image, 2);

    // Sharp: the patch's radiance in its direction, nothing a little away.
    CHECK(env->specular(centre, 0.0f).x == Approx(kPatch).epsilon(0.02));
    const glm::vec3 aside = glm::normalize(centre + glm::vec3(0.0f, -0.35f, 0.0f));
    CHECK(env->specular(aside, 0.0f).x == 0.0f);

    // Rougher levels: a lower peak, light where the sharp map has none, and
    // the energy of the patch, each level on its own.
    float previous_peak = env->specular(centre, 0.0f).x;
    for (int k = 1; k < pbr::kEnvironmentLevels; ++k) {
        const float r = pbr::PrefilteredEnvironment::level_roughness(k);
        const float peak = env->specular(centre, r).x;
        CHECK(peak < previous_peak);
        previous_peak = peak;
        if (k >= 2) CHECK(env->specular(aside, r).x > 0.01f * peak);
        const double energy =
            integrate_sphere([&](const glm::vec3& d) { return env->specular(d, r).x; }, 100000);
        INFO("level " << k);
        CHECK(energy == Approx(patch_energy).epsilon(0.03));
    }
    const double sharp_energy =
        integrate_sphere([&](const glm::vec3& d) { return env->specular(d, 0.0f).x; }, 400000);
    CHECK(sharp_energy == Approx(patch_energy).epsilon(0.03));

    // The diffuse light faces the patch: E / pi ~ energy / pi facing it.
    CHECK(env->diffuse(centre).x == Approx(patch_energy / kPi).epsilon(0.1));
    CHECK(env->diffuse(-centre).x < 0.1f * env->diffuse(centre).x);
}

TEST_CASE("environment: turning the image about +Y moves the reflections with it",
          "[environment][shade]") {
    constexpr int kWidth = 128, kHeight = 64;
    const glm::dvec3 light = glm::normalize(glm::dvec3(0.8, 0.4, -0.45));
    const pbr::EquirectRadiance image = make_image(kWidth, kHeight, [&](const glm::dvec3& d) {
        const double lobe = std::max(0.0, glm::dot(d, light));
        return glm::vec3(float(0.05 + 20.0 * std::pow(lobe, 200.0)));
    });
    // Turned by 90 degrees about +Y (right-handed): column j of the turned
    // image is column j + width/4 of the original (as in
    // test_spherical_harmonics.cpp), so the light now lies at turn_90(light).
    pbr::EquirectRadiance turned_image = image;
    for (int row = 0; row < kHeight; ++row)
        for (int column = 0; column < kWidth; ++column)
            for (int c = 0; c < 3; ++c)
                turned_image.rgb[(row * kWidth + column) * 3 + c] =
                    image.rgb[(row * kWidth + (column + kWidth / 4) % kWidth) * 3 + c];
    const pbr::SharedEnvironment env = pbr::build_environment(image, 2);
    const pbr::SharedEnvironment turned = pbr::build_environment(turned_image, 2);
    const glm::vec3 d(light);
    for (const float r : {0.0f, 0.2f, 0.5f}) {
        INFO("roughness " << r);
        const float peak = env->specular(d, r).x;
        // What the header says a caller does: the turned environment in
        // direction e is the original in R_y(-90) e, so the peak is found at
        // turn_90(d).
        CHECK(turned->specular(turn_90(d), r).x == Approx(peak).epsilon(0.05));
        CHECK(turned->specular(d, r).x < 0.2f * peak);
    }
}

TEST_CASE("environment: the studio is deterministic, neutral, lit from above as documented",
          "[environment][shade]") {
    const pbr::SharedEnvironment first = pbr::studio_environment(1);
    const pbr::SharedEnvironment second = pbr::studio_environment(2);
    CHECK(same_bits(*first, *second));
    CHECK(first->level(0).size() == 256);  // 512 x 256

    const glm::vec3 up(0, 1, 0), down(0, -1, 0);
    CHECK(first->diffuse(up).x > 3.0f * first->diffuse(down).x);
    CHECK(first->radiance(up, 0.0f).x > 2.0f * first->radiance(down, 0.0f).x);
    // A white diffuse surface facing the key, found as the brightest
    // normal: lit, not blown out.
    float brightest = 0.0f;
    glm::vec3 brightest_normal(0.0f);
    for (const glm::vec3& n : sphere_points(4000)) {
        const glm::vec3 e = first->diffuse(n);
        CHECK((e.x == e.y && e.y == e.z));  // neutral grey
        if (e.x > brightest) {
            brightest = e.x;
            brightest_normal = n;
        }
    }
    CHECK(brightest > 0.8f);
    CHECK(brightest < 1.0f);
    // The key is at the camera's front left, high: -X, +Y, +Z.
    CHECK(brightest_normal.x < 0.0f);
    CHECK(brightest_normal.y > 0.0f);
    CHECK(brightest_normal.z > 0.0f);
}

TEST_CASE("environment: prefiltering gives the same bits with 1 and 3 threads",
          "[environment][shade]") {
    constexpr int kWidth = 160, kHeight = 80;
    pbr::EquirectRadiance image{kWidth, kHeight, std::vector<float>(kWidth * kHeight * 3)};
    uint32_t state = 2024u;
    for (float& value : image.rgb) {
        state = state * 1664525u + 1013904223u;             // Numerical Recipes' LCG
        value = static_cast<float>(state >> 8) * 0x1p-22f;  // 0 .. 4
    }
    image.rgb[(40 * kWidth + 100) * 3] = 5000.0f;  // a small sun, red
    const pbr::SharedEnvironment one = pbr::build_environment(image, 1);
    const pbr::SharedEnvironment three = pbr::build_environment(image, 3);
    CHECK(same_bits(*one, *three));
    // And the maps hold something: not all equal, the sun's red visible.
    const glm::vec3 sun(pbr::equirect_direction(100.5 / kWidth, 40.5 / kHeight));
    const glm::vec3 glossy = one->specular(sun, 0.3f);
    CHECK(glossy.x > 2.0f * glossy.y);
}

namespace {

// A Radiance file by hand: the header, then texels as (mantissa R, G, B,
// exponent), which stb_image expands to mantissa * 2^(exponent - 136).
std::string radiance_header(int width, int height) {
    return "#?RADIANCE\n# written by test_environment.cpp\nFORMAT=32-bit_rle_rgbe\n\n-Y " +
           std::to_string(height) + " +X " + std::to_string(width) + "\n";
}

std::vector<uint8_t> bytes_of(const std::string& text) {
    return std::vector<uint8_t>(text.begin(), text.end());
}

}  // namespace

TEST_CASE("environment: a Radiance .hdr is read by content, flat or run-length encoded",
          "[environment][shade]") {
    test::TempDir dir("environment-hdr");
    // 8 x 4, flat: texel i is (1, 0.5, 0.25) * 2^(i % 3), exactly.
    std::vector<uint8_t> flat = bytes_of(radiance_header(8, 4));
    for (int i = 0; i < 32; ++i) {
        const uint8_t exponent = static_cast<uint8_t>(129 + i % 3);
        flat.insert(flat.end(), {128, 64, 32, exponent});
    }
    // Named .exr on purpose: the content decides.
    const std::string flat_path = test::write_bytes(dir.file("flat.exr"), flat);
    Warnings warnings;
    const pbr::EquirectRadiance image = pbr::read_environment_image(flat_path, warnings);
    REQUIRE(image.width == 8);
    REQUIRE(image.height == 4);
    CHECK(warnings.empty());
    int matching = 0;
    for (int i = 0; i < 32; ++i) {
        const float scale = static_cast<float>(1 << (i % 3));
        matching += image.rgb[i * 3] == scale && image.rgb[i * 3 + 1] == 0.5f * scale &&
                    image.rgb[i * 3 + 2] == 0.25f * scale;
    }
    CHECK(matching == 32);

    // 8 x 4, each scanline run-length encoded: the marker (2, 2, width),
    // then each channel as one run of 8 (128 + 8, value).
    std::vector<uint8_t> rle = bytes_of(radiance_header(8, 4));
    for (int row = 0; row < 4; ++row) {
        rle.insert(rle.end(), {2, 2, 0, 8});
        for (const uint8_t value :
             {uint8_t(128), uint8_t(32 * (row + 1)), uint8_t(0), uint8_t(130)})
            rle.insert(rle.end(), {uint8_t(128 + 8), value});
    }
    const std::string rle_path = test::write_bytes(dir.file("rle.hdr"), rle);
    const pbr::EquirectRadiance rle_image = pbr::read_environment_image(rle_path, warnings);
    REQUIRE(rle_image.width == 8);
    CHECK(rle_image.rgb[0] == 2.0f);                    // 128 * 2^(130 - 136)
    CHECK(rle_image.rgb[(3 * 8 + 5) * 3 + 1] == 2.0f);  // row 3: 128 * 2^-6
    CHECK(rle_image.rgb[(1 * 8 + 2) * 3 + 1] == 1.0f);  // row 1: 64 * 2^-6
    CHECK(rle_image.rgb[(2 * 8 + 7) * 3 + 2] == 0.0f);
    // Uniform red: the maps hold it to float rounding; the harmonics, from
    // only 4 rows of texel centres, to a few per cent.
    const pbr::SharedEnvironment env = pbr::load_environment(rle_path, warnings, 1);
    CHECK(env->specular({0.3f, -0.8f, 0.1f}, 0.6f).x == Approx(2.0f).epsilon(1e-5));
    CHECK(env->diffuse({0, 1, 0}).x == Approx(2.0f).epsilon(0.05));

    // The same file cut short: stb would fill the rest with zeros.
    rle.resize(rle.size() - 5);
    const std::string cut_path = test::write_bytes(dir.file("cut.hdr"), rle);
    test::require_input_error([&] { pbr::read_environment_image(cut_path, warnings); }, cut_path);
    test::require_input_error([&] { pbr::read_environment_image(cut_path, warnings); },
                              "ends before its last texel");
}

TEST_CASE("environment: an OpenEXR from output's writer is read by content",
          "[environment][shade]") {
    test::TempDir dir("environment-exr");
    constexpr int kWidth = 8, kHeight = 4;
    std::vector<float> r(kWidth * kHeight), g(kWidth * kHeight), b(kWidth * kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
        r[i] = 0.125f * i;
        g[i] = 1000.0f + i;  // beyond half's precision: float32 channels
        b[i] = 1.0f / (1 + i);
    }
    const auto channel = [](const char* name, const std::vector<float>& values) {
        return ExrChannel{name, ExrSample::float32, reinterpret_cast<const uint8_t*>(values.data()),
                          sizeof(float), sizeof(float) * kWidth};
    };
    const std::string path = test::write_bytes(
        dir.file("environment.hdr"),  // named .hdr on purpose: the content decides
        encode_exr(kWidth, kHeight, {channel("B", b), channel("G", g), channel("R", r)}));
    Warnings warnings;
    const pbr::EquirectRadiance image = pbr::read_environment_image(path, warnings);
    REQUIRE(image.width == kWidth);
    REQUIRE(image.height == kHeight);
    CHECK(warnings.empty());
    int matching = 0;
    for (int i = 0; i < kWidth * kHeight; ++i)
        matching += image.rgb[i * 3] == r[i] && image.rgb[i * 3 + 1] == g[i] &&
                    image.rgb[i * 3 + 2] == b[i];
    CHECK(matching == kWidth * kHeight);

    // facet's own colour EXR (half RGBA) too.
    HalfColorImage colour(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            colour.at(x, y) = to_half(glm::vec4(0.5f * x, 2.0f, 0.0f, 1.0f));
    const std::string half_path = test::write_bytes(dir.file("half.exr"), encode_exr_color(colour));
    const pbr::EquirectRadiance half = pbr::read_environment_image(half_path, warnings);
    CHECK(half.rgb[(3 * 16 + 5) * 3] == 2.5f);
    CHECK(half.rgb[(3 * 16 + 5) * 3 + 1] == 2.0f);

    // A negative texel is set to 0, with a warning that names the file.
    r[5] = -0.5f;
    r[6] = -2.0f;
    const std::string negative_path = test::write_bytes(
        dir.file("negative.exr"),
        encode_exr(kWidth, kHeight, {channel("R", r), channel("G", g), channel("B", b)}));
    const pbr::EquirectRadiance clamped = pbr::read_environment_image(negative_path, warnings);
    CHECK(clamped.rgb[5 * 3] == 0.0f);
    CHECK(clamped.rgb[6 * 3] == 0.0f);
    CHECK(clamped.rgb[7 * 3] == r[7]);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].where.file == negative_path);
    CHECK_THAT(warnings[0].message, Catch::Contains("2 negative"));

    // NaN and infinity are refused, naming the file and the texel.
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        g[kWidth + 3] = bad;
        const std::string bad_path = test::write_bytes(
            dir.file("bad.exr"),
            encode_exr(kWidth, kHeight, {channel("R", r), channel("G", g), channel("B", b)}));
        test::require_input_error([&] { pbr::read_environment_image(bad_path, warnings); },
                                  bad_path);
        test::require_input_error([&] { pbr::read_environment_image(bad_path, warnings); },
                                  "(column 3, row 1)");
    }
}

TEST_CASE("environment: files that are not environments are refused, naming the file",
          "[environment][shade]") {
    test::TempDir dir("environment-bad");
    Warnings warnings;
    const auto refused = [&](const std::string& path, const std::string& detail) {
        INFO(path);
        test::require_input_error([&] { pbr::load_environment(path, warnings, 1); }, path);
        test::require_input_error([&] { pbr::load_environment(path, warnings, 1); }, detail);
    };
    refused(dir.file("missing.hdr"), "no such file");
    refused(test::write_text(dir.file("notes.hdr"), "a sunny day\n"),
            "not a Radiance .hdr or OpenEXR .exr");
    PngSamples grey{8, 4, 1, 8, std::vector<uint8_t>(32, 128)};
    refused(test::write_bytes(dir.file("photo.hdr"), encode_png(grey, 6)), "(it is PNG)");
    // Square: a cube map cross or a photograph, not latitude-longitude.
    std::vector<uint8_t> square = bytes_of(radiance_header(4, 4));
    square.resize(square.size() + 4 * 4 * 4, 128);
    refused(test::write_bytes(dir.file("square.hdr"), square), "twice its height");
    // Over the limit: refused from the header, before 2 GB are decoded.
    refused(test::write_bytes(dir.file("huge.hdr"), bytes_of(radiance_header(16384, 8192))),
            "over the limit of 8192x4096");
    refused(test::write_bytes(dir.file("odd.hdr"),
                              bytes_of("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 4 +X 8\n")),
            "cannot read the Radiance .hdr header");
    HalfColorImage wide(6, 2);
    refused(test::write_bytes(dir.file("wide.exr"), encode_exr_color(wide)), "twice its height");
    DepthImage depth(8, 4, 1.0f);
    refused(test::write_bytes(dir.file("depth.exr"), encode_exr_depth(depth)),
            "needs channels R, G and B; this one has Z");
    std::vector<uint8_t> broken_exr = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    refused(test::write_bytes(dir.file("broken.exr"), broken_exr), "cannot read EXR");
}
