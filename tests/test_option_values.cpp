// The values options take (cli/option_values.hpp) and the number reading
// under them (core/number_text.hpp): one way to read a number, all of the
// text or nothing, and one error for a value an option cannot take. The
// last cases run facet itself, as a user would.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cli/option_values.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"
#include "support.hpp"

using namespace facet;
using Catch::Matchers::Contains;
using test::require_input_error;

TEST_CASE("a whole number is all of its text, in decimal, within long long", "[option_values]") {
    CHECK(read_whole_number("0") == 0);
    CHECK(read_whole_number("42") == 42);
    CHECK(read_whole_number("-7") == -7);
    CHECK(read_whole_number("010") == 10);  // decimal: not octal eight
    CHECK(read_whole_number("9223372036854775807") == 9223372036854775807LL);
    for (const char* refused : {"", " 1", "1 ", "+1", "1x", "12abc", "0x10", "1.0", "1e3", "-",
                                "1,2", "9223372036854775808", "99999999999999999999"}) {
        INFO('\'' << refused << '\'');
        CHECK_FALSE(read_whole_number(refused));
    }
}

TEST_CASE("a decimal number is all of its text and finite", "[option_values]") {
    CHECK(read_finite_number("2") == 2.0);
    CHECK(read_finite_number("-0.5") == -0.5);
    CHECK(read_finite_number(".5") == 0.5);
    CHECK(read_finite_number("1e-3") == 0.001);
    for (const char* refused : {"", "nan", "NaN", "inf", "-inf", "infinity", "1e999", " 1", "1 ",
                                "+1", "0x1p3", "1,5", "24fps", "1.2.3"}) {
        INFO('\'' << refused << '\'');
        CHECK_FALSE(read_finite_number(refused));
    }
}

TEST_CASE("the error of a bad value names the option, says what it takes and quotes the value",
          "[option_values]") {
    try {
        parse_whole_number("4k", "--threads", 0, 256);
        FAIL("4k was taken");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        CHECK(e.where().origin == "command line --threads");
        CHECK(std::string(e.what()) ==
              "command line --threads: expected a whole number from 0 to 256, got '4k'");
    }
    require_input_error([] { fail_option_value("--mask", "1,2", "x,y,width,height", "2 numbers"); },
                        "command line --mask: expected x,y,width,height, got '1,2': 2 numbers");
}

TEST_CASE("whole numbers are checked against their range", "[option_values]") {
    CHECK(parse_whole_number("0", "--threads", 0, 256) == 0);
    CHECK(parse_whole_number("256", "--threads", 0, 256) == 256);
    CHECK(parse_whole_number("-3", "-f", -10, 10) == -3);
    for (const char* refused :
         {"-1", "257", "", " 4", "4 ", "4k", "0x4", "+4", "1.5", "99999999999999999999"}) {
        INFO('\'' << refused << '\'');
        require_input_error(
            [&] { parse_whole_number(refused, "--threads", 0, 256); },
            "--threads: expected a whole number from 0 to 256, got '" + std::string(refused) + "'");
    }
    // A description of its own replaces the range in the error.
    require_input_error([] { parse_whole_number("x", "--cell", 1, 9, "a cell width"); },
                        "--cell: expected a cell width, got 'x'");
}

TEST_CASE("decimal numbers are finite and within their range", "[option_values]") {
    CHECK(parse_decimal_number("24", "--fps", 0.01, 1000) == 24.0);
    CHECK(parse_decimal_number("0.01", "--fps", 0.01, 1000) == 0.01);
    CHECK(parse_decimal_number("23.976", "--fps", 0.01, 1000) == 23.976);
    for (const char* refused : {"0", "1000.5", "nan", "inf", "1e999", "24fps", " 24", ""}) {
        INFO('\'' << refused << '\'');
        require_input_error(
            [&] { parse_decimal_number(refused, "--fps", 0.01, 1000); },
            "--fps: expected a number from 0.01 to 1000, got '" + std::string(refused) + "'");
    }
}

TEST_CASE("a size is WIDTHxHEIGHT, each side from 1 to the largest image side", "[option_values]") {
    CHECK(parse_size("1280x720", "--size") == std::pair{1280, 720});
    CHECK(parse_size("32X24", "--size") == std::pair{32, 24});
    CHECK(parse_size("1x16384", "--size") == std::pair{1, 16384});
    for (const char* refused :
         {"",          "0x24",   "24x0",     "64x",     "x64",          "big",    "64by48",
          "100000x10", "12abc",  "12x12abc", "12x12x1", " 12x12",       "12x12 ", "12 x12",
          "12x 12",    "+12x12", "12x+12",   "-1x5",    "2147483648x1", "1.5x2",  "0x10x10"}) {
        INFO('\'' << refused << '\'');
        require_input_error([&] { parse_size(refused, "--size"); },
                            "command line --size: expected WIDTHxHEIGHT with each side from 1 to "
                            "16384 (e.g. 1280x720), got '" +
                                std::string(refused) + "'");
    }
}

