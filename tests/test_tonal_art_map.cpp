// Procedural tonal art maps (Praun et al. 2001): nesting of the tone
// levels, tone increasing with level, determinism, tiling, cross-hatching,
// the tone lookup, the pencil variant and its paper grain.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "shade/paper_grain.hpp"
#include "shade/tonal_art_map.hpp"

using namespace facet;

namespace {

TamParams small_params() {
    TamParams p;
    p.size = 64;
    p.levels = 6;
    p.seed = 7;
    p.min_stroke_size = 16;
    return p;
}

double mean_coverage(const TamImage& img) {
    double sum = 0;
    for (uint8_t t : img.texels) sum += t;
    return sum / (255.0 * static_cast<double>(img.texels.size()));
}

// Coherence of the structure tensor, (l1 - l2) / (l1 + l2): near 1 when
// all strokes run one way, lower when they cross.
double orientation_coherence(const TamImage& img) {
    double xx = 0, yy = 0, xy = 0;
    const int n = img.size;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double gx = double(img.at((x + 1) % n, y)) - img.at((x + n - 1) % n, y);
            const double gy = double(img.at(x, (y + 1) % n)) - img.at(x, (y + n - 1) % n);
            xx += gx * gx;
            yy += gy * gy;
            xy += gx * gy;
        }
    const double root = std::sqrt((xx - yy) * (xx - yy) + 4 * xy * xy);
    return root / (xx + yy);
}

// Mean absolute difference between neighbouring columns x and x+1 (wrapping).
double column_step(const TamImage& img, int x) {
    double sum = 0;
    for (int y = 0; y < img.size; ++y)
        sum += std::abs(double(img.at(x, y)) - img.at((x + 1) % img.size, y));
    return sum / img.size;
}

void check_nesting(const TonalArtMap& tam) {
    for (size_t level = 0; level + 1 < tam.levels.size(); ++level)
        for (size_t mip = 0; mip < tam.levels[level].size(); ++mip) {
            const TamImage& lighter = tam.levels[level][mip];
            const TamImage& darker = tam.levels[level + 1][mip];
            size_t lost = 0, lowered = 0;
            for (size_t i = 0; i < lighter.texels.size(); ++i) {
                if (lighter.texels[i] > 0 && darker.texels[i] == 0) ++lost;
                if (darker.texels[i] < lighter.texels[i]) ++lowered;
            }
            INFO("level " << level << " mip " << mip);
            CHECK(lost == 0);
            CHECK(lowered == 0);
        }
}

}  // namespace

TEST_CASE("tonal art map: levels and mips have the expected shape", "[style][tam]") {
    const TonalArtMap tam = generate_tonal_art_map(small_params());
    REQUIRE(tam.levels.size() == 6);
    for (const auto& mips : tam.levels) {
        REQUIRE(mips.size() == 7);  // 64, 32, ..., 1
        for (size_t m = 0; m < mips.size(); ++m) {
            CHECK(mips[m].size == (64 >> m));
            CHECK(mips[m].texels.size() == size_t(mips[m].size * mips[m].size));
        }
    }
    CHECK(tam.paper.empty());  // ink: no paper
}

TEST_CASE("tonal art map: every stroke of a level is in the next darker one", "[style][tam]") {
    const TonalArtMap tam = generate_tonal_art_map(small_params());
    check_nesting(tam);
    for (size_t level = 0; level + 1 < tam.levels.size(); ++level)
        CHECK(tam.level_strokes[level] < tam.level_strokes[level + 1]);
}

TEST_CASE("tonal art map: mean darkness rises with the level and meets its target",
          "[style][tam]") {
    const TamParams p = small_params();
    const TonalArtMap tam = generate_tonal_art_map(p);
    for (int level = 0; level < p.levels; ++level) {
        const double target = p.max_darkness * (level + 1) / p.levels;
        INFO("level " << level);
        // Drawn mips (64, 32, 16) are each filled to the target; the last
        // stroke may overshoot a little.
        for (int mip = 0; mip < 3; ++mip) {
            const double mean = mean_coverage(tam.levels[level][mip]);
            CHECK(mean >= target - 0.01);
            CHECK(mean <= target + 0.08);
        }
        if (level > 0)
            CHECK(mean_coverage(tam.levels[level][0]) >
                  mean_coverage(tam.levels[level - 1][0]) + 0.05);
    }
}

