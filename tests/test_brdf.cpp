// The glTF metallic-roughness BRDF (shade/brdf.hpp, docs/pbr.md) against
// the properties it must have, each integrated numerically here with its
// own deterministic quadrature: Fresnel at normal and grazing incidence,
// GGX's normalisation, the white furnace with and without the energy
// compensation, reciprocity, and the DFG table.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "shade/brdf.hpp"

using namespace facet;
using pbr::MultipleScattering;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The quadrature for reflected energy: kSteps x kSteps midpoints in the
// unit square, mapped twice onto directions l, once with density
// (n.l)/pi (for the diffuse lobe) and once with GGX's density
// D(h)(n.h)/(4 v.h) (for the specular lobe), the two combined with the
// balance heuristic (Veach 1997): each point adds f(l)(n.l) /
// (count * (p_cosine(l) + p_ggx(l))). 2 x 192^2 = 73 728 evaluations per
// integral; doubling the resolution changes the furnace results below by
// at most 8e-4.
constexpr int kSteps = 192;

glm::dvec3 view_at(double n_dot_v) {
    return {std::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v};  // n = +z
}

// GGX's density of reflected directions l for the view v, in double and
// written out here rather than taken from the code under test.
double ggx_density(const glm::dvec3& v, const glm::dvec3& l, double alpha) {
    const glm::dvec3 h = glm::normalize(v + l);
    const double n_dot_h = h.z, v_dot_h = glm::dot(v, h);
    if (!(n_dot_h > 0.0) || !(v_dot_h > 0.0)) return 0.0;
    const double a2 = alpha * alpha;
    const double d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d) * n_dot_h / (4.0 * v_dot_h);
}

// The directional albedo: the integral of f(v, l)(n.l) over l, per channel.
glm::dvec3 reflected_energy(const pbr::Material& material, double n_dot_v,
                            MultipleScattering multiple_scattering) {
    const glm::dvec3 v = view_at(n_dot_v);
    const pbr::PbrPoint<float> point =
        pbr::prepare_shading_point({0, 0, 1}, glm::vec3(v), material, multiple_scattering);
    const double alpha = pbr::alpha_from_roughness(material.roughness), a2 = alpha * alpha;
    const double count = static_cast<double>(kSteps) * kSteps;
    glm::dvec3 sum(0.0);
    const auto add = [&](const glm::dvec3& l) {
        if (!(l.z > 0.0)) return;
        const double density = l.z / kPi + ggx_density(v, l, alpha);
        sum += glm::dvec3(pbr::brdf_cosine(point, glm::vec3(l))) / (count * density);
    };
    for (int i = 0; i < kSteps; ++i)
        for (int k = 0; k < kSteps; ++k) {
            const double u = (i + 0.5) / kSteps, phi = 2.0 * kPi * (k + 0.5) / kSteps;
            const double c = std::cos(phi), s = std::sin(phi);
            add({std::sqrt(u) * c, std::sqrt(u) * s, std::sqrt(1.0 - u)});  // density (n.l)/pi
            // h with density D(h)(n.h), then l = h's reflection of v.
            const double q = 1.0 + (a2 - 1.0) * u;
            const double sin_h = std::sqrt(a2 * u / q), cos_h = std::sqrt((1.0 - u) / q);
            const glm::dvec3 h(sin_h * c, sin_h * s, cos_h);
            add(2.0 * glm::dot(v, h) * h - v);
        }
    return sum;
}

pbr::Material white(float metallic, float roughness) {
    return {glm::vec3(1.0f), metallic, roughness, pbr::kDefaultIor};
}

}  // namespace

