// glTF 2.0 loading (src/assets/gltf_loader.cpp), broken files of our own:
// every bad reference, bad piece of data and malformed container must end in
// a facet::Error (invalid input) naming the file, never in a crash.
#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

using namespace facet::test;
using nlohmann::json;

namespace {

// Makes `g` the smallest valid document: one node showing the triangle.
void show_triangle(Gltf& g) {
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
}

// Gives the triangle's primitive material 0, and that material a base colour texture.
void texture_the_triangle(Gltf& g, int texture) {
    g.doc["materials"] =
        json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}}});
    g.doc["meshes"][0]["primitives"][0]["material"] = 0;
}

// The triangle with the value at `pointer` (a JSON pointer into the
// document) set to `value`.
struct OneValueCase {
    const char* name;
    const char* file;  // written, and named by the error
    const char* pointer;
    json value;
};

// A document built in its own way, starting from an empty one.
struct BuiltCase {
    const char* name;
    const char* file;  // written, and named by the error
    std::function<void(Gltf&)> make;
};

}  // namespace

TEST_CASE("glTF broken references and data are errors naming the file", "[assets][gltf]") {
    const std::vector<OneValueCase> one_value = {
        {"accessor longer than its buffer view", "acc_long.gltf", "/accessors/0/count", 4},
        {"accessor with an absurd count", "acc_huge.gltf", "/accessors/0/count", 1000000000},
        // 12 * count wraps around 2^64.
        {"accessor count that overflows byte arithmetic", "acc_wrap.gltf", "/accessors/0/count",
         1537228672809129302ull},
        {"accessor offset past its buffer view", "acc_offset.gltf", "/accessors/0/byteOffset", 4},
        {"accessor refers to a missing buffer view", "acc_view.gltf", "/accessors/0/bufferView", 7},
        {"buffer view past the end of its buffer", "view_long.gltf", "/bufferViews/0/byteLength",
         4000},
        {"node refers to a missing mesh", "node_mesh.gltf", "/nodes/0/mesh", 5},
        {"scene refers to a missing node", "scene_node.gltf", "/scenes/0/nodes", {0, 9}},
        {"primitive refers to a missing material", "prim_mat.gltf",
         "/meshes/0/primitives/0/material", 3},
        {"primitive without POSITION",
         "nopos.gltf",
         "/meshes/0/primitives/0/attributes",
         {{"NORMAL", 0}}},
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<BuiltCase> built = {
        {"index past the vertex count", "index_oob.gltf",
         [](Gltf& g) {
             int idx = g.indices(std::vector<uint16_t>{0, 1, 3}, kUShort);
             g.one_node_scene(
                 {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}, {"indices", idx}});
         }},
        {"accessor without data with an absurd count", "acc_nodata.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.doc["accessors"][0].erase("bufferView");
             g.doc["accessors"][0]["count"] = 2000000000;
         }},
        {"POSITION with two components", "pos_vec2.gltf",
         [](Gltf& g) {
             g.one_node_scene(
                 {{"attributes", {{"POSITION", g.floats({0, 0, 1, 0, 0, 1}, "VEC2")}}}});
         }},
        {"NaN position", "nan.gltf",
         [nan](Gltf& g) {
             g.one_node_scene(
                 {{"attributes", {{"POSITION", g.floats({0, 0, 0, 1, nan, 0, 0, 1, 0}, "VEC3")}}}});
         }},
        {"infinite normal", "infnormal.gltf",
         [inf](Gltf& g) {
             int nrm = g.floats({0, 0, 1, 0, 0, inf, 0, 0, 1}, "VEC3");
             g.one_node_scene(
                 {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}});
         }},
        {"NORMAL count differs from POSITION count", "normal_count.gltf",
         [](Gltf& g) {
             int nrm = g.floats({0, 0, 1, 0, 0, 1}, "VEC3");
             g.one_node_scene(
                 {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}});
         }},
        {"material refers to a missing texture", "mat_tex.gltf",
         [](Gltf& g) {
             show_triangle(g);
             texture_the_triangle(g, 4);
         }},
        {"texture without an image", "tex_img.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.doc["textures"] = json::array({{{"source", 2}}});
             texture_the_triangle(g, 0);
         }},
        {"only points and lines", "points.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.doc["meshes"][0]["primitives"][0]["mode"] = 0;
             g.doc["meshes"][0]["primitives"].push_back(
                 {{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
         }},
        {"buffer file that does not exist", "nobin.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.buffer_uri = "missing.bin";
         }},
        {"buffer data URI that is not base64", "b64.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.buffer_uri = "data:application/octet-stream;base64,@@@@!!!!";
         }},
        {"Draco-compressed geometry whose stream is not Draco data", "draco.gltf",
         [](Gltf& g) {
             show_triangle(g);
             g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
             g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
             g.doc["meshes"][0]["primitives"][0]["extensions"] = {
                 {"KHR_draco_mesh_compression",
                  {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
         }},
    };
    TempDir dir("gltf");
    auto require_rejected = [&](Gltf& g, const char* file) {
        std::string path = g.write(dir.file(file));
        require_input_error([&] { facet::load_gltf(path); }, file);
    };
    for (const auto& c : one_value) {
        DYNAMIC_SECTION(c.name) {
            Gltf g;
            show_triangle(g);
            g.doc[json::json_pointer(c.pointer)] = c.value;
            require_rejected(g, c.file);
        }
    }
    for (const auto& c : built) {
        DYNAMIC_SECTION(c.name) {
            Gltf g;
            c.make(g);
            require_rejected(g, c.file);
        }
    }
}

TEST_CASE("glTF malformed containers are errors naming the file", "[assets][gltf]") {
    TempDir dir("gltf");
    struct Case {
        const char* name;
        const char* file;
        std::string bytes;
    };
    for (const auto& c : std::vector<Case>{
             {"empty .gltf", "empty.gltf", ""},
             {"invalid JSON", "broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": ["},
             {"JSON that is not an object", "array.gltf", "[1, 2, 3]"},
             {"valid but empty document", "nothing.gltf", "{\"asset\": {\"version\": \"2.0\"}}"},
             {"empty .glb", "empty.glb", ""},
             {".glb with a wrong magic number", "magic.glb",
              "glTX\x02\0\0\0\x20\0\0\0" + std::string(20, '\0')},
         }) {
        DYNAMIC_SECTION(c.name) {
            std::string path = write_text(dir.file(c.file), c.bytes);
            require_input_error([&] { facet::load_gltf(path); }, c.file);
        }
    }
    SECTION("missing file") {
        require_input_error([&] { facet::load_gltf(dir.file("absent.gltf")); }, "absent.gltf");
        require_input_error([&] { facet::load_mesh(dir.file("absent.glb")); }, "absent.glb");
    }
    SECTION("truncated and corrupted real .glb") {
        std::string whole =
            read_file(kAssimpModels + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
        REQUIRE(whole.size() > 1000);
        for (size_t keep :
             {size_t(12), size_t(20), whole.size() / 3, whole.size() / 2, whole.size() - 1}) {
            std::string path = write_text(dir.file("cut.glb"), whole.substr(0, keep));
            INFO("kept " << keep << " bytes");
            require_input_error([&] { facet::load_gltf(path); }, "cut.glb");
        }
        std::string lying = whole;
        lying[12] = '\xff';  // JSON chunk length far past the file
        lying[13] = '\xff';
        std::string path = write_text(dir.file("lying.glb"), lying);
        require_input_error([&] { facet::load_gltf(path); }, "lying.glb");
    }
}