TEST_CASE("tonal art map: the same seed gives the same texels, another seed others",
          "[style][tam]") {
    const TonalArtMap a = generate_tonal_art_map(small_params());
    const TonalArtMap b = generate_tonal_art_map(small_params());
    TamParams other = small_params();
    other.seed = 8;
    const TonalArtMap c = generate_tonal_art_map(other);
    bool all_same = true, seed_matters = false;
    for (size_t level = 0; level < a.levels.size(); ++level)
        for (size_t mip = 0; mip < a.levels[level].size(); ++mip) {
            all_same = all_same && a.levels[level][mip].texels == b.levels[level][mip].texels;
            seed_matters =
                seed_matters || a.levels[level][mip].texels != c.levels[level][mip].texels;
        }
    CHECK(all_same);
    CHECK(seed_matters);
}

TEST_CASE("tonal art map: the tile has no seam", "[style][tam]") {
    const TonalArtMap tam = generate_tonal_art_map(small_params());
    const TamImage& img = tam.levels[2][0];
    double interior = 0;
    for (int x = 0; x < img.size - 1; ++x) interior += column_step(img, x);
    interior /= img.size - 1;
    // The step from the last column to the first is like any other.
    CHECK(column_step(img, img.size - 1) < 2.0 * interior);
    CHECK(interior > 0);
}

TEST_CASE("tonal art map: dark levels cross-hatch, light levels do not", "[style][tam]") {
    TamParams p = small_params();
    p.angle_jitter = 0;
    p.hatch_angle = 0;  // horizontal strokes: gradients point along v
    const TonalArtMap tam = generate_tonal_art_map(p);
    const double light = orientation_coherence(tam.levels[1][0]);
    const double dark = orientation_coherence(tam.levels[5][0]);
    INFO("coherence light " << light << ", dark " << dark);
    CHECK(light > 0.6);
    CHECK(dark < 0.5 * light);

    p.cross_from_level = p.levels;  // never cross
    const TonalArtMap parallel = generate_tonal_art_map(p);
    CHECK(orientation_coherence(parallel.levels[5][0]) > 0.6);
}

TEST_CASE("tonal art map lookup: blank at tone 1, coverage tracks 1 - tone", "[style][tam]") {
    const TamParams p = small_params();
    const TonalArtMap tam = generate_tonal_art_map(p);
    auto mean_lookup = [&](float tone, float lod) {
        double sum = 0;
        const int n = 64;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                sum += tam_coverage(tam, tone, {(x + 0.5f) / n, (y + 0.5f) / n}, lod);
        return sum / (n * n);
    };
    CHECK(mean_lookup(1.0f, 0) == 0.0);
    for (float tone : {0.85f, 0.7f, 0.5f, 0.3f, 0.15f}) {
        INFO("tone " << tone);
        CHECK(mean_lookup(tone, 0) == Approx(1.0 - tone).margin(0.05));
        CHECK(mean_lookup(tone, 2.5f) == Approx(1.0 - tone).margin(0.05));  // coarser mips too
    }
    // Below the darkest level's tone, the darkest level.
    CHECK(mean_lookup(0.0f, 0) == Approx(mean_coverage(tam.levels[5][0])).margin(0.01));
    // Halfway between two levels' tones, halfway between their coverages.
    const glm::vec2 uv{0.3f, 0.7f};
    const float tone_2 = 1.0f - p.max_darkness * 3 / 6, tone_3 = 1.0f - p.max_darkness * 4 / 6;
    const float halfway = tam_coverage(tam, 0.5f * (tone_2 + tone_3), uv, 0);
    CHECK(halfway ==
          Approx(0.5f * (tam_level_coverage(tam, 2, uv, 0) + tam_level_coverage(tam, 3, uv, 0)))
              .margin(1e-4));
    // uv wraps: one tile over is the same texel.
    CHECK(tam_coverage(tam, 0.4f, uv, 0) ==
          Approx(tam_coverage(tam, 0.4f, uv + glm::vec2(3, -2), 0)).margin(1e-4));
    // Far away (beyond the last mip) every uv gives the level's mean.
    CHECK(tam_level_coverage(tam, 4, {0.1f, 0.2f}, 20) ==
          tam_level_coverage(tam, 4, {0.6f, 0.9f}, 20));
    CHECK(tam_level_coverage(tam, 4, {0.1f, 0.2f}, 20) ==
          Approx(mean_coverage(tam.levels[4][0])).margin(0.02));
}

