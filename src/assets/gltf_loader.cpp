// glTF 2.0 (.gltf and .glb) through tinygltf. The node hierarchy of the
// default scene is flattened: every mesh instance becomes parts with its
// world transform baked in. Follows the glTF 2.0 specification §3.6-3.9.
// A file with animations, skins or morph targets also keeps what poses it
// (Mesh::rig, read by gltf_rig_loader.cpp); the baked parts stay the rest pose.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include <optional>

#include <stb/stb_image.h>
#include <tiny_gltf.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

#include "assets/gltf_accessors.hpp"
#include "assets/gltf_draco.hpp"
#include "assets/gltf_extensions.hpp"
#include "assets/gltf_meshopt.hpp"
#include "assets/gltf_rig_loader.hpp"
#include "assets/mesh.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/memory.hpp"

namespace facet {
namespace {

using gltf_detail::bad;
using gltf_detail::read_floats;
using gltf_detail::read_indices;

// Deep hierarchies beyond this are almost certainly cycles or hostile files.
constexpr int kMaxNodeDepth = 256;

constexpr int kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;
constexpr int kWrapClamp = 33071;

glm::mat4 node_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m;
        std::memcpy(glm::value_ptr(m), node.matrix.data(), sizeof(double) * 16);  // column-major
        return glm::mat4(m);
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(
            m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1],
                     node.rotation[2]);  // w, x, y, z
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3)
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(m);
}

std::vector<uint32_t> triangle_list(int mode, const std::vector<uint32_t>& idx) {
    std::vector<uint32_t> tris;
    if (mode == kModeTriangles) {
        tris.assign(idx.begin(), idx.begin() + (idx.size() / 3) * 3);
    } else if (mode == kModeStrip) {
        for (size_t i = 2; i < idx.size(); ++i) {
            // Every other triangle of a strip is reversed to keep one winding (glTF §3.7.2.1).
            if (i % 2 == 0)
                tris.insert(tris.end(), {idx[i - 2], idx[i - 1], idx[i]});
            else
                tris.insert(tris.end(), {idx[i - 1], idx[i - 2], idx[i]});
        }
    } else if (mode == kModeFan) {
        for (size_t i = 2; i < idx.size(); ++i)
            tris.insert(tris.end(), {idx[0], idx[i - 1], idx[i]});
    }
    return tris;
}

// What tinygltf's callbacks need: the file's own path and folder, the
// policy for the URIs inside it, the texture budget, and the first refusal
// (kept, and thrown once tinygltf has returned, so that no exception
// crosses it).
struct LoadContext {
    std::string path;    // the .gltf or .glb, as given
    std::string prefix;  // how tinygltf spells the paths it builds from the file's folder
    const AssetContext* assets;
    std::optional<Error> refusal;

    void refuse(const Error& e) {
        if (!refusal) refusal = e;
    }
};

// tinygltf looks for a URI in the file's folder and then in the current
// directory; only the first is the glTF specification's meaning (§2.8), so
// the second is not found. The first always "exists": reading it then says
// precisely why it cannot be read (missing, a FIFO, outside the folder...).
bool file_exists(const std::string& candidate, void* user) {
    const auto& c = *static_cast<const LoadContext*>(user);
    return candidate.compare(0, c.prefix.size(), c.prefix) == 0;
}

// No `~` or variable expansion (tinygltf's default runs wordexp on URIs).
std::string expand_file_path(const std::string& path, void*) {
    return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err,
                     const std::string& candidate, void* user) {
    auto& c = *static_cast<LoadContext*>(user);
    try {
        const std::string reference = candidate.substr(c.prefix.size());
        const std::string file =
            resolve_asset_reference(c.path, "buffer or image URI", reference, c.assets->paths);
        *out = read_input_file(file, "glTF resource", c.assets->paths.max_file_bytes);
        return true;
    } catch (const Error& e) {
        c.refuse(e);
        if (err) *err += e.what();
        return false;
    }
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
    if (err) *err += "facet never writes glTF resources";
    return false;
}

