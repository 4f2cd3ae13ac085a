// glTF 2.0 (.gltf and .glb) through tinygltf. The node hierarchy of the
// default scene is flattened: every mesh instance (and every copy of
// EXT_mesh_gpu_instancing) becomes parts with its world transform baked
// in, skins and default morph weights applied. Follows the glTF 2.0
// specification §3.5-3.10. A file with animations, skins or morph targets
// also keeps what poses it (Mesh::rig, read by gltf_rig_loader.cpp).
// Materials are read by gltf_materials.cpp, primitives by
// gltf_primitives.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

#include "assets/gltf_accessors.hpp"
#include "assets/gltf_draco.hpp"
#include "assets/gltf_extensions.hpp"
#include "assets/gltf_materials.hpp"
#include "assets/gltf_meshopt.hpp"
#include "assets/gltf_pose.hpp"
#include "assets/gltf_primitives.hpp"
#include "assets/gltf_rig_loader.hpp"
#include "assets/gltf_variants.hpp"
#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/memory.hpp"
#include "core/plain_text.hpp"
#include "core/thread_pool.hpp"

namespace facet {
namespace {

using gltf_detail::bad;
using gltf_detail::read_floats;
using gltf_detail::read_indices;

// Deep hierarchies beyond this are almost certainly cycles or hostile files.
constexpr int kMaxNodeDepth = 256;

// What tinygltf's callbacks need: the file's own path and folder, the
// policy for the URIs inside it, and what could not be read (kept, and
// thrown once tinygltf has returned if it failed, so that no exception
// crosses it; an image it could not read only loses that texture).
struct LoadContext {
    std::string path;    // the .gltf or .glb, as given
    std::string prefix;  // how tinygltf spells the paths it builds from the file's folder
    const AssetContext* assets;
    std::optional<Error> first_refusal;
    gltf_detail::UnreadImages unread;  // by the URI as the file spells it
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
    const std::string reference = candidate.substr(c.prefix.size());
    try {
        const std::string file =
            resolve_asset_reference(c.path, "buffer or image URI", reference, c.assets->paths);
        *out = read_input_file(file, "glTF resource", c.assets->paths.max_file_bytes);
        return true;
    } catch (const Error& e) {
        if (!c.first_refusal) c.first_refusal = e;
        // Reported later with the map that loses it; the file is named there.
        std::string reason = e.what();
        for (const std::string& prefix : {c.path + ": ", std::string("buffer or image URI: ")})
            if (reason.compare(0, prefix.size(), prefix) == 0) reason.erase(0, prefix.size());
        c.unread[reference] = reason;
        if (err) *err += e.what();
        return false;
    }
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
    if (err) *err += "facet never writes glTF resources";
    return false;
}

// Images are kept as their file's bytes: only those a material reads are
// decoded (gltf_materials.cpp), by their bytes, within the texture budget.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// The file read by tinygltf through facet's callbacks (path policy),
// refusals rethrown, and compressed geometry decoded.
struct ReadModel {
    tinygltf::Model model;
    std::string warnings;  // tinygltf's, trimmed
    gltf_detail::ExtensionLists lists;
    gltf_detail::ExtensionCheck extensions;  // ignored ones, and their warnings
    std::vector<Error> refusals;             // inspecting: what render refuses the file for
    gltf_detail::UnreadImages unread;
};

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

// tinygltf's parse of the file's bytes, as they are or (for compressed
// geometry) with its JSON rewritten first: meshopt's fallback buffers hold
// no data, Draco's accessors have no views.
bool parse_model(const MeshFile& file, const gltf_detail::ExtensionLists& lists,
                 tinygltf::TinyGLTF& loader, tinygltf::Model& model, std::string& err,
                 std::string& warn, int& placeholder_view) {
    // By the file's magic number, so a .glb saved under another name is
    // read as what it is.
    const bool binary = file.bytes.size() >= 4 && std::memcmp(file.bytes.data(), "glTF", 4) == 0;
    const bool meshopt = lists.lists("EXT_meshopt_compression");
    const bool draco = lists.lists("KHR_draco_mesh_compression");
    std::vector<uint8_t> rewritten;
    if (meshopt || draco)
        rewritten = gltf_detail::with_json_rewritten(file.bytes, [&](const std::string& json) {
            std::string out = meshopt ? gltf_detail::without_fallback_buffers(json) : json;
            return draco ? gltf_detail::with_placeholder_views(out, placeholder_view) : out;
        });
    const std::vector<uint8_t>& bytes = meshopt || draco ? rewritten : file.bytes;
    const size_t slash = file.path.find_last_of("/\\");
    const std::string folder = slash == std::string::npos ? "" : file.path.substr(0, slash);
    return binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                static_cast<unsigned>(bytes.size()), folder)
                  : loader.LoadASCIIFromString(&model, &err, &warn,
                                               reinterpret_cast<const char*>(bytes.data()),
                                               static_cast<unsigned>(bytes.size()), folder);
}

ReadModel read_model(const MeshFile& file, const AssetContext& context) {
    const std::string& path = file.path;
    ReadModel read;
    // Before tinygltf parses buffers that a compression extension may have
    // left without data, so the error names the extension.
    read.lists = gltf_detail::read_extension_lists(file.bytes, path);
    read.extensions = gltf_detail::check_extensions(
        read.lists, path, context.inspect_only ? &read.refusals : nullptr);
    tinygltf::TinyGLTF loader;
    LoadContext load{path, "", &context, std::nullopt, {}};
    // tinygltf joins its folder (the path up to the last slash) and a URI with a slash.
    const size_t slash = path.find_last_of("/\\");
    load.prefix = slash == std::string::npos ? "" : path.substr(0, slash) + "/";
    tinygltf::FsCallbacks fs{&file_exists, &expand_file_path, &read_whole_file, &write_whole_file,
                             &load};
    loader.SetFsCallbacks(fs);
    loader.SetImageLoader(&keep_image_bytes, &load);
    std::string err, warn;
    bool ok = false;
    int placeholder_view = -1;
    try {
        ok = parse_model(file, read.lists, loader, read.model, err, warn, placeholder_view);
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!ok && load.first_refusal) throw *load.first_refusal;
    if (!ok)
        bad(path, "cannot read glTF: " + (err.empty() ? std::string("unknown error")
                                                      : with_long_words_cut(trimmed(err))));
    // An image tinygltf could not read is reported with its material.
    std::string kept;
    std::istringstream lines(warn);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("Failed to load external 'uri' for image", 0) != 0 &&
            line.rfind("File read error", 0) != 0)
            kept += line + "\n";
    read.warnings = with_long_words_cut(trimmed(kept));
    read.unread = std::move(load.unread);
    if (read.lists.lists("EXT_meshopt_compression"))
        gltf_detail::decode_meshopt_views(read.model, path);
    if (read.lists.lists("KHR_draco_mesh_compression"))
        gltf_detail::decode_draco_primitives(read.model, path, placeholder_view);
    return read;
}

