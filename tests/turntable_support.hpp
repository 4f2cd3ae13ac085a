#pragma once
// Helpers of the model turntable tests (docs/turntables.md): small models
// the tests make in each format facet reads (a glTF with an animation, an
// OBJ, an STL standing Z-up, a PLY), and reading back what a turntable run
// wrote: its manifest, and per frame which pixels show the model and how
// opaque each is.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "gltf_anim_support.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

namespace facet::test {

// The triangles of an axis-aligned box, three corners each, wound
// counter-clockwise seen from outside.
inline std::vector<glm::vec3> box_triangles(glm::vec3 lo, glm::vec3 hi) {
    auto at = [&](int x, int y, int z) {
        return glm::vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z);
    };
    // Each face's corners in order round its outward normal.
    const int faces[6][4][3] = {
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},  // -X
        {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},  // +X
        {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},  // -Y
        {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},  // +Y
        {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}},  // -Z
        {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},  // +Z
    };
    std::vector<glm::vec3> out;
    for (const auto& f : faces) {
        const glm::vec3 q[4] = {at(f[0][0], f[0][1], f[0][2]), at(f[1][0], f[1][1], f[1][2]),
                                at(f[2][0], f[2][1], f[2][2]), at(f[3][0], f[3][1], f[3][2])};
        out.insert(out.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
    return out;
}

inline std::vector<glm::vec3> joined(std::vector<glm::vec3> a, const std::vector<glm::vec3>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

inline std::vector<float> flat_floats(const std::vector<glm::vec3>& points) {
    std::vector<float> out;
    for (const glm::vec3& p : points) out.insert(out.end(), {p.x, p.y, p.z});
    return out;
}

// A binary STL of the triangles (three corners each).
inline std::string write_binary_stl(const std::string& path,
                                    const std::vector<glm::vec3>& corners) {
    std::vector<uint8_t> bytes(80, 0);
    const std::string header = "facet test model";
    std::copy(header.begin(), header.end(), bytes.begin());
    auto put = [&](const void* data, size_t size) {
        const auto* b = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), b, b + size);
    };
    const uint32_t count = static_cast<uint32_t>(corners.size() / 3);
    put(&count, 4);
    for (size_t t = 0; t < count; ++t) {
        const glm::vec3 a = corners[3 * t], b = corners[3 * t + 1], c = corners[3 * t + 2];
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (const glm::vec3& v : {n, a, b, c}) put(&v, 12);
        const uint16_t attribute = 0;
        put(&attribute, 2);
    }
    return write_bytes(path, bytes);
}

// An OBJ (text) of the triangles.
inline std::string write_obj(const std::string& path, const std::vector<glm::vec3>& corners) {
    std::string text = "# facet test model\no model\n";
    for (const glm::vec3& p : corners)
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) +
                "\n";
    for (size_t t = 0; t < corners.size() / 3; ++t)
        text += "f " + std::to_string(3 * t + 1) + " " + std::to_string(3 * t + 2) + " " +
                std::to_string(3 * t + 3) + "\n";
    return write_text(path, text);
}

// An ASCII PLY of the triangles.
inline std::string write_ply(const std::string& path, const std::vector<glm::vec3>& corners) {
    std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(corners.size()) +
                       "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                       std::to_string(corners.size() / 3) +
                       "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const glm::vec3& p : corners)
        text += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (size_t t = 0; t < corners.size() / 3; ++t)
        text += "3 " + std::to_string(3 * t) + " " + std::to_string(3 * t + 1) + " " +
                std::to_string(3 * t + 2) + "\n";
    return write_text(path, text);
}

// A glTF of a box 0.6 wide and 1.2 tall (its centre at the origin) that
// dips by 0.5 and back over one second (animation "bob"): the lowest
// point of its poses is y = -1.1, half a second in.
inline std::string write_bobbing_box(const std::string& path) {
    Gltf g;
    const std::vector<glm::vec3> box = box_triangles({-0.3f, -0.6f, -0.3f}, {0.3f, 0.6f, 0.3f});
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(flat_floats(box), "VEC3")}}}},
                     {{"name", "Box"}});
    const int bob = add_animation(g, "bob");
    add_channel(g, bob, 0, "translation", {0, 0.5f, 1}, {0, 0, 0, 0, -0.5f, 0, 0, 0, 0});
    return g.write(path);
}

