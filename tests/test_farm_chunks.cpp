// Chunk arithmetic, chunks from the environment, frame list text, and the
// job files facet farm writes (their content, and what they do when run
// without a scheduler).
#include <catch2/catch.hpp>

#include <map>
#include <numeric>
#include <random>

#include "core/error.hpp"
#include "core/frame_range.hpp"
#include "farm/chunks.hpp"
#include "farm/job_scripts.hpp"
#include "farm/shell_word.hpp"
#include "farm_support.hpp"

using namespace facet;

namespace {

std::vector<int> range(int first, int last) {
    std::vector<int> frames(static_cast<size_t>(last - first + 1));
    std::iota(frames.begin(), frames.end(), first);
    return frames;
}

}  // namespace

TEST_CASE("chunks are contiguous, in order, cover every frame once and differ by one at most",
          "[farm]") {
    for (int count : {1, 2, 3, 5, 7, 10, 13, 48, 60}) {
        const std::vector<int> frames = range(1, 48);
        std::vector<int> joined;
        size_t shortest = frames.size(), longest = 0;
        for (int i = 0; i < count; ++i) {
            const std::vector<int> chunk = chunk_of(frames, i, count);
            for (size_t k = 1; k < chunk.size(); ++k) CHECK(chunk[k] == chunk[k - 1] + 1);
            shortest = std::min(shortest, chunk.size());
            longest = std::max(longest, chunk.size());
            joined.insert(joined.end(), chunk.begin(), chunk.end());
        }
        INFO(count << " chunks");
        CHECK(joined == frames);
        CHECK(longest - shortest <= 1);
    }
    // Uneven: the longer chunks come first.
    CHECK(chunk_of(range(1, 10), 0, 3) == range(1, 4));
    CHECK(chunk_of(range(1, 10), 1, 3) == range(5, 7));
    CHECK(chunk_of(range(1, 10), 2, 3) == range(8, 10));
    // More chunks than frames: one frame each, then empty chunks.
    CHECK(chunk_of(range(1, 3), 2, 5) == std::vector<int>{3});
    CHECK(chunk_of(range(1, 3), 3, 5).empty());
    CHECK(chunk_of(range(1, 3), 4, 5).empty());
    // A list of single frames is cut by position, not by value.
    CHECK(chunk_of({1, 5, 9, 100, 200}, 1, 2) == std::vector<int>{100, 200});
}

TEST_CASE("chunk I/N is checked, numbered from 0", "[farm]") {
    const ChunkChoice c = parse_chunk("2/6");
    CHECK(c.index == 2);
    CHECK(c.count == 6);
    test::require_error([] { parse_chunk("6/6"); }, ExitCode::invalid_input,
                        "chunks are numbered from 0, so 6 chunks are 0/6 to 5/6");
    test::require_error([] { parse_chunk("-1/6"); }, ExitCode::invalid_input, "does not exist");
    test::require_error([] { parse_chunk("1/0"); }, ExitCode::invalid_input, "from 1 to");
    for (const char* bad : {"3", "a/b", "1/", "/4", "1/4/5", "1.5/4", " 1/4"})
        test::require_error([&] { parse_chunk(bad); }, ExitCode::invalid_input, "expected I/N");
}

TEST_CASE("chunks from the environment: scheduler task indices", "[farm]") {
    std::map<std::string, std::string> env;
    auto read = [&](const char* name) -> const char* {
        auto it = env.find(name);
        return it == env.end() ? nullptr : it->second.c_str();
    };
    test::require_error([&] { chunk_from_environment(0, read); }, ExitCode::invalid_input,
                        "none of SLURM_ARRAY_TASK_ID");
    env = {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "6"}};
    ChunkChoice c = chunk_from_environment(0, read);
    CHECK(c.index == 3);
    CHECK(c.count == 6);
    CHECK(c.origin.find("SLURM_ARRAY_TASK_ID=3") != std::string::npos);
    CHECK(c.origin.find("SLURM_ARRAY_TASK_COUNT=6") != std::string::npos);
    // A resubmitted single task has a count of 1: --chunks says the job's.
    env = {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "1"}};
    test::require_error([&] { chunk_from_environment(0, read); }, ExitCode::invalid_input,
                        "does not exist");
    c = chunk_from_environment(6, read);
    CHECK(c.index == 3);
    CHECK(c.count == 6);
    env = {{"JOB_COMPLETION_INDEX", "4"}};
    test::require_error([&] { chunk_from_environment(0, read); }, ExitCode::invalid_input,
                        "give --chunks N");
    CHECK(chunk_from_environment(5, read).index == 4);
    env = {{"SLURM_ARRAY_TASK_ID", "x"}};
    test::require_error([&] { chunk_from_environment(5, read); }, ExitCode::invalid_input,
                        "SLURM_ARRAY_TASK_ID=x");
}

