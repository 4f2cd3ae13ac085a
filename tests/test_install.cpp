// Installing: cmake --install into a prefix that is then moved elsewhere,
// a render from there with the presets it installed (not the sources'),
// the man page and bash completion, and a Debian package built by CPack.
#include <catch2/catch.hpp>

#include <filesystem>

#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

TEST_CASE("install: a moved prefix renders with its own presets", "[install]") {
    TempDir dir("install");
    const std::string prefix = dir.file("prefix");
    const RunResult install =
        run_command("cmake --install '" + std::string(facet::test::build_dir()) + "' --prefix '" +
                    prefix + "' 2>&1");
    INFO(install.output);
    REQUIRE(install.exit_code == 0);
    // Relocatable: nothing in the files names the prefix they went to.
    const std::string moved = dir.file("elsewhere");
    fs::rename(prefix, moved);
    const std::string facet = "'" + moved + "/bin/facet'";
    CHECK_THAT(run_command(facet + " styles").output, Contains("toon "));
    // The presets come from the prefix, not from the source tree.
    fs::remove(moved + "/share/facet/styles/toon.yaml");
    CHECK_THAT(run_command(facet + " styles").output, !Contains("toon "));
    CHECK_THAT(run_command(facet + " styles").output, Contains("toon-outline"));

    fs::copy_file(source_path("tests/scenes/shapes.yaml"), dir.file("shapes.yaml"));
    const RunResult render =
        run_command("cd '" + dir.path() + "' && " + facet +
                    " render shapes.yaml --style gooch -f 1 --size 32x24 -q 2>&1");
    INFO(render.output);
    CHECK(render.exit_code == 0);
    CHECK(fs::exists(dir.file("out/shapes/color.0001.png")));

    CHECK(fs::exists(moved + "/share/man/man1/facet.1"));
    CHECK(fs::exists(moved + "/share/doc/facet/regression.md"));
    CHECK_THAT(read_file(moved + "/share/man/man1/facet.1"), Contains(".SS \"facet render\""));
    CHECK_THAT(read_file(moved + "/share/man/man1/facet.1"), Contains(".SS \"facet farm slurm\""));
}

TEST_CASE("install: bash completion completes commands, options and presets", "[install]") {
    const std::string script = std::string(facet::test::build_dir()) + "/facet.bash";
    auto complete = [&](const std::string& words, int index) {
        return run_command("bash -c 'source \"" + script + "\"; COMP_WORDS=(" + words +
                           "); COMP_CWORD=" + std::to_string(index) +
                           "; _facet; echo \"${COMPREPLY[*]}\"' 2>&1")
            .output;
    };
    CHECK(complete("facet ren", 1) == "render\n");
    CHECK_THAT(complete("facet render --fra", 2), Contains("--frames"));
    CHECK_THAT(complete("facet render --fra", 2), Contains("--frame"));
    CHECK(complete("facet render --style goo", 3) == "gooch\n");
    CHECK(complete("facet compare --update-reference mi", 3) == "missing\n");
}

TEST_CASE("install: CPack builds a Debian package with the program and presets", "[install]") {
    TempDir dir("cpack");
    const RunResult pack =
        run_command("cd '" + dir.path() + "' && cpack -G DEB --config '" +
                    std::string(facet::test::build_dir()) + "/CPackConfig.cmake' 2>&1");
    INFO(pack.output);
    REQUIRE(pack.exit_code == 0);
    std::string deb;
    for (const auto& entry : fs::directory_iterator(dir.path()))
        if (entry.path().extension() == ".deb") deb = entry.path().string();
    REQUIRE_FALSE(deb.empty());
    const std::string contents = run_command("dpkg-deb -c '" + deb + "'").output;
    CHECK_THAT(contents, Contains("./usr/bin/facet"));
    CHECK_THAT(contents, Contains("./usr/share/facet/styles/toon.yaml"));
    CHECK_THAT(contents, Contains("./usr/share/man/man1/facet.1"));
    const std::string depends = run_command("dpkg-deb -f '" + deb + "' Depends").output;
    CHECK_THAT(depends, Contains("libavcodec"));
}
