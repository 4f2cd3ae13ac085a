#include "farm/job_scripts.hpp"

#include <cstdio>
#include <regex>
#include <string_view>

#include "core/error.hpp"
#include "core/plain_text.hpp"
#include "farm/shell_word.hpp"
#include "scene/scene_desc.hpp"

namespace facet {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& value,
                         const std::string& why) {
    throw Error(ExitCode::invalid_input,
                "facet farm: " + option + " '" + text_for_message(value) + "': " + why);
}

// The option a render word belongs to ("the scene" for the first).
std::string option_of(const std::vector<std::string>& words, size_t i) {
    if (i == 0) return "the scene path";
    if (!words[i].empty() && words[i][0] == '-') return words[i];
    return words[i - 1];
}

void refuse_line_break(const std::string& what, const std::string& value) {
    if (const auto problem = line_breaking_character(value))
        refuse(what, value,
               "holds " + *problem +
                   ", which would end a line of the job file for bash, Slurm or a YAML reader");
}

// Every text the job file carries, whatever it came from (the command
// line, the scene's names through the merge folder, the environment): none
// may end a line for any reader of the file (core/plain_text.hpp).
void check_words(const FarmJob& job) {
    // The folders first: absolute paths in the words hold them too.
    for (const auto& [what, value] :
         {std::pair<const char*, const std::string&>{"the working folder", job.working_dir},
          {"the facet program's path", job.facet}})
        refuse_line_break(what, value);
    for (size_t i = 0; i < job.render_args.size(); ++i)
        refuse_line_break(option_of(job.render_args, i), job.render_args[i]);
    for (const auto& [what, value] :
         {std::pair<const char*, const std::string&>{"the job name", job.name},
          {"the merge folder (from the scene's output.path and names)", job.merge_folder},
          {"the frames", job.frames},
          {"the version", job.version}})
        refuse_line_break(what, value);
}

// A value in a comment line: a shell word, with anything that could end
// the line written as an escape, so that the comment stays one line even
// if a value was never checked.
std::string comment_word(const std::string& text) {
    return shell_word(text_for_message(text, text.size()));
}

// Slurm's job and partition names written in #SBATCH lines, which sbatch
// reads without a shell: only these characters, nothing to quote.
bool is_slurm_name(const std::string& text) {
    static const std::regex name("[A-Za-z0-9_.-]+");
    return std::regex_match(text, name);
}

// The job name as Slurm shows it: the characters is_slurm_name allows, the
// others as '_'.
std::string slurm_job_name(const std::string& name) {
    std::string out;
    for (char c : name) out += is_slurm_name(std::string(1, c)) ? c : '_';
    return out.empty() ? "facet" : out;
}

std::string join_words(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) {
        line += ' ';
        line += shell_word(w);
    }
    return line;
}

std::string yaml_list(const std::vector<std::string>& items) {
    std::string list = "[";
    for (size_t i = 0; i < items.size(); ++i) list += (i ? ", " : "") + yaml_quoted(items[i]);
    return list + "]";
}