// A plinth with a column on it, standing along +Z as CAD tools write STL:
// a flat base at z = 0, 2 units tall, 1 wide.
inline std::vector<glm::vec3> z_up_column() {
    return joined(box_triangles({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 0.2f}),
                  box_triangles({-0.15f, -0.15f, 0.2f}, {0.15f, 0.15f, 2.0f}));
}

// A house: a box with a pyramid roof, Y-up.
inline std::vector<glm::vec3> house() {
    std::vector<glm::vec3> out = box_triangles({-0.5f, 0, -0.4f}, {0.5f, 0.7f, 0.4f});
    const glm::vec3 top(0, 1.1f, 0);
    const glm::vec3 eaves[4] = {
        {-0.5f, 0.7f, 0.4f}, {0.5f, 0.7f, 0.4f}, {0.5f, 0.7f, -0.4f}, {-0.5f, 0.7f, -0.4f}};
    for (int i = 0; i < 4; ++i) out.insert(out.end(), {eaves[i], eaves[(i + 1) % 4], top});
    return out;
}

// An octahedron: no flat base on any axis.
inline std::vector<glm::vec3> octahedron() {
    const glm::vec3 up(0, 0.8f, 0), down(0, -0.8f, 0);
    const glm::vec3 ring[4] = {{0.5f, 0, 0}, {0, 0, -0.5f}, {-0.5f, 0, 0}, {0, 0, 0.5f}};
    std::vector<glm::vec3> out;
    for (int i = 0; i < 4; ++i) {
        out.insert(out.end(), {ring[i], ring[(i + 1) % 4], up});
        out.insert(out.end(), {ring[(i + 1) % 4], ring[i], down});
    }
    return out;
}

inline nlohmann::json read_manifest_json(const std::string& folder) {
    std::ifstream in(folder + "/manifest.json");
    REQUIRE(in);
    return nlohmann::json::parse(in);
}

// The SHA-256 of each file a manifest lists, by "pass.frame.format".
inline std::map<std::string, std::string> listed_hashes(const nlohmann::json& manifest) {
    std::map<std::string, std::string> out;
    for (const auto& f : manifest["files"])
        out[f["pass"].get<std::string>() + "." + std::to_string(f["frame"].get<int>()) + "." +
            f["format"].get<std::string>()] = f["sha256"].get<std::string>();
    return out;
}

// One frame of a run written with --passes color,object_id --formats exr.
struct TurntableFrame {
    int width = 0, height = 0;
    std::vector<float> id, alpha;  // per pixel: object id, coverage
    float id_at(int x, int y) const { return id[static_cast<size_t>(y) * width + x]; }
    float alpha_at(int x, int y) const { return alpha[static_cast<size_t>(y) * width + x]; }
};

inline const std::vector<float>& exr_channel(const DecodedExr& exr, const std::string& suffix) {
    for (size_t c = 0; c < exr.channel_names.size(); ++c) {
        const std::string& name = exr.channel_names[c];
        if (name.size() >= suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            return exr.channels[c];
    }
    FAIL("no channel ending in " << suffix);
    return exr.channels.front();
}

inline TurntableFrame read_turntable_frame(const std::string& folder, int frame) {
    char number[16];
    std::snprintf(number, sizeof number, "%04d", frame);
    const DecodedExr ids = read_exr(folder + "/object_id." + number + ".exr");
    const DecodedExr color = read_exr(folder + "/color." + number + ".exr");
    TurntableFrame out;
    out.width = ids.width;
    out.height = ids.height;
    out.id = exr_channel(ids, "id");
    out.alpha = exr_channel(color, "A");
    return out;
}

// The pixels showing object `id`: their bounding rectangle, inclusive.
struct PixelBox {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    bool empty() const { return x1 < 0; }
    int width() const { return x1 - x0 + 1; }
    int height() const { return y1 - y0 + 1; }
};

inline PixelBox pixels_of(const TurntableFrame& f, float id) {
    PixelBox box;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.id_at(x, y) == id) {
                box.x0 = std::min(box.x0, x);
                box.y0 = std::min(box.y0, y);
                box.x1 = std::max(box.x1, x);
                box.y1 = std::max(box.y1, y);
            }
    return box;
}

}  // namespace facet::test
