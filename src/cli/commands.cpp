#include "cli/commands.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "assets/mesh.hpp"
#include "cli/compare_command.hpp"
#include "cli/farm_commands.hpp"
#include "cli/inspect_commands.hpp"
#include "cli/model_commands.hpp"
#include "cli/option_values.hpp"
#include "cli/options.hpp"
#include "cli/preview_command.hpp"
#include "cli/progress.hpp"
#include "cli/render_args.hpp"
#include "cli/sheet_command.hpp"
#include "cli/shell_docs.hpp"
#include "cli/video_command.hpp"
#include "compare/thresholds.hpp"
#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/thread_pool.hpp"
#include "core/version.hpp"
#include "job/render_job.hpp"
#include "job/render_memory.hpp"
#include "job/thread_study.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "raster/raster_limits.hpp"
#include "render/world.hpp"

namespace facet {
namespace {

// Set by SIGINT/SIGTERM. A signal handler can only reach a global; this is
// the one piece of global mutable state, and only the handler writes it.
std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int) {
    g_interrupted.store(true);
}

}  // namespace

SceneOptions scene_options(const RenderArgs& args) {
    SceneOptions options;
    options.style_dirs = default_style_dirs();
    if (!args.size.empty()) {
        auto [w, h] = parse_size(args.size, "--size");
        options.overrides.push_back({"output.size",
                                     "[" + std::to_string(w) + ", " + std::to_string(h) + "]",
                                     "command line --size " + args.size});
    }
    if (!args.style.empty()) {
        std::string value = args.style;
        // A file named on the command line is relative to where facet runs.
        std::error_code ec;
        if (std::filesystem::is_regular_file(value, ec))
            value = std::filesystem::weakly_canonical(value, ec).string();
        options.overrides.push_back(
            {"style", yaml_quoted(value), "command line --style " + args.style});
    }
    // "a,b" -> "[a,b]": the scene's own list syntax, checked by the scene reader.
    if (!args.passes.empty())
        options.overrides.push_back(
            {"output.passes", "[" + args.passes + "]", "command line --passes " + args.passes});
    if (!args.formats.empty())
        options.overrides.push_back(
            {"output.formats", "[" + args.formats + "]", "command line --formats " + args.formats});
    if (args.allow_asset_paths_outside)
        options.overrides.push_back(
            {"assets.allow_paths_outside", "true", "command line --allow-asset-paths-outside"});
    if (!args.variant.empty())
        options.overrides.push_back(
            {"variant", yaml_quoted(args.variant), "command line --variant " + args.variant});
    for (const auto& d : args.defines) options.overrides.push_back(parse_define(d));
    return options;
}

std::vector<std::string> camera_names(const std::string& cameras) {
    return parse_list(cameras, "--camera", "comma-separated camera names or all");
}

void add_strict_flag(CLI::App* cmd, bool& strict) {
    cmd->add_flag("--strict", strict,
                  "Treat every warning (a lost texture, an ignored extension, a key without "
                  "effect) as an error: exit 2 before rendering");
}

void refuse_warnings(bool strict, const Warnings& warnings) {
    if (!strict || warnings.empty()) return;
    throw Error(ExitCode::invalid_input,
                "--strict: " + count_of(warnings.size(), "warning is", "warnings are") +
                    " an error; the first: " + warnings.front().describe());
}

CheckedRun check_render_inputs(const RenderCheck& check) {
    Warnings warnings = check.scene.warnings;
    warnings.insert(warnings.end(), check.extra.begin(), check.extra.end());
    // What earlier checks of the command collected (other variants' runs)
    // is said once; what this one found so far is kept even when a later
    // step fails.
    Warnings said_before;
    if (check.collected) said_before = *check.collected;
    auto is_new = [&](const Warning& w) {
        return std::none_of(said_before.begin(), said_before.end(),
                            [&](const Warning& s) { return s.describe() == w.describe(); });
    };
    auto collect = [&] {
        if (!check.collected) return;
        *check.collected = said_before;
        std::copy_if(warnings.begin(), warnings.end(), std::back_inserter(*check.collected),
                     is_new);
    };
    collect();
    JobPlan plan = plan_job(check.scene, check.options);  // before the slow part: loading meshes
    World world = build_world(check.scene, check.options.threads, check.model_mesh);
    warnings.insert(warnings.end(), world.warnings.begin(), world.warnings.end());
    collect();
    if (check.print)
        for (const Warning& w : warnings)
            if (is_new(w)) std::fprintf(stderr, "facet: warning: %s\n", w.describe().c_str());
    refuse_warnings(check.args.strict, warnings);
    const unsigned threads = check.options.threads == 0 ? available_cores() : check.options.threads;
    RenderPlan render_plan = plan_render(check.scene, world);
    check_render_memory(check.scene, world, render_plan, threads);
    return {std::move(plan), std::move(world), std::move(render_plan)};
}