// The part of the script that runs as `bash job.sh`: submits the array
// and the merge job, and with --wait reports how the merge ended.
std::string slurm_submission(const FarmJob& job, const SlurmSettings& s) {
    const std::string last = std::to_string(s.chunks - 1);
    std::string t;
    t += "tasks=0-" + last + "\n";
    t += "wait=()\n";
    t += "while [[ $# -gt 0 ]]; do\n";
    t += "    case \"$1\" in\n";
    t += "    --wait) wait=(--wait) ;;\n";
    t += "    --tasks) tasks=${2:?--tasks needs a list, e.g. 2,5}; shift ;;\n";
    t += "    *) echo \"usage: bash $0 [--wait] [--tasks LIST]\" >&2; exit 2 ;;\n";
    t += "    esac\n";
    t += "    shift\n";
    t += "done\n";
    t += "script=$(readlink -f \"$0\")\n";
    std::string limit;  // sbatch --array=0-5%M: at most M tasks at once
    if (s.max_running > 0) limit = '%' + std::to_string(s.max_running);
    t += "folder=" + shell_word(job.working_dir) + "\n";
    t += "array=$(FACET_FARM_STEP=render sbatch --parsable --chdir=\"$folder\" --array=\"$tasks\"" +
         limit + " \"$script\")\n";
    t += "array=${array%%;*}\n";
    t += "echo \"facet: render job $array: chunks $tasks of $chunks\"\n";
    t += "# The merge runs once every task succeeded; a failed task cancels it\n";
    t += "# (--kill-on-invalid-dep), so it never waits forever.\n";
    t += "merge_options=(--job-name=" + shell_word(slurm_job_name(job.name) + "-merge") +
         " --chdir=\"$folder\" --dependency=afterok:\"$array\" --kill-on-invalid-dep=yes)\n";
    t += "if [[ ${#wait[@]} -eq 0 ]]; then\n";
    t += "    FACET_FARM_STEP=merge sbatch \"${merge_options[@]}\" \"$script\"\n";
    t += "    exit 0\n";
    t += "fi\n";
    t += "# --wait: sbatch --wait returns 0 for a merge that was cancelled, so the\n";
    t += "# merge job's state decides, and failed tasks are named.\n";
    t += "code=0\n";
    t += "merge=$(FACET_FARM_STEP=merge sbatch --parsable --wait \"${merge_options[@]}\" "
         "\"$script\") || code=$?\n";
    t += "merge=${merge%%;*}\n";
    t += "state=$(scontrol -o show job \"$merge\" | sed -n 's/.* JobState=\\([A-Z_]*\\) "
         ".*/\\1/p')\n";
    t += "if [[ $code -eq 0 && $state == COMPLETED ]]; then\n";
    t += "    echo \"facet: merge job $merge completed: the job is whole\"\n";
    t += "    exit 0\n";
    t += "fi\n";
    t += "failed=$(scontrol -o show job \"$array\" | awk '!/JobState=COMPLETED/ {\n";
    t += "    if (match($0, /ArrayTaskId=[0-9]+/)) print substr($0, RSTART + 12, RLENGTH - 12) }' "
         "| paste -sd, -)\n";
    t += "echo \"facet: merge job $merge ended ${state:-unknown} (exit code $code)\" >&2\n";
    t += "if [[ -n $failed ]]; then\n";
    t += "    echo \"facet: chunks that did not complete: $failed; resubmit them with: bash $0 "
         "--tasks $failed --wait\" >&2\n";
    t += "fi\n";
    t += "exit $((code != 0 ? code : 1))\n";
    return t;
}

}  // namespace

void check_slurm_values(const FarmJob& job, const SlurmSettings& s) {
    check_words(job);
    // sbatch --time: minutes, minutes:seconds, hours:minutes:seconds,
    // days-hours, days-hours:minutes, days-hours:minutes:seconds.
    static const std::regex time(
        "[0-9]+(:[0-9]+){0,2}|[0-9]+-[0-9]+(:[0-9]+){0,2}|UNLIMITED|INFINITE|unlimited|infinite");
    if (!s.time.empty() && !std::regex_match(s.time, time))
        refuse("--time", s.time,
               "expected one of Slurm's formats: MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS "
               "or UNLIMITED");
    static const std::regex partitions("[A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*");
    if (!s.partition.empty() && !std::regex_match(s.partition, partitions))
        refuse("--partition", s.partition,
               "expected Slurm partition names: letters, digits, '_', '.' and '-', several "
               "separated by commas");
    if (!s.account.empty() && !is_slurm_name(s.account))
        refuse("--account", s.account,
               "expected a Slurm account name: letters, digits, '_', '.' and '-'");
}

void check_openjd_values(const FarmJob& job) {
    check_words(job);
    for (size_t i = 0; i < job.render_args.size(); ++i)
        if (job.render_args[i].find("{{") != std::string::npos)
            refuse(option_of(job.render_args, i), job.render_args[i],
                   "holds '{{', which Open Job Description reads as the start of a format "
                   "expression");
    for (const std::string* value : {&job.working_dir, &job.facet, &job.merge_folder})
        if (value->find("{{") != std::string::npos)
            refuse("a path", *value,
                   "holds '{{', which Open Job Description reads as the start of a format "
                   "expression");
}

