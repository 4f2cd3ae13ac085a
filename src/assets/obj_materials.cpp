// OBJ materials: MTL libraries and their materials (assets/obj_materials.hpp).
#include "assets/obj_materials.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <tiny_obj_loader.h>
#include <glm/vec2.hpp>

#include "core/error.hpp"

namespace facet {
namespace {

// Material names may contain spaces ("newmtl Hard Shiny Plastic White",
// assimp issue #545), and files differ in the blanks between the words. A
// name is matched by its words, joined with this character (which no name
// holds), and shown with spaces again in Material::name.
constexpr char kNameSpace = '\x1f';

std::string material_key(const std::string& name) {
    std::string out;
    bool gap = false;
    for (char c : name) {
        if (c == ' ' || c == '\t' || c == '\r') {
            gap = !out.empty();
            continue;
        }
        if (gap) out += kNameSpace;
        gap = false;
        out += c;
    }
    return out;
}

std::string material_name(std::string key) {
    std::replace(key.begin(), key.end(), kNameSpace, ' ');
    return key;
}

// Marks a material whose library gives its roughness (Pr) or metalness
// (Pm), the PBR extension of MTL: tinyobjloader reads an absent Pr as 0, a
// mirror, and an absent Pm as 0, which must not be mistaken for values that
// were given. Each is marked on its own: a material that gives Pm alone
// still takes its roughness from Ns.
constexpr const char* kRoughnessGiven = "facet:Pr";
constexpr const char* kMetalnessGiven = "facet:Pm";

// The scalar PBR keys (Pr, Pm) each material of a library gives, by name.
std::map<std::string, std::set<std::string>> materials_with_physical_terms(const std::string& mtl) {
    std::map<std::string, std::set<std::string>> given;
    std::istringstream lines(mtl);
    std::string line, current;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "newmtl") {
            std::getline(words >> std::ws, current);
            while (!current.empty() && (current.back() == '\r' || current.back() == ' '))
                current.pop_back();
        } else if (key == "Pr" || key == "Pm") {
            given[current].insert(key);
        }
    }
    return given;
}

// The textures loaded so far, by resolved path: each file is loaded once.
using TextureCache = std::map<std::string, std::shared_ptr<const Texture>>;

// The texture a material's map names (`key`: map_Kd, norm, ...), as colour
// or as data (Texture::as_data).
std::shared_ptr<const Texture> material_texture(const std::string& texname, const char* key,
                                                const std::string& material,
                                                const std::string& path,
                                                const AssetContext& context, TextureCache& textures,
                                                bool data = false) {
    // Files written on Windows often name textures with backslashes.
    std::string name = texname;
    std::replace(name.begin(), name.end(), '\\', '/');
    const std::string where = "material '" + material + "': " + key;
    const std::string tex_path = resolve_asset_reference(path, where, name, context.paths);
    auto& slot = textures[tex_path];
    if (!slot) {
        try {
            slot = std::make_shared<Texture>(load_texture(tex_path, context.textures));
        } catch (const Error& e) {
            throw Error(ExitCode::invalid_input, path + ": " + where + ": " + e.what());
        }
    }
    if (!data) return slot;
    auto& as_data = textures["data:" + tex_path];
    if (!as_data) as_data = std::make_shared<Texture>(slot->as_data());
    return as_data;
}