glm::dmat4 node_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m;
        std::memcpy(glm::value_ptr(m), node.matrix.data(), sizeof(double) * 16);  // column-major
        return m;
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
    return m;
}

// EXT_mesh_gpu_instancing: one transform per copy, T·R·S from the
// TRANSLATION, ROTATION and SCALE accessors (each optional, all of one
// count), applied between the mesh and its node. Empty without instancing.
std::vector<glm::dmat4> instance_matrices(const tinygltf::Model& model, const tinygltf::Node& node,
                                          const std::string& path, const std::string& what) {
    const auto it = node.extensions.find("EXT_mesh_gpu_instancing");
    if (it == node.extensions.end()) return {};
    const tinygltf::Value& e = it->second;
    if (!e.Has("attributes") || !e.Get("attributes").IsObject())
        bad(path, what + ": EXT_mesh_gpu_instancing has no attributes");
    const tinygltf::Value& attributes = e.Get("attributes");
    std::vector<float> values[3];
    const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
    const int widths[3] = {3, 4, 3};
    size_t count = 0;
    bool counted = false;
    for (int a = 0; a < 3; ++a) {
        if (!attributes.Has(names[a])) continue;
        const tinygltf::Value& index = attributes.Get(names[a]);
        if (!index.IsNumber())
            bad(path, what + ": EXT_mesh_gpu_instancing " + names[a] + " is not an accessor index");
        const std::string where = what + " EXT_mesh_gpu_instancing " + names[a];
        values[a] =
            read_floats(model, static_cast<int>(index.GetNumberAsDouble()), widths[a], path, where);
        const size_t n = values[a].size() / static_cast<size_t>(widths[a]);
        if (counted && n != count)
            bad(path, where + ": its count differs from the other attributes'");
        count = n, counted = true;
    }
    if (!counted)
        bad(path, what + ": EXT_mesh_gpu_instancing has none of TRANSLATION, ROTATION, SCALE");
    std::vector<glm::dmat4> matrices(count, glm::dmat4(1.0));
    for (size_t i = 0; i < count; ++i) {
        glm::dmat4& m = matrices[i];
        if (!values[0].empty())
            m = glm::translate(
                m, glm::dvec3(values[0][3 * i], values[0][3 * i + 1], values[0][3 * i + 2]));
        if (!values[1].empty()) {
            const float* q = &values[1][4 * i];
            const glm::dquat rotation(q[3], q[0], q[1], q[2]);  // w, x, y, z
            if (!(glm::length(rotation) > 0))
                bad(path, what + ": an instance's ROTATION has no length");
            m = m * glm::mat4_cast(glm::normalize(rotation));
        }
        if (!values[2].empty())
            m = glm::scale(
                m, glm::dvec3(values[2][3 * i], values[2][3 * i + 1], values[2][3 * i + 2]));
    }
    return matrices;
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

// The walk over the default scene's nodes that bakes each mesh instance
// into parts. Every instance is baked into parts of its own, so a small
// file whose nodes (or instancing) repeat a large mesh asks for far more
// than its size: each placement is checked against the memory there is
// before it is made.
// KHR_materials_volume gives the thickness in the mesh's own units, which
// the bake scales by each instance's node transform: a part placed at a
// scale other than 1 gets a copy of its material with the thickness
// scaled, as the Khronos sample viewer scales it by the model matrix (the
// attenuation distance is in the file's world units already).
void scale_volume_thickness(Mesh& mesh, const std::vector<double>& part_scales) {
    std::map<std::pair<uint32_t, double>, uint32_t> copies;
    // The material (the part's, or a variant's) a part placed at `scale` draws.
    const auto scaled = [&](uint32_t material, double scale) {
        if (!(mesh.materials[material].thickness > 0.0f) || std::abs(scale - 1.0) < 1e-6)
            return material;
        const auto [copy, added] = copies.try_emplace({material, scale}, mesh.materials.size());
        if (added) {
            Material thicker = mesh.materials[material];
            thicker.thickness = static_cast<float>(thicker.thickness * scale);
            mesh.materials.push_back(std::move(thicker));
        }
        return copy->second;
    };
    for (size_t i = 0; i < mesh.parts.size(); ++i) {
        MeshPart& part = mesh.parts[i];
        part.material = scaled(part.material, part_scales[i]);
        for (uint32_t& variant : part.variant_materials) variant = scaled(variant, part_scales[i]);
    }
}

class NodeWalk {
  public:
    NodeWalk(const tinygltf::Model& model, const std::string& path, Mesh& mesh, MeshRig* rig,
             ThreadPool* pool)
        : model_(model),
          path_(path),
          mesh_(mesh),
          rig_(rig),
          pool_(pool),
          memory_(memory_available()),
          default_material_(static_cast<uint32_t>(model.materials.size())) {}

    void visit(int node_index, const glm::dmat4& parent, int depth);
    bool used_default_material() const { return used_default_; }
    // Per part placed: how much its transform scales lengths.
    const std::vector<double>& part_scales() const { return part_scales_; }

  private:
    const std::vector<std::optional<gltf_detail::MeshSpacePrimitive>>& primitives(int mesh_index);
    void add_mesh(int node_index, const glm::dmat4& world);
    void place(int node_index, size_t primitive, const gltf_detail::MeshSpacePrimitive& p,
               const glm::dmat4& node_world, const glm::dmat4& instance, bool first);

    const tinygltf::Model& model_;
    const std::string& path_;
    Mesh& mesh_;
    MeshRig* rig_;
    ThreadPool* pool_;  // for the normals of primitives without them
    uint64_t memory_, planned_ = 0;
    uint32_t default_material_;
    bool used_default_ = false;
    std::map<int, std::vector<std::optional<gltf_detail::MeshSpacePrimitive>>> read_;
    std::set<int> on_path_;
    std::vector<double> part_scales_;
};

const std::vector<std::optional<gltf_detail::MeshSpacePrimitive>>& NodeWalk::primitives(
    int mesh_index) {
    if (mesh_index < 0 || static_cast<size_t>(mesh_index) >= model_.meshes.size())
        bad(path_, "node refers to missing mesh " + std::to_string(mesh_index));
    auto& list = read_[mesh_index];
    if (!list.empty()) return list;
    const tinygltf::Mesh& gm = model_.meshes[static_cast<size_t>(mesh_index)];
    for (size_t p = 0; p < gm.primitives.size(); ++p) {
        const std::string what = "mesh '" + gm.name + "' primitive " + std::to_string(p);
        const tinygltf::Primitive& prim = gm.primitives[p];
        if (const auto pos = prim.attributes.find("POSITION"); pos != prim.attributes.end()) {
            // Counts the data cannot back are the file's error, not a lack of memory.
            gltf_detail::check_accessor_data(model_, pos->second, path_, what + " POSITION");
            if (prim.indices >= 0)
                gltf_detail::check_accessor_data(model_, prim.indices, path_, what + " indices");
        }
        list.push_back(gltf_detail::read_primitive(model_, prim, path_, what, default_material_,
                                                   mesh_.warnings));
    }
    return list;
}

void NodeWalk::place(int node_index, size_t primitive, const gltf_detail::MeshSpacePrimitive& p,
                     const glm::dmat4& node_world, const glm::dmat4& instance, bool first) {
    planned_ += planned_part_bytes(p.positions.size(), p.indices.size());
    check_memory("loading " + path_, {{"mesh instances", planned_}}, memory_);
    Warnings repeated;  // an instance's copies repeat the first's warnings
    std::vector<uint32_t> source_vertex;
    const glm::dmat4 world = node_world * instance;
    mesh_.parts.push_back(gltf_detail::place_primitive(p, glm::mat4(world), path_,
                                                       first ? mesh_.warnings : repeated,
                                                       rig_ ? &source_vertex : nullptr, pool_));
    used_default_ = used_default_ || p.material == default_material_;
    part_scales_.push_back(std::cbrt(std::abs(glm::determinant(glm::dmat3(world)))));
    if (!rig_) return;
    const tinygltf::Node& node = model_.nodes[static_cast<size_t>(node_index)];
    RigPart part;
    part.node = node_index;
    part.skin = node.skin;
    part.instance = instance;
    part.rest_mirrored = glm::determinant(glm::dmat3(world)) < 0;
    part.positions = p.positions;
    const tinygltf::Primitive& prim =
        model_.meshes[static_cast<size_t>(node.mesh)].primitives[primitive];
    for (size_t i = 0; i < p.normals.size(); ++i) {
        // Posing derives a zero normal from the faces, as the bake does.
        const float length = glm::length(p.normals[i]);
        part.normals.push_back(length > 0 ? p.normals[i] / length : glm::vec3(0));
        if (length == 0) part.normals_from_faces.push_back(static_cast<uint32_t>(i));
    }
    part.tangents = p.tangents;
    gltf_detail::read_part_skin_and_morph(model_, prim, *rig_, path_, p.what, part);
    if (p.normals.empty()) {
        // The split vertices get their skin and morph data from the vertex
        // they were copied from; posing recomputes their normals.
        reorder_rig_part_vertices(part, source_vertex);
        part.normals.assign(source_vertex.size(), glm::vec3(0));
        for (size_t i = 0; i < source_vertex.size(); ++i)
            part.normals_from_faces.push_back(static_cast<uint32_t>(i));
    }
    rig_->parts.push_back(std::move(part));
}

void NodeWalk::add_mesh(int node_index, const glm::dmat4& world) {
    const tinygltf::Node& node = model_.nodes[static_cast<size_t>(node_index)];
    const std::string what = "node " + std::to_string(node_index) +
                             (node.name.empty() ? std::string() : " '" + node.name + "'");
    std::vector<glm::dmat4> instances = instance_matrices(model_, node, path_, what);
    if (!instances.empty() && node.skin >= 0) {
        mesh_.warnings.push_back(file_warning(
            path_, what + ": EXT_mesh_gpu_instancing on a skinned mesh is not drawn: " +
                       std::to_string(instances.size()) + " copies become one"));
        instances.clear();
    }
    if (instances.empty()) instances.push_back(glm::dmat4(1.0));
    const auto& list = primitives(node.mesh);
    for (size_t p = 0; p < list.size(); ++p)
        if (list[p])
            for (size_t i = 0; i < instances.size(); ++i)
                place(node_index, p, *list[p], world, instances[i], i == 0);
}

void NodeWalk::visit(int node_index, const glm::dmat4& parent, int depth) {
    if (node_index < 0 || static_cast<size_t>(node_index) >= model_.nodes.size())
        bad(path_, "scene refers to missing node " + std::to_string(node_index));
    if (on_path_.count(node_index))
        bad(path_, "node hierarchy has a cycle through node " + std::to_string(node_index));
    if (depth >= kMaxNodeDepth)  // the root is level 1, at depth 0
        bad(path_, "node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels");
    on_path_.insert(node_index);
    const tinygltf::Node& node = model_.nodes[static_cast<size_t>(node_index)];
    const glm::dmat4 world = parent * node_matrix(node);
    if (node.mesh >= 0) add_mesh(node_index, world);
    if (auto light = node_light(model_, node, glm::mat4(world), path_))
        mesh_.lights.push_back(*light);
    for (int child : node.children) visit(child, world, depth + 1);
    on_path_.erase(node_index);
}

// The nodes the walk starts from: the default scene's (the first when it
// names none), or with no scene every node that is nobody's child. glTF
// §3.5.3: nodes form strict trees; a node with several parents would be
// walked once per path to it, so a few dozen shared levels never finish.
std::vector<int> root_nodes(const tinygltf::Model& model, const std::string& path,
                            Warnings& warnings) {
    std::vector<int> parents(model.nodes.size(), 0);
    for (const auto& n : model.nodes)
        for (int c : n.children)
            if (c >= 0 && static_cast<size_t>(c) < parents.size() && ++parents[c] > 1)
                bad(path, "node " + std::to_string(c) + " has more than one parent");
    if (!model.scenes.empty()) {
        const bool valid = model.defaultScene >= 0 &&
                           static_cast<size_t>(model.defaultScene) < model.scenes.size();
        const size_t shown = valid ? static_cast<size_t>(model.defaultScene) : 0;
        if (model.scenes.size() > 1)
            warnings.push_back(file_warning(
                path, "has " + std::to_string(model.scenes.size()) + " scenes: scene " +
                          std::to_string(shown) + " (the default) is drawn, the others are not"));
        return model.scenes[shown].nodes;
    }
    std::vector<int> roots;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (parents[i] == 0) roots.push_back(static_cast<int>(i));
    return roots;
}

// The rest pose of skinned parts is their skin's at rest (§3.7.3.3: the
// node's own transform plays no part, and a quantized file keeps its
// dequantization in the inverse bind matrices), and of morphed parts their
// default weights (§3.7.2.2): the parts become that pose, so bounds,
// framing and still renders show what the author posed.
void bake_rest_pose(Mesh& mesh, MeshRig& rig) {
    std::vector<PosedPart> posed;
    pose_rest_from_rig(mesh, posed);
    for (size_t p = 0; p < mesh.parts.size(); ++p) {
        RigPart& rig_part = rig.parts[p];
        MeshPart& part = mesh.parts[p];
        part.positions = posed[p].positions;
        part.normals = posed[p].normals;
        part.tangents = posed[p].tangents;
        if (!posed[p].winding_flipped) continue;
        for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
            std::swap(part.indices[t + 1], part.indices[t + 2]);
        rig_part.rest_mirrored = !rig_part.rest_mirrored;
    }
}

// The file's bytes, for a loader called by path.
MeshFile read_gltf_file(const std::string& path, const AssetContext& context) {
    MeshFile file{path, read_input_file(path, "glTF", context.paths.max_file_bytes)};
    const bool binary = file.bytes.size() >= 4 && std::memcmp(file.bytes.data(), "glTF", 4) == 0;
    file.format = binary ? MeshFormat::glb : MeshFormat::gltf;
    return file;
}

}  // namespace