TEST_CASE("brdf: Schlick's Fresnel is F0 at normal incidence and 1 at grazing", "[shade][brdf]") {
    CHECK(pbr::f0_from_ior(1.5f) == Approx(0.04f).epsilon(1e-6));
    CHECK(pbr::f0_from_ior(2.0f) == Approx(1.0f / 9.0f).epsilon(1e-6));
    CHECK(pbr::f0_from_ior(1.0f) == 0.0f);
    for (float f0 : {0.04f, 1.0f / 9.0f, 0.5f}) {
        CHECK(pbr::schlick_fresnel(f0, pbr::schlick_weight(1.0f)) == f0);
        CHECK(pbr::schlick_fresnel(f0, pbr::schlick_weight(0.0f)) == 1.0f);
        // Halfway, (1 - 0.5)^5 = 1/32 of the way from F0 to 1.
        CHECK(pbr::schlick_fresnel(f0, pbr::schlick_weight(0.5f)) ==
              Approx(f0 + (1.0f - f0) / 32.0f).epsilon(1e-6));
        // Rises monotonically from one to the other.
        float previous = f0;
        for (float v_dot_h = 0.95f; v_dot_h >= 0.0f; v_dot_h -= 0.05f) {
            const float f = pbr::schlick_fresnel(f0, pbr::schlick_weight(v_dot_h));
            CHECK(f > previous);
            previous = f;
        }
    }
}

TEST_CASE("brdf: a smooth black dielectric seen head-on reflects F0 of the light",
          "[shade][brdf]") {
    // Base colour 0 leaves the specular layer alone; at the smallest
    // roughness its lobe is so narrow that v.h is 1 within it, so the
    // reflected energy is F0 times the lobe's albedo (1 to 1e-5 there).
    for (float ior : {1.5f, 2.0f}) {
        const pbr::Material black{glm::vec3(0.0f), 0.0f, 0.0f, ior};
        const double expected = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
        const glm::dvec3 e = reflected_energy(black, 1.0, MultipleScattering::ignored);
        INFO("ior " << ior);
        CHECK(e.x == Approx(expected).epsilon(1e-3));
        CHECK(e.y == e.x);
    }
}

TEST_CASE("brdf: GGX's D(h)(n.h) integrates to 1 over the hemisphere", "[shade][brdf]") {
    // 2 pi times the integral over theta of D cos(theta) sin(theta), by the
    // midpoint rule on theta = (pi/2) s^3, which puts most of the 20 000
    // points near the normal, where a low roughness packs the whole lobe.
    constexpr int kPoints = 20000;
    for (float roughness : {0.0f, 0.1f, 0.3f, 0.6f, 1.0f}) {
        const float alpha = pbr::alpha_from_roughness(roughness);
        double sum = 0.0;
        for (int i = 0; i < kPoints; ++i) {
            const double s = (i + 0.5) / kPoints;
            const double theta = 0.5 * kPi * s * s * s, d_theta = 1.5 * kPi * s * s / kPoints;
            const double c = std::cos(theta), sn = std::sin(theta);
            const double d =
                pbr::ggx_distribution(static_cast<float>(c), static_cast<float>(sn * sn), alpha);
            sum += d * c * sn * d_theta;
        }
        INFO("roughness " << roughness);
        CHECK(2.0 * kPi * sum == Approx(1.0).epsilon(1e-4));
    }
    // The peak, 1 / (pi alpha^2), and the form glTF writes.
    const float alpha = pbr::alpha_from_roughness(0.5f);
    CHECK(pbr::ggx_distribution(1.0f, 0.0f, alpha) ==
          Approx(1.0 / (kPi * alpha * alpha)).epsilon(1e-6));
    const float c = 0.8f, a2 = alpha * alpha;
    const double gltf = a2 / (kPi * std::pow(c * c * (a2 - 1.0) + 1.0, 2.0));
    CHECK(pbr::ggx_distribution(c, 1.0f - c * c, alpha) == Approx(gltf).epsilon(1e-5));
    CHECK(pbr::ggx_distribution(-0.1f, 0.99f, alpha) == 0.0f);  // chi+(n.h)
}

