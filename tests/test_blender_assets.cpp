// Files written by Blender 3.4's exporters and packed by gltfpack
// (scripts/make_real_assets.sh, committed in tests/assets/blender/): the
// glb against the obj, packed files against their originals, the Mapping
// node's texture scale, three animations playing together, and the
// features file's vertex colours, emission, camera and lights.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "anim/frame_state.hpp"
#include "assets/gltf_pose.hpp"
#include "core/half.hpp"
#include "real_asset_support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

std::string blender(const std::string& name) {
    return asset("blender/" + name);
}

// The colour image of `mesh` framed from the front, unlit.
ColorImage colour_of(const TempDir& dir, const std::string& mesh, const std::string& extra = "") {
    const std::string text =
        "output: { size: [200, 200], frames: \"1\" }\nstyle: unlit\n"
        "camera: { position: [0, 0, 5], frame: all }\n"
        "objects:\n  - mesh: " +
        mesh + "\n" + extra;
    return to_float_image(render_frame(load(write_text(dir.file("colour.yaml"), text)), 1).color);
}

// Light-dark changes along the middle row, where the model covers it.
int transitions(const ColorImage& image) {
    int count = 0;
    const int y = image.height / 2;
    for (int x = 1; x < image.width; ++x) {
        const float a = image.at(x - 1, y).g, b = image.at(x, y).g;
        if (a > 0.02f && b > 0.02f && (a > 0.5f) != (b > 0.5f)) ++count;
    }
    return count;
}

// The parts of `mesh` posed at `seconds` with every animation, by node name.
Bounds posed_part(const Mesh& mesh, const std::string& node, double seconds) {
    std::vector<int> all(static_cast<size_t>(animation_count(mesh)));
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    std::vector<PosedPart> parts;
    pose_mesh(mesh, all, seconds, parts);
    Bounds b;
    for (size_t p = 0; p < parts.size(); ++p)
        if (mesh.rig->nodes[static_cast<size_t>(mesh.rig->parts[p].node)].name == node)
            for (const glm::vec3& v : parts[p].positions) b.add(v);
    REQUIRE(!b.empty());
    return b;
}

}  // namespace

TEST_CASE("Blender's Suzanne: the glb and the obj render the same depth", "[real][blender]") {
    TempDir dir("blender");
    const Mesh glb = load_gltf(blender("suzanne.glb"));
    const Mesh obj = load_obj(blender("suzanne.obj"));
    CHECK(glb.triangle_count() == obj.triangle_count());
    const DepthImage a = depth_of(dir, blender("suzanne.glb"), "", 1);
    const DepthImage b = depth_of(dir, blender("suzanne.obj"), "", 1);
    const auto [coverage, largest] = depth_difference(a, b);
    CHECK(coverage < 0.001);
    // The obj's six decimals are the only difference: within float
    // precision of a few millimetres' model, everywhere both show it.
    CHECK(share_of_depth_differences(a, b, 1e-4f) < 0.003);
    CHECK(largest < 0.02);
}

TEST_CASE("gltfpack's packed Blender files render as their originals", "[real][blender]") {
    TempDir dir("blender");
    struct Case {
        const char* name;
        const char* animation;
        int frame;
    };
    for (const Case c : {Case{"suzanne", "", 1}, Case{"textured-sphere", "", 1},
                         Case{"keyed", "all", 12}, Case{"features", "", 1}}) {
        const DepthImage original =
            depth_of(dir, blender(std::string(c.name) + ".glb"), c.animation, c.frame);
        for (const char* packing : {"-quantized.glb", "-meshopt.glb"}) {
            const std::string file = blender(c.name + std::string(packing));
            INFO(file);
            CHECK(load_gltf(file).warnings.empty());
            const DepthImage packed = depth_of(dir, file, c.animation, c.frame);
            CHECK(depth_difference(original, packed).first < 0.01);
            CHECK(share_of_depth_differences(original, packed, 2e-3f) < 0.02);
        }
    }
}

