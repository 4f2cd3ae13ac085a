#pragma once
// What `facet compare` accepts as "the same image": one Tolerance per kind
// of image (docs/regression.md, "Thresholds"), with per-camera overrides,
// and the masks of regions to ignore. Plain records: the YAML file is read
// by the scene module (scene/thresholds_file.hpp), command-line overrides
// go through apply_threshold_override.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/enum_names.hpp"

namespace facet {

// How a pair of files is judged. The kind follows from the manifest's pass
// and format, or from a single file's channels (compare/compare_image.hpp).
enum class ImageKind {
    color,        // PNG colour: encoded values 0..1, absolute difference
    color_float,  // EXR colour: relative difference, one exposure per sequence
    alpha,        // coverage, judged apart from colour
    depth,        // linear depth (EXR) or its 16-bit PNG view; +inf background
    normal,       // unit vectors, by angle in degrees
    id,           // object or material ids: exact
    float_data,   // uv, position, motion and other float data: absolute + relative
};
// The kinds' names, as thresholds files, `--threshold` and reports write them.
inline constexpr EnumName<ImageKind> kImageKinds[] = {
    {ImageKind::color, "color"},     {ImageKind::color_float, "color_float"},
    {ImageKind::alpha, "alpha"},     {ImageKind::depth, "depth"},
    {ImageKind::normal, "normal"},   {ImageKind::id, "id"},
    {ImageKind::float_data, "float"}};
// The table's literal, for messages built with +.
inline const char* image_kind_name(ImageKind kind) {
    return c_name_of(kImageKinds, kind);
}

// One kind's limits. A sample's difference is measured in the kind's unit
// (colour 0..1, EXR colour relative, depth and float data in scene units,
// normals in degrees, ids 0 or 1). A pixel fails when any sample's
// difference is over `fail` (for depth and float data: over
// fail + relative * |reference|) and no pixel within `position` pixels
// matches. The file fails when
//   - more than `allowed_failures` pixels fail and they are more than
//     `fail_percent` % of the compared pixels, or
//   - any sample differs by more than `hard_fail`, or
//   - the mean SSIM (colour kinds) is below `ssim_min`.
// Warnings follow the same rule with `warn` and `warn_percent`.
struct Tolerance {
    double warn = 0;
    double fail = 0;
    double warn_percent = 0;
    double fail_percent = 0;
    uint64_t allowed_failures = 0;
    double hard_fail = 1e30;  // off
    double relative = 0;      // depth and float data
    int position = 0;         // pixels
    double ssim_min = 0;      // colour kinds; 0: off
    double floor = 0;         // EXR colour: relative error is taken against at least floor * white
};

// The names of Tolerance's fields as written in files and overrides.
inline constexpr std::string_view kToleranceKeys[] = {
    "warn",      "fail",     "warn_percent", "fail_percent", "allowed_failures",
    "hard_fail", "relative", "position",     "ssim_min",     "floor"};

// Sets one field by name. Returns "" or what is wrong (unknown key, value
// out of range), for the caller to report with its own location.
std::string set_tolerance_value(Tolerance& tolerance, std::string_view key, double value);

// A region left out of every figure: a rectangle in pixels, or a mask image
// whose non-black pixels are left out. Empty camera or kind: every one.
struct CompareMask {
    int x = 0, y = 0, width = 0, height = 0;  // when image is empty
    std::string image;                        // PNG, the images' size
    std::string camera;
    std::optional<ImageKind> kind;
};

struct CompareThresholds {
    std::map<ImageKind, Tolerance> defaults;  // every kind present
    // camera name -> kind -> key -> value: only what the camera changes, so
    // later changes to the defaults still reach the camera's other keys.
    std::map<std::string, std::map<ImageKind, std::map<std::string, double>>> cameras;
    std::vector<CompareMask> masks;
    double diff_scale = 8;  // the difference image shows |new - ref| * diff_scale
};

// The built-in defaults (docs/regression.md gives the reason for each).
CompareThresholds default_thresholds();

Tolerance tolerance_for(const CompareThresholds& thresholds, const std::string& camera,
                        ImageKind kind);

// "[camera.]kind.key=value", e.g. "color.hard_fail=0.1" or
// "side.depth.position=2". Returns "" or what is wrong.
std::string apply_threshold_override(CompareThresholds& thresholds, std::string_view text);

}  // namespace facet
