// The ./facet wrapper (README): it runs scripts/setup.sh only when the
// build is missing or older than what it is built from, and otherwise
// reaches the program at once. Checked on a copy of the wrapper in a
// made-up checkout whose setup.sh notes each run and whose "program"
// prints its arguments.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "support.hpp"

namespace fs = std::filesystem;
using facet::test::read_file;
using facet::test::run_command;
using facet::test::write_text;

namespace {

struct Checkout {
    facet::test::TempDir dir{"wrapper"};
    std::string root = dir.path();
    Checkout() {
        fs::copy_file(facet::test::source_dir() + "/facet", root + "/facet");
        fs::create_directories(root + "/src/core");
        fs::create_directories(root + "/cmake");
        fs::create_directories(root + "/scripts");
        write_text(root + "/src/core/a.cpp", "int a;\n");
        write_text(root + "/CMakeLists.txt", "\n");
        // setup.sh's contract as the wrapper sees it: it builds the program
        // and leaves the stamp.
        write_text(
            root + "/scripts/setup.sh",
            "#!/bin/sh\n"
            "echo run >> \"$(dirname \"$0\")/../setup-runs\"\n"
            "mkdir -p \"$(dirname \"$0\")/../build\"\n"
            "printf '#!/bin/sh\\necho program \"$@\"\\n' > \"$(dirname \"$0\")/../build/facet\"\n"
            "chmod +x \"$(dirname \"$0\")/../build/facet\"\n"
            "touch \"$(dirname \"$0\")/../build/setup.stamp\"\n");
        fs::permissions(root + "/scripts/setup.sh", fs::perms::owner_all);
    }
    int setup_runs() const {
        if (!fs::exists(root + "/setup-runs")) return 0;
        const std::string text = read_file(root + "/setup-runs");
        return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    }
    std::string run() const {
        return run_command("FACET_BUILD_DIR= '" + root + "/facet' --version 2>&1").output;
    }
};

}  // namespace

TEST_CASE("./facet runs setup.sh when there is no build, then not while the stamp is current",
          "[cli][wrapper]") {
    const Checkout c;
    CHECK(c.run() == "program --version\n");
    CHECK(c.setup_runs() == 1);
    CHECK(c.run() == "program --version\n");
    CHECK(c.run() == "program --version\n");
    CHECK(c.setup_runs() == 1);
}

TEST_CASE("./facet runs setup.sh again once a source is newer than the stamp", "[cli][wrapper]") {
    const Checkout c;
    c.run();
    REQUIRE(c.setup_runs() == 1);
    // The stamp put back in time: every source is now newer.
    REQUIRE(run_command("touch -d '2000-01-01' '" + c.root + "/build/setup.stamp'").exit_code == 0);
    CHECK(c.run() == "program --version\n");
    CHECK(c.setup_runs() == 2);
    // A build dir without its stamp (setup.sh did not finish) builds again.
    fs::remove(c.root + "/build/setup.stamp");
    c.run();
    CHECK(c.setup_runs() == 3);
}

TEST_CASE("./facet runs setup.sh again once a style preset or a worktree's branch is newer",
          "[cli][wrapper]") {
    // Presets are read from the checkout at run time, and the build's
    // commit check says whether the checkout is dirty: an edited preset
    // must reach that check, as a new commit must, also in a linked
    // worktree, whose .git is a file naming its folder.
    const Checkout c;
    fs::create_directories(c.root + "/styles");
    fs::create_directories(c.root + "/gitdirs/wt");
    fs::create_directories(c.root + "/gitdirs/common/refs/heads");
    write_text(c.root + "/styles/clay.yaml", "shading: phong\n");
    write_text(c.root + "/gitdirs/wt/HEAD", "ref: refs/heads/main\n");
    write_text(c.root + "/gitdirs/wt/commondir", "../common\n");
    write_text(c.root + "/gitdirs/common/refs/heads/main", "0123\n");
    write_text(c.root + "/.git", "gitdir: gitdirs/wt\n");
    c.run();
    REQUIRE(c.setup_runs() == 1);
    // Everything older than the stamp: no setup.
    auto age_all = [&] {
        REQUIRE(run_command("find '" + c.root +
                            "' -exec touch -d '1990-01-01' {} + && touch -d "
                            "'2000-01-01' '" +
                            c.root + "/build/setup.stamp'")
                    .exit_code == 0);
    };
    age_all();
    c.run();
    CHECK(c.setup_runs() == 1);
    write_text(c.root + "/styles/clay.yaml", "shading: blinn_phong\n");
    c.run();
    CHECK(c.setup_runs() == 2);
    age_all();
    write_text(c.root + "/gitdirs/common/refs/heads/main", "4567\n");
    c.run();
    CHECK(c.setup_runs() == 3);
    age_all();
    c.run();
    CHECK(c.setup_runs() == 3);
}