// MTL's roughness and metalness maps (each a grey image) as glTF's one
// metallic-roughness map: G roughness, B metalness. It takes the larger of
// the two sizes on each axis, so that neither map loses its detail; a map
// of another size is read bilinearly there (one of the same size keeps its
// texels exactly, read at their centres).
std::shared_ptr<const Texture> metal_rough_texture(const Texture* roughness, const Texture* metal) {
    const Texture& first = roughness ? *roughness : *metal;
    const int width = std::max(roughness ? roughness->width : 0, metal ? metal->width : 0);
    const int height = std::max(roughness ? roughness->height : 0, metal ? metal->height : 0);
    // A map's R at texel (x, y) of the combined map; 1 without the map.
    auto read = [&](const Texture* map, int x, int y) {
        if (!map) return 1.0f;
        if (map->width == width && map->height == height) return map->texel(0, x, y).r;
        const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                           (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
        return map->sample(uv).r;
    };
    std::vector<glm::vec4> texels(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            texels[static_cast<size_t>(y) * width + x] = {1.0f, read(roughness, x, y),
                                                          read(metal, x, y), 1.0f};
    Texture combined = Texture::from_linear(width, height, texels, Texture::Format::data8);
    combined.sampler = first.sampler;
    return std::make_shared<const Texture>(std::move(combined));
}

// MTL's PBR extension (Pr, Pm, map_Pr, map_Pm, norm). A map multiplies
// its value (as glTF's factors); a map given without its value is the
// value itself (factor 1). Without Pr or map_Pr the roughness follows the
// Phong exponent: GGX's alpha^2 = 2 / (Ns + 2), the usual match of a
// Blinn-Phong lobe's width (Walter et al. 2007, eq. 33); without Pm or
// map_Pm the material is a dielectric.
void obj_physical_terms(const tinyobj::material_t& m, const std::string& path,
                        const AssetContext& context, TextureCache& textures, Material& mat) {
    if (m.unknown_parameter.count(kRoughnessGiven)) {
        mat.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
    } else if (!m.roughness_texname.empty()) {
        mat.roughness = 1.0f;
    } else {
        const float alpha = std::sqrt(2.0f / (mat.shininess + 2.0f));
        mat.roughness = std::clamp(std::sqrt(alpha), 0.0f, 1.0f);
    }
    if (m.unknown_parameter.count(kMetalnessGiven))
        mat.metallic = std::clamp(m.metallic, 0.0f, 1.0f);
    else
        mat.metallic = m.metallic_texname.empty() ? 0.0f : 1.0f;
    std::shared_ptr<const Texture> roughness, metal;
    if (!m.roughness_texname.empty())
        roughness = material_texture(m.roughness_texname, "map_Pr", mat.name, path, context,
                                     textures, true);
    if (!m.metallic_texname.empty())
        metal =
            material_texture(m.metallic_texname, "map_Pm", mat.name, path, context, textures, true);
    if (roughness || metal)
        mat.metal_rough_map.texture = metal_rough_texture(roughness.get(), metal.get());
    if (!m.normal_texname.empty())
        mat.normal_map.texture =
            material_texture(m.normal_texname, "norm", mat.name, path, context, textures, true);
}

// What an MTL material gives that facet does not draw, named by its key
// and what is lost, in one warning per material.
void warn_undrawn_mtl_terms(const tinyobj::material_t& m, const std::string& path,
                            Warnings& warnings) {
    const std::pair<const std::string*, const char*> maps[] = {
        {&m.bump_texname, "bump (a height map; `norm` is read)"},
        {&m.displacement_texname, "disp"},
        {&m.specular_texname, "map_Ks"},
        {&m.specular_highlight_texname, "map_Ns"},
        {&m.alpha_texname, "map_d"},
        {&m.ambient_texname, "map_Ka"},
        {&m.emissive_texname, "map_Ke"},
        {&m.reflection_texname, "refl"},
        {&m.sheen_texname, "map_Ps"},
    };
    std::string lost;
    for (const auto& [name, key] : maps)
        if (!name->empty()) lost += (lost.empty() ? "" : ", ") + std::string(key);
    if (m.emission[0] > 0 || m.emission[1] > 0 || m.emission[2] > 0)
        lost += (lost.empty() ? "" : ", ") + std::string("Ke (emission)");
    if (m.dissolve < 1.0f) lost += (lost.empty() ? "" : ", ") + std::string("d (transparency)");
    if (lost.empty()) return;
    warnings.push_back(file_warning(path, "material '" + material_name(m.name) + "': " + lost +
                                              " not drawn: the surface shows without them"));
}

Material obj_material(const tinyobj::material_t& m, const std::string& path,
                      const AssetContext& context, TextureCache& textures) {
    Material mat;
    mat.name = material_name(m.name);
    mat.color = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    float ks = (m.specular[0] + m.specular[1] + m.specular[2]) / 3.0f;
    mat.specular = ks;
    if (m.shininess > 0) mat.shininess = m.shininess;
    if (!m.diffuse_texname.empty()) {
        mat.base_color_map.texture =
            material_texture(m.diffuse_texname, "map_Kd", mat.name, path, context, textures);
        // map_Kd replaces Kd in most exporters' intent; many write Kd 0 0 0 with a map.
        if (mat.color == glm::vec3(0)) mat.color = glm::vec3(1);
    }
    obj_physical_terms(m, path, context, textures, mat);
    return mat;
}

// The file names of an mtllib statement: split at spaces, a backslash
// before a space escaping it (as in "mtllib my\ model.mtl"), other
// backslashes read as '/' ("mtllib .\libs\a.mtl" from Windows exporters).
// As other OBJ readers do, an empty last name is kept: it is tried, and
// refused, like any other.
std::vector<std::string> library_names(const std::string& text) {
    std::vector<std::string> names;
    std::string name;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\\' && i + 1 < text.size() && text[i + 1] == ' ') {
            name += ' ';
            ++i;
        } else if (c == '\\') {
            name += '/';
        } else if (c == ' ') {
            if (!name.empty()) names.push_back(name);
            name.clear();
        } else {
            name += c;
        }
    }
    names.push_back(name);
    return names;
}

}  // namespace

