#include "job/render_job.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <set>

#include "core/elapsed.hpp"
#include "core/error.hpp"
#include "core/host_name.hpp"
#include "core/plain_text.hpp"
#include "core/thread_pool.hpp"
#include "core/version.hpp"
#include "job/frame_encoder.hpp"
#include "job/pass_files.hpp"
#include "job/render_memory.hpp"
#include "output/atomic_file.hpp"
#include "output/manifest.hpp"
#include "output/output_path.hpp"
#include "output/run_ledger.hpp"
#include "render/frame_renderer.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// The manifest's header for this run: everything but the frames and files.
Manifest manifest_header(const SceneDesc& scene, const OutputLayout& layout,
                         const RenderOptions& options, const std::string& output_dir) {
    Manifest m;
    const BuildInfo& build = build_info();
    m.facet_version = build.version;
    m.facet_commit = build.commit;
    m.facet_build = build.build_type + ", " + build.simd + ", " + build.compiler;
    // Relative to the manifest, so the record does not depend on where facet ran.
    std::error_code ec;
    // Normalised, so "./scenes/a.yaml" and "scenes/a.yaml" are the same scene.
    // Absolute first: weakly_canonical leaves a relative path relative when
    // its first folder does not exist yet (a first run into a new -o).
    const auto scene_path =
        std::filesystem::weakly_canonical(std::filesystem::absolute(scene.path), ec);
    const auto folder =
        std::filesystem::weakly_canonical(std::filesystem::absolute(output_dir), ec);
    m.scene = scene_path.lexically_relative(folder).generic_string();
    if (m.scene.empty()) m.scene = scene.path;
    if (scene.built) {
        // A scene facet built around a model: its text, the model and the
        // options it was built with (docs/turntables.md).
        m.scene_sha256 = scene.built->text_sha256;
        m.model = ManifestModel{m.scene, scene.built->model_sha256, scene.built->options};
    } else {
        m.scene_sha256 = scene.sha256;  // of the bytes that were read, not read again
    }
    m.style = scene.style.name;
    m.variant = scene.variant;
    m.width = scene.output.width;
    m.height = scene.output.height;
    m.fps = scene.output.fps;
    m.display = scene.output.display;
    m.output_template = layout.template_text;
    for (const Override& o : options.provenance.overrides)
        m.overrides.push_back({o.path, o.value, o.origin});
    m.command_line = options.provenance.command_line;
    m.host = options.provenance.host.empty() ? host_name() : options.provenance.host;
    return m;
}

// What the run claims in its manifest's folder: the manifest it writes
// (a part's partial manifest, or manifest.json) and its settings.
LedgerRequest ledger_request(const SceneDesc& scene, const OutputLayout& layout,
                             const RenderOptions& options, const std::string& output_dir,
                             const std::vector<int>& frames, const std::vector<size_t>& cameras) {
    LedgerRequest request;
    request.folder = output_dir;
    request.manifest_name = "manifest.json";
    request.header = manifest_header(scene, layout, options, output_dir);
    request.overwrite = options.overwrite;
    if (options.part) {
        ManifestJob job;
        job.frames = options.part->job_frames;
        for (size_t c : cameras) job.cameras.push_back(scene.cameras[c].name);
        request.header.job = job;
        request.header.part =
            ManifestPart{frames, options.part->chunk_index, options.part->chunk_count};
        if (!frames.empty())
            request.manifest_name = partial_manifest_name(frames.front(), frames.back());
    }
    return request;
}

}  // namespace

std::vector<size_t> select_cameras(const SceneDesc& scene, const std::vector<std::string>& names) {
    const bool template_names_cameras =
        scene.output.path && scene.output.path->find("{camera}") != std::string::npos;
    std::vector<size_t> selected;
    const bool all = std::find(names.begin(), names.end(), "all") != names.end();
    if (all || (names.empty() && template_names_cameras)) {
        for (size_t i = 0; i < scene.cameras.size(); ++i) selected.push_back(i);
        return selected;
    }
    if (names.empty()) return {0};
    for (const std::string& name : names) {
        auto it = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                               [&](const CameraDesc& c) { return c.name == name; });
        if (it == scene.cameras.end()) {
            const std::string list =
                comma_list(scene.cameras, [](const CameraDesc& c) { return c.name; });
            throw Error(ExitCode::invalid_input, "--camera " + name + ": " + scene.path +
                                                     " has no camera named '" + name +
                                                     "' (cameras: " + list + ", or all)");
        }
        const size_t index = static_cast<size_t>(it - scene.cameras.begin());
        if (std::find(selected.begin(), selected.end(), index) == selected.end())
            selected.push_back(index);
    }
    return selected;
}