TEST_CASE("brdf: the height-correlated Smith V meets its closed forms", "[shade][brdf]") {
    // alpha = 1: both square roots are 1, V = 1 / (2 (n.l + n.v)).
    // alpha -> 0: no masking (G = 1), V = 1 / (4 n.l n.v).
    for (float n_dot_l : {0.1f, 0.5f, 1.0f})
        for (float n_dot_v : {0.2f, 0.7f, 1.0f}) {
            INFO("n.l " << n_dot_l << ", n.v " << n_dot_v);
            CHECK(pbr::smith_ggx_correlated_visibility(n_dot_l, n_dot_v, 1.0f) ==
                  Approx(0.5f / (n_dot_l + n_dot_v)).epsilon(1e-6));
            CHECK(pbr::smith_ggx_correlated_visibility(n_dot_l, n_dot_v, 1e-4f) ==
                  Approx(0.25f / (n_dot_l * n_dot_v)).epsilon(1e-6));
            CHECK(pbr::smith_ggx_correlated_visibility(n_dot_l, n_dot_v, 0.3f) ==
                  pbr::smith_ggx_correlated_visibility(n_dot_v, n_dot_l, 0.3f));
        }
    // V is Heitz 2014's height-correlated G2 = 1 / (1 + Lambda_l + Lambda_v)
    // over 4 n.l n.v, which shadows less than the separable G1_l G1_v (that
    // counts the points both masked and shadowed twice).
    const double alpha = 0.5, n_dot_l = 0.3, n_dot_v = 0.6;
    const auto lambda = [&](double c) {
        return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c)) - 1.0);
    };
    const double correlated = 1.0 / (1.0 + lambda(n_dot_l) + lambda(n_dot_v));
    const double separable = 1.0 / ((1.0 + lambda(n_dot_l)) * (1.0 + lambda(n_dot_v)));
    CHECK(correlated > separable);
    CHECK(pbr::smith_ggx_correlated_visibility(n_dot_l, n_dot_v, alpha) ==
          Approx(correlated / (4.0 * n_dot_l * n_dot_v)).epsilon(1e-12));
}

TEST_CASE("brdf: white furnace: a white metal reflects all the light with the compensation",
          "[shade][brdf]") {
    // Issue 34 asks for 1 +- 3 %; measured, every case is within 0.8 %.
    for (float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.0f})
        for (double n_dot_v : {1.0, 0.7, 0.4, 0.15}) {
            const glm::dvec3 compensated =
                reflected_energy(white(1, roughness), n_dot_v, MultipleScattering::compensated);
            INFO("roughness " << roughness << ", n.v " << n_dot_v);
            CHECK(compensated.x == Approx(1.0).margin(0.01));
            CHECK(compensated.z == compensated.x);
        }
}

TEST_CASE("brdf: white furnace: without the compensation a rough metal loses light",
          "[shade][brdf]") {
    // The single-scattering lobe alone: close to 1 when smooth, well below
    // when rough (the light that would bounce again between microfacets).
    const auto single = [](float roughness, double n_dot_v) {
        return reflected_energy(white(1, roughness), n_dot_v, MultipleScattering::ignored).x;
    };
    CHECK(single(0.05f, 1.0) > 0.999);
    CHECK(single(0.5f, 1.0) < 0.93);
    CHECK(single(1.0f, 0.4) < 0.6);
    // At roughness 1 (alpha = 1) D = 1/pi and, head-on, V = 1 / (2 (1 + n.l)),
    // so the albedo is the integral of mu / (1 + mu) over [0, 1]: 1 - ln 2.
    CHECK(single(1.0f, 1.0) == Approx(1.0 - std::log(2.0)).epsilon(1e-3));
    for (double n_dot_v : {1.0, 0.4}) CHECK(single(0.5f, n_dot_v) < single(0.25f, n_dot_v));
}

