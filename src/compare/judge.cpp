#include "compare/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "compare/ssim.hpp"
#include "core/color.hpp"
#include "core/number_text.hpp"

namespace facet {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One pixel of the reference against one of the candidate.
struct PixelCheck {
    double worst_fail = 0;  // largest difference / fail limit over the channels
    double worst_warn = 0;  // the same against the warn limit
    bool background_mismatch = false;
};

double ratio(double difference, double limit) {
    if (difference <= limit) return limit > 0 ? difference / limit : 0.0;
    return limit > 0 ? difference / limit : kInfinity;
}

// The difference of channel c in the kind's unit, and the limits it is held
// to; calls `sample(c, difference, fail_limit, warn_limit)` per channel.
// Returns false when the pixel is a background mismatch (+inf or NaN
// against a value), which has no finite difference.
template <typename Visit>
bool visit_pixel(ImageKind kind, const Tolerance& t, const float* r, const float* n, int channels,
                 double white, Visit&& sample) {
    switch (kind) {
        case ImageKind::normal: {
            const double lr =
                std::sqrt(double(r[0]) * r[0] + double(r[1]) * r[1] + double(r[2]) * r[2]);
            const double ln =
                std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
            if (!std::isfinite(lr) || !std::isfinite(ln))
                return lr == ln || (std::isnan(lr) && std::isnan(ln));
            double degrees = 0;
            if (lr == 0 || ln == 0) {
                degrees = lr == ln ? 0 : 180;  // no normal (background) against one
            } else {
                const double dot =
                    (double(r[0]) * n[0] + double(r[1]) * n[1] + double(r[2]) * n[2]) / (lr * ln);
                degrees = std::acos(std::clamp(dot, -1.0, 1.0)) * (180.0 / 3.14159265358979323846);
            }
            sample(0, degrees, t.fail, t.warn);
            return true;
        }
        case ImageKind::id:
            sample(0, r[0] == n[0] ? 0.0 : 1.0, 0.0, 0.0);
            return true;
        default:
            break;
    }
    for (int c = 0; c < channels; ++c) {
        const double rv = r[c], nv = n[c];
        if (!std::isfinite(rv) || !std::isfinite(nv)) {
            if (rv == nv || (std::isnan(rv) && std::isnan(nv))) {
                sample(c, 0.0, t.fail, t.warn);
                continue;
            }
            return false;
        }
        double difference = std::abs(nv - rv);
        double fail = t.fail, warn = t.warn;
        if (kind == ImageKind::color_float) {
            // A tiny minimum keeps 0 / 0 (black on black with floor 0) finite.
            difference /= std::max({std::abs(rv), t.floor * white, 1e-12});
        } else if (kind == ImageKind::depth || kind == ImageKind::float_data) {
            fail += t.relative * std::abs(rv);
            warn += t.relative * std::abs(rv);
        }
        sample(c, difference, fail, warn);
    }
    return true;
}

PixelCheck check_pixel(ImageKind kind, const Tolerance& t, const float* r, const float* n,
                       int channels, double white) {
    PixelCheck check;
    const bool finite =
        visit_pixel(kind, t, r, n, channels, white, [&](int, double d, double fail, double warn) {
            check.worst_fail = std::max(check.worst_fail, ratio(d, fail));
            check.worst_warn = std::max(check.worst_warn, ratio(d, warn));
        });
    if (!finite) {
        check.background_mismatch = true;
        check.worst_fail = check.worst_warn = kInfinity;
    }
    return check;
}

// A pixel over the threshold is forgiven when the value each image has
// there appears in the other image within `radius` pixels: an edge that
// moved by less than the radius, or a tie between two surfaces.
bool matched_nearby(ImageKind kind, const Tolerance& t, const CompareImage& ref,
                    const CompareImage& candidate, int x, int y, double white) {
    const int radius = t.position, channels = ref.channels;
    auto at = [&](const CompareImage& image, int px, int py) {
        return image.samples.data() + (static_cast<size_t>(py) * image.width + px) * channels;
    };
    auto found = [&](const float* value, const CompareImage& other, bool value_is_ref) {
        for (int qy = std::max(0, y - radius); qy <= std::min(ref.height - 1, y + radius); ++qy)
            for (int qx = std::max(0, x - radius); qx <= std::min(ref.width - 1, x + radius);
                 ++qx) {
                const float* q = at(other, qx, qy);
                const PixelCheck c = value_is_ref ? check_pixel(kind, t, value, q, channels, white)
                                                  : check_pixel(kind, t, q, value, channels, white);
                if (c.worst_fail <= 1) return true;
            }
        return false;
    };
    return found(at(candidate, x, y), ref, false) && found(at(ref, x, y), candidate, true);
}

// The outcome of one channel group from its counts (thresholds.hpp).
void decide(PixelVerdict& v, const Tolerance& t, const char* what) {
    const double percent_failed = v.percent_failed();
    const double percent_warned = v.stats.pixels ? 100.0 * v.pixels_warned / v.stats.pixels : 0;
    std::string prefix = std::string(what) + ": ";
    if (v.pixels_failed > t.allowed_failures && percent_failed > t.fail_percent) {
        v.outcome = Outcome::fail;
        v.reason = prefix + std::to_string(v.pixels_failed) + " pixels (" +
                   format_number(percent_failed, 4) + "%) over the fail threshold " +
                   format_number(t.fail, 4) + "; fail_percent is " +
                   format_number(t.fail_percent, 4) + "%";
        if (v.background_mismatch)
            v.reason += ", " + std::to_string(v.background_mismatch) +
                        " of them background in one image only";
    } else if (v.stats.max > t.hard_fail || (v.background_mismatch && t.hard_fail < 1e30)) {
        v.outcome = Outcome::fail;
        v.reason = prefix + "largest difference " + format_number(v.stats.max, 4) + " at (" +
                   std::to_string(v.stats.max_x) + ", " + std::to_string(v.stats.max_y) +
                   ") is over hard_fail " + format_number(t.hard_fail, 4);
    } else if (v.pixels_warned > t.allowed_failures && percent_warned > t.warn_percent) {
        v.outcome = Outcome::warn;
        v.reason = prefix + std::to_string(v.pixels_warned) + " pixels (" +
                   format_number(percent_warned, 4) + "%) over the warn threshold " +
                   format_number(t.warn, 4);
        if (v.pixels_failed)
            v.reason += ", " + std::to_string(v.pixels_failed) + " over fail (allowed)";
    }
}

// Judges one channel group of two same-sized images.
PixelVerdict judge_group(ImageKind kind, const Tolerance& t, const CompareImage& ref,
                         const CompareImage& candidate, std::span<const uint8_t> compared,
                         double white, Judgement* maps) {
    PixelVerdict v;
    DifferenceAccumulator sum;
    const int channels = ref.channels;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const size_t p = static_cast<size_t>(y) * ref.width + x;
            if (!compared[p]) continue;
            const float* r = ref.samples.data() + p * channels;
            const float* n = candidate.samples.data() + p * channels;
            PixelCheck check;
            const bool finite = visit_pixel(
                kind, t, r, n, channels, white, [&](int c, double d, double fail, double warn) {
                    sum.add(d, x, y, c);
                    check.worst_fail = std::max(check.worst_fail, ratio(d, fail));
                    check.worst_warn = std::max(check.worst_warn, ratio(d, warn));
                });
            if (!finite) check.worst_fail = check.worst_warn = kInfinity;
            bool failed = check.worst_fail > 1;
            if (failed && t.position > 0 && matched_nearby(kind, t, ref, candidate, x, y, white)) {
                failed = false;
                ++v.forgiven_by_position;
                if (maps) maps->state[p] = 3;
            } else if (failed) {
                ++v.pixels_failed;
                v.background_mismatch += !finite;
                if (maps) maps->state[p] = 2;
            }
            const bool warned = check.worst_warn > 1;
            v.pixels_warned += warned;
            if (maps && warned && maps->state[p] == 0) maps->state[p] = 1;
            if (maps) maps->excess[p] = static_cast<float>(std::min(check.worst_fail, 1e6));
            sum.end_pixel(failed);
        }
    v.stats = sum.result();
    return v;
}

