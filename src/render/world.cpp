#include "render/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <span>

#include <glm/geometric.hpp>

#include "anim/cloth_scene.hpp"
#include "assets/gltf_pose.hpp"
#include "assets/normal_map_tangents.hpp"
#include "core/error.hpp"
#include "render/environment_file.hpp"
#include "render/principal_directions.hpp"
#include "shade/shading_models.hpp"
#include "shapes/primitives.hpp"

namespace facet {
namespace {

using TextureFiles = std::map<std::string, std::shared_ptr<const Texture>>;

// A map a scene material names, read once per file and meaning (a file
// used both as a colour and as data is read twice).
TextureSlot scene_map(const MaterialDesc::Map& map, bool data, TextureFiles& textures,
                      TextureBudget& budget) {
    auto& colour = textures[map.path];
    if (!colour) {
        try {
            colour = std::make_shared<Texture>(load_texture(map.path, &budget));
        } catch (const Error& e) {
            fail_input(map.at, map.key, e.what());
        }
    }
    TextureSlot slot;
    slot.texture = colour;
    if (data) {
        auto& as_data = textures["data:" + map.path];
        if (!as_data) as_data = std::make_shared<Texture>(colour->as_data());
        slot.texture = as_data;
    }
    return slot;
}

// The `pbr` model's keys over what the file gave.
void resolve_physical_terms(const MaterialDesc& desc, TextureFiles& textures, TextureBudget& budget,
                            Material& m) {
    if (desc.metallic) m.metallic = desc.metallic->value;
    if (desc.roughness) m.roughness = desc.roughness->value;
    for (const auto& [field, value] : desc.constants) m.*field = value;
    for (const auto& [field, value] : desc.colors) m.*field = value;
    if (desc.normal_map) m.normal_map = scene_map(*desc.normal_map, true, textures, budget);
    if (desc.occlusion_map)
        m.occlusion_map = scene_map(*desc.occlusion_map, true, textures, budget);
    if (desc.metal_rough_map)
        m.metal_rough_map = scene_map(*desc.metal_rough_map, true, textures, budget);
    if (desc.emissive_map) {
        m.emissive_map = scene_map(*desc.emissive_map, false, textures, budget);
        // glTF's rule: the map multiplies the factor, which defaults to 0
        // there; a scene that gives a map without a factor means it to glow.
        if (!desc.emissive && m.emissive == glm::vec3(0)) m.emissive = glm::vec3(1);
    }
}

Material resolve_material(const Material& base, const MaterialDesc& desc, int max_anisotropy,
                          TextureFiles& textures, TextureBudget& budget) {
    Material m = base;
    // Animated values start at their first key; frames update them.
    if (desc.color) m.color = desc.color->value;
    if (desc.ambient) m.ambient = desc.ambient->value;
    if (desc.diffuse) m.diffuse = desc.diffuse->value;
    if (desc.specular) m.specular = desc.specular->value;
    if (desc.shininess) m.shininess = desc.shininess->value;
    // Metal and roughness make a metallic-roughness material; a Phong
    // term makes a Phong one, whatever the file said (Material::metal_rough).
    if (desc.metallic || desc.roughness || desc.metal_rough_map) m.metal_rough = true;
    if (desc.specular || desc.shininess) m.metal_rough = false;
    if (desc.double_sided) m.double_sided = *desc.double_sided;
    if (desc.emissive) m.emissive = *desc.emissive;
    if (desc.unlit) m.unlit = *desc.unlit;
    if (desc.shadow_catcher) m.shadow_catcher = *desc.shadow_catcher;
    if (desc.fade) m.fade_start = desc.fade->x, m.fade_end = desc.fade->y;
    if (desc.texture)
        m.base_color_map.texture = scene_map(*desc.texture, false, textures, budget).texture;
    resolve_physical_terms(desc, textures, budget, m);
    // uv_scale multiplies the coordinates the file's mapping gives, and
    // wrap replaces its samplers', for every map alike: the file's
    // specular and clearcoat maps too, or they would slide off the others.
    // The output's texture filter applies to every map too.
    for (TextureSlot* slot : m.texture_slots()) {
        if (!*slot) continue;
        if (desc.uv_scale) slot->transform = slot->transform.scaled(glm::dvec2(*desc.uv_scale));
        if (!desc.wrap && slot->texture->sampler.max_anisotropy == max_anisotropy) continue;
        auto copy = std::make_shared<Texture>(*slot->texture);
        if (desc.wrap) copy->sampler.wrap_s = copy->sampler.wrap_t = *desc.wrap;
        copy->sampler.max_anisotropy = max_anisotropy;
        slot->texture = copy;
    }
    return m;
}

// Edge neighbours and fold cosines of a part's triangles (see
// World::edge_neighbor), whose first triangle has the world index `first`.
// Edges are matched by their end positions, so split vertices (seams)
// still pair up; positions are snapped to a millionth of the part's size
// first, because a seam's two copies are often computed apart (cos 0 and
// cos 2π differ in the last bit) and would read as a boundary.
void append_edge_adjacency(const MeshPart& part, uint32_t first, World& world) {
    using Point = std::array<int64_t, 3>;
    using EdgeKey = std::pair<Point, Point>;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : part.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const double cell = extent > 0 && std::isfinite(extent) ? extent * 1e-6 : 1.0;
    auto point = [&](uint32_t i) {
        const glm::vec3& p = part.positions[i];
        auto snap = [&](float v) { return static_cast<int64_t>(std::llround(v / cell)); };
        return Point{snap(p.x), snap(p.y), snap(p.z)};
    };
    auto key = [&](uint32_t a, uint32_t b) {
        Point pa = point(a), pb = point(b);
        return pa < pb ? EdgeKey{pa, pb} : EdgeKey{pb, pa};
    };
    const size_t triangles = part.triangle_count();
    std::vector<glm::vec3> face_normal(triangles);
    std::map<EdgeKey, std::vector<uint32_t>> edge_faces;
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t* v = &part.indices[3 * t];
        const glm::vec3 n = glm::cross(part.positions[v[1]] - part.positions[v[0]],
                                       part.positions[v[2]] - part.positions[v[0]]);
        const float len = glm::length(n);
        face_normal[t] = len > 0 ? n / len : glm::vec3(0);
        for (int e = 0; e < 3; ++e) edge_faces[key(v[(e + 1) % 3], v[(e + 2) % 3])].push_back(t);
    }
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t* v = &part.indices[3 * t];
        for (int e = 0; e < 3; ++e) {
            const auto& faces = edge_faces[key(v[(e + 1) % 3], v[(e + 2) % 3])];
            uint32_t neighbor = World::kNoNeighbor;
            float cosine = -2.0f;
            if (faces.size() == 2) {
                const uint32_t other = faces[0] == t ? faces[1] : faces[0];
                neighbor = first + other;
                cosine = glm::dot(face_normal[t], face_normal[other]);
            }
            world.edge_neighbor.push_back(neighbor);
            world.edge_cosine.push_back(cosine);
        }
    }
}

