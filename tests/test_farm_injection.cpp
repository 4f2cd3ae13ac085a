// Job files that cannot be hijacked (docs/farm.md, "What job files may
// hold"): values that are not what Slurm accepts are refused with exit 2
// naming the option; every other value reaches the scheduler and the
// render exactly as given, whatever shell or #SBATCH syntax it holds.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>

#include "farm/job_scripts.hpp"
#include "farm_support.hpp"

using namespace facet;
using test::run_command;
using test::run_facet;
using test::shell_quote;

namespace {

// Values a farm front-end might pass on from a user or a job name.
const std::vector<std::string> kHostile = {
    "1:00\ntouch PWNED", "1:00\n#SBATCH --uid=0", "$(touch PWNED)", "`touch PWNED`",    "a\"b'c",
    "#SBATCH --uid=0",   "x; touch PWNED",        "\ttab",          "1:00\rtouch PWNED"};

bool has_control(const std::string& s) {
    return std::any_of(s.begin(), s.end(), [](unsigned char c) { return c < 0x20; });
}

}  // namespace

TEST_CASE(
    "facet farm slurm refuses --time, --partition and --account values Slurm would not "
    "take, naming the option",
    "[farm][security]") {
    test::FarmFolder farm;
    for (const char* option : {"--time", "--partition", "--account"})
        for (const std::string& value : kHostile) {
            INFO(option << " " << value);
            const test::RunResult r = farm.farm(std::string(option) + " " + shell_quote(value));
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Catch::Contains(std::string("facet farm: ") + option + " '"));
            CHECK_FALSE(std::filesystem::exists(farm.dir.file("job.sh")));
        }
    // What Slurm takes is taken.
    for (const char* time :
         {"30", "30:00", "2:00:00", "1-12", "1-12:30", "1-12:30:15", "UNLIMITED"}) {
        INFO(time);
        CHECK(farm.farm(std::string("--time ") + time).exit_code == 0);
    }
    REQUIRE(farm.farm("--partition gpu.a100,cpu-long --account proj_42 --time 1:00:00").exit_code ==
            0);
    const std::string script = test::read_file(farm.dir.file("job.sh"));
    CHECK_THAT(script, Catch::Contains("#SBATCH --partition=gpu.a100,cpu-long\n#SBATCH "
                                       "--account=proj_42\n"));
    CHECK_FALSE(farm.pwned());
}

TEST_CASE(
    "a newline in any value is refused, and every other value reaches sbatch and the render "
    "intact",
    "[farm][security]") {
    test::FarmFolder farm;
    // A control character in a path: refused, naming the option.
    for (const std::string& value : kHostile)
        if (has_control(value)) {
            INFO(value);
            const test::RunResult r = farm.farm("-o " + shell_quote(value));
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Catch::Contains("facet farm: -o '") &&
                                     Catch::Contains("which would end a line of the job file"));
        }
    // In the scene file's own name too.
    test::write_text(farm.dir.file("sp\nin.yaml"), test::read_file(farm.scene));
    const test::RunResult named =
        run_command("cd " + shell_quote(farm.dir.path()) + " && " +
                    shell_quote(facet::test::facet_executable()) + " farm slurm " +
                    shell_quote("sp\nin.yaml") + " --chunks 2 --script job.sh 2>&1");
    CHECK(named.exit_code == 2);
    CHECK_THAT(named.output, Catch::Contains("facet farm: the scene path 'sp\\nin.yaml'"));
    CHECK_FALSE(std::filesystem::exists(farm.dir.file("job.sh")));
    // Shell syntax, quotes and #SBATCH text in a folder name: written, and
    // passed on as they are.
    const std::string out = "out $(touch PWNED) `touch PWNED` \"q\" 'q' #SBATCH --uid=0";
    const test::RunResult made = farm.farm("-o " + shell_quote(out));
    INFO(made.output);
    REQUIRE(made.exit_code == 0);
    const std::string script = test::read_file(farm.dir.file("job.sh"));
    // No directive but facet's own.
    std::istringstream lines(script);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("#SBATCH", 0) == 0) {
            INFO(line);
            CHECK((line.rfind("#SBATCH --job-name=facet-spin", 0) == 0));
        }
    CHECK(test::run_command("bash -n " + shell_quote(farm.dir.file("job.sh"))).exit_code == 0);
    // Submitted: sbatch gets the folder and the script, nothing ran.
    const test::RunResult submitted = farm.run_script();
    INFO(submitted.output);
    REQUIRE(submitted.exit_code == 0);
    CHECK_FALSE(farm.pwned());
    const std::vector<std::string> sbatch = farm.recorded("sbatch");
    CHECK(std::count(sbatch.begin(), sbatch.end(), "--chdir=" + farm.dir.path()) == 2);
    // A task: facet gets -o exactly as given.
    const test::RunResult task = farm.run_script("FACET_FARM_STEP=render FACET=" +
                                                 shell_quote(farm.dir.file("bin/facet-stub")));
    INFO(task.output);
    REQUIRE(task.exit_code == 0);
    CHECK_FALSE(farm.pwned());
    const std::vector<std::string> facet = farm.recorded("facet-stub");
    const auto o = std::find(facet.begin(), facet.end(), "-o");
    REQUIRE(o != facet.end());
    REQUIRE(o + 1 != facet.end());
    CHECK(*(o + 1) == out);
}

