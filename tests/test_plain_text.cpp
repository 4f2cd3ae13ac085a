// Text that cannot end a line for any reader of a file facet writes
// (core/plain_text.hpp), checked against the readers' own definitions: a
// YAML 1.1 loader (PyYAML) and the escapes a message shows.
#include <catch2/catch.hpp>

#include "core/plain_text.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

using namespace facet;

TEST_CASE("line_breaking_character finds what bash, Slurm or YAML takes as a line break",
          "[text]") {
    CHECK_FALSE(line_breaking_character("plain words, 'quotes' and $(shell) #SBATCH"));
    CHECK_FALSE(line_breaking_character("\xc3\xbcn\xc3\xaf \xe5\x90\x8d \xf0\x9f\x99\x82"));
    const std::vector<std::pair<std::string, std::string>> found = {
        {"a\nb", "a newline"},
        {"a\rb", "a carriage return"},
        {"a\tb", "a tab"},
        {"a\x1b"
         "b",
         "a control character (\\x1b)"},
        {"a\x7f"
         "b",
         "a control character (\\x7f)"},
        {"a\xc2\x85"
         "b",
         "U+0085 (a next-line character)"},
        {"a\xc2\x9b"
         "b",
         "a control character (U+009B)"},
        {"a\xe2\x80\xa8"
         "b",
         "U+2028 (a line separator)"},
        {"a\xe2\x80\xa9"
         "b",
         "U+2029 (a paragraph separator)"},
        {"a\xef\xbf\xbe"
         "b",
         "U+FFFE (not a character)"},
        {"a\xff"
         "b",
         "bytes that are not UTF-8"},
        {"a\xc0\x8a"
         "b",
         "bytes that are not UTF-8"},  // an overlong newline
        {"a\xed\xa0\x80"
         "b",
         "bytes that are not UTF-8"},               // a surrogate
        {"a\xe2\x80", "bytes that are not UTF-8"},  // cut short
    };
    for (const auto& [text, name] : found) {
        INFO(text_for_message(text));
        const auto problem = line_breaking_character(text);
        REQUIRE(problem);
        CHECK(*problem == name);
    }
}

TEST_CASE("text_for_message escapes line breaks and cuts long values", "[text]") {
    CHECK(text_for_message("a\nb\tc\xe2\x80\xa8"
                           "d\xff") == "a\\nb\\tc\\u2028d\\xff");
    CHECK(text_for_message("\xc3\xbcn\xc3\xaf") == "\xc3\xbcn\xc3\xaf");
    const std::string long_value(5000, 'x');
    CHECK(text_for_message(long_value) == std::string(80, 'x') + "... (5000 bytes)");
    CHECK(with_long_words_cut("short " + long_value + " end") ==
          "short " + std::string(80, 'x') + "... (5000 bytes) end");
    CHECK(count_of(1, "image", "images") == "1 image");
    CHECK(count_of(0, "image", "images") == "0 images");
}

TEST_CASE("yaml_quoted text reads back exactly in a YAML 1.1 loader, on one line", "[text]") {
    if (!facet::test::have_command("python3")) FACET_SKIP("python3 is not installed");
    const std::string text =
        "a\nb\rc\x1b"
        "d\xc2\x85"
        "e\xe2\x80\xa8"
        "f\xe2\x80\xa9"
        "g\xc2\x9b"
        "h\"'\\#: [x]";
    const std::string quoted = yaml_quoted(text);
    CHECK_FALSE(line_breaking_character(quoted));
    facet::test::TempDir dir("yaml-quoted");
    facet::test::write_text(dir.file("t.yaml"), "key: " + quoted + "\n");
    const facet::test::RunResult r = facet::test::run_command(
        "python3 -c 'import sys, yaml; v = yaml.safe_load(open(sys.argv[1], encoding=\"utf-8\"))"
        "[\"key\"]; sys.stdout.buffer.write(v.encode(\"utf-8\"))' " +
        dir.file("t.yaml"));
    if (r.exit_code != 0 && r.output.find("No module named") != std::string::npos)
        FACET_SKIP("python3-yaml is not installed (scripts/setup.sh --tests)");
    REQUIRE(r.exit_code == 0);
    CHECK(r.output == text);
}
