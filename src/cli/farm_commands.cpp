#include "cli/farm_commands.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/model_commands.hpp"
#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "core/plain_text.hpp"
#include "core/version.hpp"
#include "farm/chunks.hpp"
#include "farm/merge.hpp"
#include "output/atomic_file.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// --chunk-frames LIST: a part given by its frames, each one of the job's.
std::vector<int> frames_of_part(const std::string& text, const std::vector<int>& job_frames) {
    std::vector<int> frames;
    try {
        frames = parse_frame_ranges(text);
    } catch (const Error& e) {
        fail_input(command_line("--chunk-frames " + text), "", e.what());
    }
    for (int frame : frames)
        if (!std::binary_search(job_frames.begin(), job_frames.end(), frame))
            fail_input(command_line("--chunk-frames " + text), "",
                       "frame " + std::to_string(frame) + " is not one of the job's frames (" +
                           format_frame_ranges(job_frames) + ")");
    return frames;
}

}  // namespace

void add_chunk_options(CLI::App* cmd, ChunkArgs& args) {
    cmd->add_option("--chunk", args.chunk,
                    "Render chunk I of N (I/N, numbered from 0) of the frames; writes a partial "
                    "manifest for facet merge");
    cmd->add_flag("--chunk-from-env", args.from_env,
                  "Take the chunk from SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or "
                  "AWS_BATCH_JOB_ARRAY_INDEX");
    add_whole_number_option(cmd, "--chunks", args.chunks, 1, 1000000,
                            "The number of chunks, with --chunk-from-env");
    cmd->add_option("--chunk-frames", args.chunk_frames,
                    "Render these of the frames as one part (e.g. an OpenJD chunk, 9-16)");
    cmd->add_flag("--skip-existing", args.skip_existing,
                  "Skip images whose files are on disk with the hashes a manifest records");
}

std::optional<RunPart> choose_part(const ChunkArgs& args, const std::vector<int>& job_frames,
                                   std::vector<int>& run_frames, bool quiet, Warnings& warnings) {
    const int ways = (args.chunk.empty() ? 0 : 1) + (args.from_env ? 1 : 0) +
                     (args.chunk_frames.empty() ? 0 : 1);
    if (ways > 1)
        fail_input(command_line("--chunk"), "",
                   "give one of --chunk I/N, --chunk-from-env and --chunk-frames LIST");
    if (args.chunks > 0 && !args.from_env)
        fail_input(command_line("--chunks " + std::to_string(args.chunks)), "",
                   "--chunks goes with --chunk-from-env (with --chunk, write I/N)");
    run_frames = job_frames;
    if (ways == 0) {
        if (const char* task = std::getenv("SLURM_ARRAY_TASK_ID"))
            warnings.push_back({{"", 0, 0, "environment SLURM_ARRAY_TASK_ID"},
                                "",
                                "this is Slurm array task " + text_for_message(task) +
                                    ", but no --chunk or --chunk-from-env was given: every "
                                    "task renders every frame"});
        return std::nullopt;
    }
    RunPart part;
    part.job_frames = job_frames;
    std::string origin;
    if (!args.chunk_frames.empty()) {
        run_frames = frames_of_part(args.chunk_frames, job_frames);
        origin = "--chunk-frames " + args.chunk_frames;
    } else {
        const ChunkChoice choice =
            args.from_env
                ? chunk_from_environment(
                      args.chunks,
                      [](const char* name) { return static_cast<const char*>(std::getenv(name)); })
                : parse_chunk(args.chunk);
        part.chunk_index = choice.index;
        part.chunk_count = choice.count;
        run_frames = chunk_of(job_frames, choice.index, choice.count);
        origin = "chunk " + std::to_string(choice.index) + "/" + std::to_string(choice.count) +
                 (args.from_env ? " from " + choice.origin : "");
    }
    if (!quiet)
        std::fprintf(stderr, "facet: %s: frames %s of %s\n", origin.c_str(),
                     run_frames.empty() ? "(none)" : format_frame_ranges(run_frames).c_str(),
                     format_frame_ranges(job_frames).c_str());
    return part;
}

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "merge", "Check a farm job's partial manifests and combine them into manifest.json");
    cmd->add_option("folder", args.folder, "The folder with the partial manifests (OUT/SCENE)")
        ->required();
    cmd->add_flag("--keep-parts", args.keep_parts,
                  "Keep the partial manifests after merging (default: removed)");
    add_quiet_flag(cmd, args.quiet);
    return cmd;
}