std::string slurm_script(const FarmJob& job, const SlurmSettings& s) {
    const std::string last = std::to_string(s.chunks - 1);
    std::string t;
    t += "#!/bin/bash\n";
    t += "# " + comment_word(job.name) + ": frames " + comment_word(job.frames) + " (" +
         std::to_string(job.frame_count) + ") in " + std::to_string(s.chunks) +
         " chunks on Slurm, then `facet merge` of\n";
    t += "# their partial manifests into " + comment_word(job.merge_folder + "/manifest.json") +
         ".\n";
    t += "# Written by `facet farm slurm` (facet " + comment_word(job.version) +
         "); docs/farm.md explains it.\n";
    t += "#\n";
    t += "#   bash job.sh                submit the render array and the merge job\n";
    t += "#   bash job.sh --wait         the same, then wait for the merge; exit with its code\n";
    t += "#   bash job.sh --tasks 2,5    submit only those chunks again (0-" + last +
         "), and the merge\n";
    t += "#   sbatch job.sh              the same as bash job.sh, from a job of its own\n";
    t += "#\n";
    t += "# Relative paths are resolved from the folder facet farm ran in (--chdir).\n";
    t += "# Set FACET to run another facet program than the one recorded here.\n";
    // sbatch reads these lines itself, without a shell: each value is a
    // checked name or number. The folder is passed on sbatch's command
    // line (quoted) and by the `cd` below.
    t += "#SBATCH --job-name=" + slurm_job_name(job.name) + "\n";
    if (!s.partition.empty()) t += "#SBATCH --partition=" + s.partition + "\n";
    if (!s.account.empty()) t += "#SBATCH --account=" + s.account + "\n";
    if (s.cpus > 0) t += "#SBATCH --cpus-per-task=" + std::to_string(s.cpus) + "\n";
    if (!s.time.empty()) t += "#SBATCH --time=" + s.time + "\n";
    t += "set -euo pipefail\n";
    t += "cd " + shell_word(job.working_dir) + "\n";
    t += "facet=${FACET:-" + shell_word(job.facet) + "}\n";
    t += "chunks=" + std::to_string(s.chunks) + "\n\n";
    t += "# One chunk: the array task's id is the chunk's number. --skip-existing\n";
    t += "# makes a resubmitted task render only what is missing or damaged.\n";
    t += "render() {\n";
    t += "    exec \"$facet\" render" + join_words(job.render_args) + " --frames " +
         shell_word(job.frames) + " \\\n";
    t += "        --chunk-from-env --chunks \"$chunks\" --skip-existing\n";
    t += "}\n\n";
    t += "merge() {\n";
    t += "    exec \"$facet\" merge " + shell_word(job.merge_folder) + "\n";
    t += "}\n\n";
    t += "case \"${FACET_FARM_STEP:-}\" in\n";
    t += "render) render ;;\n";
    t += "merge) merge ;;\n";
    t += "esac\n";
    t += "# Submitted by hand as an array task (sbatch --array=3 job.sh): that chunk.\n";
    t += "if [[ -n \"${SLURM_ARRAY_TASK_ID:-}\" ]]; then render; fi\n\n";
    return t + slurm_submission(job, s);
}

std::string openjd_template(const FarmJob& job, const OpenJobSettings& s) {
    std::vector<std::string> render = {"render"};
    render.insert(render.end(), job.render_args.begin(), job.render_args.end());
    for (const char* word : {"--frames", "{{Param.Frames}}", "--chunk-frames",
                             "{{Task.Param.Frame}}", "--skip-existing"})
        render.push_back(word);
    std::string t;
    t += "# " + comment_word(job.name) + ": frames " + comment_word(job.frames) + " in chunks of " +
         std::to_string(s.chunk_size) + " frames, then `facet merge` of their\n";
    t += "# partial manifests into " + comment_word(job.merge_folder + "/manifest.json") + ".\n";
    t += "# Written by `facet farm openjd` (facet " + comment_word(job.version) +
         "); docs/farm.md explains it.\n";
    t += "specificationVersion: 'jobtemplate-2023-09'\n";
    t += "extensions:\n  - TASK_CHUNKING\n";
    t += "name: " + yaml_quoted(job.name) + "\n";
    t += "parameterDefinitions:\n";
    t += "  - name: Frames\n    type: STRING\n    default: " + yaml_quoted(job.frames) + "\n";
    t += "    description: \"The frames to render, e.g. 1-48, 1-48:2 or 1,5,10-20\"\n";
    t += "steps:\n";
    t += "  - name: Render\n";
    t += "    parameterSpace:\n";
    t += "      taskParameterDefinitions:\n";
    t += "        - name: Frame\n";
    t += "          type: CHUNK[INT]\n";
    t += "          range: \"{{Param.Frames}}\"\n";
    t += "          chunks:\n";
    t += "            defaultTaskCount: " + std::to_string(s.chunk_size) + "\n";
    t += "            rangeConstraint: CONTIGUOUS\n";
    if (s.target_runtime > 0)
        t += "            targetRuntimeSeconds: " + std::to_string(s.target_runtime) + "\n";
    t += "    script:\n      actions:\n        onRun:\n";
    t += "          command: " + yaml_quoted(job.facet) + "\n";
    t += "          args: " + yaml_list(render) + "\n";
    t += "  - name: Merge\n";
    t += "    dependencies:\n      - dependsOn: Render\n";
    t += "    script:\n      actions:\n        onRun:\n";
    t += "          command: " + yaml_quoted(job.facet) + "\n";
    t += "          args: " + yaml_list({"merge", job.merge_folder}) + "\n";
    return t;
}

}  // namespace facet
