#include "output/manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace facet {

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(ExitCode::io_failure, path + ": cannot open manifest");
    try {
        nlohmann::json j = nlohmann::json::parse(in);
        Manifest m;
        m.scene = j.at("scene").get<std::string>();
        m.style = j.at("style").get<std::string>();
        m.width = j.at("size").at(0).get<int>();
        m.height = j.at("size").at(1).get<int>();
        m.threads = j.value("threads", 0);
        for (const auto& f : j.at("frames"))
            m.frames.push_back({f.at("frame").get<int>(), f.value("camera", ""),
                                f.at("render_ms").get<double>(), f.at("encode_ms").get<double>()});
        for (const auto& f : j.at("files"))
            m.files.push_back({f.at("frame").get<int>(), f.value("camera", ""),
                               f.at("pass").get<std::string>(), f.at("format").get<std::string>(),
                               f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
        return m;
    } catch (const nlohmann::json::exception& e) {
        throw Error(ExitCode::invalid_input, path + ": not a facet manifest: " + e.what());
    }
}

void write_manifest(const std::string& path, Manifest manifest) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
        try {
            Manifest old = read_manifest(path);
            if (old.scene == manifest.scene && old.width == manifest.width &&
                old.height == manifest.height) {
                std::set<std::pair<std::string, int>> rendered;
                for (const auto& f : manifest.frames) rendered.insert({f.camera, f.frame});
                for (const auto& f : old.frames)
                    if (!rendered.count({f.camera, f.frame})) manifest.frames.push_back(f);
                for (const auto& f : old.files)
                    if (!rendered.count({f.camera, f.frame})) manifest.files.push_back(f);
            }
        } catch (const Error&) {
            // An unreadable old manifest is replaced.
        }
    }
    std::stable_sort(manifest.frames.begin(), manifest.frames.end(),
                     [](const auto& a, const auto& b) {
                         return std::tie(a.frame, a.camera) < std::tie(b.frame, b.camera);
                     });
    std::stable_sort(manifest.files.begin(), manifest.files.end(),
                     [](const auto& a, const auto& b) {
                         return std::tie(a.frame, a.camera, a.pass, a.format) <
                                std::tie(b.frame, b.camera, b.pass, b.format);
                     });

    nlohmann::ordered_json j;
    j["scene"] = manifest.scene;
    j["style"] = manifest.style;
    j["size"] = {manifest.width, manifest.height};
    j["threads"] = manifest.threads;
    j["frames"] = nlohmann::ordered_json::array();
    for (const auto& f : manifest.frames)
        j["frames"].push_back({{"frame", f.frame},
                               {"camera", f.camera},
                               {"render_ms", f.render_ms},
                               {"encode_ms", f.encode_ms}});
    j["files"] = nlohmann::ordered_json::array();
    for (const auto& f : manifest.files)
        j["files"].push_back({{"frame", f.frame},
                              {"camera", f.camera},
                              {"pass", f.pass},
                              {"format", f.format},
                              {"path", f.path},
                              {"sha256", f.sha256}});
    write_file_atomically(path, j.dump(2) + "\n");
}

}  // namespace facet
