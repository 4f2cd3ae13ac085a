#pragma once
// A whole run: frames rendered in order, each frame's files encoded and
// written on a separate thread while the next frame renders, then the
// manifest.
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "job/output_layout.hpp"
#include "output/run_ledger.hpp"
#include "render/render_plan.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// What the manifest records about how the run was asked for.
struct RunProvenance {
    std::vector<std::string> command_line;
    std::vector<Override> overrides;  // as resolved, in order
    std::string host;                 // where the run ran ("" : this machine's name)
};

// A farm task's share of a job (--chunk, --chunk-frames): the run renders
// RenderOptions::frames, which are part of job_frames, and writes the
// partial manifest named after its frames instead of manifest.json, for
// `facet merge` to combine (docs/farm.md).
struct RunPart {
    std::vector<int> job_frames;
    int chunk_index = -1;  // when given as --chunk I/N
    int chunk_count = 0;
};

struct RenderOptions {
    std::vector<int> frames;  // frames to render; empty means the scene's output.frames
    unsigned threads = 0;     // 0: one per core
    std::string out_dir = "out";
    // Cameras to render, by name; "all" for every one. Empty: the first
    // camera, or all of them when output.path names {camera}.
    std::vector<std::string> cameras;
    // When set (e.g. by Ctrl-C), no new frame starts; frames already rendered
    // are still written, with the manifest, and render_scene then throws.
    const std::atomic<bool>* cancel = nullptr;
    RunProvenance provenance;
    // An output folder whose manifest was made with other settings is
    // refused (exit code 2) unless this is set; then a new manifest starts.
    bool overwrite = false;
    std::optional<RunPart> part;
    // The run is one of several, one per variant (variant_runs): without
    // an output.path its files go to a folder of the variant's name, and an
    // output.path must name {variant} in its manifest's folder.
    bool several_variants = false;
    // Images whose files are all on disk with the SHA-256 a manifest or a
    // journal of the same settings records for them are not rendered again.
    bool skip_existing = false;
    // Called once before the first image: how many will be rendered, and
    // how many were skipped as already written.
    std::function<void(size_t to_render, size_t skipped)> on_plan;
};

struct FrameProgress {
    int frame;
    size_t done;  // images rendered so far (frames x cameras), this one included
    size_t total;
    double render_ms;
    std::string camera;
    size_t cameras;  // cameras in the run
};

// One image's files, written (called from the encoder's threads, one call
// at a time).
struct FrameWritten {
    int frame;
    std::string camera;
    double render_ms, encode_ms;
    std::vector<std::string> files;  // relative to the manifest's folder
};

struct RenderResult {
    std::string output_dir;  // where files and manifest.json went
    std::string manifest_path;
    size_t files_written = 0;
    size_t images_skipped = 0;  // skip_existing
};

// The indices into scene.cameras that a run renders (see RenderOptions::cameras).
// Throws facet::Error (invalid_input) for an unknown name.
std::vector<size_t> select_cameras(const SceneDesc& scene, const std::vector<std::string>& names);

// The variants a run of the scene renders, each a run of its own with a
// manifest of its own: every one the scene's models declare (`declared`,
// from scene_variants) for `variant: all`, or when output.path names
// {variant} and the scene chooses none; the scene's `variant:` alone; none
// when it chooses none. Throws facet::Error (invalid_input) as
// check_variant does, and for a variant name that cannot name a folder.
std::vector<std::string> select_variants(const SceneDesc& scene,
                                         const std::vector<std::string>& declared);

// The scene as each run renders it: a copy with `variant` set to each of
// select_variants' names, or the scene itself when the choice is none or
// one. The scene's mesh files are read into `loaded` (for build_world) to
// learn their variants when the scene chooses any.
std::vector<SceneDesc> variant_runs(const SceneDesc& scene, unsigned load_threads,
                                    LoadedMeshes& loaded);

// One job's plan, settled once and handed to every step that needs it
// (the checks, --dry-run, the farm's job files, the render): the frames and
// cameras this run renders, where its files go and what they are named,
// and what its manifest claims.
struct JobPlan {
    std::vector<int> frames;      // this run's
    std::vector<size_t> cameras;  // indices into the scene's
    OutputLayout layout;
    std::string output_dir;  // the manifest's folder
    LedgerRequest ledger;    // the manifest's header and name
};

// Plans the job and checks it without rendering: the camera choice, the
// output names (template syntax, two images to one file) and that an
// existing manifest in the output folder has the same settings (or
// options.overwrite).
JobPlan plan_job(const SceneDesc& scene, const RenderOptions& options);

// The files the job writes, in the order it writes them (frame, camera,
// pass, format), then the manifest (or the part's partial manifest):
// paths under options.out_dir. For --dry-run and the farm's job files.
std::vector<std::string> planned_files(const SceneDesc& scene, const JobPlan& plan);

// `plan` and `render_plan` are the run's, made once: the render's memory
// is checked, and its frames drawn, from them.
RenderResult render_scene(const SceneDesc& scene, const World& world, const RenderOptions& options,
                          const JobPlan& plan, RenderPlan render_plan,
                          const std::function<void(const FrameProgress&)>& on_frame,
                          const std::function<void(const FrameWritten&)>& on_written = nullptr);

// The same, planning the job and the render itself (tests, the bench, the
// preview).
RenderResult render_scene(const SceneDesc& scene, const World& world, const RenderOptions& options,
                          const std::function<void(const FrameProgress&)>& on_frame,
                          const std::function<void(const FrameWritten&)>& on_written = nullptr);

}  // namespace facet
