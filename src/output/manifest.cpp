#include "output/manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/input_file.hpp"
#include "core/plain_text.hpp"
#include "core/sha256.hpp"
#include "output/atomic_file.hpp"
#include "output/passes.hpp"

namespace facet {
namespace {

using Json = nlohmann::ordered_json;

// Version 1 kept timings in each frame entry and had no provenance;
// version 2 moved timings to their own block so identical runs list
// identical frames and files.
constexpr int kManifestVersion = 2;

// A whole number that fits Int: nlohmann's get<int> of 1e62, or of an
// integer past int's range, is undefined or wraps, and a hand-edited or
// damaged manifest may hold either.
template <typename Int>
Int whole(const nlohmann::json& v, const char* key) {
    if (v.is_number_unsigned()) {
        if (v.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<Int>::max()))
            return static_cast<Int>(v.get<uint64_t>());
    } else if (v.is_number_integer()) {
        const int64_t i = v.get<int64_t>();
        if (std::cmp_greater_equal(i, std::numeric_limits<Int>::min()) &&
            std::cmp_less_equal(i, std::numeric_limits<Int>::max()))
            return static_cast<Int>(i);
    }
    throw nlohmann::json::other_error::create(
        501, std::string("'") + key + "' must be a whole number in range, not " + v.dump(),
        nullptr);
}

template <typename Int>
Int whole_or(const nlohmann::json& object, const char* key, Int fallback) {
    const auto it = object.find(key);
    return it == object.end() ? fallback : whole<Int>(*it, key);
}

// A manifest's values are checked as they are read, for every reader
// (render's resume, compare, merge, video): a value no facet writes is an
// error naming it, exit 2.
[[noreturn]] void invalid(const std::string& what) {
    throw nlohmann::json::other_error::create(501, what, nullptr);
}

// The checks of one listed file: what facet writes, and a path that stays
// in the manifest's folder.
void check_listed_file(const ManifestFile& f) {
    if (f.pass != "multilayer" && !pass_from_name(f.pass))
        invalid("pass '" + text_for_message(f.pass) + "' is not one facet writes");
    if (f.format != "png" && f.format != "exr")
        invalid("format '" + text_for_message(f.format) + "' is not png or exr");
    const std::filesystem::path path = std::filesystem::path(f.path).lexically_normal();
    if (path.empty() || path.is_absolute() || *path.begin() == ".." ||
        line_breaking_character(f.path))
        invalid("path '" + text_for_message(f.path) + "' leaves the manifest's folder");
}

// The whole manifest: a size facet can render, a frame rate, and no file
// or image listed twice.
void check_manifest(const Manifest& m) {
    if (m.width < 1 || m.height < 1 || m.width > 16384 || m.height > 16384)
        invalid("size [" + std::to_string(m.width) + ", " + std::to_string(m.height) +
                "] is not 1 to 16384 pixels a side");
    if (!(m.fps > 0 && m.fps <= 1000))
        invalid("fps " + std::to_string(m.fps) + " is not above 0 and at most 1000");
    std::set<std::string> paths;
    std::set<std::tuple<int, std::string, std::string, std::string>> images;
    for (const ManifestFile& f : m.files) {
        if (!paths.insert(std::filesystem::path(f.path).lexically_normal().string()).second)
            invalid("file '" + text_for_message(f.path) + "' is listed twice");
        if (!images.insert({f.frame, f.camera, f.pass, f.format}).second)
            invalid("frame " + std::to_string(f.frame) + " of camera '" +
                    text_for_message(f.camera) + "' has two " + f.pass + " " + f.format + " files");
    }
}

void read_timings(const nlohmann::json& t, Manifest& m) {
    m.threads = whole_or(t, "threads", 0);
    m.host = t.value("host", "");
    m.command_line = t.value("command_line", std::vector<std::string>{});
    std::map<std::pair<std::string, int>, const nlohmann::json*> timings;
    for (const auto& entry : t.at("frames"))
        timings[{entry.value("camera", ""), whole<int>(entry.at("frame"), "frame")}] = &entry;
    for (ManifestFrame& f : m.frames)
        if (auto it = timings.find({f.camera, f.frame}); it != timings.end()) {
            f.render_ms = it->second->value("render_ms", 0.0);
            f.encode_ms = it->second->value("encode_ms", 0.0);
            f.host = it->second->value("host", "");
        }
    for (const auto& p : t.value("parts", nlohmann::json::array()))
        m.parts.push_back({p.at("name").get<std::string>(), p.value("host", ""),
                           p.value("commit", ""), whole_or(p, "threads", 0),
                           p.value("command_line", std::vector<std::string>{})});
}

// Frame lists are stored as range text ("1-48"), which reads back exactly.
std::vector<int> frames_field(const nlohmann::json& j, const char* key) {
    try {
        return parse_frame_ranges(j.at(key).get<std::string>());
    } catch (const Error& e) {
        throw nlohmann::json::other_error::create(501, std::string(key) + ": " + e.what(), nullptr);
    }
}

void read_job(const nlohmann::json& j, Manifest& m) {
    if (j.contains("job"))
        m.job = ManifestJob{frames_field(j["job"], "frames"),
                            j["job"].at("cameras").get<std::vector<std::string>>()};
    if (j.contains("part")) {
        const auto& p = j["part"];
        m.part = ManifestPart{frames_field(p, "frames"), whole_or(p, "chunk_index", -1),
                              whole_or(p, "chunk_count", 0)};
    }
}

Json job_json(const Manifest& m) {
    Json job;
    job["frames"] = format_frame_ranges(m.job->frames);
    job["cameras"] = m.job->cameras;
    return job;
}

Json model_json(const ManifestModel& model) {
    Json options = Json::object();
    for (const auto& [name, value] : model.options) options[name] = value;
    return {{"file", model.file}, {"sha256", model.sha256}, {"options", options}};
}

ManifestModel read_model(const nlohmann::json& j) {
    ManifestModel model;
    model.file = j.at("file").get<std::string>();
    model.sha256 = j.at("sha256").get<std::string>();
    const nlohmann::json options = j.value("options", nlohmann::json::object());
    for (const auto& [name, value] : options.items())
        model.options.emplace_back(name, value.get<std::string>());
    return model;
}

Json part_json(const ManifestPart& part) {
    Json j;
    j["frames"] = format_frame_ranges(part.frames);
    if (part.chunk_index >= 0) {
        j["chunk_index"] = part.chunk_index;
        j["chunk_count"] = part.chunk_count;
    }
    return j;
}

Json timings_json(const Manifest& manifest) {
    Json timings;
    timings["threads"] = manifest.threads;
    timings["host"] = manifest.host;
    timings["command_line"] = manifest.command_line;
    timings["frames"] = Json::array();
    for (const auto& f : manifest.frames)
        timings["frames"].push_back({{"frame", f.frame},
                                     {"camera", f.camera},
                                     {"host", f.host},
                                     {"render_ms", f.render_ms},
                                     {"encode_ms", f.encode_ms}});
    if (!manifest.parts.empty()) {
        timings["parts"] = Json::array();
        for (const auto& p : manifest.parts)
            timings["parts"].push_back({{"name", p.name},
                                        {"host", p.host},
                                        {"commit", p.facet_commit},
                                        {"threads", p.threads},
                                        {"command_line", p.command_line}});
    }
    return timings;
}

}  // namespace

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(ExitCode::io_failure, path + ": cannot open manifest");
    std::stringstream text;
    text << in.rdbuf();
    return parse_manifest(text.str(), path);
}