// Images: the size is read first and charged to the texture budget, so a
// small file that would decode to gigabytes is stopped before it is.
bool load_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                const unsigned char* bytes, int size, void* user) {
    auto& c = *static_cast<LoadContext*>(user);
    const std::string name = c.path + " image " + std::to_string(index) +
                             (image->uri.empty() ? "" : " '" + image->uri + "'");
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &channels)) {
        if (err) *err += name + ": cannot decode (" + stbi_failure_reason() + ")\n";
        return false;
    }
    const bool is16 = stbi_is_16_bit_from_memory(bytes, size);
    try {
        if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide)
            throw Error(ExitCode::invalid_input, name + ": " + std::to_string(w) + "x" +
                                                     std::to_string(h) +
                                                     " pixels (each side must be 1 to " +
                                                     std::to_string(kMaxImageSide) + ")");
        if (c.assets->textures)
            c.assets->textures->charge(name, w, h, texture_bytes(w, h, is16 ? 16 : 8));
    } catch (const Error& e) {
        c.refuse(e);
        if (err) *err += e.what();
        return false;
    }
    void* data =
        is16 ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &w, &h, &channels, 0))
             : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &channels, 0));
    if (!data) {
        if (err) *err += name + ": cannot decode (" + stbi_failure_reason() + ")\n";
        return false;
    }
    const size_t n = static_cast<size_t>(w) * h * channels * (is16 ? 2 : 1);
    image->image.assign(static_cast<const unsigned char*>(data),
                        static_cast<const unsigned char*>(data) + n);
    stbi_image_free(data);
    image->width = w;
    image->height = h;
    image->component = channels;
    image->bits = is16 ? 16 : 8;
    image->pixel_type =
        is16 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    return true;
}

// The file read by tinygltf through facet's callbacks (path policy,
// texture budget), refusals rethrown, and compressed geometry refused.
struct ReadModel {
    tinygltf::Model model;
    std::string warnings;         // tinygltf's, trimmed
    Warnings extension_warnings;  // extensions used that facet ignores
};

ReadModel read_model(const std::string& path, const AssetContext& context) {
    ReadModel read;
    // Before tinygltf parses buffers that a compression extension may have
    // left without data, so the error names the extension.
    const gltf_detail::ExtensionLists lists = gltf_detail::read_extension_lists(path);
    gltf_detail::check_extensions(lists, path, read.extension_warnings);
    const bool meshopt = lists.lists("EXT_meshopt_compression");
    tinygltf::Model& model = read.model;
    tinygltf::TinyGLTF loader;
    LoadContext load{path, "", &context, std::nullopt};
    // tinygltf joins its folder (the path up to the last slash) and a URI with a slash.
    const size_t slash = path.find_last_of("/\\");
    load.prefix = slash == std::string::npos ? "" : path.substr(0, slash) + "/";
    tinygltf::FsCallbacks fs{&file_exists, &expand_file_path, &read_whole_file, &write_whole_file,
                             &load};
    loader.SetFsCallbacks(fs);
    loader.SetImageLoader(&load_image, &load);
    std::string err, warn;
    bool binary = std::filesystem::path(path).extension() == ".glb" ||
                  std::filesystem::path(path).extension() == ".GLB";
    bool ok = false;
    // Compressed files are rewritten before tinygltf sees them: meshopt's
    // fallback buffers hold no data, Draco's accessors have no views.
    const bool draco = lists.lists("KHR_draco_mesh_compression");
    int placeholder_view = -1;
    try {
        if (meshopt || draco) {
            const std::vector<uint8_t> file = gltf_detail::with_json_rewritten(
                read_input_file(path, "glTF"), [&](const std::string& json) {
                    std::string out = meshopt ? gltf_detail::without_fallback_buffers(json) : json;
                    return draco ? gltf_detail::with_placeholder_views(out, placeholder_view) : out;
                });
            const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash);
            ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, file.data(),
                                                      static_cast<unsigned>(file.size()), folder)
                        : loader.LoadASCIIFromString(&model, &err, &warn,
                                                     reinterpret_cast<const char*>(file.data()),
                                                     static_cast<unsigned>(file.size()), folder);
        } else {
            ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                        : loader.LoadASCIIFromFile(&model, &err, &warn, path);
        }
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (load.refusal) throw *load.refusal;
    auto trim = [](std::string s) {
        while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
        return s;
    };
    if (!ok)
        bad(path, "cannot read glTF: " + (err.empty() ? std::string("unknown error") : trim(err)));
    read.warnings = trim(warn);
    if (meshopt) gltf_detail::decode_meshopt_views(model, path);
    if (draco) gltf_detail::decode_draco_primitives(model, path, placeholder_view);
    return read;
}

