#include "compare/thresholds.hpp"

#include <cmath>

#include "core/number_text.hpp"
#include "core/plain_text.hpp"
#include "core/suggest.hpp"

namespace facet {

std::string set_tolerance_value(Tolerance& t, std::string_view key, double value) {
    if (!std::isfinite(value) || value < 0)
        return "expected a number of at least 0, got " + std::to_string(value);
    auto whole = [&](auto& field, double max) -> std::string {
        if (value != std::floor(value) || value > max)
            return "expected a whole number from 0 to " + std::to_string(static_cast<long>(max));
        field = static_cast<std::remove_reference_t<decltype(field)>>(value);
        return "";
    };
    auto bounded = [&](double& field, double max) -> std::string {
        if (value > max) return "expected a number from 0 to " + std::to_string(max);
        field = value;
        return "";
    };
    if (key == "warn") return bounded(t.warn, 1e30);
    if (key == "fail") return bounded(t.fail, 1e30);
    if (key == "warn_percent") return bounded(t.warn_percent, 100);
    if (key == "fail_percent") return bounded(t.fail_percent, 100);
    if (key == "allowed_failures") return whole(t.allowed_failures, 1e12);
    if (key == "hard_fail") return bounded(t.hard_fail, 1e30);
    if (key == "relative") return bounded(t.relative, 1e30);
    if (key == "position") return whole(t.position, 16);
    if (key == "ssim_min") return bounded(t.ssim_min, 1);
    if (key == "floor") return bounded(t.floor, 1);
    return "unknown threshold '" + std::string(key) + "'" +
           did_you_mean(key, std::span<const std::string_view>(kToleranceKeys)) +
           " (known: warn, fail, warn_percent, fail_percent, allowed_failures, hard_fail, "
           "relative, position, ssim_min, floor)";
}

CompareThresholds default_thresholds() {
    // The reasons are in docs/regression.md, "Defaults".
    CompareThresholds t;
    Tolerance color;
    color.warn = 0.5 / 255;     // any change of an 8-bit code is worth a warning
    color.fail = 2.5 / 255;     // one or two codes: rounding in a changed computation
    color.fail_percent = 0.01;  // about a handful of isolated pixels
    color.ssim_min = 0.99;      // structure: a camera moved by a fraction of a degree
    t.defaults[ImageKind::color] = color;

    Tolerance color_float = color;
    color_float.warn = 0.001;  // relative
    color_float.fail = 0.01;
    color_float.floor = 0.01;  // below 1% of the sequence's white, errors are absolute
    t.defaults[ImageKind::color_float] = color_float;

    Tolerance alpha;
    alpha.warn = 0.5 / 255;
    alpha.fail = 2.5 / 255;
    alpha.fail_percent = 0.01;
    t.defaults[ImageKind::alpha] = alpha;

    Tolerance depth;
    depth.fail = 1e-4;      // scene units
    depth.relative = 1e-4;  // a tenth of a millimetre per metre
    depth.position = 1;     // a silhouette pixel may belong to either side
    depth.fail_percent = 0.01;
    t.defaults[ImageKind::depth] = depth;

    Tolerance normal;
    normal.warn = 0.1;  // degrees
    normal.fail = 1;
    normal.position = 1;
    normal.fail_percent = 0.01;
    t.defaults[ImageKind::normal] = normal;

    Tolerance id;  // exact: the difference is 0 or 1
    id.position = 1;
    id.fail_percent = 0.01;
    t.defaults[ImageKind::id] = id;

    Tolerance data;
    data.fail = 1e-4;
    data.relative = 1e-4;
    data.position = 1;
    data.fail_percent = 0.01;
    t.defaults[ImageKind::float_data] = data;
    return t;
}

Tolerance tolerance_for(const CompareThresholds& thresholds, const std::string& camera,
                        ImageKind kind) {
    Tolerance t = thresholds.defaults.at(kind);
    if (auto c = thresholds.cameras.find(camera); c != thresholds.cameras.end())
        if (auto k = c->second.find(kind); k != c->second.end())
            for (const auto& [key, value] : k->second) set_tolerance_value(t, key, value);
    return t;
}

std::string apply_threshold_override(CompareThresholds& thresholds, std::string_view text) {
    const size_t eq = text.find('=');
    if (eq == std::string_view::npos || eq == 0)
        return "expected [camera.]kind.key=value, e.g. color.hard_fail=0.1";
    const std::string_view path = text.substr(0, eq), value_text = text.substr(eq + 1);
    const size_t last = path.rfind('.');
    if (last == std::string_view::npos)
        return "expected [camera.]kind.key=value, e.g. color.hard_fail=0.1";
    const std::string_view key = path.substr(last + 1);
    std::string_view head = path.substr(0, last);
    std::string camera;
    if (const size_t dot = head.rfind('.'); dot != std::string_view::npos) {
        camera = std::string(head.substr(0, dot));
        head = head.substr(dot + 1);
    }
    const std::optional<ImageKind> kind = value_of(kImageKinds, head);
    if (!kind) {
        const std::vector<std::string_view> names = names_of(kImageKinds);
        return "unknown kind '" + std::string(head) + "'" + did_you_mean(head, names) +
               " (known: " + comma_list(names) + ")";
    }
    const std::optional<double> number = read_finite_number(value_text);
    if (!number) return "expected a number, got '" + std::string(value_text) + "'";
    const double value = *number;
    if (!camera.empty()) {
        Tolerance check;
        if (std::string problem = set_tolerance_value(check, key, value); !problem.empty())
            return problem;
        thresholds.cameras[camera][*kind][std::string(key)] = value;
        return "";
    }
    return set_tolerance_value(thresholds.defaults.at(*kind), key, value);
}

}  // namespace facet
