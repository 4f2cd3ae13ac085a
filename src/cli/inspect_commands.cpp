#include "cli/inspect_commands.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "assets/mesh.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/plain_text.hpp"
#include "core/suggest.hpp"

namespace facet {
namespace {

using Json = nlohmann::ordered_json;

Json place_json(const SourceLocation& where, const std::string& key, const std::string& message) {
    Json j = {{"file", where.file},
              {"line", where.line},
              {"column", where.column},
              {"key", key},
              {"message", message}};
    if (!where.origin.empty()) j["origin"] = where.origin;
    return j;
}

Json warnings_json(const Warnings& warnings) {
    Json list = Json::array();
    for (const Warning& w : warnings) list.push_back(place_json(w.where, w.key, w.message));
    return list;
}

struct MeshFacts {
    size_t morphed_parts = 0, most_targets = 0;
    size_t textured_parts = 0, colored_parts = 0;  // with texture coordinates, vertex colours
};

// The nodes an animation moves, by name, in the order its channels name them.
std::vector<std::string> driven_nodes(const MeshRig& rig, const RigAnimation& animation) {
    std::vector<std::string> names;
    for (const RigChannel& c : animation.channels) {
        const std::string& name = rig.nodes[static_cast<size_t>(c.node)].name;
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

const char* light_type_name(GltfLight::Type type) {
    return type == GltfLight::Type::directional ? "directional"
           : type == GltfLight::Type::spot      ? "spot"
                                                : "point";
}

// The materials some part is drawn with, in the file's order: a file's
// unused materials, and the default one when every part has its own, are
// not what the file shows.
std::vector<const Material*> used_materials(const Mesh& mesh) {
    std::vector<bool> used(mesh.materials.size(), false);
    for (const MeshPart& part : mesh.parts)
        if (part.material < used.size()) used[part.material] = true;
    std::vector<const Material*> out;
    for (size_t i = 0; i < used.size(); ++i)
        if (used[i]) out.push_back(&mesh.materials[i]);
    return out;
}

// A material of the file, by its index and its name.
struct NamedMaterial {
    size_t index;
    std::string name;
};

// Each variant of the file with the materials its parts are drawn in under
// it, in the file's order (by index too: files often give several one name).
std::vector<std::pair<std::string, std::vector<NamedMaterial>>> variant_materials(
    const Mesh& file) {
    std::vector<std::pair<std::string, std::vector<NamedMaterial>>> variants;
    if (file.variants.empty()) return variants;
    const auto mesh = std::make_shared<const Mesh>(file);
    for (const std::string& name : mesh->variants) {
        const std::shared_ptr<const Mesh> drawn = with_variant(mesh, name);
        std::vector<NamedMaterial> materials;
        for (const Material* m : used_materials(*drawn))
            materials.push_back({static_cast<size_t>(m - drawn->materials.data()), m->name});
        variants.push_back({name, materials});
    }
    return variants;
}

MeshFacts mesh_facts(const Mesh& mesh) {
    MeshFacts f;
    for (const MeshPart& part : mesh.parts) {
        f.textured_parts += part.uvs.empty() ? 0 : 1;
        f.colored_parts += part.colors.empty() ? 0 : 1;
    }
    if (const MeshRig* rig = mesh.rig.get())
        for (const auto& part : rig->parts)
            if (!part.morph_targets.empty()) {
                ++f.morphed_parts;
                f.most_targets = std::max(f.most_targets, part.morph_targets.size());
            }
    return f;
}

void print_mesh_json(const std::string& path, const Mesh& mesh) {
    const Bounds b = mesh.bounds();
    const MeshRig* rig = mesh.rig.get();
    const MeshFacts facts = mesh_facts(mesh);
    Json j = {
        {"file", path},
        {"loader", mesh.loader},
        {"triangles", mesh.triangle_count()},
        {"vertices", mesh.vertex_count()},
        {"parts", mesh.parts.size()},
        {"parts_with_vertex_colors", facts.colored_parts},
        {"parts_with_uvs", facts.textured_parts},
        {"bounds", {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}}}};
    j["materials"] = Json::array();
    for (const Material* m : used_materials(mesh))
        j["materials"].push_back({{"name", m->name},
                                  {"color", {m->color.r, m->color.g, m->color.b}},
                                  {"textured", m->base_color_map.texture != nullptr},
                                  {"emissive_textured", m->emissive_map.texture != nullptr},
                                  {"double_sided", m->double_sided},
                                  {"emissive", {m->emissive.r, m->emissive.g, m->emissive.b}},
                                  {"unlit", m->unlit}});
    j["variants"] = Json::array();
    for (const auto& [name, materials] : variant_materials(mesh)) {
        Json drawn = Json::array();
        for (const NamedMaterial& m : materials)
            drawn.push_back({{"index", m.index}, {"name", m.name}});
        j["variants"].push_back({{"name", name}, {"materials", drawn}});
    }
    j["extensions"] = {{"used", mesh.extensions.used},
                       {"required", mesh.extensions.required},
                       {"ignored", mesh.extensions.ignored}};
    j["animations"] = Json::array();
    if (rig)
        for (const auto& a : rig->animations)
            j["animations"].push_back({{"name", a.name},
                                       {"duration", a.duration},
                                       {"channels", a.channels.size()},
                                       {"nodes", driven_nodes(*rig, a)}});
    j["cameras"] = Json::array();
    for (const GltfCamera& c : mesh.cameras) {
        Json camera = {{"name", c.name}, {"type", c.orthographic ? "orthographic" : "perspective"}};
        if (!c.orthographic) {
            camera["yfov_degrees"] = c.yfov_degrees;
            camera["znear"] = c.znear;
            camera["zfar"] = c.zfar;
        }
        j["cameras"].push_back(camera);
    }
    j["lights"] = Json::array();
    for (const GltfLight& l : mesh.lights)
        j["lights"].push_back({{"name", l.name},
                               {"type", light_type_name(l.type)},
                               {"color", {l.color.r, l.color.g, l.color.b}},
                               {"intensity", l.intensity},
                               {"position", {l.position.x, l.position.y, l.position.z}}});
    j["skins"] = rig ? rig->skins.size() : 0;
    j["morphed_parts"] = facts.morphed_parts;
    j["most_morph_targets"] = facts.most_targets;
    // What a render of the file does: draw it, or stop with these errors.
    j["renders"] = mesh.refusals.empty();
    j["render_errors"] = Json::array();
    for (const Error& e : mesh.refusals) j["render_errors"].push_back(e.what());
    j["warnings"] = warnings_json(mesh.warnings);
    std::printf("%s\n", j.dump(2).c_str());
}

void print_mesh_text(const std::string& path, const Mesh& mesh) {
    const Bounds b = mesh.bounds();
    const MeshFacts facts = mesh_facts(mesh);
    std::printf("file:       %s\n", path.c_str());
    std::printf("loader:     %s\n", mesh.loader.c_str());
    std::printf("triangles:  %zu\n", mesh.triangle_count());
    std::printf("vertices:   %zu\n", mesh.vertex_count());
    std::printf("parts:      %zu (%zu with texture coordinates, %zu with vertex colours)\n",
                mesh.parts.size(), facts.textured_parts, facts.colored_parts);
    std::printf("bounds:     [%g, %g, %g] .. [%g, %g, %g]\n", b.min.x, b.min.y, b.min.z, b.max.x,
                b.max.y, b.max.z);
    std::printf("size:       [%g, %g, %g]\n", b.max.x - b.min.x, b.max.y - b.min.y,
                b.max.z - b.min.z);
    const std::vector<const Material*> materials = used_materials(mesh);
    std::printf("materials:  %zu\n", materials.size());
    for (const Material* m : materials) {
        std::string extra;
        if (m->base_color_map) extra += ", textured";
        if (m->double_sided) extra += ", double-sided";
        if (m->unlit) extra += ", unlit";
        if (m->emissive != glm::vec3(0)) {
            char text[96];
            std::snprintf(text, sizeof text, ", emissive [%.3g, %.3g, %.3g]%s", m->emissive.r,
                          m->emissive.g, m->emissive.b, m->emissive_map ? " x map" : "");
            extra += text;
        }
        std::printf("  - %s: color [%.3g, %.3g, %.3g]%s\n",
                    m->name.empty() ? "(unnamed)" : m->name.c_str(), m->color.r, m->color.g,
                    m->color.b, extra.c_str());
    }
    auto list = [](const std::vector<std::string>& names) {
        return names.empty() ? std::string("none") : comma_list(names);
    };
    std::printf("variants:   %zu%s\n", mesh.variants.size(),
                mesh.variants.empty() ? "" : " (render one with --variant NAME, each with all)");
    for (const auto& [name, materials] : variant_materials(mesh)) {
        std::vector<std::string> drawn;
        for (const NamedMaterial& m : materials)
            drawn.push_back((m.name.empty() ? "(unnamed)" : m.name) + " (material " +
                            std::to_string(m.index) + ")");
        std::printf("  - %s: %s\n", name.c_str(), list(drawn).c_str());
    }
    if (!mesh.extensions.used.empty() || !mesh.extensions.required.empty()) {
        std::printf("extensions: used %s\n", list(mesh.extensions.used).c_str());
        std::printf("            required %s\n", list(mesh.extensions.required).c_str());
        std::printf("            not read %s\n", list(mesh.extensions.ignored).c_str());
    }
    const MeshRig* rig = mesh.rig.get();
    std::printf("cameras:    %zu\n", mesh.cameras.size());
    for (const GltfCamera& c : mesh.cameras) {
        if (c.orthographic)
            std::printf("  - %s: orthographic (not rendered)\n", c.name.c_str());
        else if (c.zfar > 0)
            std::printf("  - %s: yfov %.4g degrees, near %g, far %g\n", c.name.c_str(),
                        c.yfov_degrees, c.znear, c.zfar);
        else
            std::printf("  - %s: yfov %.4g degrees, near %g, far infinite\n", c.name.c_str(),
                        c.yfov_degrees, c.znear);
    }
    std::printf("lights:     %zu%s\n", mesh.lights.size(),
                mesh.lights.empty() ? "" : " (used by an object with `lights: true`)");
    for (const GltfLight& l : mesh.lights)
        std::printf("  - %s: %s, intensity %g, at [%g, %g, %g]\n", l.name.c_str(),
                    light_type_name(l.type), l.intensity, l.position.x, l.position.y, l.position.z);
    std::printf("animations: %zu\n", rig ? rig->animations.size() : 0);
    if (rig)
        for (const auto& a : rig->animations) {
            std::string nodes;
            for (const std::string& n : driven_nodes(*rig, a)) {
                if (!nodes.empty()) nodes += ", ";
                nodes += n;
            }
            std::printf("  - %s: %g s, %zu %s, drives %s\n", a.name.c_str(), a.duration,
                        a.channels.size(), a.channels.size() == 1 ? "channel" : "channels",
                        nodes.c_str());
        }
    std::printf("skins:      %zu\n", rig ? rig->skins.size() : 0);
    std::printf("morphed:    %zu of %zu parts, up to %zu targets\n", facts.morphed_parts,
                mesh.parts.size(), facts.most_targets);
    for (const Warning& w : mesh.warnings) std::printf("warning: %s\n", w.describe().c_str());
}

}  // namespace

int info_command(const std::string& path, bool allow_outside, bool json, unsigned threads) {
    require_input_file(path, "mesh");
    TextureBudget textures(kDefaultTextureBudget);
    AssetContext assets;
    assets.paths.allow_outside = allow_outside;
    assets.textures = &textures;
    assets.inspect_only = true;
    assets.threads = threads;
    const Mesh mesh = load_mesh(path, assets);
    if (json)
        print_mesh_json(path, mesh);
    else
        print_mesh_text(path, mesh);
    // What render would stop with, in its words, and its exit code: info
    // shows what it can of the file, and says that it cannot be rendered.
    for (const Error& e : mesh.refusals) std::fprintf(stderr, "facet: error: %s\n", e.what());
    return mesh.refusals.empty() ? 0 : static_cast<int>(mesh.refusals.front().code());
}

int styles_command(const std::string& name, bool json) {
    const auto presets = list_style_presets(default_style_dirs());
    if (!name.empty()) {
        for (const auto& [preset, path] : presets)
            if (preset == name) {
                std::printf("%s", resolved_style_yaml(path, default_style_dirs()).c_str());
                return 0;
            }
        std::vector<std::string_view> known;
        for (const auto& [preset, path] : presets) known.push_back(preset);
        fail_input({"", 0, 0, "command line styles " + name}, "",
                   "no style preset named '" + name + "'" + did_you_mean(name, known) +
                       " (available: " + comma_list(known) + ")");
    }
    Json list = Json::array();
    size_t widest = 0;
    for (const auto& [preset, path] : presets) widest = std::max(widest, preset.size());
    for (const auto& [preset, path] : presets) {
        std::string description, extends, error;
        try {
            const StyleDesc style = load_style_file(path, default_style_dirs());
            description = style.description;
            if (!style.chain.empty()) extends = style.chain.back();
        } catch (const Error& e) {
            error = e.what();
        }
        if (json) {
            Json entry = {{"name", preset}, {"path", path}, {"description", description}};
            entry["extends"] = extends.empty() ? Json(nullptr) : Json(extends);
            if (!error.empty()) entry["error"] = error;
            list.push_back(entry);
            continue;
        }
        std::string line = error.empty() ? description : "error: " + error;
        if (!extends.empty()) line += " (extends " + extends + ")";
        std::printf("%-*s  %s\n", static_cast<int>(widest), preset.c_str(), line.c_str());
    }
    if (json) std::printf("%s\n", list.dump(2).c_str());
    return 0;
}

std::string validate_json(const ValidateFacts& f, const Warnings& warnings) {
    Json j = {{"ok", true},           {"scene", f.scene},
              {"objects", f.objects}, {"triangles", f.triangles},
              {"lights", f.lights},   {"style", f.style},
              {"shading", f.shading}, {"size", {f.width, f.height}},
              {"frames", f.frames}};
    if (!f.variants.empty()) j["variants"] = f.variants;
    j["warnings"] = warnings_json(warnings);
    return j.dump(2) + "\n";
}

std::string validate_error_json(const Error& error, const Warnings& warnings) {
    Json j = {{"ok", false}, {"exit_code", static_cast<int>(error.code())}};
    j["errors"] = Json::array({place_json(error.where(), error.key(),
                                          error.detail().empty() ? error.what() : error.detail())});
    j["errors"][0]["text"] = error.what();
    j["warnings"] = warnings_json(warnings);
    return j.dump(2) + "\n";
}

}  // namespace facet