namespace {

int dry_run(const RenderArgs& args, const std::vector<SceneDesc>& runs,
            const RenderOptions& options) {
    size_t images = 0;  // files but the manifests
    for (const SceneDesc& run : runs) {
        const std::vector<std::string> files = planned_files(run, plan_job(run, options));
        for (const std::string& file : files) std::printf("%s\n", file.c_str());
        images += files.size() - 1;
    }
    const std::string manifests =
        runs.size() == 1 ? "the manifest" : count_of(runs.size(), "manifest", "manifests");
    if (!args.quiet)
        std::fprintf(stderr, "dry run: %s and %s would be written; nothing was\n",
                     count_of(images, "file", "files").c_str(), manifests.c_str());
    return 0;
}

// A folder removed with everything in it when this goes out of scope.
struct TemporaryFolder {
    std::string path;  // "" for none
    explicit TemporaryFolder(std::string p) : path(std::move(p)) {}
    TemporaryFolder(const TemporaryFolder&) = delete;
    ~TemporaryFolder() {
        std::error_code ignored;
        if (!path.empty()) std::filesystem::remove_all(path, ignored);
    }
};

// Ctrl-C finishes the frames already rendered instead of leaving files
// half written; a second Ctrl-C is not caught and ends facet at once.
void catch_interrupts() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

// The thresholds --reference compares with (none without it).
CompareThresholds reference_thresholds(const RenderArgs& args, bool compare) {
    if (!compare && !args.comparison.update_reference.empty())
        fail_input(command_line("--update-reference"), "",
                   "give the reference folder with --reference DIR");
    return compare ? comparison_thresholds(args.comparison) : CompareThresholds{};
}

// The options the arguments set (render_command points out_dir at the
// --video-only folder).
RenderOptions render_options(const RenderArgs& args, const SceneOptions& scene_opts,
                             const std::vector<int>& frames, const std::optional<RunPart>& part) {
    RenderOptions options;
    options.frames = frames;
    options.cameras = camera_names(args.cameras);
    options.threads = args.threads;
    options.out_dir = args.out;
    options.cancel = &g_interrupted;
    options.overwrite = args.overwrite;
    options.provenance = {args.command_line, scene_opts.overrides, ""};
    options.part = part;
    options.skip_existing = args.chunk.skip_existing;
    return options;
}

// Refuses a --video or --video-only the render cannot serve; warns of a
// movie of unevenly spaced frames.
void check_video_arguments(const RenderArgs& args, const SceneDesc& scene, bool compare,
                           const std::vector<int>& frames, Warnings& warnings) {
    if (!args.video.empty()) {
        check_movie_name(args.video);
        if (!scene.output.writes(Pass::color))
            fail_input(command_line("--video " + args.video), "",
                       "a movie needs the colour pass (--passes color)");
        const std::string uneven = uneven_frames_warning(frames);
        if (!uneven.empty())
            warnings.push_back({command_line("--video " + args.video), "", uneven});
    }
    if (args.video_only && (args.video.empty() || compare))
        fail_input(command_line("--video-only"), "",
                   "give --video MOVIE, and no --reference (there are no images to compare)");
}

// The folder --video-only renders into ("" without it), named for this process.
std::string hidden_frames_folder(const RenderArgs& args) {
    return args.video_only ? (std::filesystem::path(args.video).parent_path() /
                              (".facet-frames-" + std::to_string(::getpid())))
                                 .string()
                           : "";
}

// --video: the movie of this run's colour frames.
void make_movie(const RenderArgs& args, const SceneDesc& scene, const RenderOptions& options,
                const RenderResult& result, const std::vector<int>& frames) {
    VideoArgs video{result.output_dir, args.video, "", 0, args.quiet, {}, true};
    const std::vector<size_t> cameras = select_cameras(scene, options.cameras);
    video.camera = scene.cameras[cameras.front()].name;
    video.frames = frames.empty() ? scene.output.frames : frames;  // this run's, not older ones
    video_command(video);
}

// --reference: compares the images this run rendered with the reference's.
int compare_with_reference(const RenderArgs& args, const SceneDesc& scene,
                           const RenderOptions& options, const CompareThresholds& thresholds,
                           const RenderResult& result, const std::vector<int>& frames) {
    CompareArgs comparison = args.comparison;
    comparison.quiet = args.quiet;
    std::set<std::pair<std::string, int>> rendered;
    for (size_t camera : select_cameras(scene, options.cameras))
        for (int frame : frames.empty() ? scene.output.frames : frames)
            rendered.insert({scene.cameras[camera].name, frame});
    return compare_render_output(comparison, thresholds, result.output_dir, rendered);
}

// Refuses what takes one run's images when the run is one per variant.
void check_single_run(const RenderArgs& args, bool compare, size_t runs) {
    if (runs < 2 || (!compare && args.video.empty())) return;
    fail_input(command_line(compare ? "--reference" : "--video"), "",
               "takes one run's images, and " + std::to_string(runs) +
                   " variants each render their own: give --variant NAME");
}

// One run of the command (one variant's, when there are several): its
// inputs checked, its frames rendered and written. Its warnings are added
// to `said`, and those there already are not printed again; `last`: the
// meshes read for it are let go.
RenderResult render_run(const RenderArgs& args, const SceneDesc& scene, RenderOptions options,
                        LoadedMeshes& meshes, const Warnings& extra, Warnings& said, bool last) {
    CheckedRun run =
        check_render_inputs({args, scene, options, &meshes, extra, !args.quiet, &said});
    const World& world = run.world;
    if (last) meshes.clear();  // the world holds what it uses
    ProgressReporter progress(stderr, args.quiet);
    const std::string what =
        "'" + scene.name + "'" + (scene.variant.empty() ? "" : " (" + scene.variant + ")");
    options.on_plan = [&](size_t to_render, size_t skipped) {
        if (skipped > 0 && !args.quiet)
            std::fprintf(stderr, "facet: %s already written (files match their recorded hashes)\n",
                         count_of(skipped, "image is", "images are").c_str());
        progress.start(to_render, what + " to " + args.out);
    };
    RenderResult result = render_scene(
        scene, world, options, run.plan, std::move(run.render_plan),
        [&](const FrameProgress& p) { progress.frame_done(p); },
        [&](const FrameWritten& w) { progress.frame_written(w); });
    progress.finish();
    if (!args.quiet && !args.video_only)
        std::printf("wrote %s to %s (manifest: %s)\n",
                    count_of(result.files_written, "file", "files").c_str(),
                    result.output_dir.c_str(), result.manifest_path.c_str());
    return result;
}

int render_command(const RenderArgs& args) {
    // Installed first, so an interrupt while loading also ends cleanly.
    catch_interrupts();
    SceneOptions scene_opts = scene_options(args);
    LoadedMeshes meshes;  // a model's turntable: the mesh its survey read
    SceneDesc scene = load_scene_or_model(args, scene_opts, &meshes);
    std::vector<int> frames = resolve_frames(args.frames, scene.output);
    const bool compare = !args.comparison.ref.empty();
    Warnings own_warnings;  // this command's, beside the scene's and the world's
    // A farm task: its part of the job's frames.
    std::vector<int> part_frames;
    const std::optional<RunPart> part =
        choose_part(args.chunk, frames.empty() ? scene.output.frames : frames, part_frames,
                    args.quiet, own_warnings);
    if (part) {
        if (compare || !args.video.empty())
            fail_input(command_line(compare ? "--reference" : "--video"), "",
                       "a chunk writes a partial manifest: compare or make the movie after "
                       "facet merge");
        if (part_frames.empty()) {
            if (!args.quiet)
                std::printf("this chunk has no frames (more chunks than frames): nothing to do\n");
            return 0;
        }
        frames = part_frames;
    }
    // Thresholds are checked before the long part, as the scene is.
    const CompareThresholds thresholds = reference_thresholds(args, compare);
    RenderOptions options = render_options(args, scene_opts, frames, part);
    check_video_arguments(args, scene, compare, frames.empty() ? scene.output.frames : frames,
                          own_warnings);
    const std::vector<SceneDesc> runs = variant_runs(scene, args.threads, meshes);
    options.several_variants = runs.size() > 1;
    check_single_run(args, compare, runs.size());
    // --video-only: the frames go to a hidden folder beside the movie,
    // removed when the movie is written (or the run fails).
    const TemporaryFolder frames_folder(hidden_frames_folder(args));
    if (args.video_only) options.out_dir = frames_folder.path;
    if (args.dry_run) return dry_run(args, runs, options);
    Warnings said;
    RenderResult result;
    for (size_t r = 0; r < runs.size(); ++r)
        result =
            render_run(args, runs[r], options, meshes, own_warnings, said, r + 1 == runs.size());
    if (!args.video.empty()) make_movie(args, runs.front(), options, result, frames);
    if (compare)
        return compare_with_reference(args, runs.front(), options, thresholds, result, frames);
    return 0;
}

void print_validation(const SceneDesc& scene, const World& world, const RenderOptions& options) {
    // The frames a render with these options would render.
    const std::vector<int>& frames = options.frames.empty() ? scene.output.frames : options.frames;
    const std::string asked =
        options.frames.empty()
            ? scene.output.frames_text
            : std::to_string(frames.front()) +
                  (frames.size() > 1 ? ".." + std::to_string(frames.back()) : "") +
                  " of the scene's " + scene.output.frames_text;
    const std::string variant = scene.variant.empty() ? "" : ", variant '" + scene.variant + "'";
    std::printf("%s: ok: %s, %s, %s, style '%s' (%s)%s, %dx%d, frames %s (%s)\n",
                scene.path.c_str(), count_of(scene.objects.size(), "object", "objects").c_str(),
                count_of(world.triangle_count(), "triangle", "triangles").c_str(),
                count_of(scene.lights.size(), "light", "lights").c_str(), scene.style.name.c_str(),
                shading_model_name(scene.style.shading), variant.c_str(), scene.output.width,
                scene.output.height, asked.c_str(),
                count_of(frames.size(), "frame", "frames").c_str());
}

int validate_command(const RenderArgs& args) {
    Warnings warnings;
    try {
        SceneOptions scene_opts = scene_options(args);
        LoadedMeshes meshes;
        SceneDesc scene = load_scene_or_model(args, scene_opts, &meshes);
        RenderOptions options;
        options.frames = resolve_frames(args.frames, scene.output);
        options.cameras = camera_names(args.cameras);
        options.out_dir = args.out;
        options.provenance.overrides = scene_opts.overrides;
        // The output folder's manifest is checked only when -o names one:
        // validating a scene must not depend on what some earlier run left in out/.
        options.overwrite = !args.output_given;
        options.threads = args.threads;
        const std::vector<SceneDesc> runs = variant_runs(scene, args.threads, meshes);
        options.several_variants = runs.size() > 1;
        ValidateFacts facts;
        for (const SceneDesc& run : runs) {
            const World world =
                check_render_inputs(
                    {args, run, options, &meshes, {}, !args.json && !args.quiet, &warnings})
                    .world;
            if (!run.variant.empty()) facts.variants.push_back(run.variant);
            facts.triangles = world.triangle_count();
            if (!args.json && !args.quiet) print_validation(run, world, options);
        }
        if (args.json) {
            facts.scene = scene.path;
            facts.style = scene.style.name;
            facts.shading = shading_model_name(scene.style.shading);
            facts.objects = scene.objects.size();
            facts.lights = scene.lights.size();
            facts.width = scene.output.width;
            facts.height = scene.output.height;
            facts.frames = options.frames.empty() ? scene.output.frames : options.frames;
            std::printf("%s", validate_json(facts, warnings).c_str());
        }
    } catch (const Error& e) {
        if (!args.json) throw;
        std::printf("%s", validate_error_json(e, warnings).c_str());
        return static_cast<int>(e.code());
    }
    return 0;
}

struct BenchArgs {
    RenderArgs scene;
    std::string threads = "1,2";
    std::string output = "out/bench";
};

int bench_command(const BenchArgs& args) {
    SceneDesc scene = load_scene(args.scene.scene, scene_options(args.scene));
    std::vector<int> frames = resolve_frames(args.scene.frames, scene.output);
    if (frames.empty()) frames = scene.output.frames;
    std::vector<unsigned> threads;
    for (int n : parse_whole_number_list(
             args.threads, "--threads", 0, 256,
             "comma-separated thread counts from 0 (one per core) to 256 (e.g. 1,2,4)"))
        // 0 means one per core, as everywhere else.
        threads.push_back(n == 0 ? available_cores() : static_cast<unsigned>(n));
    World world = build_world(scene);
    const bool quiet = args.scene.quiet;
    const ThreadStudy study =
        run_thread_study(scene, world, threads, frames, [&](const std::string& line) {
            if (!quiet) std::fprintf(stderr, "facet: %s\n", line.c_str());
        });
    const std::string markdown = thread_study_markdown(study);
    make_directories(args.output);
    const std::string base =
        (std::filesystem::path(args.output) / (scene.name + "-threads")).string();
    write_file_atomically(base + ".md", markdown);
    write_file_atomically(base + ".png", encode_png_color(thread_study_plot(study), 6));
    if (!quiet)
        std::printf("%s\nwrote %s.md and %s.png\n", markdown.c_str(), base.c_str(), base.c_str());
    return 0;
}

}  // namespace