CompareImage alpha_image(const CompareImage& image) {
    CompareImage a;
    a.width = image.width;
    a.height = image.height;
    a.channels = 1;
    a.samples = image.alpha;
    return a;
}

}  // namespace

std::vector<float> display_values(const CompareImage& image, ImageKind kind, double white) {
    if (kind != ImageKind::color_float) return image.samples;
    std::vector<float> out(image.samples.size());
    const double scale = white > 0 ? 1.0 / white : 1.0;
    for (size_t i = 0; i < out.size(); ++i) {
        const double v = image.samples[i];
        out[i] = std::isfinite(v)
                     ? static_cast<float>(linear_to_srgb(std::clamp(v * scale, 0.0, 1.0)))
                     : 1.0f;
    }
    return out;
}

Judgement judge_images(const CompareImage& ref, const CompareImage& candidate,
                       const JudgeInputs& in) {
    if (ref.width != candidate.width || ref.height != candidate.height ||
        ref.channels != candidate.channels)
        throw std::invalid_argument("judge_images: the images differ in size or channels");
    const size_t pixels = static_cast<size_t>(ref.width) * ref.height;
    Judgement j;
    j.excess.assign(pixels, 0.0f);
    j.state.assign(pixels, 0);
    // Pixels compared: not masked, and for colour not transparent in both
    // (straight alpha: the colour under alpha 0 is not part of the image).
    std::vector<uint8_t> compared(pixels, 1), compared_alpha(pixels, 1);
    const bool both_alpha = !ref.alpha.empty() && !candidate.alpha.empty();
    for (size_t p = 0; p < pixels; ++p) {
        if (!in.mask.empty() && in.mask[p] == 0) {
            compared[p] = compared_alpha[p] = 0;
            j.state[p] = 4;
        } else if (both_alpha && ref.alpha[p] == 0 && candidate.alpha[p] == 0) {
            compared[p] = 0;
        }
    }
    j.pixels = judge_group(in.kind, in.tolerance, ref, candidate, compared, in.white, &j);
    decide(j.pixels, in.tolerance, image_kind_name(in.kind));
    // A colour that is NaN or infinite in one image only is a broken
    // render, not a small difference: it fails whatever the share.
    const bool colour = in.kind == ImageKind::color || in.kind == ImageKind::color_float;
    if (colour && j.pixels.background_mismatch > 0) {
        j.pixels.outcome = Outcome::fail;
        j.pixels.reason = std::string(image_kind_name(in.kind)) + ": " +
                          std::to_string(j.pixels.background_mismatch) +
                          " pixels are not finite (NaN or infinite) in one image only";
    }
    j.outcome = j.pixels.outcome;

    if (!ref.alpha.empty() || !candidate.alpha.empty()) {
        CompareImage ra = alpha_image(ref), ca = alpha_image(candidate);
        // A missing alpha channel is opaque.
        if (ra.samples.empty()) ra.samples.assign(pixels, 1.0f);
        if (ca.samples.empty()) ca.samples.assign(pixels, 1.0f);
        PixelVerdict a =
            judge_group(ImageKind::alpha, in.alpha_tolerance, ra, ca, compared_alpha, 1.0, nullptr);
        decide(a, in.alpha_tolerance, "alpha");
        j.outcome = std::max(j.outcome, a.outcome);
        j.alpha = a;
    }

    if (in.kind == ImageKind::color || in.kind == ImageKind::color_float) {
        const std::vector<float> rd = display_values(ref, in.kind, in.white);
        std::vector<float> nd = display_values(candidate, in.kind, in.white);
        // Left-out pixels (masked, or transparent in both) take REF's value
        // in both images, so no SSIM window sees a difference there.
        for (size_t p = 0; p < pixels; ++p)
            if (!compared[p])
                for (int c = 0; c < ref.channels; ++c)
                    nd[p * ref.channels + c] = rd[p * ref.channels + c];
        std::vector<float> rp(pixels), np(pixels);
        j.ssim_map.assign(pixels, 0.0f);
        for (int c = 0; c < ref.channels; ++c) {
            for (size_t p = 0; p < pixels; ++p) {
                rp[p] = rd[p * ref.channels + c];
                np[p] = nd[p * ref.channels + c];
            }
            const SsimResult s =
                ssim({ref.width, ref.height, rp}, {ref.width, ref.height, np}, 1.0);
            for (size_t p = 0; p < pixels; ++p) j.ssim_map[p] += s.map[p] / ref.channels;
        }
        // The mean over compared pixels whose window lies inside the image
        // (ssim.hpp): with nothing left out, the paper's mean.
        const int pad = 5;
        double total = 0;
        uint64_t count = 0;
        for (int y = pad; y < ref.height - pad; ++y)
            for (int x = pad; x < ref.width - pad; ++x) {
                const size_t p = static_cast<size_t>(y) * ref.width + x;
                if (!compared[p]) continue;
                total += j.ssim_map[p];
                ++count;
            }
        j.ssim = count ? total / count : 1.0;
        if (in.tolerance.ssim_min > 0 && *j.ssim < in.tolerance.ssim_min) {
            if (j.pixels.outcome != Outcome::fail)
                j.pixels.reason = std::string(image_kind_name(in.kind)) + ": SSIM " +
                                  format_number(*j.ssim, 4) + " is below ssim_min " +
                                  format_number(in.tolerance.ssim_min, 4);
            j.pixels.outcome = Outcome::fail;
            j.outcome = Outcome::fail;
        }
    }
    return j;
}

