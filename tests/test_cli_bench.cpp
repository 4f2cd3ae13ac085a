// `facet bench`: the thread study writes a table with one row per thread
// count and a plot; bad thread lists are usage errors.
#include <catch2/catch.hpp>

#include <filesystem>

#include "output/encoders.hpp"
#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

TEST_CASE("facet bench writes a markdown table and a plot of the thread study", "[cli][bench]") {
    TempDir dir("bench");
    const std::string out = dir.file("study");
    RunResult r = run_facet("bench '" + source_path("tests/scenes/shapes.yaml") +
                            "' --threads 1,2,3 --frames 1-2 --size 64x48 -q -o '" + out + "'");
    REQUIRE(r.exit_code == 0);
    const std::string table = read_file(out + "/shapes-threads.md");
    CHECK_THAT(table, Contains("64x48, 2 frames"));
    for (const char* row : {"\n| 1 | ", "\n| 2 | ", "\n| 3 | "}) CHECK_THAT(table, Contains(row));
    CHECK_THAT(table, Contains("| 1.00x | 100% |"));  // one thread is the baseline
    const facet::DecodedPng plot = facet::read_png(out + "/shapes-threads.png");
    CHECK(plot.width == 840);
    CHECK(plot.height == 320);
}

TEST_CASE("facet bench rejects bad thread lists and writes nothing", "[cli][bench]") {
    TempDir dir("bench");
    const std::string out = dir.file("study");
    // 0 is not among them: it means one thread per core, as for render.
    for (const char* threads : {"-1", "1,x", "300", ",", "1,2,", "2 ", "0x2"}) {
        INFO(threads);
        RunResult r = run_facet("bench '" + source_path("tests/scenes/shapes.yaml") +
                                "' --threads '" + threads + "' -o '" + out + "'");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("command line --threads: expected") &&
                                 Contains("got '" + std::string(threads) + "'"));
        CHECK_FALSE(std::filesystem::exists(out));
    }
}