void add_asset_paths_flag(CLI::App* cmd, bool& allow) {
    cmd->add_flag("--allow-asset-paths-outside", allow,
                  "Let meshes name files outside their own folder (trusted assets only)");
}

void add_variant_option(CLI::App* cmd, std::string& variant) {
    cmd->add_option_function<std::string>(
           "--variant",
           [&variant](const std::string& value) {
               // An empty value is no choice; taking it as "not given" would
               // hide a script's missing variable behind the default materials.
               if (value.empty())
                   fail_input(command_line("--variant ''"), "",
                              "expected a variant's name or all, got an empty value");
               variant = value;
           },
           "The models' variant (a glTF colourway, KHR_materials_variants) to draw, or 'all' "
           "for a run of each into a folder of its own; -D variant=NAME")
        ->type_name("NAME|all");
}

void add_scene_options(CLI::App* cmd, RenderArgs& args) {
    cmd->add_option("scene", args.scene, "Scene file (YAML)")->required();
    cmd->add_option("--size", args.size, "Image size WIDTHxHEIGHT, e.g. 1280x720");
    cmd->add_option("--passes", args.passes,
                    "Passes to write, comma-separated: color, alpha, depth, normal, object_id, "
                    "material_id, uv, position, motion, lines (docs/passes.md)");
    cmd->add_option("--formats", args.formats, "File formats: png, exr or png,exr");
    cmd->add_option("--style", args.style, "Style preset name or file");
    add_define_option(cmd, args.defines);
    add_frame_options(cmd, args.frames);
    cmd->add_option("--camera", args.cameras,
                    "Camera(s) to render by name, comma-separated, or 'all'");
    add_variant_option(cmd, args.variant);
    add_quiet_flag(cmd, args.quiet);
    add_asset_paths_flag(cmd, args.allow_asset_paths_outside);
}

