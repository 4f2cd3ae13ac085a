// An EXR's header is checked against the file's size before OpenEXR reads
// it (the reliability issue, item 4): OpenEXR sizes an attribute to its
// declared length before reading it, so a 29-byte file could ask for 2 GB.
// Every command that reads EXR files refuses such a file with exit 2, in
// little memory.
#include <catch2/catch.hpp>

#include <cstring>

#include "compare_support.hpp"
#include "output/encoders.hpp"
#include "support.hpp"
#include "turntable_support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

void put32(std::string& out, int32_t value) {
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    out.append(bytes, 4);
}

// The magic number, version 2, and one attribute that declares `size`
// bytes, followed by `tail`.
std::string exr_with_attribute(int32_t size, const std::string& tail) {
    std::string bytes = "v/1\x01";
    put32(bytes, 2);
    bytes += std::string("comments\0string\0", 16);
    put32(bytes, size);
    return bytes + tail;
}

}  // namespace

TEST_CASE("an EXR whose header declares more bytes than the file has is refused before reading",
          "[exr][security]") {
    TempDir dir("exr-header");
    const std::string huge = write_text(dir.file("huge.exr"), exr_with_attribute(0x7ffffff0, "x"));
    REQUIRE(read_file(huge).size() == 29);
    require_input_error([&] { read_exr(huge); },
                        "attribute 'comments' (string) declares 2147483632");
    require_input_error([&] { read_exr_header(huge); }, "huge.exr");
    // A negative size, a header cut off in a name, and no end of header.
    require_input_error(
        [&] { read_exr(write_text(dir.file("negative.exr"), exr_with_attribute(-5, "xxxxxx"))); },
        "declares -5 bytes");
    std::string cut = "v/1\x01";
    put32(cut, 2);
    cut += "channe";
    require_input_error([&] { read_exr(write_text(dir.file("cut.exr"), cut)); }, "runs past");
    require_input_error(
        [&] { read_exr(write_text(dir.file("unended.exr"), exr_with_attribute(1, "x"))); },
        "past the end");
}

TEST_CASE("render and compare refuse an EXR whose 29 bytes ask for 2 GB, in bounded memory",
          "[exr][security][cli]") {
    TempDir dir("exr-header-cli");
    write_text(dir.file("b.exr"), exr_with_attribute(0x7ffffff0, "x"));
    write_binary_stl(dir.file("cube.stl"), box_triangles({-1, -1, -1}, {1, 1, 1}));
    const std::string in = "cd " + shell_quote(dir.path()) + " && ";
    // 400 MB of address space: far less than the 2 GB the header asks for.
    // An environment is an input (exit 2); compare reports a file it cannot
    // read with its own code, 4 (docs/regression.md).
    for (const auto& [args, code] :
         {std::pair<std::string, int>{
              "render cube.stl -f 1 --size 64x48 --environment b.exr -o out", 2},
          {"compare b.exr b.exr -o report", 4}}) {
        INFO(args);
        // (AddressSanitizer reserves terabytes up front: there only time counts.)
        const std::string limit = kAddressSanitizer ? "" : "ulimit -v 400000; ";
        const RunResult r = run_command(in + "sh -c \"" + limit + "exec timeout -s KILL 60 " +
                                        shell_quote(facet_executable()) + " " + args + " 2>&1\"");
        INFO(r.output);
        CHECK(r.exit_code == code);
        CHECK_THAT(r.output, Contains("b.exr") && Contains("declares 2147483632 bytes"));
    }
}