int merge_command(const MergeArgs& args) {
    const MergeReport report =
        merge_partial_manifests({args.folder, args.keep_parts, args.command_line});
    for (const std::string& w : report.warnings)
        std::fprintf(stderr, "facet: warning: %s\n", w.c_str());
    if (!report.problems.empty()) {
        for (const std::string& p : report.problems)
            std::fprintf(stderr, "facet: merge: %s\n", p.c_str());
        std::fprintf(stderr,
                     "facet: error: %s: the job is not whole (%s); manifest.json was not "
                     "written\n",
                     args.folder.c_str(),
                     count_of(report.problems.size(), "problem", "problems").c_str());
        return static_cast<int>(ExitCode::comparison_failed);
    }
    if (args.quiet) return 0;
    if (report.checked_only)
        std::printf(
            "%s: no partial manifests; checked: %s and %s, all present with their "
            "hashes\n",
            report.manifest_path.c_str(), count_of(report.frames, "image", "images").c_str(),
            count_of(report.files, "file", "files").c_str());
    else
        std::printf("merged %s into %s: %s and %s, all present with their hashes\n",
                    count_of(report.parts.size(), "partial manifest", "partial manifests").c_str(),
                    report.manifest_path.c_str(),
                    count_of(report.frames, "image", "images").c_str(),
                    count_of(report.files, "file", "files").c_str());
    return 0;
}

}  // namespace facet

