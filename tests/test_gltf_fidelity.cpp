// glTF files drawn as their authors made them (docs/scene-format.md,
// "glTF"): emissive maps with their own coordinate set and transform,
// EXT_mesh_gpu_instancing, samplers per axis, default morph weights and
// skins at rest. Image formats, lost textures and what facet says about
// them are tests/test_gltf_textures_and_warnings.cpp. Every file is made here.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/image_decode.hpp"
#include "core/half.hpp"
#include "gltf_quad_support.hpp"
#include "render_check.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

// The linear colour a texel of palette_image() decodes to: its 8-bit sRGB
// value read back (the PNG holds bytes, not the floats).
glm::vec3 palette_texel(int x, int y) {
    static const Texture decoded = [] {
        const std::vector<uint8_t> png = png_bytes(palette_image());
        return decode_texture(png.data(), png.size(), "palette", nullptr);
    }();
    return glm::vec3(decoded.texel(0, x, y));
}

// The palette as image 0, in texture 0 with a nearest-filter sampler, so a
// pixel shows one texel exactly.
void palette_texture(Gltf& g) {
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png_bytes(palette_image()))}}};
    g.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};
    g.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
}

glm::vec3 rgb(const HalfColorImage& image, int x, int y) {
    return glm::vec3(to_float(image.at(x, y)));
}

bool same_images(const FrameImages& a, const FrameImages& b) {
    auto same = [](const auto& x, const auto& y) {
        return x.width == y.width && x.height == y.height &&
               std::equal(
                   x.pixels.begin(), x.pixels.end(), y.pixels.begin(),
                   [](const auto& p, const auto& q) { return std::memcmp(&p, &q, sizeof p) == 0; });
    };
    return same(a.color, b.color) && same(a.depth, b.depth) &&
           same(a.surface.normal, b.surface.normal) &&
           same(a.surface.object_id, b.surface.object_id) &&
           same(a.surface.material_id, b.surface.material_id) && same(a.surface.uv, b.surface.uv) &&
           same(a.surface.position, b.surface.position) && same(a.surface.motion, b.surface.motion);
}

}  // namespace