TEST_CASE("Blender's Mapping node scales the texture by 2 through KHR_texture_transform",
          "[real][blender]") {
    TempDir dir("blender");
    const Mesh sphere = load_gltf(blender("textured-sphere.glb"));
    float most_u = 0;
    const facet::TextureSlot& slot = sphere.materials.at(sphere.parts[0].material).base_color_map;
    for (const glm::vec2& uv : sphere.parts[0].uvs) most_u = std::max(most_u, slot.map(uv).x);
    CHECK(most_u == Approx(2).epsilon(1e-3));  // Blender's UVs span 0..1
    // Twice as many checker squares across the sphere as with the scale
    // undone (uv_scale multiplies the transformed coordinates).
    for (const char* file : {"textured-sphere.glb", "textured-sphere-quantized.glb"}) {
        INFO(file);
        const int scaled = transitions(colour_of(dir, blender(file)));
        const int undone =
            transitions(colour_of(dir, blender(file), "    material: { uv_scale: 0.5 }\n"));
        // Across the visible half of the equator: 8 squares of the 16 round
        // it at scale 2 (7 or 8 changes), 4 of 8 with the scale undone.
        CHECK(scaled >= 6);
        CHECK(scaled <= 9);
        CHECK(undone >= 2);
        CHECK(undone <= 5);
        CHECK(scaled >= 1.5 * undone);
    }
}

TEST_CASE("Blender's three actions play together with animation: all", "[real][blender]") {
    const Mesh mesh = load_gltf(blender("keyed.glb"));
    REQUIRE(animation_count(mesh) == 3);
    // The box moves 2 along +X.
    const Bounds box0 = posed_part(mesh, "Box", 0), box1 = posed_part(mesh, "Box", 1);
    CHECK(box1.min.x - box0.min.x == Approx(2).epsilon(0.01));
    // The arm spans 0.5 to 1.5 up the two bones; its top half turns 90
    // degrees at the joint (height 1): it drops to about 1.075 (its half
    // thickness past the joint) and reaches out sideways (glTF +Y is
    // Blender's +Z).
    const Bounds arm0 = posed_part(mesh, "Arm", 0), arm1 = posed_part(mesh, "Arm", 1);
    CHECK(arm0.max.y == Approx(1.5).epsilon(0.01));
    CHECK(arm1.max.y == Approx(1.075).epsilon(0.02));
    CHECK(std::max(arm1.max.z - arm0.max.z, arm0.min.z - arm1.min.z) ==
          Approx(0.425).epsilon(0.05));
    // The sheet's bump rises by one.
    const Bounds sheet0 = posed_part(mesh, "Sheet", 0), sheet1 = posed_part(mesh, "Sheet", 1);
    CHECK(sheet1.max.y - sheet0.max.y == Approx(1).epsilon(0.02));
    // Packed, the same motion (gltfpack renames some nodes: compared whole).
    auto whole = [](const Mesh& m, double seconds) {
        std::vector<int> all(static_cast<size_t>(animation_count(m)));
        for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
        std::vector<PosedPart> parts;
        pose_mesh(m, all, seconds, parts);
        Bounds b;
        for (const PosedPart& p : parts)
            for (const glm::vec3& v : p.positions) b.add(v);
        return b;
    };
    for (const char* file : {"keyed-quantized.glb", "keyed-meshopt.glb"}) {
        INFO(file);
        const Mesh packed = load_gltf(blender(file));
        REQUIRE(animation_count(packed) == 3);
        for (double t : {0.0, 0.5, 1.0}) {
            INFO("at " << t << " s");
            const Bounds a = whole(mesh, t), b = whole(packed, t);
            CHECK(glm::length(a.min - b.min) < 0.01f);
            CHECK(glm::length(a.max - b.max) < 0.01f);
        }
    }
}