TEST_CASE("frame lists are written as range text that reads back exactly", "[farm]") {
    CHECK(format_frame_ranges(range(1, 48)) == "1-48");
    CHECK(format_frame_ranges({1, 3, 5, 7}) == "1-7:2");
    CHECK(format_frame_ranges({1, 5, 10, 11, 12, 13}) == "1,5,10-13");
    CHECK(format_frame_ranges({4, 5}) == "4,5");
    CHECK(format_frame_ranges({-3, -2, -1, 0}) == "-3-0");
    CHECK(format_frame_ranges({}).empty());
    std::mt19937 random(7);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<int> frames;
        for (int f = -20; f < 200; ++f)
            if (random() % 3 == 0) frames.push_back(f);
        if (frames.empty()) continue;
        CHECK(parse_frame_ranges(format_frame_ranges(frames)) == frames);
    }
}

TEST_CASE("job files quote every word and pass the render options through", "[farm]") {
    FarmJob job;
    job.name = "facet-spin";
    job.facet = "/opt/facet/bin/facet";
    job.working_dir = "/home/me/shots";
    job.render_args = {"scenes/spin.yaml", "-o", "out dir", "-D", "style.palette.0=it's"};
    job.frames = "1-48";
    job.frame_count = 48;
    job.merge_folder = "out dir/spin";
    job.version = "1.2.3";
    SlurmSettings slurm;
    slurm.chunks = 6;
    slurm.partition = "render";
    slurm.cpus = 4;
    slurm.time = "30:00";
    slurm.max_running = 2;
    const std::string script = slurm_script(job, slurm);
    for (const char* line :
         {"#SBATCH --partition=render\n", "#SBATCH --cpus-per-task=4\n", "#SBATCH --time=30:00\n",
          "folder=/home/me/shots\n", "--chdir=\"$folder\"", "chunks=6\n", "tasks=0-5\n",
          "--array=\"$tasks\"%2", "--dependency=afterok:\"$array\" --kill-on-invalid-dep=yes",
          "render scenes/spin.yaml -o 'out dir' -D 'style.palette.0=it'\\''s' --frames 1-48",
          "--chunk-from-env --chunks \"$chunks\" --skip-existing", "merge 'out dir/spin'\n",
          "facet=${FACET:-/opt/facet/bin/facet}\n"}) {
        INFO(line);
        CHECK(script.find(line) != std::string::npos);
    }
    OpenJobSettings openjd;
    openjd.chunk_size = 8;
    openjd.target_runtime = 600;
    const std::string t = openjd_template(job, openjd);
    for (const char* line :
         {"specificationVersion: 'jobtemplate-2023-09'\n", "  - TASK_CHUNKING\n",
          "type: CHUNK[INT]\n", "range: \"{{Param.Frames}}\"\n", "defaultTaskCount: 8\n",
          "rangeConstraint: CONTIGUOUS\n", "targetRuntimeSeconds: 600\n", "default: \"1-48\"\n",
          "\"--frames\", \"{{Param.Frames}}\", \"--chunk-frames\", \"{{Task.Param.Frame}}\"",
          "- dependsOn: Render\n", "args: [\"merge\", \"out dir/spin\"]\n",
          "\"style.palette.0=it's\""}) {
        INFO(line);
        CHECK(t.find(line) != std::string::npos);
    }
    CHECK(shell_word("plain/path-1.yaml") == "plain/path-1.yaml");
    CHECK(shell_word("") == "''");
    CHECK(shell_word("$HOME") == "'$HOME'");
}
