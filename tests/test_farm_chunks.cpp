// Chunk arithmetic, chunks from the environment, frame list text, and what
// the job files facet farm writes do: the Slurm script run with stubs, the
// OpenJD template loaded as YAML.
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

#include <nlohmann/json.hpp>
#include <sstream>

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

TEST_CASE("job files run the render and the merge with every word as given", "[farm]") {
    // What the files do, not how they read: the Slurm script is run with
    // stubs for sbatch and facet that record their words (as a user
    // submits it, then as a render task and as the merge), and the Open
    // Job Description template is loaded as OpenJD loads it (YAML).
    test::FarmFolder farm;
    FarmJob job;
    job.name = "facet-spin";
    job.facet = farm.dir.file("bin/facet-stub");
    job.working_dir = farm.dir.path();
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
    test::write_text(farm.dir.file("job.sh"), script);
    // sbatch reads its options from the script's #SBATCH lines.
    std::vector<std::string> directives;
    std::istringstream lines(script);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("#SBATCH ", 0) == 0) directives.push_back(line.substr(8));
    CHECK(directives == std::vector<std::string>{"--job-name=facet-spin", "--partition=render",
                                                 "--cpus-per-task=4", "--time=30:00"});
    // Submitted: the render array (six chunks, two at once), then the merge
    // after it, both from the working folder.
    REQUIRE(farm.run_script().exit_code == 0);
    const std::vector<std::string> submitted = farm.recorded("sbatch");
    const std::vector<std::string> expected = {"--parsable",
                                               "--chdir=" + farm.dir.path(),
                                               "--array=0-5%2",
                                               farm.dir.file("job.sh"),
                                               "--job-name=facet-spin-merge",
                                               "--chdir=" + farm.dir.path(),
                                               "--dependency=afterok:4242",
                                               "--kill-on-invalid-dep=yes",
                                               farm.dir.file("job.sh")};
    CHECK(submitted == expected);
    // A render task: facet render with the job's words, its frames and the
    // chunk from the environment; the merge: facet merge of the folder.
    REQUIRE(farm.run_script("FACET_FARM_STEP=render SLURM_ARRAY_TASK_ID=3").exit_code == 0);
    REQUIRE(farm.run_script("FACET_FARM_STEP=merge").exit_code == 0);
    CHECK(farm.recorded("facet-stub") ==
          std::vector<std::string>{"render", "scenes/spin.yaml", "-o", "out dir", "-D",
                                   "style.palette.0=it's", "--frames", "1-48", "--chunk-from-env",
                                   "--chunks", "6", "--skip-existing", "merge", "out dir/spin"});

    OpenJobSettings openjd;
    openjd.chunk_size = 8;
    openjd.target_runtime = 600;
    test::write_text(farm.dir.file("job.yaml"), openjd_template(job, openjd));
    const test::RunResult loaded = test::run_command(
        "python3 -c 'import sys, json, yaml; "
        "print(json.dumps(yaml.safe_load(open(sys.argv[1]))))' " +
        test::shell_quote(farm.dir.file("job.yaml")) + " 2>&1");
    if (loaded.exit_code != 0 && loaded.output.find("No module named") != std::string::npos)
        FACET_SKIP("python3-yaml is not installed (scripts/setup.sh --tests)");
    REQUIRE(loaded.exit_code == 0);
    const nlohmann::json t = nlohmann::json::parse(loaded.output);
    CHECK(t["specificationVersion"] == "jobtemplate-2023-09");
    const nlohmann::json& render = t["steps"][0];
    const nlohmann::json& frame = render["parameterSpace"]["taskParameterDefinitions"][0];
    CHECK(frame["type"] == "CHUNK[INT]");
    CHECK(frame["range"] == "{{Param.Frames}}");
    CHECK(frame["chunks"]["defaultTaskCount"] == 8);
    CHECK(frame["chunks"]["targetRuntimeSeconds"] == 600);
    CHECK(frame["chunks"]["rangeConstraint"] == "CONTIGUOUS");
    CHECK(render["script"]["actions"]["onRun"]["command"] == job.facet);
    std::vector<std::string> args = render["script"]["actions"]["onRun"]["args"];
    CHECK(args == std::vector<std::string>{"render", "scenes/spin.yaml", "-o", "out dir", "-D",
                                           "style.palette.0=it's", "--frames", "{{Param.Frames}}",
                                           "--chunk-frames", "{{Task.Param.Frame}}",
                                           "--skip-existing"});
    const nlohmann::json& merge = t["steps"][1];
    CHECK(merge["dependencies"][0]["dependsOn"] == "Render");
    CHECK(merge["script"]["actions"]["onRun"]["args"] ==
          nlohmann::json::array({"merge", "out dir/spin"}));
    bool frames_default = false;
    for (const nlohmann::json& p : t["parameterDefinitions"])
        frames_default |= p["name"] == "Frames" && p["default"] == "1-48";
    CHECK(frames_default);
    CHECK(shell_word("plain/path-1.yaml") == "plain/path-1.yaml");
    CHECK(shell_word("") == "''");
    CHECK(shell_word("$HOME") == "'$HOME'");
}
