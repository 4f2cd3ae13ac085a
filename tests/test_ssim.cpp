// facet's SSIM (compare/ssim.cpp) against an independent implementation:
// scikit-image's structural_similarity (Debian's python3-skimage), run on
// the same planes, with the same choices (Gaussian window, sigma 1.5,
// population statistics).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "compare/ssim.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

// A smooth pattern with some noise, 8-bit range: something like a render.
std::vector<float> pattern(int w, int h, uint32_t seed, float shift) {
    std::vector<float> v(static_cast<size_t>(w) * h);
    uint32_t state = seed;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            state = state * 1664525u + 1013904223u;
            const float noise = static_cast<float>(state >> 24) / 255.0f - 0.5f;
            const float base = 128 + 90 * std::sin(0.13f * x + shift) * std::cos(0.07f * y);
            v[static_cast<size_t>(y) * w + x] = std::clamp(base + 20 * noise, 0.0f, 255.0f);
        }
    return v;
}

void write_floats(const std::string& path, const std::vector<float>& v) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * 4));
}

// scikit-image's mean SSIM of the two planes.
double skimage_ssim(const TempDir& dir, int w, int h, const std::vector<float>& a,
                    const std::vector<float>& b) {
    write_floats(dir.file("a.f32"), a);
    write_floats(dir.file("b.f32"), b);
    const std::string script =
        "import numpy as np\n"
        "from skimage.metrics import structural_similarity as s\n"
        "a = np.fromfile('" +
        dir.file("a.f32") +
        "', dtype=np.float32).astype(np.float64)"
        ".reshape(" +
        std::to_string(h) + ", " + std::to_string(w) +
        ")\n"
        "b = np.fromfile('" +
        dir.file("b.f32") +
        "', dtype=np.float32).astype(np.float64)"
        ".reshape(" +
        std::to_string(h) + ", " + std::to_string(w) +
        ")\n"
        "print('%.12f' % s(a, b, gaussian_weights=True, sigma=1.5, "
        "use_sample_covariance=False, data_range=255))\n";
    write_text(dir.file("ssim.py"), script);
    const RunResult r = run_command("/usr/bin/python3 '" + dir.file("ssim.py") + "' 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return std::stod(r.output);
}

}  // namespace

TEST_CASE("SSIM agrees with scikit-image's structural_similarity", "[compare][ssim]") {
    TempDir dir("ssim");
    const int w = 64, h = 48;
    const std::vector<float> ref = pattern(w, h, 1, 0.0f);
    struct Case {
        const char* name;
        std::vector<float> other;
    };
    std::vector<float> brighter = ref, one_pixel = ref;
    for (float& v : brighter) v = std::min(255.0f, v + 12);
    one_pixel[static_cast<size_t>(20) * w + 30] = 255 - one_pixel[static_cast<size_t>(20) * w + 30];
    const std::vector<Case> cases = {
        {"identical", ref},
        {"other noise", pattern(w, h, 2, 0.0f)},
        {"shifted pattern", pattern(w, h, 1, 0.4f)},
        {"brighter", brighter},
        {"one pixel", one_pixel},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const SsimResult ours = ssim({w, h, ref}, {w, h, c.other}, 255);
        const double theirs = skimage_ssim(dir, w, h, ref, c.other);
        CHECK(ours.mean == Approx(theirs).margin(1e-6));
        REQUIRE(ours.map.size() == static_cast<size_t>(w) * h);
    }
    CHECK(ssim({w, h, ref}, {w, h, ref}, 255).mean == 1.0);
}

TEST_CASE("SSIM's map locates a change and small planes compare by equality", "[compare][ssim]") {
    const int w = 40, h = 30;
    const std::vector<float> ref = pattern(w, h, 3, 0.0f);
    std::vector<float> changed = ref;
    for (int y = 12; y < 16; ++y)
        for (int x = 18; x < 22; ++x) changed[static_cast<size_t>(y) * w + x] = 0;
    const SsimResult r = ssim({w, h, ref}, {w, h, changed}, 255);
    CHECK(r.mean < 1.0);
    // Lowest where the change is; untouched far away.
    const auto worst = std::min_element(r.map.begin(), r.map.end()) - r.map.begin();
    CHECK(std::abs(static_cast<int>(worst % w) - 20) <= 3);
    CHECK(std::abs(static_cast<int>(worst / w) - 14) <= 3);
    CHECK(r.map[static_cast<size_t>(7) * w + 7] == 1.0f);  // its window misses the change

    const std::vector<float> tiny_a(8 * 8, 10.0f), tiny_b(8 * 8, 11.0f);
    CHECK(ssim({8, 8, tiny_a}, {8, 8, tiny_a}, 255).mean == 1.0);
    CHECK(ssim({8, 8, tiny_a}, {8, 8, tiny_b}, 255).mean == 0.0);
    CHECK_THROWS_AS(ssim({8, 8, tiny_a}, {4, 16, tiny_b}, 255), std::invalid_argument);
}
