// One vocabulary across the subcommands, and help with mistakes (README,
// "Command-line options"): each case is an inconsistency or a silent
// surprise that was found once and must not come back.
#include <catch2/catch.hpp>

#include <filesystem>

#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string scene() {
    std::string quoted = "'";
    quoted += source_path("tests/scenes/shapes.yaml");
    quoted += "'";
    return quoted;
}

}  // namespace

TEST_CASE("cli: -o/--output (and --out) name the output of every writing command", "[cli]") {
    TempDir dir("cli-output");
    for (const char* flag : {"-o", "--output", "--out"}) {
        INFO(flag);
        const std::string out = dir.file(std::string("render") + flag);
        const RunResult r =
            run_facet("render " + scene() + " -f 1 --size 32x24 -q " + flag + " '" + out + "'");
        CHECK(r.exit_code == 0);
        CHECK(std::filesystem::exists(out + "/shapes/manifest.json"));
    }
    const std::string sheet = dir.file("sheet.png");
    CHECK(
        run_facet("sheet " + scene() + " --styles flat --size 32x24 -f 2 -q --out '" + sheet + "'")
            .exit_code == 0);
    CHECK(std::filesystem::exists(sheet));
    const std::string bench = dir.file("bench");
    CHECK(run_facet("bench " + scene() + " --threads 0,1 -f 1 --size 32x24 -q --output '" + bench +
                    "'")
              .exit_code == 0);
    CHECK(std::filesystem::exists(bench + "/shapes-threads.md"));
    const std::string report = dir.file("report");
    CHECK(run_facet("compare '" + dir.file("render-o/shapes") + "' '" +
                    dir.file("render--out/shapes") + "' -q -o '" + report + "'")
              .exit_code == 0);
    CHECK(std::filesystem::exists(report + "/report.json"));
}

TEST_CASE("cli: frames are chosen the same way everywhere, and only inside the scene", "[cli]") {
    // shapes.yaml has frames 1-3.
    const RunResult outside =
        run_facet("render " + scene() + " --frames 100 --size 32x24 -o /nonexistent -q");
    CHECK(outside.exit_code == 2);
    CHECK_THAT(outside.output, Contains("frame 100 is outside the scene's frames 1-3"));
    CHECK_THAT(outside.output, Contains("--allow-outside"));
    const RunResult validate = run_facet("validate " + scene() + " --frames 1-1000");
    CHECK(validate.exit_code == 2);
    CHECK_THAT(validate.output, Contains("frame 4 is outside"));
    // validate reports what it was given.
    const RunResult some = run_facet("validate " + scene() + " -s 2 -e 3");
    CHECK(some.exit_code == 0);
    CHECK_THAT(some.output, Contains("frames 2..3 of the scene's 1-3 (2 frames)"));
    CHECK_THAT(run_facet("validate " + scene() + " -f 2").output, Contains("(1 frame)"));
    CHECK(run_facet("validate " + scene() + " -f 5 --allow-outside").exit_code == 0);
    const RunResult both = run_facet("validate " + scene() + " -f 2 --frames 1-2");
    CHECK(both.exit_code == 2);
    CHECK_THAT(both.output, Contains("give frames one way"));
    CHECK(run_facet("sheet " + scene() + " --styles flat -f 9 -o /nonexistent/x.png").exit_code ==
          2);
    // -s/-e keep the scene's step, inside its range, and beyond it only when allowed.
    const std::string stepped = " -D output.frames=1-9:2 ";
    CHECK_THAT(run_facet("validate " + scene() + stepped + "-s 4 -e 8").output,
               Contains("frames 5..7 of the scene's 1-9:2 (2 frames)"));
    CHECK(run_facet("validate " + scene() + stepped + "-s 4 -e 13").exit_code == 2);
    CHECK_THAT(run_facet("validate " + scene() + stepped + "-s 4 -e 13 --allow-outside").output,
               Contains("frames 5..13 of the scene's 1-9:2 (5 frames)"));
    // -j: every Nth of the frames -s/-e give, or of the scene's (Blender's -j).
    const std::string ten = " -D output.frames=1-10 --passes color --formats png --dry-run ";
    const RunResult jump = run_facet("render " + scene() + ten + "-s 2 -e 9 -j 3");
    CHECK(jump.exit_code == 0);
    CHECK(jump.output.find("color.0002.png\n") != std::string::npos);
    CHECK(jump.output.find("color.0005.png\n") != std::string::npos);
    CHECK(jump.output.find("color.0008.png\n") != std::string::npos);
    CHECK(jump.output.find("color.0003.png") == std::string::npos);
    CHECK(jump.output.find("color.0009.png") == std::string::npos);
    const RunResult alone = run_facet("render " + scene() + ten + "-j 4");
    CHECK_THAT(alone.output, Contains("color.0009.png") && !Contains("color.0002.png"));
    CHECK(run_facet("render " + scene() + ten + "--frames 1-4 -j 2").exit_code == 2);
}