TEST_CASE("brdf: white furnace: a white dielectric conserves energy only away from grazing views",
          "[shade][brdf]") {
    // glTF's fresnel_mix weights the Lambertian base by 1 - F(v.h), which
    // does not take out what the specular layer reflects at other angles:
    // the sum is neither energy-preserving nor, at grazing views,
    // energy-conserving (Appendix B.3.6, "Coupling Diffuse and Specular
    // Reflection"). Seen from n.v >= 0.7 a white dielectric reflects 0.97 to
    // 1.002 (rough ones lose some of the specular layer's multiple
    // scattering to the diffuse weight); smooth ones seen from n.v <= 0.4
    // reflect more than they receive. That gain is intended: facet draws the
    // specification's BRDF, as the Khronos sample viewer does, so that a
    // file looks as its author saw it there; this test pins the gain, so a
    // change to the coupling (an energy-preserving one, say) shows here.
    for (float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.0f})
        for (double n_dot_v : {1.0, 0.7}) {
            const glm::dvec3 e =
                reflected_energy(white(0, roughness), n_dot_v, MultipleScattering::compensated);
            INFO("roughness " << roughness << ", n.v " << n_dot_v);
            CHECK(e.x <= 1.005);
            CHECK(e.x >= 0.95);
        }
    const auto smooth = [](double n_dot_v) {
        return reflected_energy(white(0, 0.05f), n_dot_v, MultipleScattering::compensated).x;
    };
    CHECK(smooth(0.4) > 1.05);
    CHECK(smooth(0.15) > 1.3);
}

TEST_CASE("brdf: the specification's BRDF is reciprocal: f(v, l) = f(l, v)", "[shade][brdf]") {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 directions[] = {glm::normalize(glm::vec3(0.3f, 0.1f, 0.9f)),
                                    glm::normalize(glm::vec3(-0.7f, 0.2f, 0.4f)),
                                    glm::normalize(glm::vec3(0.1f, -0.9f, 0.2f)),
                                    glm::normalize(glm::vec3(0.9f, 0.4f, 0.05f)), n};
    const pbr::Material materials[] = {{{0.9f, 0.5f, 0.2f}, 0.0f, 0.3f, 1.5f},
                                       {{0.9f, 0.5f, 0.2f}, 1.0f, 0.6f, 1.5f},
                                       {{0.2f, 0.7f, 0.4f}, 0.4f, 0.1f, 2.0f},
                                       {{1.0f, 1.0f, 1.0f}, 1.0f, 1.0f, 1.5f}};
    for (const pbr::Material& m : materials)
        for (const glm::vec3& v : directions)
            for (const glm::vec3& l : directions) {
                const float n_dot_l = glm::dot(n, l), n_dot_v = glm::dot(n, v);
                const glm::vec3 forward = pbr::brdf_cosine(n, v, l, m, MultipleScattering::ignored);
                const glm::vec3 backward =
                    pbr::brdf_cosine(n, l, v, m, MultipleScattering::ignored);
                for (int c = 0; c < 3; ++c) {
                    INFO("metallic " << m.metallic << ", channel " << c);
                    CHECK(forward[c] / n_dot_l == Approx(backward[c] / n_dot_v).epsilon(1e-6));
                    CHECK(forward[c] > 0.0f);
                }
            }
}