TEST_CASE("Blender's features file: colours, emission, its camera and its lights",
          "[real][blender]") {
    TempDir dir("blender");
    const std::string file = blender("features.glb");
    const Mesh mesh = load_gltf(file);
    // The script paints the six faces six colours; Blender 3.4's exporter
    // writes two of them (red and green, as the file's own bytes say).
    size_t painted = 0;
    for (const MeshPart& part : mesh.parts)
        if (!part.colors.empty()) {
            ++painted;
            std::vector<glm::vec3> distinct = part.colors;
            std::sort(distinct.begin(), distinct.end(), [](const glm::vec3& a, const glm::vec3& b) {
                return std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b);
            });
            distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
            CHECK(distinct == std::vector<glm::vec3>{{0, 1, 0}, {1, 0, 0}});
        }
    CHECK(painted == 1);
    // Emission colour (1, 0.5, 0) at strength 4.
    const auto glow = std::find_if(mesh.materials.begin(), mesh.materials.end(),
                                   [](const Material& m) { return m.name == "Glow"; });
    REQUIRE(glow != mesh.materials.end());
    CHECK(glow->emissive.r == Approx(4).epsilon(1e-3));
    CHECK(glow->emissive.g == Approx(2).epsilon(1e-3));
    // The camera dollies from 6 to 4 in front (Blender's -Y is glTF's +Z).
    const SceneDesc scene =
        load(write_text(dir.file("features.yaml"),
                        "output: { size: [160, 90], frames: \"1-30\", fps: 24 }\nlights: []\n"
                        "camera: { from: " +
                            file +
                            ", name: Camera }\n"
                            "objects:\n  - mesh: " +
                            file + "\n    lights: true\n"));
    const World world = build_world(scene);
    const FrameAssets assets{{}, world.file_cameras, world.object_lights};
    const FrameState first = evaluate_frame(scene, world.object_bounds, 1, 0, assets);
    // Past the end of the action (frame 24 is 1 s in Blender's timing), held.
    const FrameState last = evaluate_frame(scene, world.object_bounds, 30, 0, assets);
    CHECK(first.camera.position.z == Approx(6).epsilon(1e-3));
    CHECK(last.camera.position.z == Approx(4).epsilon(1e-3));
    CHECK(first.camera.position.y == Approx(0.5).epsilon(1e-3));
    // Its point light and sun: Blender's watts times 683 / 4π candela,
    // which facet lights as candela / π (kGltfLightUnit).
    REQUIRE(first.lights.size() == 2);
    CHECK(first.lights[0].type == LightType::point);
    CHECK(first.lights[0].position.z == Approx(2).epsilon(1e-3));
    CHECK(first.lights[0].intensity == Approx(500 * 683 / (4 * M_PI) / M_PI).epsilon(1e-3));
    CHECK(first.lights[1].type == LightType::directional);
}

TEST_CASE("Blender's Suzanne fills the frame: fit: geometry, and a default turntable",
          "[real][blender][framing]") {
    TempDir dir("blender");
    // The share of the width and of the height the covered pixels span.
    auto span = [&](const std::string& camera, const std::string& frames, int frame) {
        const SceneDesc scene = load(write_text(
            dir.file("fill.yaml"), "output: { size: [160, 90], frames: \"" + frames +
                                       "\" }\nstyle: unlit\ncamera: " + camera +
                                       "\nobjects:\n  - mesh: " + blender("suzanne.glb") + "\n"));
        const FrameImages images = render_frame(scene, frame);
        int left = 160, right = -1, top = 90, bottom = -1;
        for (int y = 0; y < 90; ++y)
            for (int x = 0; x < 160; ++x)
                if (std::isfinite(images.depth.at(x, y)))
                    left = std::min(left, x), right = std::max(right, x), top = std::min(top, y),
                    bottom = std::max(bottom, y);
        REQUIRE(right >= left);
        // Nothing touches the image's edge unless the fit allows it.
        return std::pair<double, double>((right - left + 1) / 160.0, (bottom - top + 1) / 90.0);
    };
    // A still: one side spans the whole image at margin 0.
    const auto still = span(
        "{ position: [1, 0.5, 3], frame: { objects: all, fit: geometry, margin: 0 } }", "1", 1);
    CHECK(std::max(still.first, still.second) >= 0.98);
    // A turntable with every default: never more than 1/1.1 of the frame,
    // and at its widest at least 80% of it across (the docs' "most of the
    // frame"; the orbit keeps its aim on the model's centre, so one side
    // reaches 1/1.1 of the half-frame and the other a little less: 83% here).
    double widest = 0;
    for (int f = 1; f <= 24; f += 2) {
        INFO("frame " << f);
        const auto s = span("{ frame: all, orbit: { elevation: 15 } }", "1-24", f);
        CHECK(s.first <= 1 / 1.1 + 0.02);
        CHECK(s.second <= 1 / 1.1 + 0.03);
        widest = std::max({widest, s.first, s.second});
    }
    CHECK(widest >= 0.80);
}