TEST_CASE("the job name Slurm shows keeps only the characters its #SBATCH line can hold",
          "[farm][security]") {
    test::FarmFolder farm;
    test::write_text(farm.dir.file("my shot $(x).yaml"), test::read_file(farm.scene));
    const test::RunResult r =
        run_command("cd " + shell_quote(farm.dir.path()) + " && " +
                    shell_quote(facet::test::facet_executable()) +
                    " farm slurm 'my shot $(x).yaml' --chunks 2 --script job.sh 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::string script = test::read_file(farm.dir.file("job.sh"));
    CHECK_THAT(script, Catch::Contains("#SBATCH --job-name=facet-my_shot___x_\n"));
    // The comment names it as a shell word.
    CHECK_THAT(script, Catch::Contains("# 'facet-my shot $(x)': frames"));
}

TEST_CASE("facet farm openjd refuses control characters and OpenJD's {{ in values",
          "[farm][security]") {
    test::FarmFolder farm;
    auto openjd = [&](const std::string& options) {
        return run_command("cd " + shell_quote(farm.dir.path()) + " && " +
                           shell_quote(facet::test::facet_executable()) +
                           " farm openjd spin.yaml --script job.yaml " + options + " 2>&1");
    };
    const test::RunResult newline = openjd("-o " + shell_quote("a\nb"));
    CHECK(newline.exit_code == 2);
    CHECK_THAT(newline.output, Catch::Contains("facet farm: -o '") && Catch::Contains("a\\nb'"));
    const test::RunResult braces = openjd("-o " + shell_quote("out{{Param.Frames}}"));
    CHECK(braces.exit_code == 2);
    CHECK_THAT(braces.output, Catch::Contains("format expression"));
    // Quotes, $ and # are YAML-quoted and read back exactly.
    const std::string out = "out \"q\" 'q' $(x) #c \\ end";
    REQUIRE(openjd("-o " + shell_quote(out)).exit_code == 0);
    const test::RunResult read = run_command(
        "python3 -c 'import sys, yaml; t = yaml.safe_load(open(sys.argv[1])); "
        "a = t[\"steps\"][0][\"script\"][\"actions\"][\"onRun\"][\"args\"]; "
        "print(a[a.index(\"-o\") + 1])' " +
        shell_quote(farm.dir.file("job.yaml")));
    if (read.exit_code != 0 && read.output.find("No module named") != std::string::npos)
        FACET_SKIP("python3-yaml is not installed (scripts/setup.sh --tests)");
    REQUIRE(read.exit_code == 0);
    CHECK(read.output == farm.dir.path() + "/" + out + "\n");  // OpenJD's paths are absolute
}
