#pragma once
// glTF files made for the fidelity tests (tests/test_gltf_fidelity.cpp,
// tests/test_gltf_textures_and_warnings.cpp): a palette texture, a quad
// facing the camera, a scene that frames it, and gltf-transform's output.
#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "core/image.hpp"
#include "support.hpp"

namespace facet::test {

// A 4x4 texture of distinct linear colours, as a PNG (8-bit sRGB).
inline ColorImage palette_image() {
    ColorImage image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            image.at(x, y) = {0.1f + 0.25f * static_cast<float>(x),
                              0.9f - 0.25f * static_cast<float>(y), (x + y) % 2 ? 0.8f : 0.2f, 1};
    return image;
}

// A quad from (-1,-1) to (1,1) facing +Z, UV set 0 running (0,1) at the
// bottom left to (1,0) at the top right (glTF's top-left origin), set 1
// the same mirrored in u.
inline void quad_mesh(Gltf& g, const nlohmann::json& material) {
    g.doc["materials"] = nlohmann::json::array({material});
    g.one_node_scene({{"attributes",
                       {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
                        {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                        {"TEXCOORD_0", g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2")},
                        {"TEXCOORD_1", g.floats({1, 1, 0, 1, 0, 0, 1, 0}, "VEC2")}}},
                      {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort)},
                      {"material", 0}});
}

// A scene of one object, `mesh`, seen head on by a camera that frames the
// quad exactly, with no lights: what shows is emission alone.
inline std::string framing_scene(const std::string& mesh, const std::string& extra = "") {
    // tan(fov/2) = 1/2 at distance 2: the quad's half-size, 1.
    return "output: { size: [64, 64], frames: \"1\", background: [0, 0, 0, 1] }\n"
           "style: blinn-phong\nlights: []\n"
           "camera: { position: [0, 0, 2], target: [0, 0, 0], fov: 53.130102354 }\n"
           "objects:\n  - name: quad\n    mesh: " +
           mesh + "\n" + extra;
}

// `gltf-transform COMMAND IN OUT`, as a pipeline would run it, then OUT loaded.
inline Mesh transformed(const std::string& command, const std::string& in, const std::string& out) {
    const RunResult made =
        run_command("gltf-transform " + command + " '" + in + "' '" + out + "' 2>&1");
    INFO(made.output);
    REQUIRE(made.exit_code == 0);
    return load_gltf(out);
}

inline bool uses(const Mesh& mesh, const std::string& extension) {
    const auto& used = mesh.extensions.used;
    return std::find(used.begin(), used.end(), extension) != used.end();
}

inline const char* const kNoGltfTransform =
    "gltf-transform is not installed (scripts/setup.sh --tests)";

}  // namespace facet::test