namespace {

// A JSON library message in the manifest's terms: its bracketed code
// dropped, "key 'x' not found" as "'x' is missing".
std::string plain_json_error(const nlohmann::json::exception& e) {
    std::string text = e.what();
    if (const size_t bracket = text.find("] ");
        text.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
        text.erase(0, bracket + 2);
    const std::string key = "key '";
    if (text.rfind(key, 0) == 0 && text.size() > key.size() + 11 &&
        text.compare(text.size() - 11, 11, "' not found") == 0)
        return "'" + text.substr(key.size(), text.size() - key.size() - 11) + "' is missing";
    if (text.find("cannot use at() with") != std::string::npos ||
        text.find("cannot use operator[]") != std::string::npos)
        return "an entry is " + text.substr(text.rfind(' ') + 1) + " where an object belongs";
    return text;
}

}  // namespace

Manifest parse_manifest(const std::string& text, const std::string& where) {
    const std::string& path = where;
    std::string entry;  // the part being read, for messages: "files[3]"
    try {
        nlohmann::json j = nlohmann::json::parse(text);
        if (!j.is_object())
            throw Error(ExitCode::invalid_input,
                        path + ": not a facet manifest: not a JSON object");
        Manifest m;
        if (j.contains("facet")) {
            m.facet_version = j["facet"].value("version", "");
            m.facet_commit = j["facet"].value("commit", "");
            m.facet_build = j["facet"].value("build", "");
        }
        entry = "manifest_version";
        if (const int version = whole_or(j, "manifest_version", 1);
            version < 1 || version > kManifestVersion)
            invalid("version " + std::to_string(version) + " is not one this facet reads (1 to " +
                    std::to_string(kManifestVersion) + "): written by a newer facet?");
        entry = "";
        m.scene = j.at("scene").get<std::string>();
        m.style = j.at("style").get<std::string>();
        m.variant = j.value("variant", "");
        m.width = whole<int>(j.at("size").at(0), "size");
        m.height = whole<int>(j.at("size").at(1), "size");
        m.output_template = j.value("output_template", "");
        m.scene_sha256 = j.value("scene_sha256", "");
        entry = "model";
        if (j.contains("model")) m.model = read_model(j["model"]);
        entry = "";
        m.fps = j.value("fps", 24.0);
        if (j.contains("display")) {
            m.display.exposure = j["display"].value("exposure", 0.0f);
            const std::string tonemap = j["display"].value("tonemap", "none");
            const std::optional<Tonemap> curve = value_of(kTonemaps, tonemap);
            if (!curve) invalid("tonemap '" + text_for_message(tonemap) + "' is not one facet has");
            m.display.tonemap = *curve;
        }
        for (const auto& o : j.value("overrides", nlohmann::json::array()))
            m.overrides.push_back({o.at("key").get<std::string>(), o.at("value").get<std::string>(),
                                   o.value("origin", "")});
        entry = "frames";
        for (const auto& f : j.at("frames")) {
            entry = "frames[" + std::to_string(m.frames.size()) + "]";
            m.frames.push_back({whole<int>(f.at("frame"), "frame"), f.value("camera", ""),
                                f.value("render_ms", 0.0), f.value("encode_ms", 0.0), ""});
        }
        entry = "files";
        for (const auto& f : j.at("files")) {
            entry = "files[" + std::to_string(m.files.size()) + "]";
            m.files.push_back({whole<int>(f.at("frame"), "frame"), f.value("camera", ""),
                               f.at("pass").get<std::string>(), f.at("format").get<std::string>(),
                               f.at("path").get<std::string>(), f.at("sha256").get<std::string>(),
                               f.value("style", m.style)});
            check_listed_file(m.files.back());
        }
        entry = "ids";
        for (const char* pass : {"object_id", "material_id"})
            for (const auto& id :
                 j.value("ids", nlohmann::json::object()).value(pass, nlohmann::json::array()))
                m.ids.push_back({pass, whole<uint32_t>(id.at("id"), "id"),
                                 id.at("name").get<std::string>(), id.value("object", "")});
        entry = "";
        m.threads = whole_or(j, "threads", 0);
        entry = "job or part";
        read_job(j, m);
        entry = "timings";
        if (j.contains("timings")) read_timings(j["timings"], m);
        entry = "";
        check_manifest(m);
        return m;
    } catch (const nlohmann::json::exception& e) {
        throw Error(ExitCode::invalid_input,
                    path + ": not a facet manifest: " + (entry.empty() ? "" : entry + ": ") +
                        plain_json_error(e));
    }
}

std::string manifest_file_path(const std::string& folder, const std::string& relative) {
    const std::filesystem::path path = std::filesystem::path(relative).lexically_normal();
    if (path.empty() || path.is_absolute() || *path.begin() == "..")
        throw Error(ExitCode::invalid_input,
                    (std::filesystem::path(folder) / "manifest.json").string() + ": file path '" +
                        relative + "' leaves the manifest's folder");
    return (std::filesystem::path(folder) / path).string();
}

std::string listed_file_problem(const std::string& folder, const ManifestFile& file) {
    try {
        const std::string path = manifest_file_path(folder, file.path);
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return "missing";
        if (sha256_hex(read_input_file(path, "output file")) != file.sha256)
            return "its SHA-256 is not the one recorded: the file changed after it was written";
        return "";
    } catch (const Error& e) {
        return e.what();
    }
}

std::string manifest_settings_difference(const Manifest& a, const Manifest& b) {
    auto differ = [](const std::string& what, const std::string& there, const std::string& now) {
        return what + ": '" + there + "' there, '" + now + "' now";
    };
    if (a.scene != b.scene) return differ("scene", a.scene, b.scene);
    if (a.style != b.style) return differ("style", a.style, b.style);
    if (a.variant != b.variant) return differ("variant", a.variant, b.variant);
    if (a.width != b.width || a.height != b.height)
        return differ("size", std::to_string(a.width) + "x" + std::to_string(a.height),
                      std::to_string(b.width) + "x" + std::to_string(b.height));
    // A version-1 manifest recorded no template or scene hash: not a difference.
    if (!a.output_template.empty() && a.output_template != b.output_template)
        return differ("output template", a.output_template, b.output_template);
    if (a.model.has_value() != b.model.has_value())
        return std::string("the scene is ") + (a.model ? "" : "not ") +
               "built around a model there, and " + (b.model ? "" : "not ") + "now";
    // A model's turntable: its scene text follows from the model (and from
    // facet's version), so the model is the change to name.
    if (a.model && a.model->sha256 != b.model->sha256)
        return "the model file changed since the manifest was written";
    if (!a.scene_sha256.empty() && !b.scene_sha256.empty() && a.scene_sha256 != b.scene_sha256)
        return a.model ? "facet's turntable scene changed since the manifest was written"
                       : "the scene file changed since the manifest was written";
    // The overrides as a set: order does not matter, the last value of a key
    // wins, and settings that change no pixel are left out, as is the
    // variant, compared above as the one drawn (`all` is each in turn).
    auto overrides = [](const Manifest& m) {
        std::map<std::string, std::string> effective;
        for (const ManifestOverride& o : m.overrides)
            if (o.key != "assets.allow_paths_outside" && o.key != "variant")
                effective[o.key] = o.value;
        std::string text;
        for (const auto& [key, value] : effective)
            text += (text.empty() ? "" : " ") + key + "=" + value;
        return text.empty() ? std::string("none") : text;
    };
    if (overrides(a) != overrides(b)) return differ("overrides", overrides(a), overrides(b));
    return "";
}

std::string manifest_json(Manifest manifest, bool indented) {
    std::stable_sort(manifest.frames.begin(), manifest.frames.end(),
                     [](const auto& a, const auto& b) {
                         return std::tie(a.frame, a.camera) < std::tie(b.frame, b.camera);
                     });
    std::stable_sort(manifest.files.begin(), manifest.files.end(),
                     [](const auto& a, const auto& b) {
                         return std::tie(a.frame, a.camera, a.pass, a.format) <
                                std::tie(b.frame, b.camera, b.pass, b.format);
                     });

    Json j;
    j["manifest_version"] = kManifestVersion;
    j["facet"] = {{"version", manifest.facet_version},
                  {"commit", manifest.facet_commit},
                  {"build", manifest.facet_build}};
    j["scene"] = manifest.scene;
    j["scene_sha256"] = manifest.scene_sha256;
    if (manifest.model) j["model"] = model_json(*manifest.model);
    j["style"] = manifest.style;
    if (!manifest.variant.empty()) j["variant"] = manifest.variant;
    j["size"] = {manifest.width, manifest.height};
    j["fps"] = manifest.fps;
    j["display"] = {{"exposure", manifest.display.exposure},
                    {"tonemap", name_of(kTonemaps, manifest.display.tonemap)}};
    j["output_template"] = manifest.output_template;
    j["overrides"] = Json::array();
    for (const ManifestOverride& o : manifest.overrides)
        j["overrides"].push_back({{"key", o.key}, {"value", o.value}, {"origin", o.origin}});
    if (manifest.job) j["job"] = job_json(manifest);
    if (manifest.part) j["part"] = part_json(*manifest.part);
    j["frames"] = Json::array();
    for (const auto& f : manifest.frames)
        j["frames"].push_back({{"frame", f.frame}, {"camera", f.camera}});
    j["files"] = Json::array();
    for (const auto& f : manifest.files)
        j["files"].push_back({{"frame", f.frame},
                              {"camera", f.camera},
                              {"pass", f.pass},
                              {"format", f.format},
                              {"style", f.style},
                              {"path", f.path},
                              {"sha256", f.sha256}});
    if (!manifest.ids.empty()) {
        Json ids = Json::object();
        for (const ManifestId& id : manifest.ids) {
            Json entry = {{"id", id.id}, {"name", id.name}};
            if (!id.object.empty()) entry["object"] = id.object;
            ids[id.pass].push_back(entry);
        }
        j["ids"] = ids;
    }
    j["timings"] = timings_json(manifest);
    return indented ? j.dump(2) + "\n" : j.dump() + "\n";
}

void write_manifest(const std::string& path, Manifest manifest, bool merge) {
    std::error_code ec;
    if (merge && std::filesystem::exists(path, ec)) {
        try {
            Manifest old = read_manifest(path);
            if (manifest_settings_difference(old, manifest).empty()) {
                std::set<std::pair<std::string, int>> rendered;
                for (const auto& f : manifest.frames) rendered.insert({f.camera, f.frame});
                for (const auto& f : old.frames)
                    if (!rendered.count({f.camera, f.frame})) manifest.frames.push_back(f);
                // An old entry whose file this run has just rewritten (a name
                // without {camera} or {frame}) would state a stale hash.
                std::set<std::string> written;
                for (const auto& f : manifest.files) written.insert(f.path);
                for (const auto& f : old.files)
                    if (!rendered.count({f.camera, f.frame}) && !written.count(f.path))
                        manifest.files.push_back(f);
                if (!manifest.job) manifest.job = old.job;
                if (manifest.parts.empty()) manifest.parts = old.parts;
            }
        } catch (const Error&) {
            // An unreadable old manifest is replaced.
        }
    }
    write_file_atomically(path, manifest_json(manifest, true));
}

std::string partial_manifest_name(int first, int last) {
    auto padded = [](int frame) {
        std::string digits = std::to_string(frame < 0 ? -static_cast<long long>(frame) : frame);
        if (digits.size() < 4) digits.insert(0, 4 - digits.size(), '0');
        return (frame < 0 ? "m" : "") + digits;  // "m0005": no second '-' in the name
    };
    return "manifest.part-" + padded(first) + "-" + padded(last) + ".json";
}

bool is_partial_manifest_name(const std::string& file_name) {
    const std::string prefix = "manifest.part-", suffix = ".json";
    return file_name.size() > prefix.size() + suffix.size() &&
           file_name.compare(0, prefix.size(), prefix) == 0 &&
           file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace facet
