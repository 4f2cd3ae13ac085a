#include "shade/brdf.hpp"

#include <cstdint>
#include <limits>

#include "core/exact_trig.hpp"
#include "shade/hammersley.hpp"

namespace facet::pbr {

namespace {

constexpr int kLast = DfgTable::kSize - 1;
constexpr double kPiDouble = 3.14159265358979323846;

// The grid's perceptual roughness at row j (DfgTable's comment).
double node_roughness(int j) {
    return kMinRoughness + (1.0 - kMinRoughness) * j / kLast;
}

// One node of the table: Karis 2013's estimate of the split-sum terms with
// h drawn from D(h)(n.h) by inverting its distribution (Walter et al.
// 2007): cos^2 theta_h = (1 - u) / (1 + (alpha^2 - 1) u), phi = 2 pi t
// for the Hammersley point (t, u). Reflecting v about h gives l, whose
// density is D (n.h) / (4 v.h), so each sample adds
//   D V F (n.l) / density = V F (n.l) 4 (v.h) / (n.h).
// The view is v = (sin theta_v, 0, cos theta_v) with n = +z, so only cos
// phi enters: v.h = sin theta_v sin theta_h cos phi + cos theta_v cos theta_h.
DfgTerms integrate_dfg_node(double n_dot_v, double alpha) {
    const double a2 = alpha * alpha;
    const double sin_v = std::sqrt(1.0 - n_dot_v * n_dot_v);
    double scale = 0.0, bias = 0.0;
    for (uint32_t i = 0; i < DfgTable::kSamples; ++i) {
        const double u = radical_inverse_base2(i);
        const double phi_turns = static_cast<double>(i) / DfgTable::kSamples;
        const double denominator = 1.0 + (a2 - 1.0) * u;
        const double cos_h = std::sqrt((1.0 - u) / denominator);
        const double sin_h = std::sqrt(a2 * u / denominator);  // sqrt(1 - cos_h^2), not cancelling
        const double v_dot_h = sin_v * sin_h * cos_turns(phi_turns) + n_dot_v * cos_h;
        const double n_dot_l = 2.0 * v_dot_h * cos_h - n_dot_v;
        if (!(v_dot_h > 0.0) || !(n_dot_l > 0.0)) continue;
        const double visibility = smith_ggx_correlated_visibility(n_dot_l, n_dot_v, alpha);
        const double weight = visibility * 4.0 * n_dot_l * v_dot_h / cos_h;
        const double m = 1.0 - v_dot_h;
        const double fresnel_weight = m * m * m * m * m;
        scale += (1.0 - fresnel_weight) * weight;
        bias += fresnel_weight * weight;
    }
    scale /= DfgTable::kSamples;
    bias /= DfgTable::kSamples;
    // A lobe cannot reflect more than it receives, but the estimate of a
    // smooth one can come out a few 1e-5 above 1: scale such nodes back to 1,
    // so that the compensation never darkens.
    const double albedo = scale + bias;
    if (albedo > 1.0) {
        scale /= albedo;
        bias /= albedo;
    }
    return {static_cast<float>(scale), static_cast<float>(bias)};
}

// The sheen's directional albedo at one node: the lobe with a white colour
// (sheen_brdf_cosine) summed over light directions at the midpoints of a
// kSheenSteps x kSheenSteps grid of n.l in (0, 1) and azimuth in (0, pi)
// (the lobe is symmetric about the plane of n and v), each cell of solid
// angle d(n.l) d(phi), the sum doubled for the other half. Eight lights
// at a time; `cos_phi` and `sin_phi` hold the azimuths' cosines and sines.
constexpr int kSheenSteps = 48;
constexpr int kSheenGroups = kSheenSteps / simd::kLanes;

float integrate_sheen_node(float n_dot_v, float roughness, const simd::vf (&cos_phi)[kSheenGroups],
                           const simd::vf (&sin_phi)[kSheenGroups]) {
    using simd::vf;
    const vf alpha = simd::splat(alpha_from_roughness(roughness));
    const SheenMasking<vf> masking = sheen_masking(alpha);
    const vf lambda_v = sheen_lambda(masking, simd::splat(n_dot_v));
    const float sin_v = std::sqrt(std::max(0.0f, 1.0f - n_dot_v * n_dot_v));
    const lanes::Vec3<vf> n = {simd::splat(0.0f), simd::splat(0.0f), simd::splat(1.0f)};
    const lanes::Vec3<vf> v = {simd::splat(sin_v), simd::splat(0.0f), simd::splat(n_dot_v)};
    double sum = 0.0;
    for (int a = 0; a < kSheenSteps; ++a) {
        const float n_dot_l = (static_cast<float>(a) + 0.5f) / kSheenSteps;
        const float sin_l = std::sqrt(1.0f - n_dot_l * n_dot_l);
        vf row = simd::splat(0.0f);
        for (int b = 0; b < kSheenGroups; ++b) {
            const lanes::Vec3<vf> l = {sin_l * cos_phi[b], sin_l * sin_phi[b],
                                       simd::splat(n_dot_l)};
            const HalfVector<vf> h = half_vector(n, v, l);
            row += sheen_brdf_cosine(h.n_cross_h_squared, simd::splat(n_dot_l),
                                     simd::splat(n_dot_v), lambda_v, alpha, masking);
        }
        for (int lane = 0; lane < simd::kLanes; ++lane) sum += row[lane];
    }
    const double cell = (1.0 / kSheenSteps) * (kPiDouble / kSheenSteps);
    return static_cast<float>(std::min(1.0, 2.0 * cell * sum));
}

}  // namespace

DfgTerms DfgTable::lookup(float n_dot_v, float roughness) const {
    const Lanes lanes = lookup(simd::splat(n_dot_v), simd::splat(roughness));
    return {lanes.scale[0], lanes.bias[0]};
}

namespace {

// Where points fall on DfgTable's grid: each lane's node below and left,
// and its fractions of the way to the next node along n.v (tx) and
// roughness (ty).
struct GridPoint {
    simd::vi i, j;
    simd::vf tx, ty;
};

GridPoint grid_point(simd::vf n_dot_v, simd::vf roughness) {
    using simd::splat;
    using simd::vf;
    using simd::vi;
    // vmax(x, low) first: a NaN becomes the low end.
    const float last = static_cast<float>(kLast);
    const vf x = simd::vmin(simd::vmax(n_dot_v, splat(0.0f)), splat(1.0f)) * last;
    const vf y =
        (simd::vmin(simd::vmax(roughness, splat(kMinRoughness)), splat(1.0f)) - kMinRoughness) /
        (1.0f - kMinRoughness) * last;
    // x, y >= 0: truncation is floor.
    vi i = __builtin_convertvector(x, vi), j = __builtin_convertvector(y, vi);
    const vi highest = simd::splat_i(kLast - 1);
    i = i < highest ? i : highest;
    j = j < highest ? j : highest;
    return {i, j, x - __builtin_convertvector(i, vf), y - __builtin_convertvector(j, vf)};
}

// A value of the grid's nodes (`value(node index)`), bilinearly
// interpolated between the four nodes round each point, read one lane at
// a time.
template <typename Value>
simd::vf blend_nodes(const GridPoint& g, Value&& value) {
    constexpr int kSize = DfgTable::kSize;
    simd::vf corner[4];
    for (int lane = 0; lane < simd::kLanes; ++lane) {
        const size_t low = static_cast<size_t>(g.j[lane] * kSize + g.i[lane]);
        const size_t nodes[4] = {low, low + 1, low + kSize, low + kSize + 1};
        for (int k = 0; k < 4; ++k) corner[k][lane] = value(nodes[k]);
    }
    const simd::vf low = corner[0] + (corner[1] - corner[0]) * g.tx;
    const simd::vf high = corner[2] + (corner[3] - corner[2]) * g.tx;
    return low + (high - low) * g.ty;
}

}  // namespace

DfgTable::Lanes DfgTable::lookup(simd::vf n_dot_v, simd::vf roughness) const {
    const GridPoint g = grid_point(n_dot_v, roughness);
    return {blend_nodes(g, [&](size_t node) { return terms[node].scale; }),
            blend_nodes(g, [&](size_t node) { return terms[node].bias; })};
}

simd::vf SheenTable::lookup(simd::vf n_dot_v, simd::vf sheen_roughness) const {
    return blend_nodes(grid_point(n_dot_v, sheen_roughness),
                       [&](size_t node) { return albedo[node]; });
}

DfgTable compute_dfg_table() {
    DfgTable table;
    for (int j = 0; j < DfgTable::kSize; ++j) {
        const double r = node_roughness(j);
        for (int i = 0; i < DfgTable::kSize; ++i) {
            const double n_dot_v =
                std::max(static_cast<double>(i) / kLast, static_cast<double>(kMinNdotV));
            table.terms[j * DfgTable::kSize + i] = integrate_dfg_node(n_dot_v, r * r);
        }
    }
    return table;
}

const DfgTable& dfg_table() {
    static const DfgTable table = compute_dfg_table();
    return table;
}

SheenTable compute_sheen_table() {
    simd::vf cos_phi[kSheenGroups], sin_phi[kSheenGroups];
    for (int b = 0; b < kSheenSteps; ++b) {
        const double turns = (b + 0.5) / (2.0 * kSheenSteps);
        cos_phi[b / simd::kLanes][b % simd::kLanes] = static_cast<float>(cos_turns(turns));
        sin_phi[b / simd::kLanes][b % simd::kLanes] = static_cast<float>(sin_turns(turns));
    }
    SheenTable table;
    for (int j = 0; j < DfgTable::kSize; ++j)
        for (int i = 0; i < DfgTable::kSize; ++i) {
            const double n_dot_v =
                std::max(static_cast<double>(i) / kLast, static_cast<double>(kMinNdotV));
            table.albedo[j * DfgTable::kSize + i] =
                integrate_sheen_node(static_cast<float>(n_dot_v),
                                     static_cast<float>(node_roughness(j)), cos_phi, sin_phi);
        }
    return table;
}

const SheenTable& sheen_table() {
    static const SheenTable table = compute_sheen_table();
    return table;
}

SurfaceTerms<float> surface_terms(const Material& material) {
    const float f0 = f0_from_ior(material.ior);
    SurfaceTerms<float> terms{};
    terms.base = {material.base_color.x, material.base_color.y, material.base_color.z};
    terms.metallic = material.metallic;
    terms.roughness = material.roughness;
    terms.occlusion = 1.0f;
    terms.f0 = {f0, f0, f0};
    terms.f90 = 1.0f;
    terms.coat_normal = {0.0f, 1.0f, 0.0f};
    terms.iridescence_ior = 1.3f;
    terms.iridescence_thickness = 400.0f;
    terms.ior = material.ior;
    terms.attenuation_color = {1.0f, 1.0f, 1.0f};
    terms.attenuation_distance = std::numeric_limits<float>::infinity();
    return terms;
}

}  // namespace facet::pbr
