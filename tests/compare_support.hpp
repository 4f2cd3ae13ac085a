#pragma once
// Helpers for the `facet compare` tests: small renders of a test scene into
// folders, edits of their images, and reading the report.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

namespace facet::test {

// `s` as one word for sh: single quotes, each ' written as '\''.
inline std::string shell_quote(const std::string& s) {
    std::string quoted = "'";
    for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// Renders tests/scenes/shapes.yaml at 320x180 into DIR/shapes/. Returns
// the output folder.
inline std::string render_shapes(const std::string& dir, const std::string& extra = "",
                                 const std::string& passes = "color,depth",
                                 const std::string& formats = "png,exr") {
    const RunResult r =
        run_facet("render '" + source_path("tests/scenes/shapes.yaml") + "' --passes " + passes +
                  " --formats " + formats + " -q --out '" + dir + "' " +
                  (extra.find("--size") == std::string::npos ? "--size 320x180 " : "") + extra);
    if (r.exit_code != 0) throw std::runtime_error("render failed: " + r.output);
    return (std::filesystem::path(dir) / "shapes").string();
}

inline nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

// An 8-bit PNG decoded, edited by `edit(samples, channels, width)` and
// written back (to `out`, or over itself).
template <typename Edit>
void edit_png(const std::string& path, const std::string& out, Edit&& edit) {
    DecodedPng png = read_png(path);
    std::vector<uint8_t> bytes(png.samples.begin(), png.samples.end());
    edit(bytes, png.channels, png.width);
    write_bytes(out, encode_png({.width = png.width,
                                 .height = png.height,
                                 .channels = png.channels,
                                 .bit_depth = 8,
                                 .bytes = std::move(bytes)},
                                6));
}

// After a test edits a run's files by hand: the manifest's hashes made to
// match, as if a run had written those bytes (compare refuses files that
// differ from their manifest).
inline void refresh_manifest_hashes(const std::string& dir) {
    nlohmann::json m = read_json(dir + "/manifest.json");
    for (auto& f : m["files"]) {
        const std::string bytes = read_file(dir + "/" + f["path"].get<std::string>());
        f["sha256"] = sha256_hex(bytes.data(), bytes.size());
    }
    write_text(dir + "/manifest.json", m.dump(2));
}

inline void copy_folder(const std::string& from, const std::string& to) {
    std::filesystem::copy(from, to, std::filesystem::copy_options::recursive);
}

// The report's entry for the file whose path ends with `suffix`.
inline nlohmann::json report_file(const nlohmann::json& report, const std::string& label_suffix) {
    for (const auto& f : report["files"]) {
        const std::string path = f["new"].get<std::string>().empty() ? f["ref"].get<std::string>()
                                                                     : f["new"].get<std::string>();
        if (path.size() >= label_suffix.size() &&
            path.compare(path.size() - label_suffix.size(), label_suffix.size(), label_suffix) == 0)
            return f;
    }
    return nullptr;
}

}  // namespace facet::test