struct ObjMaterials::Libraries {
    std::string obj_path;
    AssetContext context;
    std::vector<tinyobj::material_t> materials;
    std::map<std::string, int> index_by_key;  // by material_key of the name
    std::set<std::string> read;               // library names read
    std::set<std::string> unknown;            // usemtl names warned about

    // Reads one library; false when it does not exist (a warning).
    bool read_library(const std::string& name, int line, Warnings& warnings) {
        const std::string where = "line " + std::to_string(line) + ": mtllib";
        std::string text;
        try {
            const std::string mtl = resolve_asset_reference(obj_path, where, name, context.paths);
            const std::vector<uint8_t> bytes =
                read_input_file(mtl, "MTL", context.paths.max_file_bytes);
            text.assign(bytes.begin(), bytes.end());
        } catch (const Error& e) {
            // A missing library is common in downloaded models: the faces
            // keep a default material. Anything else is refused.
            const std::string what = e.what();
            const bool missing = what.find("no such file") != std::string::npos &&
                                 what.find("outside the asset's folder") == std::string::npos;
            if (!missing) throw;
            Warning w = file_warning(obj_path, "material library '" + name + "' not found");
            w.where.line = line;
            w.where.column = 1;
            warnings.push_back(std::move(w));
            return false;
        }
        std::istringstream in(text);
        const size_t first = materials.size();
        std::map<std::string, int> by_name;  // index_by_key below replaces it
        std::string warn, err;
        tinyobj::LoadMtl(&by_name, &materials, &in, &warn, &err);
        for (std::istringstream lines(warn); std::getline(lines, warn);)
            if (!warn.empty()) warnings.push_back(file_warning(obj_path, warn));
        const auto physical = materials_with_physical_terms(text);
        for (size_t i = first; i < materials.size(); ++i) {
            auto& m = materials[i];
            if (const auto keys = physical.find(m.name); keys != physical.end()) {
                if (keys->second.count("Pr")) m.unknown_parameter[kRoughnessGiven] = "1";
                if (keys->second.count("Pm")) m.unknown_parameter[kMetalnessGiven] = "1";
            }
            m.name = material_key(m.name);
            index_by_key.emplace(m.name, static_cast<int>(i));
        }
        return true;
    }
};

ObjMaterials::ObjMaterials(const std::string& obj_path, const AssetContext& context)
    : libraries_(std::make_unique<Libraries>()) {
    libraries_->obj_path = obj_path;
    libraries_->context = context;
}

ObjMaterials::~ObjMaterials() = default;

void ObjMaterials::read_libraries(const ObjStatement& mtllib, Warnings& warnings) {
    for (const std::string& name : library_names(mtllib.text)) {
        if (libraries_->read.count(name)) continue;
        if (libraries_->read_library(name, mtllib.line, warnings)) {
            libraries_->read.insert(name);
            return;
        }
    }
}

std::optional<uint32_t> ObjMaterials::find(const ObjStatement& usemtl, Warnings& warnings) {
    const auto it = libraries_->index_by_key.find(material_key(usemtl.text));
    if (it != libraries_->index_by_key.end()) return static_cast<uint32_t>(it->second);
    if (libraries_->unknown.insert(usemtl.text).second) {
        Warning w = file_warning(libraries_->obj_path,
                                 "usemtl '" + usemtl.text +
                                     "': no material library read so far has this material; its "
                                     "faces have the default material");
        w.where.line = usemtl.line;
        w.where.column = 1;
        warnings.push_back(std::move(w));
    }
    return std::nullopt;
}

size_t ObjMaterials::size() const {
    return libraries_->materials.size();
}

std::vector<Material> ObjMaterials::build(Warnings& warnings) const {
    std::vector<Material> out;
    TextureCache textures;
    for (const auto& m : libraries_->materials) {
        out.push_back(obj_material(m, libraries_->obj_path, libraries_->context, textures));
        warn_undrawn_mtl_terms(m, libraries_->obj_path, warnings);
    }
    return out;
}

}  // namespace facet