// COLOR_0 (glTF §3.7.2.1): linear RGB or RGBA, floats or normalised
// integers. The alpha is read past: facet's surfaces are opaque.
std::vector<glm::vec3> read_vertex_colors(const tinygltf::Model& model, int accessor, size_t count,
                                          const std::string& path, const std::string& what) {
    const tinygltf::Accessor& a =
        gltf_detail::accessor_at(model, accessor, path, what + " COLOR_0");
    if (a.type != TINYGLTF_TYPE_VEC3 && a.type != TINYGLTF_TYPE_VEC4)
        bad(path, what + ": COLOR_0 must be VEC3 or VEC4");
    const int components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    const std::vector<float> values =
        read_floats(model, accessor, components, path, what + " COLOR_0");
    if (values.size() / static_cast<size_t>(components) != count)
        bad(path, what + ": COLOR_0 count differs from POSITION count");
    std::vector<glm::vec3> colors(count);
    for (size_t i = 0; i < count; ++i) {
        const float* c = &values[i * static_cast<size_t>(components)];
        colors[i] = glm::clamp(glm::vec3(c[0], c[1], c[2]), glm::vec3(0), glm::vec3(1));
    }
    return colors;
}

// The emission of a material: emissiveFactor scaled by
// KHR_materials_emissive_strength (which lets it pass 1).
glm::vec3 emission(const tinygltf::Material& m, const std::string& path) {
    if (m.emissiveFactor.size() < 3) return glm::vec3(0);
    glm::vec3 e(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
    const auto it = m.extensions.find("KHR_materials_emissive_strength");
    if (it != m.extensions.end() && it->second.Has("emissiveStrength")) {
        const tinygltf::Value& v = it->second.Get("emissiveStrength");
        const double strength = v.IsNumber() ? v.GetNumberAsDouble() : -1;
        if (!(strength >= 0 && strength <= 1e6))
            bad(path, "material '" + m.name + "': emissiveStrength must be a number from 0 to 1e6");
        e *= static_cast<float>(strength);
    }
    if (!(e.x >= 0 && e.y >= 0 && e.z >= 0 && std::isfinite(e.x + e.y + e.z)))
        bad(path, "material '" + m.name + "': emissiveFactor must be finite and not negative");
    return e;
}

// The file's materials, with textures decoded once each.
std::vector<Material> read_materials(const tinygltf::Model& model, const std::string& path) {
    std::vector<Material> materials;
    std::map<int, std::shared_ptr<const Texture>> textures;
    auto texture_for = [&](int tex_index) -> std::shared_ptr<const Texture> {
        if (tex_index < 0) return nullptr;
        if (static_cast<size_t>(tex_index) >= model.textures.size())
            bad(path, "material refers to missing texture " + std::to_string(tex_index));
        auto& slot = textures[tex_index];
        if (slot) return slot;
        const auto& t = model.textures[tex_index];
        if (t.source < 0 || static_cast<size_t>(t.source) >= model.images.size())
            bad(path, "texture " + std::to_string(tex_index) + " has no image");
        const auto& img = model.images[t.source];
        if (img.image.empty()) bad(path, "image '" + img.uri + "' could not be decoded");
        if (img.image.size() <
            static_cast<size_t>(img.width) * img.height * img.component * (img.bits / 8))
            bad(path, "image '" + img.uri + "' has fewer bytes than its size says");
        Texture tex;
        try {
            tex = texture_from_pixels(img.width, img.height, img.component, img.bits,
                                      img.image.data());
        } catch (const Error& e) {
            bad(path, "image '" + img.uri + "': " + e.what());
        }
        if (t.sampler >= 0 && static_cast<size_t>(t.sampler) < model.samplers.size())
            tex.wrap = model.samplers[t.sampler].wrapS == kWrapClamp ? Wrap::clamp : Wrap::repeat;
        slot = std::make_shared<Texture>(std::move(tex));
        return slot;
    };
    for (const auto& m : model.materials) {
        Material mat;
        mat.name = m.name;
        const auto& pbr = m.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() >= 3)
            mat.color = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
        mat.texture = texture_for(pbr.baseColorTexture.index);
        // A Phong reading of metal/roughness: smoother surfaces get tighter,
        // stronger highlights (documented in docs/scene-format.md).
        float roughness = static_cast<float>(std::clamp(pbr.roughnessFactor, 0.05, 1.0));
        mat.shininess =
            std::min(2.0f / (roughness * roughness * roughness * roughness) - 2.0f, 2048.0f);
        mat.shininess = std::max(mat.shininess, 1.0f);
        mat.specular = 0.15f + 0.6f * (1.0f - roughness);
        mat.double_sided = m.doubleSided;
        mat.emissive = emission(m, path);
        if (pbr.baseColorFactor.size() >= 4)
            mat.alpha = static_cast<float>(std::clamp(pbr.baseColorFactor[3], 0.0, 1.0));
        if (m.alphaMode == "MASK")
            mat.alpha_mode = AlphaMode::mask;
        else if (m.alphaMode == "BLEND")
            mat.alpha_mode = AlphaMode::blend;
        else if (!m.alphaMode.empty() && m.alphaMode != "OPAQUE")
            bad(path, "material '" + m.name + "': alphaMode must be OPAQUE, MASK or BLEND");
        if (!(m.alphaCutoff >= 0 && m.alphaCutoff <= 1))
            bad(path, "material '" + m.name + "': alphaCutoff must be 0 to 1");
        mat.alpha_cutoff = static_cast<float>(m.alphaCutoff);
        mat.unlit = m.extensions.count("KHR_materials_unlit") > 0;
        materials.push_back(mat);
    }
    return materials;
}

