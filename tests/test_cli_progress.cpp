// Progress as users see it: a bar redrawn in place in a 40-column terminal
// (a real pseudo-terminal through util-linux's `script`), and one line per
// image in logs, with elapsed time, ETA as h:mm:ss and a summary.
#include <catch2/catch.hpp>

#include <regex>

#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

TEST_CASE("progress: in a 40-column terminal the bar fits and is redrawn in place",
          "[cli][progress]") {
    TempDir dir("progress-pty");
    const std::string log = dir.file("pty.log");
    const std::string command = "stty cols 40; '" + std::string(facet::test::facet_executable()) +
                                "' render '" + source_path("tests/scenes/shapes.yaml") +
                                "' --size 48x32 --frames 1-3 -o '" + dir.file("out") + "'";
    const RunResult r =
        run_command("script -q -e -c \"" + command + "\" '" + log + "' > /dev/null 2>&1");
    REQUIRE(r.exit_code == 0);
    const std::string text = read_file(log);
    // The bar's redraws: the pieces between carriage returns, each without
    // the erase-to-end code. None may reach the 40th column, or it would wrap.
    std::vector<std::string> bars;
    size_t at = 0;
    while ((at = text.find('\r', at)) != std::string::npos) {
        const size_t end = text.find_first_of("\r\n", at + 1);
        std::string piece =
            text.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
        const size_t erase = piece.find("\x1b[K");
        if (erase != std::string::npos) piece.erase(erase);
        if (!piece.empty() && piece[0] == '[') bars.push_back(piece);
        at = end == std::string::npos ? text.size() : end;
    }
    INFO(text);
    REQUIRE(bars.size() >= 4);  // before the first frame, then one per frame
    for (const std::string& bar : bars) CHECK(bar.size() <= 39);
    CHECK_THAT(bars.front(), Contains("0/3 0%"));
    CHECK_THAT(bars.back(), Contains("3/3 100%"));
    CHECK_THAT(bars.back(), Contains("eta 0:00:00"));  // nothing left, however slow
    // The times are whatever the machine took: only their format is checked.
    CHECK(std::regex_search(text, std::regex(R"(rendered 3 images in \d+:\d\d:\d\d)")));
}

TEST_CASE("progress: in a log, one line per image with elapsed time, camera and ETA",
          "[cli][progress]") {
    TempDir dir("progress-log");
    const RunResult r = run_facet("render '" + source_path("tests/scenes/shapes.yaml") +
                                  "' --size 48x32 --frames 1-2 -o '" + dir.file("out") + "'");
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("rendering 'shapes' to "));
    // Two encoders may finish out of order: the count is of images written.
    CHECK(std::regex_search(
        r.output,
        std::regex(
            R"(\[\d+:\d\d:\d\d\] frame [12] camera main \(1/2, 50%\) rendered in [0-9.]+ ms, wrote color\.000[12]\.png in [0-9.]+ ms, eta \d+:\d\d:\d\d)")));
    CHECK(std::regex_search(
        r.output,
        std::regex(
            R"(rendered 2 images in \d+:\d\d:\d\d \([0-9.]+ (ms|s) per image, [0-9.]+ fps\))")));
}