// A cloth's rest pose as a mesh of one double-sided part.
Mesh cloth_mesh(const ClothModel& model) {
    Mesh mesh;
    mesh.source = "cloth";
    mesh.loader = "facet";
    mesh.parts.push_back(model.rest_part);
    mesh.materials.push_back(Material{});
    mesh.materials.back().name = "cloth";
    mesh.materials.back().double_sided = true;  // both faces show
    return mesh;
}

}  // namespace

namespace {

// The cameras `from:` glTF files, one per scene camera (without a rig for
// the others); errors name the camera's `from` key.
std::vector<FileCamera> load_file_cameras(const SceneDesc& scene, const AssetContext& assets,
                                          Warnings& warnings) {
    std::vector<FileCamera> out(scene.cameras.size());
    std::map<std::string, GltfCameras> files;
    for (size_t c = 0; c < scene.cameras.size(); ++c) {
        const CameraDesc& cam = scene.cameras[c];
        if (cam.from.empty()) continue;
        const std::string key = cam.key + ".from";
        auto found = files.find(cam.from);
        if (found == files.end()) {
            try {
                found = files.emplace(cam.from, load_gltf_cameras(cam.from, assets)).first;
            } catch (const Error& e) {
                fail_input(cam.from_at, key, e.what());
            }
            warnings.insert(warnings.end(), found->second.warnings.begin(),
                            found->second.warnings.end());
        }
        const GltfCameras& file = found->second;
        std::string names;
        for (const GltfCamera& g : file.cameras) {
            if (!names.empty()) names += ", ";
            names += "'" + g.name + "'";
        }
        if (file.cameras.empty()) fail_input(cam.from_at, key, cam.from + " has no cameras");
        const GltfCamera* chosen = &file.cameras.front();
        if (cam.name_given) {
            chosen = nullptr;
            for (const GltfCamera& g : file.cameras)
                if (g.name == cam.name) chosen = &g;
            if (!chosen)
                fail_input(
                    cam.from_at, key,
                    cam.from + " has no camera named '" + cam.name + "' (it has " + names + ")");
        }
        if (chosen->orthographic)
            fail_input(cam.from_at, key,
                       cam.from + ": camera '" + chosen->name +
                           "' is orthographic; facet renders perspective cameras only");
        out[c] = {*chosen, file.rig, animations_moving(*file.rig, chosen->node)};
    }
    return out;
}

}  // namespace