namespace {

// Whether output.path names {variant}: a run of each variant when the
// scene chooses none, as {camera} is for cameras.
bool template_names_variant(const SceneDesc& scene) {
    return scene.output.path && scene.output.path->find("{variant}") != std::string::npos;
}

// Every variant, each to name a folder (`at` is where `all` was asked for).
const std::vector<std::string>& all_variants(const std::vector<std::string>& declared,
                                             const SourceLocation& at, const std::string& key) {
    for (const std::string& name : declared)
        if (const auto problem = line_breaking_character(name))
            fail_input(at, key,
                       "the variant '" + text_for_message(name) + "' holds " + *problem +
                           ", which no folder name may hold; choose the others by name");
    return declared;
}

}  // namespace

std::vector<std::string> select_variants(const SceneDesc& scene,
                                         const std::vector<std::string>& declared) {
    if (scene.variant.empty()) {
        if (!template_names_variant(scene)) return {};
        if (declared.empty())
            fail_input(scene.output.path_at, "output.path",
                       "{variant} names a variant, and no model in the scene declares variants "
                       "(KHR_materials_variants)");
        return all_variants(declared, scene.output.path_at, "output.path");
    }
    check_variant(scene, declared, false);
    if (scene.variant != kAllVariants) return {scene.variant};
    return all_variants(declared, scene.variant_at, "variant");
}

std::vector<SceneDesc> variant_runs(const SceneDesc& scene, unsigned load_threads,
                                    LoadedMeshes& loaded) {
    if (scene.variant.empty() && !template_names_variant(scene)) return {scene};
    std::vector<SceneDesc> runs;
    for (const std::string& name :
         select_variants(scene, scene_variants(scene, load_threads, loaded))) {
        runs.push_back(scene);
        runs.back().variant = name;
    }
    return runs;
}

namespace {

// The template of a run without output.path: a folder per camera when it
// renders several, inside a folder per variant when it is one of several
// variants' runs.
std::string default_output_template(bool several_cameras, bool several_variants) {
    if (several_variants)
        return several_cameras ? kMultiVariantCameraOutputTemplate : kMultiVariantOutputTemplate;
    return several_cameras ? kMultiCameraOutputTemplate : kDefaultOutputTemplate;
}

OutputLayout plan_outputs(const SceneDesc& scene, const std::vector<size_t>& cameras,
                          const std::vector<int>& frames, const std::string& root,
                          bool several_variants) {
    const OutputDesc& out = scene.output;
    std::string text =
        out.path.value_or(default_output_template(cameras.size() > 1, several_variants));
    OutputLayout layout;
    layout.root = root;
    layout.template_text = text;
    std::vector<std::string> camera_names, passes, exts;
    for (size_t c : cameras) camera_names.push_back(scene.cameras[c].name);
    layout.frame_files = frame_files(out);
    for (const PassFile& file : layout.frame_files) {
        if (std::find(passes.begin(), passes.end(), file.pass) == passes.end())
            passes.push_back(file.pass);
        if (std::find(exts.begin(), exts.end(), file.format) == exts.end())
            exts.push_back(file.format);
    }
    try {
        layout.names = parse_output_template(text);
        if (several_variants &&
            !manifest_directory_names_variant(layout.names, cameras.size() == 1))
            throw Error(ExitCode::invalid_input,
                        "output template '" + text +
                            "': each variant's run has a manifest of its own, so {variant} must "
                            "name a folder before any other placeholder but {scene}, as in "
                            "{scene}/{variant}/{pass}.{frame}.{ext}");
        if (scene.variant.empty() && layout.names.uses(Placeholder::variant))
            throw Error(ExitCode::invalid_input,
                        "output template '" + text +
                            "': {variant} names a variant, and the run draws none (give "
                            "--variant NAME or all, or `variant:`)");
        check_unique_outputs(layout.names, scene.name, camera_names, passes, exts, frames,
                             scene.variant);
        layout.manifest_dir = manifest_directory(
            layout.names, file_fields(scene, camera_names.front(), "", 0, ""), cameras.size() == 1);
    } catch (const Error& e) {
        if (out.path) fail_input(out.path_at, "output.path", e.what());
        throw;
    }
    return layout;
}

}  // namespace