Mesh load_gltf(const std::string& path, const AssetContext& context) {
    return load_gltf(read_gltf_file(path, context), context);
}

Mesh load_gltf(const MeshFile& file, const AssetContext& context) {
    const std::string& path = file.path;
    ReadModel read = read_model(file, context);
    const tinygltf::Model& model = read.model;
    Mesh mesh;
    mesh.source = path;
    mesh.loader = "tinygltf";
    mesh.extensions = {read.lists.used, read.lists.required, read.extensions.ignored};
    if (!read.warnings.empty()) mesh.warnings.push_back(file_warning(path, read.warnings));
    mesh.warnings.insert(mesh.warnings.end(), read.extensions.warnings.begin(),
                         read.extensions.warnings.end());
    mesh.refusals = read.refusals;
    const bool basisu_required = std::count(read.lists.required.begin(), read.lists.required.end(),
                                            "KHR_texture_basisu") > 0;
    gltf_detail::check_basisu_fallbacks(model, path, basisu_required, mesh.warnings,
                                        context.inspect_only ? &mesh.refusals : nullptr);
    std::shared_ptr<MeshRig> rig;
    if (gltf_detail::has_rig_data(model)) {
        rig = std::make_shared<MeshRig>();
        gltf_detail::read_rig_nodes_and_animations(model, path, *rig, mesh.warnings);
    }
    mesh.materials = gltf_detail::read_materials(model, path, read.unread, context.textures,
                                                 basisu_required, mesh.warnings);
    mesh.variants = gltf_detail::read_variant_names(model, path, &mesh.warnings);
    // Threads for the normals of a big file's primitives; a small file's
    // would cost more to start than they save.
    constexpr size_t kParallelBytes = size_t(4) << 20;
    size_t buffer_bytes = 0;
    for (const tinygltf::Buffer& b : model.buffers) buffer_bytes += b.data.size();
    std::optional<ThreadPool> threads;
    if (buffer_bytes >= kParallelBytes && context.threads != 1) threads.emplace(context.threads);
    NodeWalk walk(model, path, mesh, rig.get(), threads ? &*threads : nullptr);
    for (int root : root_nodes(model, path, mesh.warnings)) walk.visit(root, glm::dmat4(1.0), 0);
    if (walk.used_default_material()) {
        Material fallback;
        fallback.name = "default";
        fallback.color = glm::vec3(1);
        mesh.materials.push_back(fallback);
    }
    scale_volume_thickness(mesh, walk.part_scales());
    if (mesh.triangle_count() == 0) bad(path, "the glTF file has no triangles to render");
    mesh.rig = rig;
    if (rig) bake_rest_pose(mesh, *rig);
    mesh.cameras = read_cameras(model, path);
    return mesh;
}

GltfCameras load_gltf_cameras(const std::string& path, const AssetContext& context) {
    ReadModel read = read_model(read_gltf_file(path, context), context);
    GltfCameras out;
    out.warnings = read.extensions.warnings;
    auto rig = std::make_shared<MeshRig>();
    gltf_detail::read_rig_nodes_and_animations(read.model, path, *rig, out.warnings);
    out.cameras = read_cameras(read.model, path);
    out.rig = std::move(rig);
    return out;
}

}  // namespace facet