double animation_clock(const AnimatedMesh& mesh, double seconds) {
    if (mesh.loop && mesh.duration > 0) {
        seconds = std::fmod(seconds, mesh.duration);
        if (seconds < 0) seconds += mesh.duration;
    }
    return seconds;
}

namespace {

// Appends a per-vertex stream that only some draws have: `values` for this
// draw's vertices, or `fill` for draws without it. The stream stays empty
// until a draw has it, then is filled back to the first vertex.
template <typename T>
void append_optional(std::vector<T>& stream, const std::vector<T>& values, size_t first_vertex,
                     size_t vertex_count, T fill) {
    if (values.empty()) {
        if (!stream.empty()) stream.resize(first_vertex + vertex_count, fill);
        return;
    }
    stream.resize(first_vertex, fill);
    stream.insert(stream.end(), values.begin(), values.end());
}

// Which per-triangle extras some style needs.
struct WorldExtras {
    bool wireframes = false;  // feature edges cost a pass over every edge
    bool hatching = false;
};

WorldExtras extras_of(const SceneDesc& scene) {
    WorldExtras x{scene.style.wireframe.enabled, scene.style.hatching.has_value()};
    for (const ObjectDesc& obj : scene.objects) {
        x.wireframes = x.wireframes || (obj.style && obj.style->wireframe.enabled);
        x.hatching = x.hatching || (obj.style && obj.style->hatching);
    }
    return x;
}

// One part of object `object` as a draw: its vertices, indices and extras
// appended to the world's arrays.
void append_part(World& world, const MeshPart& part, uint32_t object, uint32_t material_base,
                 const WorldExtras& extras) {
    Draw d;
    d.object = object;
    d.first_vertex = static_cast<uint32_t>(world.positions.size());
    d.vertex_count = static_cast<uint32_t>(part.positions.size());
    d.first_triangle = static_cast<uint32_t>(world.triangle_draw.size());
    d.triangle_count = static_cast<uint32_t>(part.triangle_count());
    d.material = material_base + part.material;
    d.has_uvs = !part.uvs.empty() || !part.uvs1.empty();
    d.has_colors = !part.colors.empty();
    // Only the frames of normal-mapped and anisotropic draws are kept: the
    // stages pay for tangents only where a shader reads them.
    d.has_tangents = world.materials[d.material].tangent_uv_set() && !part.tangents.empty();
    const uint32_t draw_index = static_cast<uint32_t>(world.draws.size());
    world.positions.insert(world.positions.end(), part.positions.begin(), part.positions.end());
    world.normals.insert(world.normals.end(), part.normals.begin(), part.normals.end());
    if (part.uvs.empty())
        world.uvs.resize(world.uvs.size() + part.positions.size(), glm::vec2(0));
    else
        world.uvs.insert(world.uvs.end(), part.uvs.begin(), part.uvs.end());
    append_optional(world.uvs1, part.uvs1, d.first_vertex, d.vertex_count, glm::vec2(0));
    append_optional(world.colors, part.colors, d.first_vertex, d.vertex_count, glm::vec3(1));
    append_optional(world.tangents, d.has_tangents ? part.tangents : std::vector<glm::vec4>(),
                    d.first_vertex, d.vertex_count, glm::vec4(0));
    world.vertex_draw.resize(world.positions.size(), draw_index);
    for (uint32_t i : part.indices) world.indices.push_back(d.first_vertex + i);
    world.triangle_draw.resize(world.triangle_draw.size() + d.triangle_count, draw_index);
    world.cull_back.resize(world.cull_back.size() + d.triangle_count,
                           world.materials[d.material].double_sided ? 0 : 1);
    if (extras.wireframes) append_edge_adjacency(part, d.first_triangle, world);
    if (extras.hatching) {
        const std::vector<glm::vec3> directions = principal_directions(part);
        world.hatch_directions.insert(world.hatch_directions.end(), directions.begin(),
                                      directions.end());
    }
    world.draws.push_back(d);
}

using MeshesByPath = std::map<std::string, std::shared_ptr<const Mesh>>;

// The mesh file at `path`: the one in `loaded`, its textures charged to
// the run's budget as reading them would have, or else the file read.
std::shared_ptr<const Mesh> read_mesh(const std::string& path, const AssetContext& assets,
                                      const LoadedMeshes* loaded) {
    const auto found = loaded ? loaded->find(path) : LoadedMeshes::const_iterator{};
    if (!loaded || found == loaded->end()) return std::make_shared<Mesh>(load_mesh(path, assets));
    for (const TextureBudget::Charge& c : found->second.texture_charges)
        assets.textures->charge(c.name, c.width, c.height, c.bytes);
    return found->second.mesh;
}

// The mesh file object `o` names; errors point at its `mesh:` key.
std::shared_ptr<const Mesh> object_file_mesh(const SceneDesc& scene, uint32_t o,
                                             const AssetContext& assets,
                                             const LoadedMeshes* loaded) {
    const ObjectDesc& obj = scene.objects[o];
    try {
        return read_mesh(obj.mesh, assets, loaded);
    } catch (const Error& e) {
        fail_input(obj.mesh_at, "objects." + std::to_string(o) + ".mesh", e.what());
    }
}

// The mesh object `o` shows: its file (read once per path, its warnings
// kept), its cloth's rest pose, or its primitive. Errors point at its key.
std::shared_ptr<const Mesh> object_mesh(const SceneDesc& scene, uint32_t o,
                                        const AssetContext& assets, MeshesByPath& meshes,
                                        const LoadedMeshes* loaded, World& world) {
    const ObjectDesc& obj = scene.objects[o];
    if (!obj.mesh.empty()) {
        auto& slot = meshes[obj.mesh];
        if (!slot) {
            slot = object_file_mesh(scene, o, assets, loaded);
            world.warnings.insert(world.warnings.end(), slot->warnings.begin(),
                                  slot->warnings.end());
        }
        return slot;
    }
    const std::string key = "objects." + std::to_string(o);
    try {
        if (obj.cloth) {
            std::shared_ptr<const ClothModel> model = build_scene_cloth(obj, scene.output);
            if (obj.visible)
                world.cloths.push_back({o, static_cast<uint32_t>(world.draws.size()), model});
            return std::make_shared<Mesh>(cloth_mesh(*model));
        }
        return std::make_shared<Mesh>(make_primitive(obj.primitive->spec));
    } catch (const Error& e) {
        if (obj.cloth) fail_input(obj.cloth->where, key + ".cloth", e.what());
        fail_input(obj.primitive->where, key + ".primitive", e.what());
    }
}

// The variants of `mesh` added to `names`, each name once.
void add_variant_names(const Mesh& mesh, std::vector<std::string>& names) {
    for (const std::string& name : mesh.variants)
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

// The style that draws each object: its own, else the scene's.
const StyleDesc& object_style(const SceneDesc& scene, const ObjectDesc& obj) {
    return obj.style ? *obj.style : scene.style;
}

bool draws_pbr(const SceneDesc& scene) {
    if (scene.style.shading == ShadingModel::pbr) return true;
    return std::any_of(scene.objects.begin(), scene.objects.end(), [&](const ObjectDesc& obj) {
        return obj.visible && object_style(scene, obj).shading == ShadingModel::pbr;
    });
}

// The environment the scene's `pbr` styles and background read, made once.
std::shared_ptr<const pbr::PrefilteredEnvironment> scene_environment(const SceneDesc& scene,
                                                                     Warnings& warnings) {
    const std::optional<EnvironmentDesc>& e = scene.environment;
    const bool lights = draws_pbr(scene), shown = e && e->background;
    if (e && e->source != EnvironmentDesc::Source::none && !lights && !shown)
        warnings.push_back({e->where, "environment",
                            "lights only `shading: pbr` styles, and the scene has none: it is "
                            "not drawn (give `background: true` to show it behind the scene)"});
    if ((!lights && !shown) || (e && e->source == EnvironmentDesc::Source::none)) return nullptr;
    if (!e || e->source == EnvironmentDesc::Source::studio) return pbr::shared_studio_environment();
    if (e->source == EnvironmentDesc::Source::color) return pbr::uniform_environment(e->color);
    try {
        return pbr::load_environment(e->file, warnings);
    } catch (const Error& error) {
        fail_input(e->file_at, "environment.file", error.what());
    }
}

// Objects drawn by another model than `pbr` lose their materials'
// physically based inputs: said once per object.
void warn_unlit_physical_terms(const SceneDesc& scene, uint32_t object,
                               std::span<const Material> materials, Warnings& warnings) {
    const StyleDesc& style = object_style(scene, scene.objects[object]);
    if (style.shading == ShadingModel::pbr) return;
    // The Phong family reads the metal and roughness of metallic-roughness
    // materials, their map included (shade/metal_rough_phong.hpp); the
    // features only pbr draws (its other maps, sheen, thin film, anisotropy
    // and both transmissions) and coats are lost: glass is drawn opaque.
    // Whether the metal is drawn is drawn_features' answer, the shading
    // stage's own; a style's base colour replaces it on purpose, and an
    // unlit material shows its colour alone.
    const bool reads_metal = phong_family(style.shading);
    const bool own_color = style.base_color.has_value();
    bool lost = false, metal_lost = false;
    for (const Material& m : materials) {
        const bool metal_drawn =
            (drawn_features(style.shading, own_color, m.features()) & kMetalRough) != 0;
        Material drawn_as = m;
        if (metal_drawn) drawn_as.metal_rough_map = {};
        lost = lost || (drawn_as.features() & kPbrOnlyFeatures) != 0 || m.clearcoat > 0.0f;
        metal_lost = metal_lost || (reads_metal && !metal_drawn && !own_color && !m.unlit &&
                                    (m.metallic > 0.0f || m.metal_rough_map));
    }
    if (!lost && !metal_lost) return;
    const ObjectDesc& obj = scene.objects[object];
    warnings.push_back({obj.where, "objects." + std::to_string(object),
                        "'" + obj.name + "' has " + (metal_lost ? "metal, " : "") +
                            "physically based maps, a clear coat, a sheen, a thin film, "
                            "an anisotropy, a diffuse transmission or glass that only "
                            "`shading: pbr` draws: under " +
                            shading_model_name(style.shading) + " its relief, occlusion, " +
                            (metal_lost || !reads_metal ? "metal, " : "") +
                            "specular colour, coat, sheen, film, anisotropy and light through it "
                            "are lost (glass is opaque)" +
                            (metal_lost ? "; its metal is a Phong material's (one that gives "
                                          "`specular` or `shininess`, or an OBJ's), which the "
                                          "Phong family draws as a dielectric"
                                        : "")});
}

// `mesh` with tangent frames for the parts that the object's materials
// (from world.materials[material_base]) give a normal map, and the
// warnings for the parts that cannot have them, each once per run.
std::shared_ptr<const Mesh> with_object_tangents(World& world, uint32_t material_base,
                                                 std::shared_ptr<const Mesh> mesh,
                                                 bool keep_vertices) {
    const std::vector<Material> materials(world.materials.begin() + material_base,
                                          world.materials.end());
    Warnings warnings;
    mesh = with_normal_map_tangents(std::move(mesh), materials, warnings, keep_vertices);
    for (const Warning& w : warnings) {
        const bool known =
            std::any_of(world.warnings.begin(), world.warnings.end(), [&](const Warning& k) {
                return k.where.file == w.where.file && k.message == w.message;
            });
        if (!known) world.warnings.push_back(w);
    }
    return mesh;
}

}  // namespace

std::vector<std::string> scene_variants(const SceneDesc& scene, unsigned load_threads,
                                        LoadedMeshes& loaded) {
    TextureBudget texture_budget(scene.assets.texture_budget_bytes);
    const AssetContext assets = asset_context(scene.assets, texture_budget, load_threads);
    std::vector<std::string> names;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const std::string& path = scene.objects[o].mesh;
        if (path.empty()) continue;
        if (!loaded.count(path)) {
            // What its textures take, for build_world's budget to take too.
            const size_t charged_before = texture_budget.charges().size();
            LoadedMesh read{object_file_mesh(scene, o, assets, nullptr), {}};
            const std::vector<TextureBudget::Charge> charges = texture_budget.charges();
            read.texture_charges.assign(
                charges.begin() + static_cast<std::ptrdiff_t>(charged_before), charges.end());
            loaded[path] = std::move(read);
        }
        add_variant_names(*loaded[path].mesh, names);
    }
    return names;
}