namespace {

// The frames this run renders, and the frames whose names must not clash:
// the whole job's for a part, so two parts never write one file.
const std::vector<int>& run_frames(const SceneDesc& scene, const RenderOptions& options) {
    return options.frames.empty() ? scene.output.frames : options.frames;
}
const std::vector<int>& named_frames(const SceneDesc& scene, const RenderOptions& options) {
    return options.part ? options.part->job_frames : run_frames(scene, options);
}

// One image's files: their names under the output folder, in the order
// they are written (pass, then format).
std::vector<std::string> image_files(const SceneDesc& scene, const OutputLayout& layout, int frame,
                                     const std::string& camera) {
    std::vector<std::string> names;
    for (const PassFile& file : layout.frame_files)
        names.push_back(
            expand(layout.names, file_fields(scene, camera, file.pass, frame, file.format)));
    return names;
}

}  // namespace

JobPlan plan_job(const SceneDesc& scene, const RenderOptions& options) {
    JobPlan plan;
    plan.frames = run_frames(scene, options);
    plan.cameras = select_cameras(scene, options.cameras);
    plan.layout = plan_outputs(scene, plan.cameras, named_frames(scene, options), options.out_dir,
                               options.several_variants);
    plan.output_dir = (std::filesystem::path(options.out_dir) / plan.layout.manifest_dir).string();
    plan.ledger =
        ledger_request(scene, plan.layout, options, plan.output_dir, plan.frames, plan.cameras);
    check_manifest_claims(plan.ledger);
    return plan;
}

std::vector<std::string> planned_files(const SceneDesc& scene, const JobPlan& plan) {
    std::vector<std::string> files;
    for (int frame : plan.frames)
        for (size_t camera : plan.cameras)
            for (const std::string& name :
                 image_files(scene, plan.layout, frame, scene.cameras[camera].name))
                files.push_back((std::filesystem::path(plan.layout.root) / name).string());
    files.push_back((std::filesystem::path(plan.output_dir) / plan.ledger.manifest_name).string());
    return files;
}

namespace {

// --skip-existing: the images already on disk as a same-settings record
// says, moved out of `todo` into `kept`. Every folder the run writes to
// is rid of what a killed run on this host left half-written, even when
// nothing in it is rendered again.
Manifest skip_written_images(const SceneDesc& scene, const OutputLayout& layout,
                             const RunLedger& ledger, bool skip_existing,
                             std::vector<std::pair<int, size_t>>& todo) {
    Manifest kept;
    std::set<std::string> folders;
    std::vector<std::pair<int, size_t>> remaining;
    for (const auto& [frame, camera] : todo) {
        const std::string& name = scene.cameras[camera].name;
        std::vector<std::string> relative;
        for (const std::string& file : image_files(scene, layout, frame, name)) {
            folders.insert((std::filesystem::path(layout.root) / file).parent_path().string());
            relative.push_back(path_relative_to_manifest(file, layout.manifest_dir));
        }
        const auto recorded = skip_existing ? ledger.verified(frame, name, relative) : std::nullopt;
        if (!recorded) {
            remaining.push_back({frame, camera});
            continue;
        }
        kept.frames.push_back(recorded->frame);
        kept.files.insert(kept.files.end(), recorded->files.begin(), recorded->files.end());
    }
    for (const std::string& folder : folders) remove_stale_temporaries(folder);
    todo = std::move(remaining);
    return kept;
}

}  // namespace

