// Every text that reaches a job file, whatever its source (-o, the scene
// file's name, the working folder, the scene's camera name and output.path,
// -D), is either refused with exit 2 naming where it came from, when some
// reader of the file would take a character of it as the end of a line
// (core/plain_text.hpp), or reaches every reader exactly as given: bash
// runs facet with these words and nothing else, Slurm's #SBATCH reader
// finds facet's one directive, and a YAML loader finds the template's keys
// and nothing else (docs/farm.md, "What job files may hold").
#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <set>

#include <nlohmann/json.hpp>

#include "farm_support.hpp"

using namespace facet;
using test::shell_quote;

namespace {

namespace fs = std::filesystem;

// Texts that every reader must take as plain characters: shell syntax,
// quotes, #SBATCH, YAML's indicators, and UTF-8 beyond ASCII.
const std::vector<std::string> kPlainHostile = {
    "$(touch PWNED)",   "`touch PWNED`",    "a\"b'c",
    "#SBATCH --uid=0",  "x; touch PWNED #", "\xc3\xbcn\xc3\xaf \xe5\x90\x8d",
    ": - [x] & *a !t |"};

// Characters that bash, Slurm or a YAML 1.1 reader take as the end of a
// line, or refuse: raw, and as a YAML double-quoted escape (empty where
// YAML has none: bytes that are not UTF-8 cannot be written in a scene).
struct Breaker {
    std::string raw, yaml;
};
const std::vector<Breaker> kBreakers = {{"\n", "\\n"},
                                        {"\r", "\\r"},
                                        {"\t", "\\t"},
                                        {"\x1b", "\\u001b"},
                                        {"\xc2\x85", "\\u0085"},
                                        {"\xe2\x80\xa8", "\\u2028"},
                                        {"\xe2\x80\xa9", "\\u2029"},
                                        {"\xc2\x9b", "\\u009b"},
                                        {"\xff", ""}};

// `text` inside YAML double quotes.
std::string yaml_text(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// The scene, with its camera's name and output.path as YAML values.
std::string scene_text(const std::string& camera_name, const std::string& path) {
    return "output: { size: [32, 18], frames: \"1-4\", passes: [color], formats: [png], path: " +
           path + " }\ncamera: { name: " + camera_name +
           ", orbit: { radius: 4, turns: 1 } }\n"
           "lights: [ { type: directional, direction: [-1, -1, -1] } ]\n"
           "objects: [ { primitive: { type: torus } } ]\n";
}

const std::string kCameraPath = "\"{scene}/{camera}/{pass}.{frame}.{ext}\"";

// One way a value reaches the job, set up in `farm`'s folder.
struct JobCase {
    std::string folder;       // where facet farm runs
    std::string scene;        // the scene word (relative to folder)
    std::string out = "out";  // -o
    std::vector<std::string> defines;
    std::string merge_folder;  // what `facet merge` is given, relative to folder
    std::string refusal;       // what the error names when the value is refused
};

// The sources. `raw` is the value, `yaml` the same as a YAML scalar
// (empty: it cannot be written in YAML).
struct Source {
    const char* name;
    bool from_yaml;  // the value goes through the scene's YAML
    std::function<JobCase(const test::FarmFolder&, const std::string& raw, const std::string& yaml)>
        make;
};

const std::vector<Source>& sources() {
    static const std::vector<Source> all = {
        {"-o", false,
         [](const test::FarmFolder& f, const std::string& raw, const std::string&) {
             return JobCase{f.dir.path(), "spin.yaml",         "o" + raw,
                            {},           "o" + raw + "/spin", "facet farm: -o '"};
         }},
        {"the scene file's name", false,
         [](const test::FarmFolder& f, const std::string& raw, const std::string&) {
             const std::string name = "s" + raw + ".yaml";
             test::write_text(f.dir.file(name), test::read_file(f.scene));
             return JobCase{f.dir.path(), name, "out", {}, "out/s" + raw, "the scene path '"};
         }},
        {"the working folder", false,
         [](const test::FarmFolder& f, const std::string& raw, const std::string&) {
             const std::string folder = f.dir.file("w" + raw);
             test::write_text(folder + "/spin.yaml", test::read_file(f.scene));
             return JobCase{folder, "spin.yaml", "out", {}, "out/spin", "the working folder '"};
         }},
        {"the scene's camera name", true,
         [](const test::FarmFolder& f, const std::string& raw, const std::string& yaml) {
             test::write_text(f.dir.file("cam.yaml"), scene_text(yaml, kCameraPath));
             return JobCase{f.dir.path(), "cam.yaml",        "out",
                            {},           "out/cam/c" + raw, "'camera.name': holds"};
         }},
        {"the scene's output.path", true,
         [](const test::FarmFolder& f, const std::string& raw, const std::string& yaml) {
             // "p" + the value + "/{pass}...", as one YAML scalar. A '#' in
             // a template is a frame digit: '+' instead.
             auto no_hash = [](std::string text) {
                 std::replace(text.begin(), text.end(), '#', '+');
                 return text;
             };
             const std::string path = "\"{scene}/p" + no_hash(yaml.substr(1, yaml.size() - 2)) +
                                      "/{pass}.{frame}.{ext}\"";
             test::write_text(f.dir.file("path.yaml"), scene_text("main", path));
             return JobCase{
                 f.dir.path(),          "path.yaml", "out", {}, "out/path/p" + no_hash(raw),
                 "'output.path': holds"};
         }},
        {"-D camera.name", true,
         [](const test::FarmFolder& f, const std::string& raw, const std::string& yaml) {
             test::write_text(f.dir.file("cam.yaml"), scene_text("main", kCameraPath));
             return JobCase{f.dir.path(),
                            "cam.yaml",
                            "out",
                            {"camera.name=" + yaml},
                            "out/cam/c" + raw,
                            "'camera.name': holds"};
         }},
    };
    return all;
}

// The camera sources put a "c" before the value: names start with it.
std::string yaml_for(const Source& source, const std::string& yaml) {
    if (source.name == std::string("the scene's camera name") ||
        source.name == std::string("-D camera.name"))
        return "\"c" + yaml.substr(1);
    return yaml;
}

std::string farm_command(const JobCase& c, const std::string& kind, const std::string& script) {
    std::string args = "farm " + kind + " " + shell_quote(c.scene) + " -o " + shell_quote(c.out) +
                       " --script " + shell_quote(script);
    if (kind == "slurm") args += " --chunks 2";
    for (const std::string& d : c.defines) args += " -D " + shell_quote(d);
    return args;
}

// Slurm shows job names with only [A-Za-z0-9_.-]; every other byte is '_'.
std::string slurm_name(const std::string& name) {
    std::string out;
    for (unsigned char c : name)
        out += std::isalnum(c) || c == '_' || c == '.' || c == '-' ? static_cast<char>(c) : '_';
    return out;
}

test::RunResult check_file(const std::string& mode, const std::string& file) {
    return test::run_command("python3 " +
                             shell_quote(test::source_path("tests/farm/job_file_check.py")) + " " +
                             mode + " " + shell_quote(file));
}

// The words `facet render` gets, as the job writes them, before the
// frame and chunk options.
std::vector<std::string> render_words(const JobCase& c, bool absolute) {
    auto path = [&](const std::string& p) {
        return absolute ? (fs::path(c.folder) / p).lexically_normal().string() : p;
    };
    std::vector<std::string> words = {path(c.scene), "-o", path(c.out)};
    for (const std::string& d : c.defines) {
        words.push_back("-D");
        words.push_back(d);
    }
    return words;
}

void check_slurm_job(const test::FarmFolder& farm, const JobCase& c,
                     const std::string& scene_name) {
    const std::string script = c.folder + "/job.sh";
    // Slurm's reader: facet's job name, nothing else.
    const test::RunResult directives = check_file("sbatch", script);
    REQUIRE(directives.exit_code == 0);
    CHECK(nlohmann::json::parse(directives.output) ==
          nlohmann::json::array({"--job-name=" + slurm_name("facet-" + scene_name)}));
    // bash: the submission, then each step, with stubs for sbatch and facet.
    const std::string copy = farm.dir.file("run.sh");
    fs::copy_file(script, copy, fs::copy_options::overwrite_existing);
    const test::RunResult submitted = farm.run_script("", "run.sh");
    INFO(submitted.output);
    CHECK(submitted.exit_code == 0);
    const std::vector<std::string> sbatch = farm.recorded("sbatch");
    CHECK(std::count(sbatch.begin(), sbatch.end(), "--chdir=" + c.folder) == 2);
    const std::string stub = "FACET=" + shell_quote(farm.dir.file("bin/facet-stub"));
    CHECK(farm.run_script("FACET_FARM_STEP=render " + stub, "run.sh").exit_code == 0);
    CHECK(farm.run_script("FACET_FARM_STEP=merge " + stub, "run.sh").exit_code == 0);
    std::vector<std::string> expected = {"render"};
    for (const std::string& w : render_words(c, false)) expected.push_back(w);
    for (const char* w :
         {"--frames", "1-4", "--chunk-from-env", "--chunks", "2", "--skip-existing", "merge"})
        expected.push_back(w);
    expected.push_back(c.merge_folder);
    CHECK(farm.recorded("facet-stub") == expected);
    CHECK_FALSE(fs::exists(farm.dir.file("PWNED")));
    CHECK_FALSE(fs::exists(c.folder + "/PWNED"));
}

void check_openjd_job(const JobCase& c, const std::string& scene_name) {
    const test::RunResult loaded = check_file("yaml", c.folder + "/job.yaml");
    if (loaded.exit_code == 77)
        FACET_SKIP("python3-yaml is not installed (scripts/setup.sh --tests)");
    REQUIRE(loaded.exit_code == 0);
    const nlohmann::json t = nlohmann::json::parse(loaded.output);
    std::set<std::string> keys;
    for (const auto& [key, value] : t.items()) keys.insert(key);
    CHECK(keys == std::set<std::string>{"specificationVersion", "extensions", "name",
                                        "parameterDefinitions", "steps"});
    CHECK(t["name"] == "facet-" + scene_name);
    REQUIRE(t["steps"].size() == 2);
    std::vector<std::string> render = {"render"};
    for (const std::string& w : render_words(c, true)) render.push_back(w);
    for (const char* w : {"--frames", "{{Param.Frames}}", "--chunk-frames", "{{Task.Param.Frame}}",
                          "--skip-existing"})
        render.push_back(w);
    CHECK(t["steps"][0]["script"]["actions"]["onRun"]["args"] == nlohmann::json(render));
    const std::string merge = (fs::path(c.folder) / c.merge_folder).lexically_normal().string();
    CHECK(t["steps"][1]["script"]["actions"]["onRun"]["args"] ==
          nlohmann::json::array({"merge", merge}));
    for (const auto& step : t["steps"]) {
        std::set<std::string> step_keys;
        for (const auto& [key, value] : step.items()) step_keys.insert(key);
        CHECK(step_keys == (step["name"] == "Render"
                                ? std::set<std::string>{"name", "parameterSpace", "script"}
                                : std::set<std::string>{"name", "dependencies", "script"}));
    }
}

// The scene's name: its file's, without the extension.
std::string scene_name_of(const JobCase& c) {
    return fs::path(c.scene).stem().string();
}

}  // namespace

TEST_CASE(
    "a text from any source that holds a line break for bash, Slurm or YAML is refused before "
    "a job file is written, naming its source",
    "[farm][security]") {
    for (const Source& source : sources())
        for (const Breaker& b : kBreakers) {
            if (source.from_yaml && b.yaml.empty()) continue;
            const std::string raw = "a" + b.raw + "b";
            const std::string yaml = yaml_for(source, "\"a" + b.yaml + "b\"");
            for (const char* kind : {"slurm", "openjd"}) {
                test::FarmFolder farm;
                const JobCase c = source.make(farm, raw, yaml);
                INFO(source.name << " " << kind << " " << b.yaml);
                const test::RunResult r = farm.run_in(c.folder, farm_command(c, kind, "job.file"));
                INFO(r.output);
                CHECK(r.exit_code == 2);
                CHECK_THAT(r.output, Catch::Contains(c.refusal));
                CHECK_FALSE(fs::exists(c.folder + "/job.file"));
            }
        }
}

TEST_CASE(
    "a text from any source with shell, Slurm or YAML syntax in it reaches bash, sbatch and a "
    "YAML loader as exactly that text, and runs nothing",
    "[farm][security]") {
    for (const Source& source : sources())
        for (const std::string& value : kPlainHostile) {
            test::FarmFolder farm;
            const JobCase c = source.make(farm, value, yaml_for(source, yaml_text(value)));
            INFO(source.name << ": " << value);
            const test::RunResult slurm = farm.run_in(c.folder, farm_command(c, "slurm", "job.sh"));
            INFO(slurm.output);
            REQUIRE(slurm.exit_code == 0);
            check_slurm_job(farm, c, scene_name_of(c));
            const test::RunResult openjd =
                farm.run_in(c.folder, farm_command(c, "openjd", "job.yaml"));
            INFO(openjd.output);
            REQUIRE(openjd.exit_code == 0);
            check_openjd_job(c, scene_name_of(c));
        }
}