// The KHR_lights_punctual light a node carries, placed by `world`.
std::optional<GltfLight> node_light(const tinygltf::Model& model, const tinygltf::Node& node,
                                    const glm::mat4& world, const std::string& path) {
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end() || !it->second.Has("light")) return std::nullopt;
    const tinygltf::Value& index_value = it->second.Get("light");
    const int index =
        index_value.IsNumber() ? static_cast<int>(index_value.GetNumberAsDouble()) : -1;
    if (index < 0 || static_cast<size_t>(index) >= model.lights.size())
        bad(path, "node '" + node.name + "' refers to missing light " + std::to_string(index));
    const tinygltf::Light& l = model.lights[static_cast<size_t>(index)];
    GltfLight light;
    light.name = l.name.empty() ? node.name : l.name;
    const std::string what = "light '" + light.name + "'";
    if (l.type == "directional")
        light.type = GltfLight::Type::directional;
    else if (l.type == "point")
        light.type = GltfLight::Type::point;
    else if (l.type == "spot")
        light.type = GltfLight::Type::spot;
    else
        bad(path, what + ": unknown type '" + l.type + "' (directional, point or spot)");
    if (l.color.size() >= 3)
        light.color = glm::vec3(static_cast<float>(l.color[0]), static_cast<float>(l.color[1]),
                                static_cast<float>(l.color[2]));
    light.intensity = static_cast<float>(l.intensity);
    light.range = static_cast<float>(l.range);
    light.inner_degrees = static_cast<float>(glm::degrees(l.spot.innerConeAngle));
    light.outer_degrees = static_cast<float>(glm::degrees(l.spot.outerConeAngle));
    const bool finite = std::isfinite(light.intensity) && std::isfinite(light.range) &&
                        std::isfinite(light.color.r + light.color.g + light.color.b);
    if (!finite || light.intensity < 0 || light.range < 0 ||
        glm::any(glm::lessThan(light.color, glm::vec3(0))))
        bad(path, what + ": colour, intensity and range must be finite and not negative");
    if (!(light.inner_degrees >= 0 && light.inner_degrees < light.outer_degrees &&
          light.outer_degrees <= 90))
        bad(path, what + ": spot cone angles must satisfy 0 <= inner < outer <= 90 degrees");
    light.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
    const glm::vec3 direction(world * glm::vec4(0, 0, -1, 0));
    const float length = glm::length(direction);
    if (!(length > 0) || !std::isfinite(length))
        bad(path, what + ": its node's transform has no direction");
    light.direction = direction / length;
    return light;
}

