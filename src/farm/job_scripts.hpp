#pragma once
// Job files for schedulers (facet farm): a Slurm batch script and an Open
// Job Description template that render a job's chunks, then merge them
// (docs/farm.md, "Job scripts").
#include <string>
#include <vector>

namespace facet {

// What every task runs, as plain words: the generator knows no scene.
struct FarmJob {
    std::string name;         // e.g. "facet-turntable"
    std::string facet;        // the program, an absolute path
    std::string working_dir;  // absolute: the folder relative paths are resolved from
    // `facet render` arguments after the subcommand, without frame or chunk
    // options: the scene, -o, and the options passed through.
    std::vector<std::string> render_args;
    std::string frames;        // the job's frames as range text
    size_t frame_count = 0;    // how many
    std::string merge_folder;  // the folder `facet merge` combines (manifests' folder)
    std::string version;       // facet's, for the header comment
};

struct SlurmSettings {
    int chunks = 1;
    std::string partition;  // "" : the cluster's default; one or more names, comma-separated
    std::string account;    // "" : the user's default
    int cpus = 0;           // per task; 0 : the cluster's default
    std::string time;       // per task, Slurm's format; "" : the partition's limit
    int max_running = 0;    // tasks at once (sbatch --array=...%M); 0 : no limit
};

// What may reach a job file from the command line (docs/farm.md, "What
// job files may hold"): --time in one of Slurm's formats, --partition and
// --account as Slurm names ([A-Za-z0-9_.-], partitions comma-separated),
// and no control character in any word (a newline would end a line of the
// script). Throws facet::Error (invalid_input) naming the option and
// showing the value with its control characters escaped.
void check_slurm_values(const FarmJob& job, const SlurmSettings& settings);

// The same for OpenJD, which also reads "{{" as the start of a format
// expression in any string: refused.
void check_openjd_values(const FarmJob& job);

// A bash script that, run with bash or submitted with sbatch, submits the
// render array and a merge job that runs after all of it succeeded. Every
// value in it, comments included, is a shell word (farm/shell_word.hpp);
// the #SBATCH lines hold only checked names and numbers. Call
// check_slurm_values first.
std::string slurm_script(const FarmJob& job, const SlurmSettings& settings);

struct OpenJobSettings {
    int chunk_size = 10;     // frames per task by default (CHUNK[INT] defaultTaskCount)
    int target_runtime = 0;  // seconds per task the scheduler may aim for; 0 : none
};

// An Open Job Description template (jobtemplate-2023-09 with the
// TASK_CHUNKING extension): a render step over CHUNK[INT] frames and a
// merge step that depends on it. Paths in it are absolute: OpenJD runs
// each task in a session folder of its own.
std::string openjd_template(const FarmJob& job, const OpenJobSettings& settings);

}  // namespace facet