World build_world(const SceneDesc& scene, unsigned load_threads, const LoadedMeshes* loaded) {
    World world;
    const WorldExtras extras = extras_of(scene);
    MeshesByPath meshes;
    std::map<std::string, std::shared_ptr<const Texture>> textures;
    TextureBudget texture_budget(scene.assets.texture_budget_bytes);
    const AssetContext assets = asset_context(scene.assets, texture_budget, load_threads);
    std::vector<std::string> variants;  // that the scene's models declare
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const ObjectDesc& obj = scene.objects[o];
        std::shared_ptr<const Mesh> mesh = object_mesh(scene, o, assets, meshes, loaded, world);
        add_variant_names(*mesh, variants);
        mesh = with_variant(std::move(mesh), scene.variant);
        world.object_bounds.push_back(mesh->bounds());
        if (obj.file_lights)
            for (const GltfLight& light : mesh->lights)
                world.object_lights.push_back({o, light, *obj.file_lights});
        world.casts_shadows.push_back(obj.cast_shadows ? 1 : 0);
        world.receives_shadows.push_back(obj.receive_shadows ? 1.0f : 0.0f);
        if (!obj.visible) continue;

        const uint32_t material_base = static_cast<uint32_t>(world.materials.size());
        for (const Material& m : mesh->materials) {
            world.materials.push_back(resolve_material(m, obj.material,
                                                       max_anisotropy(scene.output.texture_filter),
                                                       textures, texture_budget));
            world.material_object.push_back(o);
        }
        warn_unlit_physical_terms(scene, o,
                                  std::span<const Material>(world.materials).subspan(material_base),
                                  world.warnings);
        // The scene's material may give a normal map to a mesh whose file
        // had none; a cloth's vertices are its solver's and do not split.
        mesh = with_object_tangents(world, material_base, mesh, obj.cloth.has_value());
        if (obj.animation) {
            const std::string key = "objects." + std::to_string(o) + ".animation";
            try {
                const std::vector<int> animations = find_animations(*mesh, obj.animation->names);
                world.animated_meshes.push_back(
                    {o, mesh, animations, animations_duration(*mesh, animations),
                     obj.animation->loop, static_cast<uint32_t>(world.draws.size())});
            } catch (const Error& e) {
                fail_input(obj.animation->where, key, e.what());
            }
        }
        for (const MeshPart& part : mesh->parts) append_part(world, part, o, material_base, extras);
    }
    check_variant(scene, variants, true);
    world.file_cameras = load_file_cameras(scene, assets, world.warnings);
    world.environment = scene_environment(scene, world.warnings);
    if (world.positions.size() >= 0xffffffffu)
        throw Error(ExitCode::invalid_input, "the scene has more than 4 billion vertices");
    return world;
}

const std::vector<glm::vec2>& World::uv_set(const TextureSlot& slot) const {
    return slot.uv_set == 1 && !uvs1.empty() ? uvs1 : uvs;
}

std::array<glm::vec2, 3> World::corner_uvs(uint32_t triangle, const TextureSlot& slot) const {
    const std::vector<glm::vec2>& set = uv_set(slot);
    const uint32_t* c = &indices[3 * static_cast<size_t>(triangle)];
    return {slot.map(set[c[0]]), slot.map(set[c[1]]), slot.map(set[c[2]])};
}

}  // namespace facet
