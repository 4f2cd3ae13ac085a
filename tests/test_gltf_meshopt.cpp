// Real files from gltfpack (scripts/make_real_assets.sh): quantized
// (KHR_mesh_quantization) and meshopt-compressed (EXT_meshopt_compression,
// decoded with libmeshoptimizer) versions of the demo assets must render as
// their originals do, animations included; damaged streams are errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "assets/gltf_pose.hpp"
#include "assets/mesh.hpp"
#include "real_asset_support.hpp"

using namespace facet;
using namespace facet::test;

TEST_CASE("gltfpack's quantized and meshopt-compressed knots render as the original",
          "[gltf][meshopt][real]") {
    TempDir dir("meshopt");
    const Mesh original = load_gltf(source_path("scenes/assets/knot.glb"));
    for (const char* name : {"knot-quantized.glb", "knot-meshopt.glb"}) {
        INFO(name);
        const Mesh packed = load_gltf(asset(name));
        CHECK(packed.triangle_count() == original.triangle_count());
        CHECK(packed.warnings.empty());
        // 14-bit positions: within 1/16384 of the size, and a little more.
        const Bounds a = original.bounds(), b = packed.bounds();
        const float size = glm::length(a.max - a.min);
        CHECK(glm::length(a.min - b.min) < size * 2e-4f);
        CHECK(glm::length(a.max - b.max) < size * 2e-4f);
        const auto [coverage, depth] =
            depth_difference(depth_of(dir, source_path("scenes/assets/knot.glb"), "", 1),
                             depth_of(dir, asset(name), "", 1));
        CHECK(coverage < 0.003);  // edge pixels only
        CHECK(depth < 2e-3);
    }
    // Compression is lossless on top of the quantization: the two files hold
    // the same vertices (in another order: -cc reorders them for the codec).
    const Mesh quantized = load_gltf(asset("knot-quantized.glb"));
    const Mesh compressed = load_gltf(asset("knot-meshopt.glb"));
    REQUIRE(quantized.parts.size() == compressed.parts.size());
    auto sorted = [](std::vector<glm::vec3> v) {
        std::sort(v.begin(), v.end(), [](const glm::vec3& a, const glm::vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        return v;
    };
    CHECK(sorted(quantized.parts[0].positions) == sorted(compressed.parts[0].positions));
}

TEST_CASE("a meshopt-compressed animated file plays as the original", "[gltf][meshopt][real]") {
    TempDir dir("meshopt");
    const Mesh packed = load_gltf(asset("tentacle-meshopt.glb"));
    const Mesh original = load_gltf(source_path("scenes/assets/tentacle.glb"));
    REQUIRE(animation_count(packed) == animation_count(original));
    REQUIRE(animation_count(packed) >= 1);
    CHECK(animation_duration(packed, 0) == Approx(animation_duration(original, 0)).epsilon(1e-3));
    for (int frame : {1, 13, 30}) {
        INFO("frame " << frame);
        const DepthImage a = depth_of(dir, source_path("scenes/assets/tentacle.glb"), "0", frame);
        const DepthImage b = depth_of(dir, asset("tentacle-meshopt.glb"), "0", frame);
        const auto [coverage, depth] = depth_difference(a, b);
        CHECK(coverage < 0.01);
        CHECK(depth < 5e-3);
    }
    // And it moves: frame 13 is not frame 1.
    const auto moved = depth_difference(depth_of(dir, asset("tentacle-meshopt.glb"), "0", 1),
                                        depth_of(dir, asset("tentacle-meshopt.glb"), "0", 13));
    CHECK(moved.first > 0.01);
}

TEST_CASE("damaged meshopt streams are errors naming the view", "[gltf][meshopt]") {
    TempDir dir("meshopt");
    const std::string good = read_file(asset("knot-meshopt.glb"));
    std::vector<uint8_t> bytes(good.begin(), good.end());
    // The BIN chunk follows the JSON chunk; damage the compressed bytes in
    // several places, and cut the file short.
    const uint32_t json_length = bytes[12] | bytes[13] << 8 | bytes[14] << 16 | bytes[15] << 24;
    const size_t bin = 20 + json_length + 8;
    REQUIRE(bin + 4096 < bytes.size());
    // Every compressed byte changed cannot decode. Sparse damage may still
    // decode (the format has no checksum) into other numbers: then the load
    // either succeeds or is an error, never a crash (the sanitizer build
    // watches).
    for (size_t step : {size_t(1), size_t(97), size_t(1021)}) {
        INFO("every " << step << " bytes");
        std::vector<uint8_t> damaged = bytes;
        for (size_t i = bin; i < damaged.size(); i += step) damaged[i] ^= 0x5a;
        const std::string path = write_bytes(dir.file("damaged.glb"), damaged);
        bool failed = false;
        try {
            load_gltf(path);
        } catch (const Error& e) {
            CHECK(e.code() == ExitCode::invalid_input);
            CHECK_THAT(e.what(), Catch::Matchers::Contains("damaged.glb"));
            failed = true;
        }
        if (step == 1) CHECK(failed);
    }
    std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<long>(bin + 1000));
    require_input_error([&] { load_gltf(write_bytes(dir.file("cut.glb"), cut)); }, "cut.glb");
}