std::vector<std::string> default_style_dirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("FACET_STYLE_PATH")) {
        std::string list = env;
        size_t start = 0;
        while (start <= list.size()) {
            size_t colon = list.find(':', start);
            std::string dir =
                list.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
            if (!dir.empty()) dirs.push_back(dir);
            if (colon == std::string::npos) break;
            start = colon + 1;
        }
    }
    // The presets that come with facet, found from the executable, so an
    // installed or moved facet needs no source tree: PREFIX/bin/facet reads
    // PREFIX/share/facet/styles; in a build folder, BUILD/share/facet/styles
    // (a link to the sources' styles/, made by CMake).
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path bin = exe.parent_path();
        for (const auto& dir :
             {bin / ".." / "share" / "facet" / "styles", bin / "share" / "facet" / "styles"})
            if (std::filesystem::is_directory(dir, ec)) {
                dirs.push_back(dir.lexically_normal().string());
                break;
            }
    }
    return dirs;
}

namespace {

// The subcommands' options, one function each (add_subcommands stays a
// list of commands).
CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a scene's frames to PNG/EXR files, or a turntable of a model file");
    add_scene_options(cmd, args);
    cmd->get_option("scene")->description(
        "Scene file (YAML), or a model (a mesh file: .glb, .gltf, .obj, .stl, .ply, .fbx, .dae, "
        ".3ds) to render facet's turntable of");
    add_output_option(cmd, args.out, "Output folder (files go to OUTPUT/SCENE/)");
    add_threads_option(cmd, args.threads);
    cmd->add_option("--video", args.video,
                    "Also make a movie of the colour frames: .mp4 (H.264), .webm (VP9), .gif");
    cmd->add_flag("--video-only", args.video_only,
                  "Keep only the movie: the frames are written to a temporary folder");
    cmd->add_flag("--dry-run", args.dry_run,
                  "List the files the render would write (then the manifest); write nothing");
    cmd->add_flag("--overwrite", args.overwrite,
                  "Start a new manifest when the output folder holds one of other settings");
    add_chunk_options(cmd, args.chunk);
    add_strict_flag(cmd, args.strict);
    cmd->add_option("--reference", args.comparison.ref,
                    "Compare the output with this reference folder (facet compare)");
    add_comparison_options(cmd, args.comparison, false);
    add_turntable_options(cmd, args.turntable);
    return cmd;
}

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "compare", "Compare two runs' outputs (or two images) against thresholds; write a report");
    cmd->add_option("ref", args.ref, "Reference output folder or image")->required();
    cmd->add_option("new", args.candidate, "New output folder or image");
    cmd->add_flag(
        "--self-test", args.self_test,
        "Judge each reference frame against the next: can the thresholds tell them apart?");
    add_quiet_flag(cmd, args.quiet);
    add_comparison_options(cmd, args, true);
    return cmd;
}