// The cameras on the file's nodes (§3.10), checked.
std::vector<GltfCamera> read_cameras(const tinygltf::Model& model, const std::string& path) {
    std::vector<GltfCamera> cameras;
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        const int index = model.nodes[n].camera;
        if (index < 0) continue;
        if (static_cast<size_t>(index) >= model.cameras.size())
            bad(path,
                "node " + std::to_string(n) + " refers to missing camera " + std::to_string(index));
        const tinygltf::Camera& c = model.cameras[static_cast<size_t>(index)];
        GltfCamera camera;
        // Named as the rig names nodes (gltf_rig_loader.cpp) when neither has a name.
        camera.name = !c.name.empty()                ? c.name
                      : !model.nodes[n].name.empty() ? model.nodes[n].name
                                                     : "node" + std::to_string(n);
        camera.node = static_cast<int>(n);
        camera.orthographic = c.type != "perspective";
        if (camera.orthographic) {
            cameras.push_back(camera);
            continue;
        }
        const double yfov = c.perspective.yfov * 180.0 / 3.14159265358979323846;
        if (!(yfov >= 1 && yfov <= 179))
            bad(path, "camera '" + camera.name + "': yfov must be 1 to 179 degrees");
        if (!(c.perspective.znear > 0) ||
            !(c.perspective.zfar == 0 || c.perspective.zfar > c.perspective.znear))
            bad(path, "camera '" + camera.name + "': znear must be positive and zfar beyond it");
        camera.yfov_degrees = yfov;
        camera.znear = c.perspective.znear;
        camera.zfar = c.perspective.zfar;
        cameras.push_back(camera);
    }
    return cameras;
}

}  // namespace

