// facet::parse_frame_ranges: the frame list syntax of docs/scene-format.md ("Frame ranges")
// ("1-120", "1-120:2", "1,5,10-20"), inclusive ranges, sorted and distinct.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/frame_range.hpp"

using facet::parse_frame_ranges;

namespace {

// first, first+step, ... up to and including last (when it is on the step).
std::vector<int> sequence(int first, int last, int step = 1) {
    std::vector<int> out;
    for (int f = first; f <= last; f += step) out.push_back(f);
    return out;
}

}  // namespace

TEST_CASE("a single frame number is a list of one frame", "[frame_range]") {
    CHECK(parse_frame_ranges("1") == std::vector<int>{1});
    CHECK(parse_frame_ranges("42") == std::vector<int>{42});
    CHECK(parse_frame_ranges("0") == std::vector<int>{0});
    CHECK(parse_frame_ranges("-7") == std::vector<int>{-7});
}

TEST_CASE("a range includes both ends", "[frame_range]") {
    auto frames = parse_frame_ranges("1-120");
    REQUIRE(frames.size() == 120);
    CHECK(frames.front() == 1);
    CHECK(frames.back() == 120);
    CHECK(frames == sequence(1, 120));
    CHECK(parse_frame_ranges("3-3") == std::vector<int>{3});
    CHECK(parse_frame_ranges("9-10") == std::vector<int>{9, 10});
}

TEST_CASE("a step takes every n-th frame from the first", "[frame_range]") {
    auto frames = parse_frame_ranges("1-120:2");
    REQUIRE(frames.size() == 60);  // 1, 3, ..., 119
    CHECK(frames.front() == 1);
    CHECK(frames.back() == 119);
    CHECK(frames == sequence(1, 119, 2));

    // The last frame is included only when it falls on the step.
    CHECK(parse_frame_ranges("1-10:3") == std::vector<int>{1, 4, 7, 10});
    CHECK(parse_frame_ranges("1-10:4") == std::vector<int>{1, 5, 9});
    CHECK(parse_frame_ranges("0-10:5") == std::vector<int>{0, 5, 10});
    // A step larger than the range leaves only the first frame.
    CHECK(parse_frame_ranges("5-8:100") == std::vector<int>{5});
    // A step after a single frame changes nothing.
    CHECK(parse_frame_ranges("7:3") == std::vector<int>{7});
}

TEST_CASE("comma-separated items combine single frames and ranges", "[frame_range]") {
    std::vector<int> expected = {1, 5, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
    CHECK(parse_frame_ranges("1,5,10-20") == expected);
    CHECK(parse_frame_ranges("1-4,10-20:5,100") == std::vector<int>{1, 2, 3, 4, 10, 15, 20, 100});
    CHECK(parse_frame_ranges("2-6:2,3-7:2") == std::vector<int>{2, 3, 4, 5, 6, 7});
}

TEST_CASE("items out of order are sorted and duplicates merged", "[frame_range]") {
    CHECK(parse_frame_ranges("10-12,1-3") == std::vector<int>{1, 2, 3, 10, 11, 12});
    CHECK(parse_frame_ranges("5,5,5") == std::vector<int>{5});
    CHECK(parse_frame_ranges("1-5,3-8") == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8});
    CHECK(parse_frame_ranges("20,1-10:2,4,3") == std::vector<int>{1, 3, 4, 5, 7, 9, 20});
    CHECK(parse_frame_ranges("1-10,2-9") == sequence(1, 10));
}

TEST_CASE("spaces around numbers, dashes, colons and commas are allowed", "[frame_range]") {
    CHECK(parse_frame_ranges(" 1 - 3 ") == std::vector<int>{1, 2, 3});
    CHECK(parse_frame_ranges("1, 5 ,10-12") == std::vector<int>{1, 5, 10, 11, 12});
    CHECK(parse_frame_ranges("1-9 : 4") == std::vector<int>{1, 5, 9});
    CHECK(parse_frame_ranges("  8  ") == std::vector<int>{8});
}

TEST_CASE("negative frame numbers, also as range bounds", "[frame_range]") {
    CHECK(parse_frame_ranges("-5--1") == std::vector<int>{-5, -4, -3, -2, -1});
    CHECK(parse_frame_ranges("-2-2") == std::vector<int>{-2, -1, 0, 1, 2});
    CHECK(parse_frame_ranges("-10--2:4") == std::vector<int>{-10, -6, -2});
    CHECK(parse_frame_ranges("3,-3") == std::vector<int>{-3, 3});
    CHECK(parse_frame_ranges(" -5 - -4 ") == std::vector<int>{-5, -4});
}

TEST_CASE("a list of exactly one million frames is still accepted", "[frame_range]") {
    // 1..1000000 is 1000000 frames; the limit is "more than one million".
    auto frames = parse_frame_ranges("1-1000000");
    REQUIRE(frames.size() == 1000000);
    CHECK(frames.front() == 1);
    CHECK(frames.back() == 1000000);
    // With a step the count is what matters, not the span.
    auto stepped = parse_frame_ranges("0-1999998:2");
    CHECK(stepped.size() == 1000000);
    CHECK(stepped.back() == 1999998);
}

TEST_CASE("invalid frame lists throw facet::Error", "[frame_range]") {
    auto invalid = GENERATE(as<std::string>{},
                            "",             // nothing
                            " ",            // only spaces
                            ",",            // only a separator
                            "a",            // not a number
                            "1a",           // trailing garbage
                            "1.5",          // not whole
                            "+1",           // no plus sign
                            "1 2",          // two numbers without a separator
                            "5-1",          // ends before it starts
                            "-1--5",        // same, negative
                            "1-10:0",       // zero step
                            "1-10:-2",      // negative step
                            "1-10:",        // missing step
                            ":2",           // missing range
                            "1-10:x",       // step not a number
                            "1,,2",         // empty item
                            "1,",           // trailing comma
                            ",1",           // leading comma
                            "1, ,2",        // item of spaces
                            "1-",           // missing end
                            "-",            // only a dash
                            "--1",          // dash without a start
                            "1-2-3",        // two dashes
                            "99999999999",  // does not fit an int
                            "1-99999999999",
                            "1-1000001",                // more than one million frames
                            "-2147483648-2147483647",   // the whole int range
                            "1-600000,700001-1300000",  // too many in total
                            "x-5", "5-x");
    CAPTURE(invalid);
    CHECK_THROWS_AS(parse_frame_ranges(invalid), facet::Error);
}

TEST_CASE("frame list errors say what is wrong", "[frame_range]") {
    CHECK_THROWS_WITH(parse_frame_ranges(""), Catch::Contains("empty"));
    CHECK_THROWS_WITH(parse_frame_ranges("1,,2"), Catch::Contains("empty item"));
    CHECK_THROWS_WITH(parse_frame_ranges("5-1"),
                      Catch::Contains("5-1") && Catch::Contains("before"));
    CHECK_THROWS_WITH(parse_frame_ranges("1-10:0"), Catch::Contains("step"));
    CHECK_THROWS_WITH(parse_frame_ranges("1-b"), Catch::Contains("'b'") && Catch::Contains("1-b"));
    CHECK_THROWS_WITH(parse_frame_ranges("1-5000000"), Catch::Contains("1000000"));
}