CLI::App* add_validate_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd =
        app.add_subcommand("validate", "Check a scene, its styles and assets; write nothing");
    add_scene_options(cmd, args);
    cmd->add_flag("--json", args.json, "Print the result, every warning and the error as JSON");
    add_strict_flag(cmd, args.strict);
    add_output_option(cmd, args.out,
                      "Output folder a render would use (checks its manifest's settings)");
    cmd->get_option("scene")->description("Scene file (YAML), or a model (a mesh file)");
    add_turntable_options(cmd, args.turntable);
    // The threads a render would use: they read the meshes here, and the
    // memory check counts the frames a render keeps in flight with them.
    add_threads_option(cmd, args.threads);
    return cmd;
}

CLI::App* add_bench_command(CLI::App& app, BenchArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "bench", "Thread study: render a scene's frames at several thread counts; table and plot");
    add_scene_options(cmd, args.scene);
    cmd->add_option("--threads", args.threads,
                    "Thread counts, e.g. 1,2,4 (0: one per core; default 1,2)");
    add_output_option(cmd, args.output, "Folder for SCENE-threads.md and .png (default out/bench)");
    return cmd;
}

CLI::App* add_video_command(CLI::App& app, VideoArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "video", "Make a movie (.mp4, .webm, .gif) of a run's colour frames, through its manifest");
    cmd->add_option("output", args.output_dir, "A run's folder (holds manifest.json)")->required();
    cmd->add_option("movie", args.movie, "Movie to write: .mp4, .webm or .gif")->required();
    cmd->add_option("--camera", args.camera, "Camera, when the run has several");
    add_decimal_option(cmd, "--fps", args.fps, 0.01, 1000.0,
                       "Frames per second (default: the scene's)");
    add_quiet_flag(cmd, args.quiet);
    return cmd;
}