TEST_CASE("pencil tonal art map: lighter strokes on a grainy paper", "[style][tam]") {
    TamParams pencil = TamParams::pencil();
    pencil.size = 64;
    pencil.seed = 3;
    TamParams ink = small_params();
    ink.seed = 3;
    const TonalArtMap p = generate_tonal_art_map(pencil);
    const TonalArtMap i = generate_tonal_art_map(ink);
    check_nesting(p);
    // Lighter: the darkest pencil level is lighter than the darkest ink one,
    // and a single stroke deposits less (mean over touched texels, level 0).
    CHECK(p.level_darkness.back() < i.level_darkness.back() - 0.1f);
    auto touched_mean = [](const TamImage& img) {
        double sum = 0;
        int count = 0;
        for (uint8_t t : img.texels)
            if (t > 0) sum += t, ++count;
        return sum / count / 255.0;
    };
    CHECK(touched_mean(p.levels[0][0]) < 0.75 * touched_mean(i.levels[0][0]));

    REQUIRE(p.paper.size() == p.levels[0].size());
    float lo = 1, hi = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float s = tam_paper_shade(p, {(x + 0.5f) / 64, (y + 0.5f) / 64}, 0);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
    CHECK(lo >= 1.0f - pencil.paper_shading);
    CHECK(hi <= 1.0f);
    CHECK(hi - lo > 0.5f * pencil.paper_shading);  // the grain shows
    CHECK(tam_paper_shade(i, {0.5f, 0.5f}, 0) == 1.0f);
}

TEST_CASE("paper grain: tileable noise in [0, 1] around 0.5", "[style][tam]") {
    const std::vector<float> g = make_paper_grain({64, 8, 3, 11});
    REQUIRE(g.size() == 64 * 64);
    double sum = 0, interior = 0, seam = 0;
    for (float v : g) {
        CHECK(v >= 0.0f);
        CHECK(v <= 1.0f);
        sum += v;
    }
    CHECK(sum / g.size() == Approx(0.5).margin(0.1));
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 63; ++x) interior += std::abs(g[y * 64 + x + 1] - g[y * 64 + x]);
        seam += std::abs(g[y * 64] - g[y * 64 + 63]);
    }
    CHECK(seam / 64 < 2.0 * interior / (63 * 64));
    CHECK(make_paper_grain({64, 8, 3, 11}) == g);
    CHECK(make_paper_grain({64, 8, 3, 12}) != g);
}

TEST_CASE("tonal art map: parameters out of range are refused", "[style][tam]") {
    TamParams p = small_params();
    p.size = 100;
    CHECK_THROWS_AS(generate_tonal_art_map(p), facet::Error);
    p = small_params();
    p.max_darkness = 1.0f;
    CHECK_THROWS_AS(generate_tonal_art_map(p), facet::Error);
    p = small_params();
    p.levels = 0;
    CHECK_THROWS_AS(generate_tonal_art_map(p), facet::Error);
    CHECK_THROWS_AS(make_paper_grain({64, 7, 3, 1}), facet::Error);
}
