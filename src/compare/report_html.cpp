// The HTML report: one file with its images inlined as data: URIs, so it
// can be archived by CI and opened offline. Failures come first; each
// changed file shows REF and NEW in one frame (hover flips to REF, a
// slider wipes between them) on a checkerboard, with the difference and
// heat images beside them; sequences get a per-frame plot.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "compare/reports.hpp"
#include "core/base64.hpp"
#include "core/input_file.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// Cards past this many, or past this many bytes of inlined images, show
// no images, only their names: a long failing sequence of large frames
// would otherwise make a page no browser opens.
constexpr size_t kCardsWithImages = 60;
constexpr size_t kInlineBytes = size_t(64) << 20;

std::string number(double v, const char* format = "%.4g") {
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::string data_uri(const std::string& path) {
    if (path.empty() || !input_file_problem(path).empty()) return "";
    try {
        return "data:image/png;base64," + base64_encode(read_input_file(path, "image"));
    } catch (const std::exception&) {
        return "";
    }
}

const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.5em; }
table { border-collapse: collapse; } td, th { padding: 2px 8px; border-bottom: 1px solid #ddd; text-align: left; }
.fail { color: #b00; } .warn { color: #b60; } .pass { color: #070; }
.card { border: 1px solid #ccc; border-radius: 6px; padding: 10px; margin: 12px 0; }
.card.fail { border-color: #d66; } .card.warn { border-color: #db6; }
.card h3 { margin: 0 0 6px; font-size: 1em; }
.images { display: flex; gap: 10px; flex-wrap: wrap; align-items: flex-start; }
.images figure { margin: 0; } figcaption { font-size: 12px; color: #555; }
.checker { background-color: #fff; background-image:
  linear-gradient(45deg, #ccc 25%, transparent 25%), linear-gradient(-45deg, #ccc 25%, transparent 25%),
  linear-gradient(45deg, transparent 75%, #ccc 75%), linear-gradient(-45deg, transparent 75%, #ccc 75%);
  background-size: 16px 16px; background-position: 0 0, 0 8px, 8px -8px, -8px 0; }
.viewer { position: relative; display: inline-block; line-height: 0; }
.viewer img { display: block; max-width: 640px; image-rendering: pixelated; }
.viewer img.top { position: absolute; left: 0; top: 0; }
.viewer:hover img.top { visibility: hidden; }
.viewer .tag { position: absolute; left: 4px; top: 4px; line-height: 1.2; font-size: 12px;
  background: rgba(0,0,0,.6); color: #fff; padding: 1px 5px; border-radius: 3px; }
.viewer .tag.ref { display: none; } .viewer:hover .tag.ref { display: block; } .viewer:hover .tag.new { display: none; }
.small img { max-width: 320px; image-rendering: pixelated; }
.reason { font-family: ui-monospace, monospace; font-size: 12px; }
)";

const char* kScript = R"(
for (const s of document.querySelectorAll('input.wipe'))
  s.addEventListener('input', () => {
    document.getElementById(s.dataset.target).style.clipPath = 'inset(0 ' + (100 - s.value) + '% 0 0)';
  });
window.addEventListener('load', () => {
  let loaded = 0, broken = 0;
  for (const img of document.images) (img.complete && img.naturalWidth > 0) ? loaded++ : broken++;
  document.body.dataset.imagesLoaded = loaded;
  document.body.dataset.imagesBroken = broken;
  document.getElementById('image-status').textContent =
    loaded + ' images shown' + (broken ? ', ' + broken + ' could not be shown' : '');
});
)";

std::string status_word(const FileResult& r) {
    if (r.status == FileStatus::compared || r.status == FileStatus::identical)
        return outcome_name(r.outcome);
    return file_status_name(r.status);
}

std::string summary(const CompareReport& report) {
    std::string html = "<p class=\"" + std::string(outcome_name(report.outcome)) + "\"><b>" +
                       (report.outcome == Outcome::fail   ? "FAILED"
                        : report.outcome == Outcome::warn ? "PASSED with warnings"
                                                          : "PASSED") +
                       "</b> (exit code " + std::to_string(compare_exit_code(report)) + ")</p>\n";
    html += "<p>REF <code>" + escape_markup(report.ref) + "</code><br>NEW <code>" +
            escape_markup(report.candidate) + "</code></p>\n<table>";
    for (const auto& [name, count] : named_counts(report.counts))
        html += "<tr><th>" + std::string(name) + "</th><td>" + std::to_string(count) + "</td></tr>";
    return html + "</table>\n<p id=\"image-status\"></p>\n";
}

std::string thresholds_table(const CompareThresholds& t) {
    std::string html = "<h2>Thresholds</h2>\n<table><tr><th>kind</th>";
    for (std::string_view key : kToleranceKeys) html += "<th>" + std::string(key) + "</th>";
    html += "</tr>\n";
    for (const auto& [kind, name] : kImageKinds) {
        const Tolerance& v = t.defaults.at(kind);
        html += "<tr><td>" + std::string(name) + "</td>";
        for (double value : {v.warn, v.fail, v.warn_percent, v.fail_percent,
                             static_cast<double>(v.allowed_failures), v.hard_fail, v.relative,
                             static_cast<double>(v.position), v.ssim_min, v.floor})
            html += "<td>" + (value >= 1e29 ? std::string("off") : number(value)) + "</td>";
        html += "</tr>\n";
    }
    html += "</table>\n";
    for (const auto& [camera, kinds] : t.cameras)
        for (const auto& [kind, values] : kinds)
            for (const auto& [key, value] : values)
                html += "<p>camera <b>" + escape_markup(camera) + "</b>: " + image_kind_name(kind) +
                        "." + escape_markup(key) + " = " + number(value) + "</p>\n";
    for (const CompareMask& m : t.masks)
        html +=
            "<p>mask: " +
            (m.image.empty() ? "rectangle " + std::to_string(m.x) + ", " + std::to_string(m.y) +
                                   ", " + std::to_string(m.width) + " x " + std::to_string(m.height)
                             : "image " + escape_markup(m.image)) +
            (m.camera.empty() ? "" : ", camera " + escape_markup(m.camera)) + "</p>\n";
    return html;
}

// Per-frame share of failing pixels, with the fail_percent line.
std::string sequence_plot(const CompareReport& report, const SequenceResult& s) {
    std::vector<std::pair<int, double>> points;
    for (const FileResult& r : report.files)
        if (r.key.camera == s.camera && r.key.pass == s.pass && r.key.format == s.format)
            points.push_back({r.key.frame, r.pixels ? r.pixels->percent_failed() : 0.0});
    std::sort(points.begin(), points.end());
    if (points.size() < 2) return "";
    const double limit = tolerance_for(report.thresholds, s.camera, s.kind).fail_percent;
    double top = limit * 2;
    for (auto& p : points) top = std::max(top, p.second);
    const double first = points.front().first, last = points.back().first;
    const double w = 600, h = 140, left = 50, bottom = 20;
    auto x = [&](double f) {
        return left + (f - first) / std::max(1.0, last - first) * (w - left - 10);
    };
    auto y = [&](double v) { return h - bottom - v / top * (h - bottom - 10); };
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(w) +
                      "\" height=\"" + number(h) +
                      "\" class=\"plot\"><polyline fill=\"none\" stroke=\"#c00\" points=\"";
    for (auto& [frame, value] : points)
        svg += number(x(frame), "%.1f") + "," + number(y(value), "%.1f") + " ";
    svg += "\"/><line x1=\"" + number(left) + "\" x2=\"" + number(w - 10) + "\" y1=\"" +
           number(y(limit), "%.1f") + "\" y2=\"" + number(y(limit), "%.1f") +
           "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>";
    svg += "<text x=\"2\" y=\"14\" font-size=\"11\">" + number(top) + "%</text><text x=\"2\" y=\"" +
           number(h - bottom) + "\" font-size=\"11\">0%</text>";
    svg += "<text x=\"" + number(left) + "\" y=\"" + number(h - 4) + "\" font-size=\"11\">frame " +
           number(first) + "</text><text x=\"" + number(w - 70) + "\" y=\"" + number(h - 4) +
           "\" font-size=\"11\">frame " + number(last) + "</text></svg>";
    return svg;
}

std::string sequences_section(const CompareReport& report) {
    std::string html =
        "<h2>Sequences</h2>\n<table><tr><th>camera</th><th>pass</th><th>format</th>"
        "<th>frames</th><th>worst frame</th><th>% failing there</th><th>flicker</th>"
        "<th>exposure white</th></tr>\n";
    for (const SequenceResult& s : report.sequences)
        html += "<tr><td>" + escape_markup(s.camera) + "</td><td>" + escape_markup(s.pass) +
                "</td><td>" + escape_markup(s.format) + "</td><td>" + std::to_string(s.frames) +
                "</td><td>" + (s.worst_frame ? std::to_string(*s.worst_frame) : "-") + "</td><td>" +
                number(s.worst_percent) + "</td><td>" + number(s.flicker) +
                (s.flicker_frame ? " (frame " + std::to_string(*s.flicker_frame) + ")" : "") +
                "</td><td>" + (s.kind == ImageKind::color_float ? number(s.white) : "-") +
                "</td></tr>\n";
    html += "</table>\n";
    for (const SequenceResult& s : report.sequences) {
        const std::string plot = sequence_plot(report, s);
        if (!plot.empty())
            html += "<h3>" + escape_markup(s.camera.empty() ? s.pass : s.camera + " / " + s.pass) +
                    " (" + escape_markup(s.format) +
                    "): % of pixels failing per frame; dashed: fail_percent</h3>\n" + plot + "\n";
    }
    return html;
}

std::string figures(const FileResult& r) {
    std::string html;
    if (r.pixels) {
        const PixelVerdict& v = *r.pixels;
        html +=
            "<table><tr><th>mean</th><th>RMS</th><th>max (at x, y)</th><th>failing pixels</th>"
            "<th>forgiven by position</th><th>SSIM</th></tr><tr><td>" +
            number(v.stats.mean) + "</td><td>" + number(v.stats.rms) + "</td><td>" +
            number(v.stats.max) + " (" + std::to_string(v.stats.max_x) + ", " +
            std::to_string(v.stats.max_y) + ")</td><td>" + std::to_string(v.pixels_failed) + " (" +
            number(v.percent_failed()) + "%)</td><td>" + std::to_string(v.forgiven_by_position) +
            "</td><td>" + (r.ssim ? number(*r.ssim, "%.5f") : "-") + "</td></tr></table>\n";
    }
    return html;
}

std::string card(const CompareReport& report, const FileResult& r, size_t index, bool with_images) {
    const fs::path dir(report.report_dir);
    auto report_file = [&](const std::string& name) {
        return name.empty() ? "" : (dir / name).string();
    };
    const std::string ref_image = !r.ref_preview.empty()  ? report_file(r.ref_preview)
                                  : r.key.format == "png" ? r.ref_path
                                                          : "";
    const std::string new_image = !r.new_preview.empty()  ? report_file(r.new_preview)
                                  : r.key.format == "png" ? r.new_path
                                                          : "";
    const std::string word = status_word(r);
    std::string html =
        "<div class=\"card " + std::string(outcome_name(r.outcome)) + "\" data-status=\"" + word +
        "\"><h3><span class=\"" + outcome_name(r.outcome) + "\">" + word + "</span> " +
        escape_markup(r.key.label()) + " <small>(" + image_kind_name(r.kind) + ")</small></h3>\n";
    if (!r.reason.empty()) html += "<div class=\"reason\">" + escape_markup(r.reason) + "</div>\n";
    html += figures(r);
    if (!with_images) {
        html += "<p>images: " + escape_markup(r.diff_image) + " " + escape_markup(r.heat_image) +
                "</p></div>\n";
        return html;
    }
    const std::string ref_uri = data_uri(ref_image), new_uri = data_uri(new_image);
    html += "<div class=\"images\">";
    if (!ref_uri.empty() && !new_uri.empty()) {
        const std::string id = "new" + std::to_string(index);
        html +=
            "<figure><div class=\"viewer checker\"><img alt=\"REF\" src=\"" + ref_uri +
            "\"><img class=\"top\" id=\"" + id + "\" alt=\"NEW\" src=\"" + new_uri +
            "\"><span class=\"tag new\">NEW (hover: REF)</span><span class=\"tag "
            "ref\">REF</span></div>"
            "<figcaption>wipe REF | NEW <input type=\"range\" class=\"wipe\" min=\"0\" max=\"100\" "
            "value=\"100\" data-target=\"" +
            id + "\"></figcaption></figure>";
    } else {
        for (auto [label, uri] : {std::pair{"REF", ref_uri}, std::pair{"NEW", new_uri}})
            if (!uri.empty())
                html += "<figure class=\"small checker\"><img alt=\"" + std::string(label) +
                        "\" src=\"" + uri + "\"><figcaption>" + label + "</figcaption></figure>";
    }
    for (auto [label, name] :
         {std::pair{"difference x" + number(report.thresholds.diff_scale), r.diff_image},
          std::pair{std::string(r.kind == ImageKind::color || r.kind == ImageKind::color_float
                                    ? "1 - SSIM"
                                    : "pixels: failed red, forgiven yellow"),
                    r.heat_image}})
        if (!name.empty())
            html += "<figure class=\"small\"><img alt=\"" + escape_markup(label) + "\" src=\"" +
                    data_uri(report_file(name)) + "\"><figcaption>" + escape_markup(label) +
                    "</figcaption></figure>";
    html += "</div></div>\n";
    return html;
}

}  // namespace

std::string report_html(const CompareReport& report) {
    std::string html =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<title>facet compare: " +
        escape_markup(report.candidate) + "</title><style>" + kStyle +
        "</style></head><body>\n<h1>facet compare</h1>\n";
    html += summary(report);
    html += sequences_section(report);
    std::string cards, identical;
    size_t shown = 0, inlined = 0, identical_count = 0;
    for (const FileResult& r : report.files) {
        if (r.status == FileStatus::identical ||
            (r.status == FileStatus::compared && r.outcome == Outcome::pass &&
             r.diff_image.empty())) {
            identical += "<li>" + escape_markup(r.key.label()) + " (" + status_word(r) + ")</li>";
            ++identical_count;
            continue;
        }
        const bool with_images = shown < kCardsWithImages && cards.size() < kInlineBytes;
        if (with_images) ++inlined;
        cards += card(report, r, shown, with_images);
        ++shown;
    }
    html += "<h2>Files that differ (" + std::to_string(shown) + ")</h2>\n<div id=\"files\">" +
            cards + "</div>\n";
    if (shown > inlined)
        html += "<p>Images are shown for the first " + std::to_string(inlined) +
                " files; the rest are in the report's images/ folder.</p>\n";
    html += "<details><summary>" + std::to_string(identical_count) +
            " files identical or passing without difference images</summary><ul>" + identical +
            "</ul></details>\n";
    html += thresholds_table(report.thresholds);
    html += "<script>" + std::string(kScript) + "</script>\n</body></html>\n";
    return html;
}

}  // namespace facet
