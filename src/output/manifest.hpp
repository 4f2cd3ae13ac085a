#pragma once
// manifest.json: what a run wrote, so tools and tests find outputs without
// guessing file names (docs/scene-format.md, "manifest.json").
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/display_transform.hpp"

namespace facet {

struct ManifestFrame {
    int frame;
    std::string camera;
    double render_ms;
    double encode_ms;
    std::string host;  // that rendered it ("" in manifests from before render farms)
};

struct ManifestFile {
    int frame;
    std::string camera;
    std::string pass;    // output/passes.hpp, or multilayer
    std::string format;  // png, exr
    std::string path;    // relative to the manifest
    std::string sha256;
    std::string style;  // the style the file was rendered with
};

// What a job that was cut into parts (render farm chunks) renders as a
// whole, so that `facet merge` can tell a complete set of parts from an
// incomplete one.
struct ManifestJob {
    std::vector<int> frames;  // every part's, ascending
    std::vector<std::string> cameras;
};

// The part of a job a partial manifest covers.
struct ManifestPart {
    std::vector<int> frames;  // this part's: the frames it was asked to render
    int chunk_index = -1;     // --chunk I/N (numbered from 0); -1 when given by frames
    int chunk_count = 0;
};

// Where each part of a merged manifest came from (its timings block).
struct ManifestPartRecord {
    std::string name;  // the partial manifest's file name
    std::string host, facet_commit;
    int threads = 0;
    std::vector<std::string> command_line;
};

// A command-line override as the run resolved it.
// What an id in the object_id or material_id pass stands for.
struct ManifestId {
    std::string pass;  // object_id, material_id
    uint32_t id;
    std::string name;    // the object's, or the material's
    std::string object;  // material ids: the object the material belongs to
};

struct ManifestOverride {
    std::string key, value, origin;
};

// A scene facet built around a model (`facet render MODEL`): the model,
// its SHA-256 and the turntable's options (docs/turntables.md).
struct ManifestModel {
    std::string file;    // relative to the manifest's folder
    std::string sha256;  // of the model file: an edited model is other settings
    std::vector<std::pair<std::string, std::string>> options;  // name, value
};

struct Manifest {
    // Provenance: the build that wrote it (core/version.hpp).
    std::string facet_version, facet_commit, facet_build;
    std::string scene;  // relative to the manifest's folder
    // Of the scene file's bytes (an edited scene is other settings); of the
    // text facet made, for a scene built around a model.
    std::string scene_sha256;
    std::optional<ManifestModel> model;  // set when the scene was built around a model
    std::string style;
    // The KHR_materials_variants variant the models were drawn in ("" for
    // their default materials): a run of `variant: all` is one per variant.
    std::string variant;
    int width = 0, height = 0;
    double fps = 24;           // the scene's, for movies made from the files
    DisplayTransform display;  // the scene's exposure and tone curve, for movies from EXR
    std::string output_template;
    std::vector<ManifestOverride> overrides;
    std::vector<ManifestFrame> frames;
    std::vector<ManifestFile> files;
    std::vector<ManifestId> ids;       // when an id pass is written
    std::optional<ManifestJob> job;    // farm jobs: the whole job (partial and merged manifests)
    std::optional<ManifestPart> part;  // partial manifests only
    // The timings block: what differs between identical runs.
    int threads = 0;
    std::string host;                       // of the run that wrote the manifest last
    std::vector<std::string> command_line;  // of the run that wrote the manifest last
    std::vector<ManifestPartRecord> parts;  // merged manifests: one per part
};

// "manifest.part-0001-0008.json": the partial manifest of a part whose
// frames run from `first` to `last` (padded as file names are).
std::string partial_manifest_name(int first, int last);
bool is_partial_manifest_name(const std::string& file_name);

// What must be equal for two runs to share a manifest: scene (path and
// content, and a model's content), style, variant, size, output template
// and overrides (as a set, without ones that change no pixel). "" when they are; else the first
// difference, e.g. "style: 'toon' there, 'wireframe' now".
std::string manifest_settings_difference(const Manifest& existing, const Manifest& run);

// Writes the manifest atomically. With `merge`, entries of an existing
// manifest with the same settings, for (camera, frame) pairs this run did
// not render, are kept, so a sequence rendered in pieces (e.g. on several
// machines in turn) ends with one complete manifest. An existing manifest
// with other settings is never merged (render refuses first, unless told
// to overwrite).
void write_manifest(const std::string& path, Manifest manifest, bool merge = true);

// Reads and checks a manifest: every reader (render resuming a run,
// compare, merge, video) goes through it, so all refuse the same manifests
// with exit 2 naming the value: one that is not facet's (not JSON, or
// without its keys), a version newer than this facet reads, a size outside
// 1 to 16384, an fps outside (0, 1000], a pass or format facet does not
// write, a path that leaves the folder, and a file or an image listed
// twice.
Manifest read_manifest(const std::string& path);

// The manifest as JSON text, frames and files sorted: indented (the file),
// or on one line ending in a newline (journal lines).
std::string manifest_json(Manifest manifest, bool indented);
// Reads manifest JSON text; `where` names it in errors (invalid_input).
Manifest parse_manifest(const std::string& text, const std::string& where);

// The file a manifest in `folder` lists as `relative`. A manifest may have
// been edited by hand: a path that leaves the folder (absolute, or through
// "..") throws Error(invalid_input), so no reader touches files elsewhere.
// (read_manifest refuses such a manifest already.)
std::string manifest_file_path(const std::string& folder, const std::string& relative);

// Whether the file a manifest in `folder` lists is on disk with the SHA-256
// the manifest records for it: "" when it is, else why not ("missing",
// "its SHA-256 is not the one recorded: the file changed after it was
// written", or why it cannot be read, its path included).
std::string listed_file_problem(const std::string& folder, const ManifestFile& file);

}  // namespace facet