// Prints an error as every command does and returns its exit code.
int report_error(const std::exception& error) {
    std::fprintf(stderr, "facet: error: %s\n", error.what());
    if (const auto* e = dynamic_cast<const Error*>(&error)) return static_cast<int>(e->code());
    return static_cast<int>(ExitCode::runtime_failure);
}

// `facet help [COMMAND]`: the same text as --help.
int help_command(const CLI::App& app, const std::string& topic) {
    if (topic.empty()) {
        // app.help() would describe the parsed subcommand (help) instead.
        std::printf(
            "%s",
            app.get_formatter()->make_help(&app, "facet", CLI::AppFormatMode::Normal).c_str());
        return 0;
    }
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub->get_name() == topic) {
            std::printf("%s", sub->help().c_str());
            return 0;
        }
    char name[] = "facet";
    char* argv[] = {name, const_cast<char*>(topic.c_str())};
    check_subcommand_name(app, 2, argv);  // throws with a did-you-mean
    return 0;
}

// `facet styles [NAME]`.
struct StylesArgs {
    std::string name;
    bool json = false;
};

CLI::App* add_styles_command(CLI::App& app, StylesArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "styles", "List the style presets, or print one with its extends chain applied");
    cmd->add_option("name", args.name, "Preset to print, resolved");
    cmd->add_flag("--json", args.json, "The list as JSON");
    return cmd;
}