namespace facet {
namespace {

namespace fs = std::filesystem;

void add_farm_render_options(CLI::App* cmd, FarmArgs& args) {
    add_scene_options(cmd, args.render);
    add_strict_flag(cmd, args.render.strict);
    add_output_option(cmd, args.render.out,
                      "Output folder of every task (files go to OUTPUT/SCENE/)");
    add_threads_option(cmd, args.render.threads);
    cmd->add_flag("--overwrite", args.render.overwrite,
                  "Every task starts new manifests where the folder holds other settings'");
    cmd->add_option("--script", args.script, "Write the job file here instead of standard output");
}

// The `facet render` words every task runs, after the subcommand and
// before the frame and chunk options the job file adds.
std::vector<std::string> render_words(const FarmArgs& args, bool absolute_paths) {
    const RenderArgs& r = args.render;
    auto path = [&](const std::string& p) {
        return absolute_paths ? fs::absolute(p).lexically_normal().string() : p;
    };
    std::vector<std::string> words = {path(r.scene), "-o", path(r.out)};
    auto add = [&](const char* option, const std::string& value) {
        if (value.empty()) return;
        words.push_back(option);
        words.push_back(value);
    };
    add("--size", r.size);
    add("--passes", r.passes);
    add("--formats", r.formats);
    std::error_code ec;
    add("--style", fs::is_regular_file(r.style, ec) ? path(r.style) : r.style);
    add("--camera", r.cameras);
    add("--variant", r.variant);
    for (const std::string& d : r.defines) add("-D", d);
    if (r.threads > 0)
        add("--threads", std::to_string(r.threads));
    else if (!absolute_paths && args.slurm.cpus > 0)
        add("--threads", std::to_string(args.slurm.cpus));  // the task's cores, not the node's
    if (r.overwrite) words.push_back("--overwrite");
    if (r.allow_asset_paths_outside) words.push_back("--allow-asset-paths-outside");
    if (r.strict) words.push_back("--strict");
    if (r.frames.allow_outside) words.push_back("--allow-outside");
    return words;
}

}  // namespace

CLI::App* add_farm_command(CLI::App& app, FarmArgs& slurm, FarmArgs& openjd) {
    CLI::App* farm = app.add_subcommand(
        "farm", "Write a render farm job: a Slurm script or an Open Job Description template");
    farm->require_subcommand(1);
    CLI::App* s = farm->add_subcommand(
        "slurm", "A bash script that submits a Slurm job array of chunks, then facet merge");
    add_farm_render_options(s, slurm);
    add_whole_number_option(s, "--chunks", slurm.slurm.chunks, 1, 100000,
                            "Number of chunks (array tasks)")
        ->required();
    s->add_option("--partition", slurm.slurm.partition,
                  "Slurm partition, or several comma-separated (default: the cluster's)");
    s->add_option("--account", slurm.slurm.account, "Slurm account to charge (default: yours)");
    add_whole_number_option(s, "--cpus", slurm.slurm.cpus, 1, 4096,
                            "CPUs per task (--cpus-per-task; sets --threads)");
    s->add_option("--time", slurm.slurm.time, "Time limit per task, e.g. 30:00 or 2:00:00");
    add_whole_number_option(s, "--max-running", slurm.slurm.max_running, 1, 100000,
                            "Tasks running at once (default: all)");
    CLI::App* o = farm->add_subcommand(
        "openjd", "An Open Job Description template: CHUNK[INT] render tasks, then facet merge");
    add_farm_render_options(o, openjd);
    add_whole_number_option(o, "--chunk-size", openjd.openjd.chunk_size, 1, 1000000,
                            "Frames per task (default 10)");
    add_whole_number_option(
        o, "--target-runtime", openjd.openjd.target_runtime, 1, 1000000,
        "Seconds per task the scheduler may size chunks for (default: fixed size)");
    for (CLI::App* sub : {s, o}) sub->allow_extras();
    return farm;
}

int farm_command(const FarmArgs& args, bool openjd) {
    const RenderArgs& r = args.render;
    SceneOptions scene_opts = scene_options(r);
    LoadedMeshes model_mesh;
    const SceneDesc scene = load_scene_or_model(r, scene_opts, &model_mesh);
    std::vector<int> frames = resolve_frames(r.frames, scene.output);
    if (frames.empty()) frames = scene.output.frames;
    RenderOptions options;
    options.frames = frames;
    options.cameras = camera_names(r.cameras);
    options.out_dir = r.out;
    options.overwrite = r.overwrite;
    options.threads = r.threads;
    options.provenance.overrides = scene_opts.overrides;
    // Every task runs `facet render` with these words: what render would
    // refuse (a mesh it cannot read, a warning under --strict, too little
    // memory) is refused here, before anything is submitted.
    const CheckedRun run = check_render_inputs({r, scene, options, &model_mesh, {}, !r.quiet});
    // The folder every task writes its partial manifest to, and the names
    // checked, as render would check them.
    const std::vector<std::string> planned = planned_files(scene, run.plan);
    const std::string folder = fs::path(planned.back()).parent_path().string();
    FarmJob job;
    job.name = "facet-" + scene.name;
    std::error_code ec;
    job.facet = fs::read_symlink("/proc/self/exe", ec).string();
    job.working_dir = fs::current_path().string();
    job.render_args = render_words(args, openjd);
    job.frames = format_frame_ranges(frames);
    job.frame_count = frames.size();
    job.merge_folder = openjd ? fs::absolute(folder).lexically_normal().string() : folder;
    job.version = build_info().version;
    SlurmSettings slurm = args.slurm;
    if (!openjd && static_cast<size_t>(slurm.chunks) > frames.size()) {
        if (!r.quiet)
            std::fprintf(stderr, "facet: --chunks %d for %s: %zu chunks of one frame\n",
                         slurm.chunks, count_of(frames.size(), "frame", "frames").c_str(),
                         frames.size());
        slurm.chunks = static_cast<int>(frames.size());
    }
    if (openjd)
        check_openjd_values(job);
    else
        check_slurm_values(job, slurm);
    const std::string text = openjd ? openjd_template(job, args.openjd) : slurm_script(job, slurm);
    if (args.script.empty()) {
        std::printf("%s", text.c_str());
        return 0;
    }
    write_file_atomically(args.script, text);
    if (!openjd) ::chmod(args.script.c_str(), 0755);
    if (!r.quiet)
        std::fprintf(stderr, "facet: wrote %s: %s\n", args.script.c_str(),
                     openjd ? "submit it with your Open Job Description scheduler (e.g. "
                              "deadline bundle submit)"
                            : ("bash " + args.script + " submits " + std::to_string(slurm.chunks) +
                               " render tasks and the merge")
                                  .c_str());
    return 0;
}

}  // namespace facet