namespace {

// After a failure (exit 4 for a full disk): the manifest of the images that
// were finished, if the disk still takes it, and the failure rethrown with
// what the user has and how to go on.
[[noreturn]] void finish_after_failure(RunLedger& ledger, Manifest manifest,
                                       std::exception_ptr failure) {
    const size_t finished = manifest.frames.size();
    std::string listed;
    try {
        listed = "; " + count_of(finished, "image finished is", "images finished are") +
                 " listed in " + ledger.finish(std::move(manifest));
    } catch (const Error&) {
        listed =
            "; no manifest could be written either: the same command with --skip-existing "
            "finds the " +
            count_of(finished, "image", "images") + " finished and renders the rest";
    }
    try {
        std::rethrow_exception(failure);
    } catch (const Error& e) {
        throw Error(e.code(), e.what() + listed);
    }
}

}  // namespace

RenderResult render_scene(const SceneDesc& scene, const World& world, const RenderOptions& options,
                          const std::function<void(const FrameProgress&)>& on_frame,
                          const std::function<void(const FrameWritten&)>& on_written) {
    return render_scene(scene, world, options, plan_job(scene, options), plan_render(scene, world),
                        on_frame, on_written);
}

RenderResult render_scene(const SceneDesc& scene, const World& world, const RenderOptions& options,
                          const JobPlan& plan, RenderPlan render_plan,
                          const std::function<void(const FrameProgress&)>& on_frame,
                          const std::function<void(const FrameWritten&)>& on_written) {
    const std::vector<int>& frames = plan.frames;
    const std::vector<size_t>& cameras = plan.cameras;
    const OutputLayout& layout = plan.layout;
    RenderResult result;
    result.output_dir = plan.output_dir;
    const LedgerRequest& request = plan.ledger;
    ThreadPool pool(options.threads);
    check_render_memory(scene, world, render_plan, static_cast<unsigned>(pool.size()));
    make_directories(result.output_dir);
    RunLedger ledger(request);
    std::vector<std::pair<int, size_t>> todo;
    for (int frame : frames)
        for (size_t camera : cameras) todo.push_back({frame, camera});
    Manifest kept = skip_written_images(scene, layout, ledger, options.skip_existing, todo);
    result.images_skipped = kept.frames.size();
    if (options.on_plan) options.on_plan(todo.size(), result.images_skipped);

    FrameRenderer renderer(scene, world, std::move(render_plan), pool);
    // Encoding a 1080p frame can take longer than rendering it, so with
    // more than one thread two frames are encoded at once.
    FrameEncoder encoder(scene, layout, encoder_workers(pool.size()), ledger, request.header.host,
                         on_written);
    size_t rendered = 0;
    auto cancelled = [&] { return options.cancel && options.cancel->load(); };
    // A failure (an encoder's, surfaced by push, or the renderer's) stops
    // the loop; the images finished before it are still listed.
    std::exception_ptr failure;
    try {
        for (const auto& [frame, camera] : todo) {
            if (cancelled()) break;
            const auto start = Clock::now();
            FrameImages images = encoder.take_spare();
            renderer.render(frame, camera, images);
            const double render_ms = ms_since(start);
            const std::string& name = scene.cameras[camera].name;
            encoder.push({frame, name, render_ms, std::move(images)});
            ++rendered;
            if (on_frame) on_frame({frame, rendered, todo.size(), render_ms, name, cameras.size()});
        }
    } catch (...) {
        failure = std::current_exception();
    }
    Manifest written = encoder.finish(failure);
    Manifest manifest = request.header;
    manifest.frames = std::move(written.frames);
    manifest.files = std::move(written.files);
    result.files_written = manifest.files.size();
    manifest.frames.insert(manifest.frames.end(), kept.frames.begin(), kept.frames.end());
    manifest.files.insert(manifest.files.end(), kept.files.begin(), kept.files.end());
    manifest.threads = static_cast<int>(pool.size());
    manifest.ids = pass_ids(scene, world);
    if (failure) finish_after_failure(ledger, std::move(manifest), failure);
    result.manifest_path = ledger.finish(std::move(manifest));
    if (rendered < todo.size())
        throw Error(ExitCode::interrupted,
                    "interrupted: " + std::to_string(rendered + result.images_skipped) + " of " +
                        std::to_string(frames.size() * cameras.size()) +
                        " images are written and listed in " + result.manifest_path +
                        "; the same command with --skip-existing renders the rest");
    return result;
}

}  // namespace facet