// `facet info MESH`.
struct InfoArgs {
    std::string mesh;
    bool allow_outside = false;
    bool json = false;
    unsigned threads = 0;  // that may read one big file
};

CLI::App* add_info_command(CLI::App& app, InfoArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "info", "Describe a mesh file: triangles, bounds, materials, animations");
    cmd->add_option("mesh", args.mesh,
                    "Mesh file: .obj, .gltf, .glb, .stl, .ply, .fbx, .dae or .3ds")
        ->required();
    cmd->add_flag("--json", args.json, "Print the description as JSON");
    add_asset_paths_flag(cmd, args.allow_outside);
    add_threads_option(cmd, args.threads);
    return cmd;
}

CLI::App* add_completion_command(CLI::App& app, std::string& shell) {
    CLI::App* cmd = app.add_subcommand("completion", "Print a shell completion script (bash)");
    cmd->add_option("shell", shell, "Shell: bash")->required()->check(CLI::IsMember({"bash"}));
    return cmd;
}

CLI::App* add_help_command(CLI::App& app, std::string& topic) {
    CLI::App* cmd = app.add_subcommand("help", "Show the help of facet or of one command");
    cmd->add_option("command", topic, "Command to describe");
    return cmd;
}

// What CLI11 parses each subcommand's arguments into.
struct CommandArgs {
    RenderArgs render;
    CompareArgs compare;
    RenderArgs validate;
    SceneFileArgs scene;
    StylesArgs styles;
    SheetArgs sheet;
    BenchArgs bench;
    InfoArgs info;
    VideoArgs video;
    RenderArgs preview;
    MergeArgs merge;
    FarmArgs slurm, openjd;
    std::string shell;       // completion
    std::string help_topic;  // help
};

// The subcommands, to tell which one was given.
struct Subcommands {
    CLI::App *render, *scene, *compare, *validate, *styles, *sheet, *bench, *info, *video, *preview,
        *merge, *farm, *completion, *man, *help;
};

// Every subcommand, in the order the help lists them.
Subcommands add_subcommands(CLI::App& app, CommandArgs& args) {
    Subcommands cmd;
    cmd.render = add_render_command(app, args.render);
    cmd.compare = add_compare_command(app, args.compare);
    cmd.validate = add_validate_command(app, args.validate);
    cmd.scene = add_scene_command(app, args.scene);
    cmd.styles = add_styles_command(app, args.styles);
    cmd.sheet = add_sheet_command(app, args.sheet);
    cmd.bench = add_bench_command(app, args.bench);
    cmd.info = add_info_command(app, args.info);
    cmd.video = add_video_command(app, args.video);
    cmd.preview = add_preview_command(app, args.preview);
    cmd.merge = add_merge_command(app, args.merge);
    cmd.farm = add_farm_command(app, args.slurm, args.openjd);
    cmd.completion = add_completion_command(app, args.shell);
    cmd.man = app.add_subcommand("man", "Print facet's man page (roff), facet(1)");
    cmd.help = add_help_command(app, args.help_topic);
    return cmd;
}

