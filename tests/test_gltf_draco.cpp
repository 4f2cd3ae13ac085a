// KHR_draco_mesh_compression, decoded with libdraco: Khronos' 2CylinderEngine
// sample in its Draco-compressed form (assimp-testmodels) renders as the
// plain .glb of the same model; damaged streams are errors naming the
// primitive.
#include <catch2/catch.hpp>

#include <filesystem>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "real_asset_support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

const std::string kDraco = kAssimpModels + "glTF2/draco/2CylinderEngine.gltf";
const std::string kPlain = kAssimpModels + "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

bool have_engines() {
    return std::filesystem::exists(kDraco) && std::filesystem::exists(kPlain);
}
const char* const kNoEngines =
    "2CylinderEngine is missing (scripts/setup.sh --tests installs assimp-testmodels)";

}  // namespace

TEST_CASE("a Draco-compressed glTF renders as the uncompressed file", "[gltf][draco][real]") {
    if (!have_engines()) FACET_SKIP(kNoEngines);
    const Mesh draco = load_gltf(kDraco);
    const Mesh plain = load_gltf(kPlain);
    CHECK(draco.parts.size() == plain.parts.size());
    // Draco's encoder leaves out triangles with a repeated corner; the
    // plain file has 11154 of them. The rest are the same triangles.
    size_t repeated = 0;
    for (const MeshPart& part : plain.parts)
        for (size_t t = 0; t < part.indices.size(); t += 3) {
            const uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
            if (a == b || b == c || a == c) ++repeated;
        }
    CHECK(repeated > 10000);
    CHECK(draco.triangle_count() <= plain.triangle_count() - repeated);
    CHECK(draco.triangle_count() + 20 >= plain.triangle_count() - repeated);
    for (const Warning& w : draco.warnings)
        CHECK_THAT(w.describe(), !Catch::Matchers::Contains("draco"));
    // Draco quantizes positions (14 bits here): the bounds agree within
    // a few thousandths of the size.
    const Bounds a = plain.bounds(), b = draco.bounds();
    const float size = glm::length(a.max - a.min);
    CHECK(glm::length(a.min - b.min) < size * 2e-3f);
    CHECK(glm::length(a.max - b.max) < size * 2e-3f);
    TempDir dir("draco");
    const DepthImage a_depth = depth_of(dir, kPlain, "", 1), b_depth = depth_of(dir, kDraco, "", 1);
    CHECK(depth_difference(a_depth, b_depth).first < 0.01);  // coverage differs at edges only
    // Where both show a surface, it is the same one: the engine's many thin
    // parts let an edge pixel see another part, so a few pixels may differ.
    CHECK(share_of_depth_differences(a_depth, b_depth, 2e-3f) < 0.01);
}

TEST_CASE("a damaged Draco stream is an error naming the primitive", "[gltf][draco]") {
    if (!have_engines()) FACET_SKIP(kNoEngines);
    TempDir dir("draco");
    const std::string bin = read_file(kAssimpModels + "glTF2/draco/2CylinderEngine.bin");
    std::string gltf = read_file(kDraco);
    write_text(dir.file("2CylinderEngine.gltf"), gltf);
    // Every byte changed: no stream decodes.
    std::vector<uint8_t> damaged(bin.begin(), bin.end());
    for (uint8_t& byte : damaged) byte ^= 0x5a;
    write_bytes(dir.file("2CylinderEngine.bin"), damaged);
    require_input_error([&] { load_gltf(dir.file("2CylinderEngine.gltf")); }, "primitive");
    // Cut short: the views run past the buffer.
    std::vector<uint8_t> cut(bin.begin(), bin.begin() + 1000);
    write_bytes(dir.file("2CylinderEngine.bin"), cut);
    require_input_error([&] { load_gltf(dir.file("2CylinderEngine.gltf")); },
                        "2CylinderEngine.gltf");
}
