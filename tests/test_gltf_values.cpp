// glTF values that were silently wrapped or ignored (the reliability
// issue, item 8): an index past 2^31 - 1, a texCoord of 2^32, a sampler's
// wrap given as a word, a sparse count past the accessor's, and a node
// scale that puts vertices past facet's range are errors naming the field;
// a file whose instances do not fit in memory is named.
#include <catch2/catch.hpp>

#include <functional>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

// A textured quad of material 0, with texture 0 of image 0 (a 1x1 PNG).
Gltf textured_quad() {
    Gltf g;
    g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    g.doc["textures"] = {{{"source", 0}}};
    g.doc["images"] = {{{"uri", "white.png"}}};
    g.one_quad_scene();
    return g;
}

}  // namespace

TEST_CASE("a glTF index of 2^31 or more is an error, not a wrap to a valid index",
          "[gltf][untrusted]") {
    TempDir dir("gltf-index-range");
    write_bytes(dir.file("white.png"), flat_png(255));
    const uint64_t huge = uint64_t(1) << 32;  // wraps to 0 in 32 bits
    const std::vector<std::pair<std::string, std::function<void(json&)>>> cases = {
        {"baseColorTexture.index",
         [&](json& d) {
             d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = huge;
         }},
        {"baseColorTexture.texCoord",
         [&](json& d) {
             d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = huge;
         }},
        {"primitives[0].material",
         [&](json& d) { d["meshes"][0]["primitives"][0]["material"] = huge; }},
        {"primitives[0].indices",
         [&](json& d) { d["meshes"][0]["primitives"][0]["indices"] = huge; }},
        {"attributes.POSITION",
         [&](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = huge; }},
        {"textures[0].source", [&](json& d) { d["textures"][0]["source"] = huge; }},
        {"nodes[0].mesh", [&](json& d) { d["nodes"][0]["mesh"] = huge; }},
        {"scenes[0].nodes[0]", [&](json& d) { d["scenes"][0]["nodes"][0] = huge; }},
        {"accessors[0].bufferView", [&](json& d) { d["accessors"][0]["bufferView"] = huge; }},
        {"bufferViews[0].buffer", [&](json& d) { d["bufferViews"][0]["buffer"] = huge; }},
    };
    for (const auto& [field, edit] : cases) {
        INFO(field);
        Gltf g = textured_quad();
        edit(g.doc);
        const std::string file = g.write(dir.file("huge.gltf"));
        require_input_error([&] { load_mesh(file); }, field);
        require_input_error([&] { load_mesh(file); },
                            "an index (a whole number from 0 to 2147483647)");
    }
}

TEST_CASE("a sampler's filter or wrap given as a word is an error, not ignored", "[gltf]") {
    TempDir dir("gltf-sampler-word");
    write_bytes(dir.file("white.png"), flat_png(255));
    for (const char* key : {"wrapS", "wrapT", "magFilter", "minFilter"}) {
        INFO(key);
        Gltf g = textured_quad();
        g.doc["samplers"] = {{{key, "repeat"}}};
        g.doc["textures"][0]["sampler"] = 0;
        const std::string file = g.write(dir.file("word.gltf"));
        require_input_error([&] { load_mesh(file); }, std::string("samplers[0].") + key);
        // --strict or not: the same error, before anything is drawn.
        const RunResult r = run_facet("info '" + file + "'");
        CHECK(r.exit_code == 2);
    }
}

TEST_CASE("a sparse accessor's count past its accessor's is an error, not ignored", "[gltf]") {
    TempDir dir("gltf-sparse-count");
    for (const json& count : {json(1e9), json(1000000000), json(0), json(5)}) {
        INFO(count.dump());
        Gltf g;
        const int positions = g.floats(kTriangle, "VEC3");
        const int index_view = g.view(bytes_of(std::vector<uint16_t>{1, 0}));
        const int value_view = g.view(bytes_of(std::vector<float>{2, 2, 0}));
        g.sparse(positions, 1, index_view, kUShort, value_view);
        g.doc["accessors"][positions]["sparse"]["count"] = count;
        g.one_node_scene({{"attributes", {{"POSITION", positions}}}});
        const std::string file = g.write(dir.file("sparse.gltf"));
        require_input_error([&] { load_mesh(file); }, "accessors[0].sparse.count");
    }
}

TEST_CASE("a node scale that puts vertices past facet's range is an error, not half a quad",
          "[gltf]") {
    TempDir dir("gltf-scale");
    Gltf g;
    g.doc["materials"] = json::array({json::object()});
    g.one_quad_scene();
    g.doc["nodes"][0]["scale"] = {1e10, 1e10, 1e10};
    const std::string file = g.write(dir.file("huge-scale.gltf"));
    require_input_error([&] { load_mesh(file); }, "past the largest coordinate facet draws");
    // 1e6 stays within it.
    g.doc["nodes"][0]["scale"] = {1e6, 1e6, 1e6};
    CHECK(load_mesh(g.write(dir.file("large-scale.gltf"))).triangle_count() == 2);
}

TEST_CASE("a file whose instances do not fit in memory is named, not 'out of memory' alone",
          "[gltf][memory]") {
    // AddressSanitizer reserves terabytes of address space: no limit fits.
    if (kAddressSanitizer)
        FACET_SKIP("an address-space limit cannot be set under AddressSanitizer");
    TempDir dir("gltf-instances");
    // One triangle, two million times (EXT_mesh_gpu_instancing).
    Gltf g;
    const int positions = g.floats(kTriangle, "VEC3");
    std::vector<float> translations;
    for (int i = 0; i < 2000000; ++i)
        translations.insert(translations.end(), {float(i % 1000) * 2, float(i / 1000) * 2, 0});
    const int moved = g.floats(translations, "VEC3");
    g.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    g.one_node_scene({{"attributes", {{"POSITION", positions}}}},
                     {{"extensions",
                       {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", moved}}}}}}}});
    const std::string file = g.write(dir.file("many.gltf"));
    const RunResult r = run_facet_limited("info '" + file + "'", 120, 600);
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Contains("many.gltf"));
}