// Parses the command line into the subcommands' arguments. The exit code
// when that ends the run (--help, --version, a parse error), else none.
std::optional<int> parse_command_line(CLI::App& app, CLI::App& farm, int argc, char** argv) {
    try {
        check_subcommand_name(app, argc, argv);
        if (argc > 2 && std::string(argv[1]) == "farm")
            check_subcommand_name(farm, argc - 1, argv + 1);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : static_cast<int>(ExitCode::invalid_input);
    } catch (const Error& e) {
        return report_error(e);
    }
    return std::nullopt;
}

// `facet completion bash`: the script completes style names too.
int completion_command(const CLI::App& app) {
    std::vector<std::string> names;
    for (const auto& preset : list_style_presets(default_style_dirs()))
        names.push_back(preset.first);
    std::printf("%s", bash_completion(app, names).c_str());
    return 0;
}

// Refuses words no option takes, then runs the subcommand that was parsed;
// invalid_input when there is none.
int run_subcommand(CLI::App& app, const Subcommands& cmd, CommandArgs& args) {
    for (CLI::App* sub : app.get_subcommands()) {
        reject_unknown_arguments(sub);
        for (CLI::App* nested : sub->get_subcommands()) reject_unknown_arguments(nested);
    }
    args.validate.output_given = cmd.validate->get_option("--output")->count() > 0;
    if (cmd.render->parsed()) return render_command(args.render);
    if (cmd.scene->parsed()) return scene_command(args.scene);
    if (cmd.compare->parsed()) return compare_command(args.compare);
    if (cmd.validate->parsed()) return validate_command(args.validate);
    if (cmd.info->parsed())
        return info_command(args.info.mesh, args.info.allow_outside, args.info.json,
                            args.info.threads);
    if (cmd.styles->parsed()) return styles_command(args.styles.name, args.styles.json);
    if (cmd.bench->parsed()) return bench_command(args.bench);
    if (cmd.sheet->parsed()) return sheet_command(args.sheet);
    if (cmd.video->parsed()) return video_command(args.video);
    if (cmd.preview->parsed()) return preview_command(args.preview);
    if (cmd.merge->parsed()) return merge_command(args.merge);
    if (cmd.farm->parsed())
        return farm_command(cmd.farm->get_subcommand("openjd")->parsed() ? args.openjd : args.slurm,
                            cmd.farm->get_subcommand("openjd")->parsed());
    if (cmd.help->parsed()) return help_command(app, args.help_topic);
    if (cmd.completion->parsed()) return completion_command(app);
    if (cmd.man->parsed()) {
        std::printf("%s", man_page(app, version_line()).c_str());
        return 0;
    }
    return static_cast<int>(ExitCode::invalid_input);
}

}  // namespace

int run_command_line(int argc, char** argv) {
    CLI::App app{"facet: scene-file driven offline renderer"};
    app.require_subcommand(1);
    app.set_version_flag("--version", version_line());
    CommandArgs args;
    const Subcommands cmd = add_subcommands(app, args);

    // Unknown words are reported by facet with a did-you-mean, not by CLI11.
    for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        sub->allow_extras();
    args.render.command_line.assign(argv, argv + argc);
    args.merge.command_line = args.render.command_line;
    args.preview.command_line = args.render.command_line;
    if (const std::optional<int> code = parse_command_line(app, *cmd.farm, argc, argv))
        return *code;
    try {
        return run_subcommand(app, cmd, args);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "facet: error: out of memory\n");
        return static_cast<int>(ExitCode::runtime_failure);
    } catch (const std::exception& e) {
        return report_error(e);
    }
}

}  // namespace facet
