#include "scene/thresholds_file.hpp"

#include <filesystem>

#include "scene/yaml_field.hpp"

namespace facet {
namespace {

// The kinds' names as keys.
std::vector<const char*> kind_keys() {
    std::vector<const char*> keys;
    for (const auto& [kind, name] : kImageKinds) keys.push_back(c_name_of(kImageKinds, kind));
    return keys;
}

// One kind's mapping: `apply(key, value)` per entry, after range checks.
template <typename Apply>
void read_tolerance(const Field& field, Apply&& apply) {
    field.expect_map();
    field.check_keys({"warn", "fail", "warn_percent", "fail_percent", "allowed_failures",
                      "hard_fail", "relative", "position", "ssim_min", "floor"});
    for (const std::string& key : field.keys()) {
        const Field value = field[key];
        const double number = value.number(0, 1e30);
        Tolerance check;
        if (std::string problem = set_tolerance_value(check, key, number); !problem.empty())
            value.fail(problem);
        apply(key, number);
    }
}

CompareMask read_mask(const Field& field, const std::string& folder) {
    field.expect_map();
    field.check_keys({"rect", "image", "camera", "kind"});
    CompareMask mask;
    if (field.has("rect") == field.has("image"))
        field.fail("a mask is either `rect: [x, y, width, height]` or `image: FILE`");
    if (field.has("rect")) {
        const Field rect = field["rect"];
        if (!rect.is_sequence() || rect.size() != 4)
            rect.fail("expected [x, y, width, height] in pixels");
        mask.x = rect[size_t{0}].integer(0, 1 << 20);
        mask.y = rect[size_t{1}].integer(0, 1 << 20);
        mask.width = rect[size_t{2}].integer(1, 1 << 20);
        mask.height = rect[size_t{3}].integer(1, 1 << 20);
    } else {
        const Field image = field["image"];
        mask.image = (std::filesystem::path(folder) / image.text()).lexically_normal().string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(mask.image, ec))
            image.fail("no such mask image: " + mask.image);
    }
    if (field.has("camera")) mask.camera = field["camera"].text();
    if (field.has("kind")) mask.kind = field["kind"].choice_of(kImageKinds);
    return mask;
}

}  // namespace

CompareThresholds load_thresholds_file(const std::string& path) {
    CompareThresholds thresholds = default_thresholds();
    const auto doc = read_yaml_file(path);
    const Field root = root_field(doc);
    if (root.is_null()) return thresholds;
    root.expect_map();
    std::vector<const char*> keys = {"version", "cameras", "masks", "diff_scale"};
    for (const char* kind : kind_keys()) keys.push_back(kind);
    root.check_keys(keys);
    if (root.has("version")) root["version"].integer(1, 1);
    for (const auto& [kind, name] : kImageKinds)
        if (root.has(std::string(name))) {
            Tolerance& target = thresholds.defaults.at(kind);
            read_tolerance(root[std::string(name)], [&](const std::string& key, double value) {
                set_tolerance_value(target, key, value);
            });
        }
    if (root.has("cameras")) {
        const Field cameras = root["cameras"];
        cameras.expect_map();
        for (const std::string& camera : cameras.keys()) {
            const Field kinds = cameras[camera];
            kinds.expect_map();
            kinds.check_keys(kind_keys());
            for (const std::string& name : kinds.keys()) {
                auto& values = thresholds.cameras[camera][*value_of(kImageKinds, name)];
                read_tolerance(kinds[name],
                               [&](const std::string& key, double value) { values[key] = value; });
            }
        }
    }
    if (root.has("masks")) {
        const Field masks = root["masks"];
        if (!masks.is_sequence()) masks.fail("expected a list of masks");
        const std::string folder = std::filesystem::path(path).parent_path().string();
        for (size_t i = 0; i < masks.size(); ++i)
            thresholds.masks.push_back(read_mask(masks[i], folder));
    }
    if (root.has("diff_scale")) thresholds.diff_scale = root["diff_scale"].number(0.001, 1e6);
    return thresholds;
}

}  // namespace facet