double frame_change(const CompareImage& a, const CompareImage& b, ImageKind kind, double white) {
    if (a.samples.size() != b.samples.size() || a.samples.empty()) return 0;
    const std::vector<float> da = display_values(a, kind, white),
                             db = display_values(b, kind, white);
    double sum = 0;
    for (size_t i = 0; i < da.size(); ++i) {
        const double x = da[i], y = db[i];
        if (std::isfinite(x) && std::isfinite(y))
            sum += std::abs(x - y);
        else if (!(x == y))
            sum += 1;
    }
    return sum / static_cast<double>(da.size());
}

double change_difference(const CompareImage& ref_prev, const CompareImage& ref,
                         const CompareImage& candidate_prev, const CompareImage& candidate,
                         ImageKind kind, double white) {
    const size_t n = ref.samples.size();
    if (n == 0 || ref_prev.samples.size() != n || candidate.samples.size() != n ||
        candidate_prev.samples.size() != n)
        return 0;
    const std::vector<float> rp = display_values(ref_prev, kind, white);
    const std::vector<float> r = display_values(ref, kind, white);
    const std::vector<float> cp = display_values(candidate_prev, kind, white);
    const std::vector<float> c = display_values(candidate, kind, white);
    double sum = 0;
    for (size_t i = 0; i < n; ++i) {
        const double ref_change = double(r[i]) - rp[i];
        const double new_change = double(c[i]) - cp[i];
        if (std::isfinite(ref_change) && std::isfinite(new_change))
            sum += std::abs(new_change - ref_change);
        else if (!(r[i] == c[i] && rp[i] == cp[i]))
            sum += 1;
    }
    return sum / static_cast<double>(n);
}

}  // namespace facet