TEST_CASE("brdf: the energy compensation depends on n.v alone, so it is not reciprocal",
          "[shade][brdf]") {
    // Turquin's and Filament's scaling multiplies the lobe by a factor of the
    // view; f(v, l) / f(l, v) is then the ratio of the two views' factors.
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 v = glm::normalize(glm::vec3(0.8f, 0.0f, 0.3f));
    const glm::vec3 l = glm::normalize(glm::vec3(-0.2f, 0.1f, 0.9f));
    const pbr::Material rough_gold{{1.0f, 0.78f, 0.34f}, 1.0f, 0.8f, 1.5f};
    const auto compensated = [&](const glm::vec3& from, const glm::vec3& to) {
        return pbr::brdf_cosine(n, from, to, rough_gold, MultipleScattering::compensated) /
               glm::dot(n, to);
    };
    const pbr::PbrPoint<float> at_v =
        pbr::prepare_shading_point(n, v, rough_gold, MultipleScattering::compensated);
    const pbr::PbrPoint<float> at_l =
        pbr::prepare_shading_point(n, l, rough_gold, MultipleScattering::compensated);
    const glm::vec3 ratio = compensated(v, l) / compensated(l, v);
    for (int c = 0; c < 3; ++c) {
        const float expected = at_v.metal_compensation[c] / at_l.metal_compensation[c];
        CHECK(ratio[c] == Approx(expected).epsilon(1e-5));
    }
    CHECK(ratio.x != Approx(1.0f).epsilon(0.01));
}

TEST_CASE("brdf: the DFG table's albedo is above 0, at most 1, and falls with roughness",
          "[shade][brdf]") {
    const pbr::DfgTable& table = pbr::dfg_table();
    constexpr int kLast = pbr::DfgTable::kSize - 1;
    for (const pbr::DfgTerms& t : table.terms) {
        CHECK(t.scale >= 0.0f);
        CHECK(t.bias >= 0.0f);
        CHECK(t.albedo() > 0.0f);
        CHECK(t.albedo() <= 1.0f);
    }
    // Seen head-on, a smooth lobe keeps all the light (to 1e-7) and every
    // step of roughness loses more, down to 1 - ln 2 at roughness 1 (the
    // previous test says why).
    CHECK(table.lookup(1.0f, 0.0f).albedo() > 0.9999f);
    CHECK(table.lookup(1.0f, 1.0f).albedo() == Approx(1.0 - std::log(2.0)).epsilon(3e-3));
    for (int j = 1; j <= kLast; ++j) {
        const float here = table.terms[j * pbr::DfgTable::kSize + kLast].albedo();
        const float smoother = table.terms[(j - 1) * pbr::DfgTable::kSize + kLast].albedo();
        INFO("roughness row " << j);
        CHECK(here <= smoother);
        if (smoother < 0.9999f) CHECK(here < smoother);
    }
    // The table agrees with this file's own quadrature of the bare lobe.
    for (float roughness : {0.3f, 0.7f, 1.0f})
        for (double n_dot_v : {1.0, 0.5, 0.2}) {
            const double integrated =
                reflected_energy(white(1, roughness), n_dot_v, MultipleScattering::ignored).x;
            INFO("roughness " << roughness << ", n.v " << n_dot_v);
            CHECK(table.lookup(static_cast<float>(n_dot_v), roughness).albedo() ==
                  Approx(integrated).epsilon(0.01));
        }
}

TEST_CASE("brdf: the DFG table's lookup hits its nodes and interpolates between them",
          "[shade][brdf]") {
    const pbr::DfgTable& table = pbr::dfg_table();
    constexpr int kSize = pbr::DfgTable::kSize, kLast = kSize - 1;
    const auto roughness_at = [](int j) {
        return pbr::kMinRoughness + (1.0f - pbr::kMinRoughness) * static_cast<float>(j) / kLast;
    };
    CHECK(table.lookup(1.0f, 1.0f).scale == table.terms[kLast * kSize + kLast].scale);
    CHECK(table.lookup(0.0f, 0.0f).bias == table.terms[0].bias);
    const pbr::DfgTerms corner = table.lookup(10.0f / kLast, roughness_at(7));
    CHECK(corner.scale == Approx(table.terms[7 * kSize + 10].scale).epsilon(1e-5));
    // Halfway between two n.v nodes: their mean.
    const pbr::DfgTerms mid = table.lookup(10.5f / kLast, roughness_at(7));
    const float mean =
        0.5f * (table.terms[7 * kSize + 10].albedo() + table.terms[7 * kSize + 11].albedo());
    CHECK(mid.albedo() == Approx(mean).epsilon(1e-5));
}