TEST_CASE("a list is its comma-separated items as typed, none of them empty", "[option_values]") {
    using List = std::vector<std::string>;
    CHECK(parse_list("", "--camera", "names").empty());  // the option was not given
    CHECK(parse_list("front", "--camera", "names") == List{"front"});
    CHECK(parse_list("front,side", "--camera", "names") == List{"front", "side"});
    CHECK(parse_list("close up,all", "--camera", "names") == List{"close up", "all"});
    struct Refused {
        const char* text;
        const char* why;
    };
    for (const Refused& r :
         {Refused{",", "item 1 is empty"}, Refused{"a,", "item 2 is empty"},
          Refused{",a", "item 1 is empty"}, Refused{"a,,b", "item 2 is empty"}}) {
        INFO(r.text);
        require_input_error(
            [&] { parse_list(r.text, "--camera", "names"); },
            "command line --camera: expected names, got '" + std::string(r.text) + "': " + r.why);
    }
}

TEST_CASE("a list of whole numbers has at least one, each in its range", "[option_values]") {
    const std::string expected = "thread counts";
    CHECK(parse_whole_number_list("1,2,4", "--threads", 0, 256, expected) ==
          std::vector<int>{1, 2, 4});
    CHECK(parse_whole_number_list("0", "--threads", 0, 256, expected) == std::vector<int>{0});
    CHECK(parse_whole_number_list("4,4", "--threads", 0, 256, expected) == std::vector<int>{4, 4});
    struct Refused {
        const char* text;
        const char* says;
    };
    for (const Refused& r : {
             Refused{"", "got ''"},
             Refused{",", "item 1 is empty"},
             Refused{"1,,2", "item 2 is empty"},
             Refused{"1,2,", "item 3 is empty"},
             Refused{"1,x", "'x' is not a whole number from 0 to 256"},
             Refused{"1, 2", "' 2' is not"},
             Refused{"-1", "'-1' is not"},
             Refused{"300", "'300' is not"},
             Refused{"2,99999999999999999999", "'99999999999999999999' is not"},
             Refused{"1;2", "'1;2' is not"},
         }) {
        INFO(r.text);
        require_input_error(
            [&] { parse_whole_number_list(r.text, "--threads", 0, 256, expected); },
            "command line --threads: expected thread counts, got '" + std::string(r.text) + "'");
        require_input_error([&] { parse_whole_number_list(r.text, "--threads", 0, 256, expected); },
                            r.says);
    }
}

TEST_CASE("facet refuses a bad --size or --threads with exit code 2, naming the option",
          "[option_values][cli]") {
    test::TempDir dir("option-values");
    const std::string scene = "'" + test::source_path("tests/scenes/shapes.yaml") + "' ";
    const std::string out = dir.file("out");
    const std::string to_folder = " -q -o '" + out + "'";
    const std::string to_png = " -q -o '" + out + "/sheet.png'";
    struct Case {
        std::string command;
        std::string option;
        std::string says;  // the rest of the message, or part of it
    };
    const std::vector<Case> cases = {
        {"render " + scene + "--size 12x12abc" + to_folder, "--size",
         "expected WIDTHxHEIGHT with each side from 1 to 16384 (e.g. 1280x720), got '12x12abc'"},
        {"render " + scene + "--size ' 64x48'" + to_folder, "--size", "got ' 64x48'"},
        {"render " + scene + "--threads 4k" + to_folder, "--threads",
         "expected a whole number from 0 (one per core) to 256, got '4k'"},
        {"render " + scene + "--threads 0x4" + to_folder, "--threads", "got '0x4'"},
        {"render " + scene + "--threads 257" + to_folder, "--threads", "got '257'"},
        {"bench " + scene + "--threads 1,,2" + to_folder, "--threads",
         "got '1,,2': item 2 is empty"},
        {"sheet " + scene + "--styles flat --cell 320x" + to_png, "--size", "got '320x'"},
        {"render " + scene + "-f 1e3" + to_folder, "-f", "expected a frame number"},
        {"farm slurm " + scene + "--chunks 2x" + to_folder, "--chunks",
         "expected a whole number from 1 to 100000, got '2x'"},
    };
    for (const Case& c : cases) {
        INFO(c.command);
        const test::RunResult r = test::run_facet(c.command);
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("facet: error: command line " + c.option + ": expected"));
        CHECK_THAT(r.output, Contains(c.says));
        CHECK_FALSE(std::filesystem::exists(out));
    }
}