Mesh load_gltf(const std::string& path, const AssetContext& context) {
    require_input_file(path, "glTF");
    ReadModel read = read_model(path, context);
    const tinygltf::Model& model = read.model;
    Mesh mesh;
    mesh.source = path;
    mesh.loader = "tinygltf";
    if (!read.warnings.empty()) mesh.warnings.push_back(file_warning(path, read.warnings));
    mesh.warnings.insert(mesh.warnings.end(), read.extension_warnings.begin(),
                         read.extension_warnings.end());
    // The rest pose below is baked as always; a file that can move also
    // keeps what moves it (gltf_rig_loader.cpp).
    std::shared_ptr<MeshRig> rig;
    if (gltf_detail::has_rig_data(model)) {
        rig = std::make_shared<MeshRig>();
        gltf_detail::read_rig_nodes_and_animations(model, path, *rig, mesh.warnings);
    }

    mesh.materials = read_materials(model, path);
    const uint32_t default_material = static_cast<uint32_t>(mesh.materials.size());
    Material fallback;
    fallback.name = "default";
    fallback.color = glm::vec3(1);
    mesh.materials.push_back(fallback);

    // Every mesh instance is baked into parts of its own, so a small file
    // whose nodes repeat a large mesh, or whose primitives share one large
    // accessor, asks for far more than its size: each primitive's share is
    // checked against the memory there is before it is read.
    const uint64_t memory = memory_available();
    uint64_t planned = 0;
    auto plan_primitive = [&](const tinygltf::Primitive& prim, int position_accessor,
                              const std::string& what) {
        constexpr uint64_t kPerVertex = 64, kPerIndex = 16;  // the part and what builds it
        // Counts the data cannot back are the file's error, not a lack of memory.
        gltf_detail::check_accessor_data(model, position_accessor, path, what + " POSITION");
        planned += static_cast<uint64_t>(model.accessors[position_accessor].count) * kPerVertex;
        if (prim.indices >= 0) {
            gltf_detail::check_accessor_data(model, prim.indices, path, what + " indices");
            planned += static_cast<uint64_t>(model.accessors[prim.indices].count) * kPerIndex;
        }
        check_memory("loading " + path, {{"mesh instances", planned}}, memory);
    };
    auto add_mesh = [&](int mesh_index, const glm::mat4& world, int node_index) {
        if (mesh_index < 0 || static_cast<size_t>(mesh_index) >= model.meshes.size())
            bad(path, "node refers to missing mesh " + std::to_string(mesh_index));
        glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(world));
        bool mirrored = glm::determinant(glm::mat3(world)) < 0;
        const auto& gm = model.meshes[mesh_index];
        for (size_t p = 0; p < gm.primitives.size(); ++p) {
            const auto& prim = gm.primitives[p];
            std::string what = "mesh '" + gm.name + "' primitive " + std::to_string(p);
            int mode = prim.mode < 0 ? kModeTriangles : prim.mode;
            if (mode != kModeTriangles && mode != kModeStrip && mode != kModeFan) {
                mesh.warnings.push_back(
                    file_warning(path, what + ": points and lines are not rendered"));
                continue;
            }
            auto pos_it = prim.attributes.find("POSITION");
            if (pos_it == prim.attributes.end()) {
                mesh.warnings.push_back(
                    file_warning(path, what + ": no POSITION attribute, skipped"));
                continue;
            }
            MeshPart part;
            plan_primitive(prim, pos_it->second, what);
            auto pos = read_floats(model, pos_it->second, 3, path, what + " POSITION");
            size_t count = pos.size() / 3;
            for (size_t i = 0; i < count; ++i)
                part.positions.push_back(
                    glm::vec3(world * glm::vec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1)));
            RigPart rig_part;  // the same vertices before the node transform
            if (rig) {
                rig_part.node = node_index;
                rig_part.skin = model.nodes[node_index].skin;
                rig_part.rest_mirrored = mirrored;
                for (size_t i = 0; i < count; ++i)
                    rig_part.positions.push_back({pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]});
            }
            bool has_normals = false;
            std::vector<uint32_t> unusable_normals;  // zero length, or a singular node matrix
            if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
                auto nrm = read_floats(model, it->second, 3, path, what + " NORMAL");
                if (nrm.size() / 3 != count)
                    bad(path, what + ": NORMAL count differs from POSITION count");
                for (size_t i = 0; i < count; ++i) {
                    const glm::vec3 file_normal(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
                    glm::vec3 n = normal_matrix * file_normal;
                    float len = glm::length(n);
                    bool usable = len > 0 && std::isfinite(len);
                    part.normals.push_back(usable ? n / len : glm::vec3(0));
                    if (!usable) unusable_normals.push_back(static_cast<uint32_t>(i));
                    if (rig) {
                        // Posing derives a zero normal from the faces, as
                        // the bake below does.
                        float file_len = glm::length(file_normal);
                        rig_part.normals.push_back(file_len > 0 ? file_normal / file_len
                                                                : glm::vec3(0));
                        if (file_len == 0)
                            rig_part.normals_from_faces.push_back(static_cast<uint32_t>(i));
                    }
                }
                has_normals = true;
            }
            if (rig) gltf_detail::read_part_skin_and_morph(model, prim, *rig, path, what, rig_part);
            part.material = default_material;
            // The base colour texture is the one facet samples, so its
            // coordinate set and KHR_texture_transform become the part's UVs.
            gltf_detail::UvTransform uv_transform;
            if (prim.material >= 0) {
                if (static_cast<size_t>(prim.material) >= model.materials.size())
                    bad(path,
                        what + " refers to missing material " + std::to_string(prim.material));
                part.material = static_cast<uint32_t>(prim.material);
                uv_transform = gltf_detail::texture_transform(
                    model.materials[prim.material].pbrMetallicRoughness.baseColorTexture, path,
                    "material " + std::to_string(prim.material) + " baseColorTexture");
            }
            const std::string uv_name = "TEXCOORD_" + std::to_string(uv_transform.tex_coord);
            if (auto it = prim.attributes.find(uv_name); it != prim.attributes.end()) {
                auto uv = read_floats(model, it->second, 2, path, what + " " + uv_name);
                if (uv.size() / 2 != count)
                    bad(path, what + ": " + uv_name + " count differs from POSITION count");
                for (size_t i = 0; i < count; ++i) {
                    const glm::vec2 file_uv = {uv[2 * i], uv[2 * i + 1]};
                    part.uvs.push_back(uv_transform.identity() ? file_uv
                                                               : uv_transform.apply(file_uv));
                }
            }
            if (auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end())
                part.colors = read_vertex_colors(model, it->second, count, path, what);
            std::vector<uint32_t> idx;
            if (prim.indices >= 0) {
                idx = read_indices(model, prim.indices, path);
            } else {
                idx.resize(count);
                for (size_t i = 0; i < count; ++i) idx[i] = static_cast<uint32_t>(i);
            }
            for (uint32_t i : idx)
                if (i >= count)
                    bad(path, what + ": index " + std::to_string(i) + " is out of range (" +
                                  std::to_string(count) + " vertices)");
            part.indices = triangle_list(mode, idx);
            if (mirrored)
                for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
                    std::swap(part.indices[t + 1], part.indices[t + 2]);
            if (part.indices.empty()) continue;
            // glTF §3.7.2.1: without normals, flat normals are used.
            if (!has_normals) {
                std::vector<uint32_t> source_vertex;
                compute_normals(part, 0.0f, &source_vertex);
                if (rig) {
                    // The split vertices get their skin and morph data from
                    // the vertex they were copied from; posing recomputes
                    // their normals from the posed faces.
                    gltf_detail::reorder_part_vertices(rig_part, source_vertex);
                    rig_part.normals.assign(source_vertex.size(), glm::vec3(0));
                    for (size_t i = 0; i < source_vertex.size(); ++i)
                        rig_part.normals_from_faces.push_back(static_cast<uint32_t>(i));
                }
            }
            if (!unusable_normals.empty()) {
                // Zero normals (BoxBadNormals) would shade as if facing an
                // arbitrary way; the faces around the vertex know better.
                std::vector<glm::vec3> sum(count, glm::vec3(0));
                for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
                    const uint32_t a = part.indices[t], b = part.indices[t + 1],
                                   c = part.indices[t + 2];
                    glm::vec3 face = glm::cross(part.positions[b] - part.positions[a],
                                                part.positions[c] - part.positions[a]);
                    for (uint32_t v : {a, b, c}) sum[v] += face;
                }
                for (uint32_t v : unusable_normals) {
                    float len = glm::length(sum[v]);
                    part.normals[v] =
                        len > 0 && std::isfinite(len) ? sum[v] / len : glm::vec3(0, 1, 0);
                }
                mesh.warnings.push_back(
                    file_warning(path, what + ": " + std::to_string(unusable_normals.size()) +
                                           " normals of zero length replaced by face normals"));
            }
            validate_part(part, path);
            mesh.parts.push_back(std::move(part));
            if (rig) rig->parts.push_back(std::move(rig_part));
        }
    };

    std::function<void(int, const glm::mat4&, int, std::set<int>&)> visit =
        [&](int node_index, const glm::mat4& parent, int depth, std::set<int>& on_path) {
            if (node_index < 0 || static_cast<size_t>(node_index) >= model.nodes.size())
                bad(path, "scene refers to missing node " + std::to_string(node_index));
            if (on_path.count(node_index))
                bad(path, "node hierarchy has a cycle through node " + std::to_string(node_index));
            if (depth > kMaxNodeDepth)
                bad(path,
                    "node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels");
            on_path.insert(node_index);
            const auto& node = model.nodes[node_index];
            glm::mat4 world = parent * node_matrix(node);
            if (node.mesh >= 0) add_mesh(node.mesh, world, node_index);
            if (auto light = node_light(model, node, world, path)) mesh.lights.push_back(*light);
            for (int child : node.children) visit(child, world, depth + 1, on_path);
            on_path.erase(node_index);
        };

    // glTF §3.5.3: nodes form strict trees. A node with several parents is
    // walked once per path to it, so a few dozen shared levels never finish.
    std::vector<int> parents(model.nodes.size(), 0);
    for (const auto& n : model.nodes)
        for (int c : n.children)
            if (c >= 0 && static_cast<size_t>(c) < parents.size() && ++parents[c] > 1)
                bad(path, "node " + std::to_string(c) + " has more than one parent");

    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int scene =
            model.defaultScene >= 0 && static_cast<size_t>(model.defaultScene) < model.scenes.size()
                ? model.defaultScene
                : 0;
        roots = model.scenes[scene].nodes;
    } else {
        // No scene: every node that is nobody's child is a root.
        std::vector<bool> is_child(model.nodes.size(), false);
        for (const auto& n : model.nodes)
            for (int c : n.children)
                if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[c] = true;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    std::set<int> on_path;
    for (int root : roots) visit(root, glm::mat4(1.0f), 0, on_path);
    if (mesh.triangle_count() == 0) bad(path, "the glTF file has no triangles to render");
    mesh.rig = std::move(rig);
    mesh.cameras = read_cameras(model, path);
    return mesh;
}

GltfCameras load_gltf_cameras(const std::string& path, const AssetContext& context) {
    require_input_file(path, "glTF");
    ReadModel read = read_model(path, context);
    GltfCameras out;
    out.warnings = read.extension_warnings;
    auto rig = std::make_shared<MeshRig>();
    gltf_detail::read_rig_nodes_and_animations(read.model, path, *rig, out.warnings);
    out.cameras = read_cameras(read.model, path);
    out.rig = std::move(rig);
    return out;
}

}  // namespace facet
