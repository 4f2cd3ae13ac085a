#include <filesystem>

#include <nlohmann/json.hpp>

#include "compare/reports.hpp"
#include "output/atomic_file.hpp"

namespace facet {
namespace {

using Json = nlohmann::ordered_json;

// JSON has no infinity: limits that are off are written as null.
Json number(double v) {
    return std::isfinite(v) && v < 1e29 ? Json(v) : Json(nullptr);
}

Json tolerance_json(const Tolerance& t) {
    return {{"warn", number(t.warn)},
            {"fail", number(t.fail)},
            {"warn_percent", t.warn_percent},
            {"fail_percent", t.fail_percent},
            {"allowed_failures", t.allowed_failures},
            {"hard_fail", number(t.hard_fail)},
            {"relative", t.relative},
            {"position", t.position},
            {"ssim_min", t.ssim_min},
            {"floor", t.floor}};
}

Json verdict_json(const PixelVerdict& v) {
    return {{"outcome", outcome_name(v.outcome)},
            {"reason", v.reason},
            {"mean", v.stats.mean},
            {"rms", v.stats.rms},
            {"max", v.stats.max},
            {"max_at", {v.stats.max_x, v.stats.max_y}},
            {"max_channel", v.stats.max_channel},
            {"pixels", v.stats.pixels},
            {"pixels_failed", v.pixels_failed},
            {"percent_failed", v.percent_failed()},
            {"pixels_warned", v.pixels_warned},
            {"forgiven_by_position", v.forgiven_by_position},
            {"background_mismatch", v.background_mismatch}};
}

Json file_json(const FileResult& r) {
    Json j = {{"camera", r.key.camera},
              {"pass", r.key.pass},
              {"frame", r.key.frame},
              {"format", r.key.format},
              {"kind", image_kind_name(r.kind)},
              {"status", file_status_name(r.status)},
              {"outcome", outcome_name(r.outcome)},
              {"decoded", r.decoded},
              {"reason", r.reason},
              {"ref", r.ref_path},
              {"new", r.new_path}};
    if (r.decoded)
        j["size"] = {{"ref", {r.ref_width, r.ref_height}}, {"new", {r.new_width, r.new_height}}};
    if (r.pixels) j["metrics"] = verdict_json(*r.pixels);
    if (r.alpha) j["alpha"] = verdict_json(*r.alpha);
    if (r.ssim) j["ssim"] = *r.ssim;
    if (r.change_ref) j["change_ref"] = *r.change_ref;
    if (r.change_new) j["change_new"] = *r.change_new;
    if (r.flicker) j["flicker"] = *r.flicker;
    Json images = Json::object();
    for (auto [name, path] : {std::pair{"diff", &r.diff_image}, std::pair{"heat", &r.heat_image},
                              std::pair{"ref", &r.ref_preview}, std::pair{"new", &r.new_preview}})
        if (!path->empty()) images[name] = *path;
    j["images"] = images;
    return j;
}

}  // namespace

std::string report_json(const CompareReport& report) {
    Json j;
    j["schema"] = "facet-compare";
    j["version"] = CompareReport::kSchemaVersion;
    j["ref"] = report.ref;
    j["new"] = report.candidate;
    j["outcome"] = outcome_name(report.outcome);
    j["exit_code"] = compare_exit_code(report);
    j["counts"] = Json::object();
    for (const auto& [name, count] : named_counts(report.counts)) j["counts"][name] = count;
    Json thresholds = Json::object();
    for (const auto& [kind, name] : kImageKinds)
        thresholds[std::string(name)] = tolerance_json(report.thresholds.defaults.at(kind));
    Json cameras = Json::object();
    for (const auto& [camera, kinds] : report.thresholds.cameras)
        for (const auto& [kind, values] : kinds)
            for (const auto& [key, value] : values)
                cameras[camera][image_kind_name(kind)][key] = value;
    thresholds["cameras"] = cameras;
    Json masks = Json::array();
    for (const CompareMask& m : report.thresholds.masks) {
        Json mask = m.image.empty() ? Json{{"rect", {m.x, m.y, m.width, m.height}}}
                                    : Json{{"image", m.image}};
        if (!m.camera.empty()) mask["camera"] = m.camera;
        if (m.kind) mask["kind"] = image_kind_name(*m.kind);
        masks.push_back(mask);
    }
    thresholds["masks"] = masks;
    thresholds["diff_scale"] = report.thresholds.diff_scale;
    j["thresholds"] = thresholds;
    Json sequences = Json::array();
    for (const SequenceResult& s : report.sequences)
        sequences.push_back(
            {{"camera", s.camera},
             {"pass", s.pass},
             {"format", s.format},
             {"kind", image_kind_name(s.kind)},
             {"frames", s.frames},
             {"white", s.white},
             {"worst_frame", s.worst_frame ? Json(*s.worst_frame) : Json(nullptr)},
             {"worst_percent_failed", s.worst_percent},
             {"flicker", s.flicker},
             {"flicker_frame", s.flicker_frame ? Json(*s.flicker_frame) : Json(nullptr)}});
    j["sequences"] = sequences;
    Json files = Json::array();
    for (const FileResult& r : report.files) files.push_back(file_json(r));
    j["files"] = files;
    j["updated"] = report.updated;
    // Paths need not be UTF-8; JSON must be: invalid bytes become U+FFFD.
    return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void write_reports(const CompareReport& report) {
    const std::filesystem::path dir(report.report_dir);
    make_directories(dir.string());
    write_file_atomically((dir / "report.json").string(), report_json(report));
    write_file_atomically((dir / "junit.xml").string(), report_junit(report));
    write_file_atomically((dir / "index.html").string(), report_html(report));
}

}  // namespace facet