TEST_CASE("an emissive map glows where it is bright, scaled by its factor and strength",
          "[gltf][emission]") {
    TempDir dir("gltf-emission");
    Gltf g;
    palette_texture(g);
    // Base colour black: the lit colour is 0, and only emission shows.
    quad_mesh(g,
              {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
               {"emissiveFactor", {0.5, 1, 1}},
               {"emissiveTexture", {{"index", 0}, {"texCoord", 1}}},
               {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const std::string file = g.write(dir.file("emissive.gltf"));
    const FrameImages images = render_yaml(dir.path(), framing_scene(file));
    // Pixel (px, py) of the 64x64 image sees texel (px/16, py/16) of set 0;
    // the map reads set 1, mirrored in u.
    const glm::vec3 factor(1, 2, 2);
    int checked = 0;
    for (int ty = 0; ty < 4; ++ty)
        for (int tx = 0; tx < 4; ++tx)
            for (int py = ty * 16 + 2; py < ty * 16 + 14; py += 5)
                for (int px = tx * 16 + 2; px < tx * 16 + 14; px += 5) {
                    INFO("pixel " << px << ", " << py);
                    const glm::vec3 want = factor * palette_texel(3 - tx, ty);
                    const glm::vec3 got = rgb(images.color, px, py);
                    for (int a = 0; a < 3; ++a)
                        CHECK(got[a] == Approx(want[a]).epsilon(2e-3).margin(1e-3));
                    ++checked;
                }
    CHECK(checked == 16 * 9);
}

TEST_CASE("KHR_texture_transform applies to the emissive map's own coordinates",
          "[gltf][emission]") {
    TempDir dir("gltf-emission");
    Gltf g;
    palette_texture(g);
    // Set 0, offset by half the image in u, wrapping (repeat): the left
    // half of the quad shows texel columns 2-3, the right half 0-1.
    quad_mesh(
        g, {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
            {"emissiveFactor", {1, 1, 1}},
            {"emissiveTexture",
             {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    const FrameImages images = render_yaml(dir.path(), framing_scene(g.write(dir.file("t.gltf"))));
    for (int tx = 0; tx < 4; ++tx) {
        const glm::vec3 want = palette_texel((tx + 2) % 4, 1);
        const glm::vec3 got = rgb(images.color, tx * 16 + 8, 24);
        for (int a = 0; a < 3; ++a) CHECK(got[a] == Approx(want[a]).epsilon(2e-3).margin(1e-3));
    }
}

TEST_CASE("a lost emissive map takes its emission with it, with a warning", "[gltf][emission]") {
    TempDir dir("gltf-emission");
    Gltf g;
    g.doc["images"] = {{{"uri", "glow.png"}}};  // not there
    g.doc["textures"] = {{{"source", 0}}};
    quad_mesh(g, {{"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}}});
    const Mesh mesh = load_gltf(g.write(dir.file("lost.gltf")));
    std::string all;
    for (const Warning& w : mesh.warnings) all += w.describe() + "\n";
    INFO(all);
    CHECK(mesh.materials[0].emissive == glm::vec3(0));
    bool warned = false;
    for (const Warning& w : mesh.warnings)
        if (w.message.find("emissiveTexture") != std::string::npos &&
            w.message.find("glow.png") != std::string::npos &&
            w.message.find("emission is not drawn") != std::string::npos)
            warned = true;
    CHECK(warned);
}

namespace {

// A unit cube mesh (mesh 0) with normals, one material.
int cube_mesh(Gltf& g) {
    std::vector<float> p, n;
    std::vector<uint16_t> idx;
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {-1, 1}) {
            const glm::vec3 normal = glm::vec3(axis == 0, axis == 1, axis == 2) * float(side);
            const glm::vec3 u(axis == 1, axis == 2, axis == 0), v = glm::cross(normal, u);
            const uint16_t base = static_cast<uint16_t>(p.size() / 3);
            for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                const glm::vec3 q = 0.5f * (normal + float(a) * u + float(b) * v);
                p.insert(p.end(), {q.x, q.y, q.z});
                n.insert(n.end(), {normal.x, normal.y, normal.z});
            }
            for (uint16_t i : {0, 1, 2, 0, 2, 3}) idx.push_back(static_cast<uint16_t>(base + i));
        }
    return g.mesh(
        {{"attributes", {{"POSITION", g.floats(p, "VEC3")}, {"NORMAL", g.floats(n, "VEC3")}}},
         {"indices", g.indices(idx, kUShort)}});
}

struct Placement {
    glm::vec3 t;
    glm::quat r;
    glm::vec3 s;
};

// A 3x3 grid of turned and scaled cubes.
std::vector<Placement> grid() {
    std::vector<Placement> out;
    for (int i = 0; i < 9; ++i) {
        const float x = static_cast<float>(i % 3) - 1, y = static_cast<float>(i / 3) - 1;
        out.push_back(
            {{1.6f * x, 1.6f * y, 0},
             glm::angleAxis(0.3f * static_cast<float>(i), glm::normalize(glm::vec3(1, 2, 0.5f))),
             glm::vec3(0.5f + 0.05f * static_cast<float>(i))});
    }
    return out;
}

std::string grid_as_nodes(const std::string& path) {
    Gltf g;
    const int mesh = cube_mesh(g);
    std::vector<int> nodes;
    for (const Placement& p : grid())
        nodes.push_back(g.node({{"mesh", mesh},
                                {"translation", {p.t.x, p.t.y, p.t.z}},
                                {"rotation", {p.r.x, p.r.y, p.r.z, p.r.w}},
                                {"scale", {p.s.x, p.s.y, p.s.z}}}));
    g.scene(nodes);
    return g.write(path);
}

std::string grid_instanced(const std::string& path) {
    Gltf g;
    const int mesh = cube_mesh(g);
    std::vector<float> t, r, s;
    for (const Placement& p : grid()) {
        t.insert(t.end(), {p.t.x, p.t.y, p.t.z});
        r.insert(r.end(), {p.r.x, p.r.y, p.r.z, p.r.w});
        s.insert(s.end(), {p.s.x, p.s.y, p.s.z});
    }
    const json attributes = {{"TRANSLATION", g.floats(t, "VEC3")},
                             {"ROTATION", g.floats(r, "VEC4")},
                             {"SCALE", g.floats(s, "VEC3")}};
    g.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    g.scene(
        {g.node({{"mesh", mesh},
                 {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}})});
    return g.write(path);
}

// Every pass of frame 2 of a turning camera (so motion has a frame before).
FrameImages every_pass(const TempDir& dir, const std::string& mesh) {
    return render_yaml(
        dir.path(),
        "output: { size: [96, 72], frames: \"1-4\", formats: [png, exr], passes: [color, "
        "depth, normal, object_id, material_id, uv, position, motion] }\n"
        "style: blinn-phong\n"
        "camera: { fov: 40, frame: all, orbit: { elevation: 25, turns: 0.25 } }\n"
        "lights:\n  - { type: directional, direction: [-1, -2, -1], shadows: true }\n"
        "objects:\n  - name: boxes\n    mesh: " +
            mesh + "\n    spin: { axis: y, turns: 0.1 }\n",
        2);
}

}  // namespace

TEST_CASE("EXT_mesh_gpu_instancing draws every copy, as nodes would", "[gltf][instancing]") {
    TempDir dir("gltf-instancing");
    const std::string nodes = grid_as_nodes(dir.file("nodes.gltf"));
    const std::string instanced = grid_instanced(dir.file("instanced.gltf"));
    const Mesh a = load_gltf(nodes), b = load_gltf(instanced);
    CHECK(b.warnings.empty());
    REQUIRE(b.triangle_count() == 9 * 12);
    CHECK(a.triangle_count() == b.triangle_count());
    CHECK(a.bounds().min == b.bounds().min);
    CHECK(a.bounds().max == b.bounds().max);
    // Every pass, shadows and a moving object included, bit for bit.
    CHECK(same_images(every_pass(dir, nodes), every_pass(dir, instanced)));
    // And `facet info` counts the copies.
    const RunResult info = run_facet("info --json '" + instanced + "'");
    REQUIRE(info.exit_code == 0);
    CHECK(json::parse(info.output)["triangles"] == 9 * 12);
}

TEST_CASE("gltf-transform's instancing renders as the file it came from",
          "[gltf][instancing][tools]") {
    if (!have_command("gltf-transform")) FACET_SKIP(kNoGltfTransform);
    TempDir dir("gltf-instancing");
    const std::string nodes = grid_as_nodes(dir.file("nodes.gltf"));
    const std::string instanced = dir.file("instanced.glb");
    const Mesh b = transformed("instance --min 2", nodes, instanced);
    CHECK(uses(b, "EXT_mesh_gpu_instancing"));
    CHECK(b.triangle_count() == 9 * 12);
    // Its accessors hold floats of the file's values: the same transforms.
    const FrameImages x = every_pass(dir, nodes), y = every_pass(dir, instanced);
    const ColorImage fx = to_float_image(x.color), fy = to_float_image(y.color);
    double most = 0;
    for (size_t i = 0; i < fx.pixels.size(); ++i)
        most = std::max<double>(most, glm::length(fx.pixels[i] - fy.pixels[i]));
    CHECK(most < 0.02);
}

TEST_CASE("a sampler wraps each axis its own way", "[gltf][texture]") {
    // Two texels across (u) and two down (v): red, green / blue, white.
    Texture t = Texture::from_linear(2, 2, {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}},
                                     Texture::Format::half);
    t.sampler.mag = Filter::nearest;
    auto texel_u = [&](float u) { return t.sample({u, 0.25f}); };  // row 0
    auto texel_v = [&](float v) { return t.sample({0.25f, v}); };  // column 0
    const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1), blue(0, 0, 1, 1);
    SECTION("repeat") {
        CHECK(texel_u(1.25f) == red);
        CHECK(texel_u(-0.25f) == green);
        CHECK(texel_v(1.75f) == blue);
    }
    SECTION("clamp to edge, on u only") {
        t.sampler.wrap_s = Wrap::clamp;
        CHECK(texel_u(1.25f) == green);
        CHECK(texel_u(-3.0f) == red);
        CHECK(texel_v(1.25f) == red);  // v still repeats
    }
    SECTION("mirrored repeat, on v only") {
        t.sampler.wrap_t = Wrap::mirror;
        CHECK(texel_v(1.25f) == blue);  // the mirror image's first half is the original's second
        CHECK(texel_v(1.75f) == red);
        CHECK(texel_v(-0.25f) == red);
        CHECK(texel_v(2.25f) == red);  // period 2
        CHECK(texel_u(1.25f) == red);  // u still repeats
    }
    SECTION("mirrored repeat on u, clamp on v") {
        t.sampler.wrap_s = Wrap::mirror;
        t.sampler.wrap_t = Wrap::clamp;
        CHECK(texel_u(1.25f) == green);
        CHECK(texel_u(-0.75f) == green);
        CHECK(texel_v(5.0f) == blue);
    }
}

TEST_CASE(
    "glTF samplers are read per axis, with their filters, NEAREST mipmaps as the magnification "
    "filter",
    "[gltf][texture]") {
    TempDir dir("gltf-sampler");
    for (auto [wrap_s, wrap_t, s, t] : std::vector<std::tuple<int, int, Wrap, Wrap>>{
             {33648, 33071, Wrap::mirror, Wrap::clamp},
             {33071, 10497, Wrap::clamp, Wrap::repeat},
             {10497, 33648, Wrap::repeat, Wrap::mirror}}) {
        Gltf g;
        palette_texture(g);
        g.doc["samplers"] = {
            {{"wrapS", wrap_s}, {"wrapT", wrap_t}, {"magFilter", 9728}, {"minFilter", 9986}}};
        quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
        const Mesh mesh = load_gltf(g.write(dir.file("sampler.gltf")));
        const Sampler& sampler = mesh.materials[0].base_color_map.texture->sampler;
        CHECK(sampler.wrap_s == s);
        CHECK(sampler.wrap_t == t);
        CHECK(sampler.mag == Filter::nearest);
        CHECK(sampler.min == Filter::nearest);  // NEAREST_MIPMAP_LINEAR
        CHECK(sampler.mipmaps);
        CHECK(sampler.mip == Filter::linear);
    }
    // NEAREST within the mipmaps follows the magnification filter: kept for
    // pixel art (magFilter NEAREST, above), linear otherwise, so an
    // exporter's default does not point-sample minified pixels.
    for (const json& mag : {json(9729), json()})
        for (const int min : {9984, 9986}) {
            Gltf g;
            palette_texture(g);
            json sampler = {{"minFilter", min}};
            if (!mag.is_null()) sampler["magFilter"] = mag;
            g.doc["samplers"] = json::array({sampler});
            quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
            const Mesh mesh = load_gltf(g.write(dir.file("mipmap-nearest.gltf")));
            const Sampler& read = mesh.materials[0].base_color_map.texture->sampler;
            INFO("magFilter " << mag.dump() << ", minFilter " << min);
            CHECK(read.min == Filter::linear);
            CHECK(read.mip == (min == 9984 ? Filter::nearest : Filter::linear));
            CHECK(read.mipmaps);
        }
    Gltf g;
    palette_texture(g);
    g.doc["samplers"] = {{{"wrapS", 12345}}};
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const std::string bad = g.write(dir.file("bad.gltf"));
    require_input_error([&] { load_gltf(bad); }, "sampler 0 wrapS: wrap mode 12345");
}

namespace {

// A triangle whose vertex 2 a morph target lifts by 2 in z; with
// `targets`, the file holds the target and default weights `weights` on
// the mesh (and `node_weights` on the node, when given); without, the
// shape those weights make, written out.
std::string morph_file(const std::string& path, bool targets, double weight,
                       const json& node_weights = nullptr) {
    Gltf g;
    const std::vector<float> base = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<float> shaped = base;
    shaped[8] = static_cast<float>(2 * weight);
    json primitive = {{"attributes", {{"POSITION", g.floats(targets ? base : shaped, "VEC3")}}}};
    if (targets)
        primitive["targets"] = {{{"POSITION", g.floats({0, 0, 0, 0, 0, 0, 0, 0, 2}, "VEC3")}}};
    g.mesh(primitive);
    if (targets) g.doc["meshes"][0]["weights"] = json::array({weight});
    json node = {{"mesh", 0}};
    if (!node_weights.is_null()) node["weights"] = node_weights;
    g.scene({g.node(node)});
    return g.write(path);
}

}  // namespace

TEST_CASE("default morph weights shape a mesh that no animation drives", "[gltf][morph]") {
    TempDir dir("gltf-morph");
    const Mesh weighted = load_gltf(morph_file(dir.file("weights.gltf"), true, 0.5));
    const Mesh explicit_shape = load_gltf(morph_file(dir.file("shape.gltf"), false, 0.5));
    REQUIRE(weighted.parts.size() == 1);
    for (size_t v = 0; v < 3; ++v)
        CHECK(glm::length(weighted.parts[0].positions[v] - explicit_shape.parts[0].positions[v]) <
              1e-6f);
    CHECK(weighted.bounds().max.z == Approx(1));
    // node.weights over mesh.weights.
    const Mesh node = load_gltf(morph_file(dir.file("node.gltf"), true, 0.5, json::array({1.0})));
    CHECK(node.bounds().max.z == Approx(2));
    // Rendered, the two files are the same picture.
    auto picture = [&](const std::string& file) {
        return render_yaml(dir.path(),
                           "output: { size: [48, 48], frames: \"1\" }\nstyle: blinn-phong\n"
                           "camera: { position: [3, -2, 4], target: [0.3, 0.3, 0.5], fov: 50 }\n"
                           "objects:\n  - mesh: " +
                               file + "\n    material: { double_sided: true }\n");
    };
    const ColorImage a = to_float_image(picture(dir.file("weights.gltf")).color);
    const ColorImage b = to_float_image(picture(dir.file("shape.gltf")).color);
    double most = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        most = std::max<double>(most, glm::length(a.pixels[i] - b.pixels[i]));
    CHECK(most < 1e-3);
}

namespace {

// Two bones up +Y; the mesh node carries a transform the skin must ignore
// (§3.7.3.3), and the inverse bind matrices move the mesh by (0, -1, 0)
// at rest: its rest pose spans y from -1 to 1.
std::string skinned_file(const std::string& path) {
    Gltf g;
    std::vector<float> p;
    std::vector<uint8_t> joints;
    std::vector<float> weights;
    for (int row = 0; row <= 4; ++row)
        for (int col = 0; col < 2; ++col) {
            p.insert(p.end(), {0.3f * static_cast<float>(col) - 0.15f,
                               0.5f * static_cast<float>(row), 0.1f});
            joints.insert(joints.end(), {0, 1, 0, 0});
            const float w = static_cast<float>(row) / 4;
            weights.insert(weights.end(), {1 - w, w, 0, 0});
        }
    std::vector<uint16_t> idx;
    for (uint16_t row = 0; row < 4; ++row) {
        const uint16_t a = static_cast<uint16_t>(2 * row);
        idx.insert(idx.end(), {a, static_cast<uint16_t>(a + 1), static_cast<uint16_t>(a + 3), a,
                               static_cast<uint16_t>(a + 3), static_cast<uint16_t>(a + 2)});
    }
    const int mesh =
        g.mesh({{"attributes",
                 {{"POSITION", g.floats(p, "VEC3")},
                  {"JOINTS_0", g.accessor(g.view(joints), kUByte, joints.size() / 4, "VEC4")},
                  {"WEIGHTS_0", g.floats(weights, "VEC4")}}},
                {"indices", g.indices(idx, kUShort)}});
    std::vector<float> inverse_bind;
    for (float y : {1.0f, 2.0f}) {  // translate(0, -1) and translate(0, -2)
        const std::vector<float> m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -y, 0, 1};
        inverse_bind.insert(inverse_bind.end(), m.begin(), m.end());
    }
    const int bind = g.accessor(g.view(bytes_of(inverse_bind)), kFloat, 2, "MAT4");
    const int root = g.node({{"name", "root"}, {"children", {1}}});
    g.node({{"name", "tip"}, {"translation", {0, 1, 0}}});
    g.doc["skins"] = {{{"joints", {root, 1}}, {"inverseBindMatrices", bind}}};
    const int shown = g.node({{"mesh", mesh}, {"skin", 0}, {"translation", {50, 0, 0}}});
    g.scene({root, shown});
    // The animation gltf-transform keeps: the tip turns.
    g.doc["animations"] = {
        {{"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "rotation"}}}}}},
         {"samplers",
          {{{"input", g.floats({0, 1}, "SCALAR")},
            {"output", g.floats({0, 0, 0, 1, 0, 0, 0.38268343f, 0.92387953f}, "VEC4")}}}}}};
    return g.write(path);
}

}  // namespace

TEST_CASE("a skinned mesh rests where its skin puts it, quantized or not", "[gltf][skin]") {
    TempDir dir("gltf-skin-bounds");
    const std::string file = skinned_file(dir.file("skinned.gltf"));
    const Mesh mesh = load_gltf(file);
    // Joint 0 at the origin with inverse bind y-1, joint 1 at y 1 with y-2:
    // every joint matrix moves by -1 in y, whatever the node's +50 in x.
    CHECK(mesh.bounds().min.x == Approx(-0.15f));
    CHECK(mesh.bounds().min.y == Approx(-1.0f));
    CHECK(mesh.bounds().max.y == Approx(1.0f));
    if (!have_command("gltf-transform")) FACET_SKIP(kNoGltfTransform);
    const std::string quantized = dir.file("quantized.glb");
    const Mesh q = transformed("quantize", file, quantized);
    REQUIRE(uses(q, "KHR_mesh_quantization"));
    // Positions of 14 or 16 bits over a 2-unit box.
    for (int k = 0; k < 3; ++k) {
        CHECK(q.bounds().min[k] == Approx(mesh.bounds().min[k]).margin(1e-3));
        CHECK(q.bounds().max[k] == Approx(mesh.bounds().max[k]).margin(1e-3));
    }
    const RunResult info = run_facet("info --json '" + quantized + "'");
    REQUIRE(info.exit_code == 0);
    const json bounds = json::parse(info.output)["bounds"];
    CHECK(bounds["min"][1].get<double>() == Approx(-1).margin(1e-3));
    CHECK(bounds["max"][1].get<double>() == Approx(1).margin(1e-3));
}