TEST_CASE("cli: mistakes get a did-you-mean", "[cli]") {
    const RunResult command = run_facet("rendr " + scene());
    CHECK(command.exit_code == 2);
    CHECK_THAT(command.output, Contains("unknown command 'rendr'; did you mean 'render'?"));
    CHECK_THAT(command.output, Contains("commands: render, compare, validate"));
    const RunResult nested = run_facet("farm slurmm " + scene() + " --chunks 2");
    CHECK(nested.exit_code == 2);
    CHECK_THAT(nested.output, Contains("unknown command 'slurmm'; did you mean 'slurm'?"));
    const RunResult option = run_facet("render " + scene() + " --fames 1");
    CHECK(option.exit_code == 2);
    CHECK_THAT(option.output,
               Contains("unknown option '--fames' for facet render; did you mean '--frames'?"));
    const RunResult style = run_facet("validate " + scene() + " --style tooon");
    CHECK(style.exit_code == 2);
    CHECK_THAT(style.output, Contains("no style preset named 'tooon'; did you mean 'toon'?"));
    const RunResult pass = run_facet("validate " + scene() + " --passes colr");
    CHECK(pass.exit_code == 2);
    CHECK_THAT(
        pass.output,
        Contains("got 'colr'; did you mean 'color'? (must be one of: color, alpha, depth, normal, "
                 "object_id, material_id, uv, position, motion, lines)"));
    const RunResult extra = run_facet("validate " + scene() + " stray");
    CHECK(extra.exit_code == 2);
    CHECK_THAT(extra.output, Contains("unexpected argument 'stray' for facet validate"));
}

TEST_CASE("cli: facet help and facet help COMMAND", "[cli]") {
    const RunResult all = run_facet("help");
    CHECK(all.exit_code == 0);
    CHECK_THAT(all.output, Contains("render"));
    CHECK_THAT(all.output, Contains("compare"));
    const RunResult render = run_facet("help render");
    CHECK(render.exit_code == 0);
    CHECK_THAT(render.output, Contains("--frames"));
    CHECK_THAT(render.output, Contains("-o,--output"));
    const RunResult typo = run_facet("help rendr");
    CHECK(typo.exit_code == 2);
    CHECK_THAT(typo.output, Contains("did you mean 'render'?"));
}

TEST_CASE("cli: -D reaches list items by name, and explains YAML mappings", "[cli]") {
    CHECK(run_facet("validate " + scene() + " -D objects.cube.material.color=[1,0,0]").exit_code ==
          0);
    const RunResult typo =
        run_facet("validate " + scene() + " -D objects.cub.material.color=[1,0,0]");
    CHECK(typo.exit_code == 2);
    CHECK_THAT(typo.output, Contains("'objects' has no item named 'cub'; did you mean 'cube'?"));
    CHECK_THAT(typo.output, Contains("or a name: sphere, cube, cylinder, cone, floor"));
    const RunResult colon = run_facet("validate " + scene() + " -D 'output.path=a: b'");
    CHECK(colon.exit_code == 2);
    CHECK_THAT(colon.output, Contains("YAML reads 'a: b' as a mapping"));
    // What bash's brace expansion makes of -D objects.0.material={color:[1,0,0]}.
    const RunResult split = run_facet(
        "validate " + scene() +
        " -D 'objects.0.material=color:[1' 'objects.0.material=0' 'objects.0.material=0]'");
    CHECK(split.exit_code == 2);
    CHECK_THAT(split.output, Contains("a -D value that the shell split"));
}

TEST_CASE("cli: totals use correct plurals, and a sheet is PNG or JPEG", "[cli]") {
    TempDir dir("cli-plurals");
    const RunResult one =
        run_facet("render " + scene() + " -f 1 --size 32x24 --passes color --formats png -o '" +
                  dir.file("out") + "'");
    CHECK_THAT(one.output, Contains("wrote 1 file to"));
    const RunResult sheet = run_facet("sheet " + scene() + " --styles flat --size 32x24 -o '" +
                                      dir.file("s.png") + "'");
    CHECK_THAT(sheet.output, Contains("(1 cell)"));
    // A sheet is written in the format its name says: PNG or JPEG.
    const std::string jpg = dir.file("s.jpg");
    const RunResult jpeg =
        run_facet("sheet " + scene() + " --styles flat --size 32x24 -q -o '" + jpg + "'");
    CHECK(jpeg.exit_code == 0);
    const std::string bytes = read_file(jpg);
    REQUIRE(bytes.size() > 4);
    CHECK(static_cast<unsigned char>(bytes[0]) == 0xff);  // JPEG's SOI marker
    CHECK(static_cast<unsigned char>(bytes[1]) == 0xd8);
    const RunResult tiff = run_facet("sheet " + scene() + " --styles flat --size 32x24 -o '" +
                                     dir.file("s.tiff") + "'");
    CHECK(tiff.exit_code == 2);
    CHECK_THAT(tiff.output, Contains("*.png, *.jpg or *.jpeg"));
    CHECK_FALSE(std::filesystem::exists(dir.file("s.tiff")));
}
