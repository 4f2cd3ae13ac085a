// Wavefront OBJ + MTL through tinyobjloader.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <tuple>

#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "assets/mesh.hpp"
#include "assets/polygon_triangulation.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

// OBJ files rarely say which edges are sharp; this angle separates the
// edges of a cube from the facets of a tessellated sphere.
constexpr float kObjCreaseDegrees = 60.0f;

std::vector<std::string> split_lines(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(prefix + text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

void append_utf8(std::string& out, uint32_t u) {
    if (u < 0x80) {
        out += static_cast<char>(u);
    } else if (u < 0x800) {
        out += static_cast<char>(0xC0 | (u >> 6));
        out += static_cast<char>(0x80 | (u & 0x3F));
    } else if (u < 0x10000) {
        out += static_cast<char>(0xE0 | (u >> 12));
        out += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (u & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (u >> 18));
        out += static_cast<char>(0x80 | ((u >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (u & 0x3F));
    }
}

// The file as UTF-8 text. Some exporters write UTF-16 with a byte order mark
// (assimp's box_UTF16BE.obj); tinyobjloader only reads bytes, so such a file
// would silently come out empty.
std::string read_obj_text(const std::string& path) {
    const std::vector<uint8_t> bytes = read_input_file(path, "OBJ");
    const std::string raw(bytes.begin(), bytes.end());
    auto byte = [&](size_t i) { return static_cast<unsigned char>(raw[i]); };
    if (raw.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF)
        return raw.substr(3);
    const bool be = raw.size() >= 2 && byte(0) == 0xFE && byte(1) == 0xFF;
    const bool le = raw.size() >= 2 && byte(0) == 0xFF && byte(1) == 0xFE;
    if (!be && !le) return raw;
    std::string out;
    out.reserve(raw.size() / 2);
    auto unit = [&](size_t i) -> uint32_t {
        return be ? (byte(i) << 8) | byte(i + 1) : byte(i) | (byte(i + 1) << 8);
    };
    for (size_t i = 2; i + 1 < raw.size(); i += 2) {
        uint32_t u = unit(i);
        if (u >= 0xD800 && u <= 0xDBFF && i + 3 < raw.size()) {
            uint32_t low = unit(i + 2);
            if (low >= 0xDC00 && low <= 0xDFFF) {
                u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
                i += 2;
            }
        }
        append_utf8(out, u);
    }
    return out;
}

// tinyobjloader reads only the first word after "usemtl", but material names
// may contain spaces ("newmtl Hard Shiny Plastic White", assimp issue #545),
// so such faces silently lost their material. Names are joined with this
// character in both files before parsing, and split again in Material::name.
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

// A vertex line's word that is not a number ("nan", "inf", "1.0f"):
// tinyobjloader reads it as 0 without a word, which moves the vertex.
// Letters other than an exponent's 'e' have no place in a number.
void check_vertex_words(const std::string& text, size_t from, size_t end, const std::string& path,
                        int line, size_t line_start) {
    for (size_t k = from; k < end && text[k] != '#'; ++k) {
        const char c = text[k];
        if (!std::isalpha(static_cast<unsigned char>(c)) || c == 'e' || c == 'E') continue;
        size_t first = text.find_last_of(" \t", k);
        first = first == std::string::npos || first < from ? from : first + 1;
        const size_t last = std::min(end, text.find_first_of(" \t\r", k));
        fail_input(SourceLocation{path, line, static_cast<int>(first - line_start) + 1, ""}, "",
                   "'" + text.substr(first, last - first) +
                       "' is not a finite number, which vertex data must be");
    }
}

// Rewrites the two kinds of line tinyobjloader misreads: material names with
// spaces (see above), and "mtllib .\\libs\\a.mtl" from Windows exporters, where
// it takes each backslash as an escape and drops it. A backslash before a
// space stays: that is tinyobjloader's escape for a space in the file name.
// Refuses vertex values that are not numbers (check_vertex_words).
std::string normalise_obj_lines(const std::string& text, const std::string& path) {
    std::string out;
    out.reserve(text.size());
    size_t start = 0;
    for (int line = 1; start < text.size(); ++line) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        size_t i = text.find_first_not_of(" \t", start);
        if (i < end && text.compare(i, 6, "usemtl") == 0 && i + 6 < end &&
            (text[i + 6] == ' ' || text[i + 6] == '\t')) {
            out += "usemtl " + material_key(text.substr(i + 7, end - i - 7));
        } else if (i < end && text.compare(i, 6, "mtllib") == 0) {
            for (size_t k = start; k < end; ++k)
                out += text[k] == '\\' && k + 1 < end && text[k + 1] != ' ' ? '/' : text[k];
        } else {
            const size_t words = i < end ? text.find_first_of(" \t", i) : end;
            const std::string_view keyword =
                words < end ? std::string_view(text).substr(i, words - i) : std::string_view();
            if (keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "vp")
                check_vertex_words(text, words, end, path, line, start);
            out.append(text, start, end - start);
        }
        if (end < text.size()) out += '\n';
        start = end + 1;
    }
    return out;
}

// The line of each file named by an mtllib line, for messages.
std::map<std::string, int> mtllib_lines(const std::string& text) {
    std::map<std::string, int> lines;
    int line = 1;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::istringstream words(text.substr(start, end - start));
        std::string word;
        if (words >> word && word == "mtllib")
            while (words >> word) lines.emplace(word, line);
        ++line;
        start = end + 1;
    }
    return lines;
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

// .mtl files named by mtllib, resolved and checked by the asset path policy
// (core/input_file.hpp). tinyobjloader's own reader splits its search path
// at ':', so models in a folder whose name has a colon lost their materials;
// and it opens whatever it is given. A refusal is kept and thrown after
// parsing, so that no exception crosses tinyobjloader.
class MtlReader : public tinyobj::MaterialReader {
  public:
    MtlReader(std::string obj_path, const AssetPathPolicy& policy, std::map<std::string, int> lines)
        : obj_path_(std::move(obj_path)), policy_(policy), lines_(std::move(lines)) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn,
                    std::string* err) override {
        const auto line = lines_.find(name);
        const std::string where =
            line == lines_.end() ? "mtllib" : "line " + std::to_string(line->second) + ": mtllib";
        std::string text;
        try {
            const std::string mtl = resolve_asset_reference(obj_path_, where, name, policy_);
            const std::vector<uint8_t> bytes = read_input_file(mtl, "MTL", policy_.max_file_bytes);
            text.assign(bytes.begin(), bytes.end());
        } catch (const Error& e) {
            // A missing library is common in downloaded models: the faces
            // keep a default material. Anything else is refused.
            const bool missing =
                std::string(e.what()).find("no such file") != std::string::npos &&
                std::string(e.what()).find("outside the asset's folder") == std::string::npos;
            if (missing) {
                if (warn) *warn += "material library '" + name + "' not found\n";
            } else if (!refusal_) {
                refusal_ = e;
            }
            return false;
        }
        std::istringstream in(text);
        const size_t first = materials->size();
        tinyobj::LoadMtl(names, materials, &in, warn, err);
        const auto physical = materials_with_physical_terms(text);
        for (size_t i = first; i < materials->size(); ++i) {
            auto& m = (*materials)[i];
            if (const auto keys = physical.find(m.name); keys != physical.end()) {
                if (keys->second.count("Pr")) m.unknown_parameter[kRoughnessGiven] = "1";
                if (keys->second.count("Pm")) m.unknown_parameter[kMetalnessGiven] = "1";
            }
            std::string key = material_key(m.name);
            if (key == m.name) continue;
            auto it = names->find(m.name);
            if (it != names->end() && it->second == static_cast<int>(i)) names->erase(it);
            names->emplace(key, static_cast<int>(i));
            m.name = key;
        }
        return true;
    }
    // The first library refused by the policy, if any.
    const std::optional<Error>& refusal() const { return refusal_; }

  private:
    std::string obj_path_;
    AssetPathPolicy policy_;
    std::map<std::string, int> lines_;
    std::optional<Error> refusal_;
};

// What tinyobjloader read from one OBJ file.
struct ObjContents {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
};

// Parses `text` into `obj`, emptied first; false when tinyobjloader fails.
// Throws the asset path policy's refusal of a material library.
bool parse_obj(const std::string& text, const std::string& path, const AssetContext& context,
               const std::map<std::string, int>& libraries, bool triangulate, ObjContents& obj) {
    obj.attrib = tinyobj::attrib_t();
    obj.shapes.clear();
    obj.materials.clear();
    obj.warn.clear();
    obj.err.clear();
    std::istringstream in(text);
    MtlReader mtl(path, context.paths, libraries);
    const bool parsed = tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &obj.warn,
                                         &obj.err, &in, &mtl, triangulate, false);
    if (mtl.refusal()) throw *mtl.refusal();
    return parsed;
}

// tinyobjloader keeps corner counts in an unsigned char: a face with more
// than 255 corners wraps, and the counts no longer add up to the indices.
bool corner_counts_add_up(const std::vector<tinyobj::shape_t>& shapes) {
    bool whole_polygons = true;
    for (const auto& shape : shapes) {
        size_t sum = 0;
        for (unsigned char c : shape.mesh.num_face_vertices) sum += c;
        if (sum != shape.mesh.indices.size()) whole_polygons = false;
    }
    return whole_polygons;
}

// The file at `path`, parsed; throws invalid_input when it cannot be read.
ObjContents read_obj(const std::string& path, const AssetContext& context) {
    const std::string text = normalise_obj_lines(read_obj_text(path), path);
    const std::map<std::string, int> libraries = mtllib_lines(text);
    ObjContents obj;
    // Polygons are triangulated here (see triangulate_polygon), so ask for them whole.
    bool ok = parse_obj(text, path, context, libraries, false, obj);
    // Files whose corner counts wrapped (corner_counts_add_up) fall back to
    // tinyobjloader's own triangulation.
    const bool whole_polygons = corner_counts_add_up(obj.shapes);
    if (ok && !whole_polygons) {
        ok = parse_obj(text, path, context, libraries, true, obj);
        // In that mode tinyobjloader drops quads with bad indices with only a warning.
        if (ok && obj.warn.find("invalid vertex index") != std::string::npos)
            throw Error(ExitCode::invalid_input,
                        path + ": a face refers to a vertex that does not exist");
    }
    if (!ok) {
        std::string why = obj.err;
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
        throw Error(ExitCode::invalid_input,
                    path + ": cannot read OBJ: " + (why.empty() ? "unknown error" : why));
    }
    return obj;
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

// One part per material; vertices are unique per (position, normal, uv) index triple.
struct PartBuilder {
    MeshPart part;
    std::map<std::tuple<int, int, int>, uint32_t> unique;
    bool missing_normals = false;
    bool any_uv = false;
};

// Sorts the shapes' faces into one part per material, as triangles.
struct PartAssembly {
    PartAssembly(const tinyobj::attrib_t& attrib, const std::string& path, uint32_t material_count)
        : attrib(attrib),
          path(path),
          default_material(material_count),
          position_count(attrib.vertices.size() / 3),
          normal_count(attrib.normals.size() / 3),
          uv_count(attrib.texcoords.size() / 2) {}

    void add_shape(const tinyobj::shape_t& shape) {
        const auto& m = shape.mesh;
        size_t offset = 0;
        for (size_t face = 0; face < m.num_face_vertices.size(); ++face) {
            const size_t count = m.num_face_vertices[face];
            if (count < 3 || offset + count > m.indices.size()) {  // not a surface: skip it
                offset += count;
                continue;
            }
            check_face_vertices(shape, face, offset, count);
            const std::vector<std::array<size_t, 3>> triangles = face_triangles(m, offset, count);
            PartBuilder& b = face_part(m, face);
            for (const auto& tri : triangles)
                for (size_t corner : tri) add_corner(b, m.indices[offset + corner]);
            offset += count;
        }
    }

    const tinyobj::attrib_t& attrib;
    const std::string& path;
    // One past the file's materials: the material of faces without a valid one.
    const uint32_t default_material;
    const size_t position_count, normal_count, uv_count;
    std::map<uint32_t, PartBuilder> parts;
    bool used_default = false;

    void check_face_vertices(const tinyobj::shape_t& shape, size_t face, size_t offset,
                             size_t count) const {
        for (size_t k = 0; k < count; ++k) {
            const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
            if (idx.vertex_index < 0 || static_cast<size_t>(idx.vertex_index) >= position_count)
                throw Error(ExitCode::invalid_input,
                            path + ": shape '" + shape.name + "' face " + std::to_string(face + 1) +
                                " refers to vertex " + std::to_string(idx.vertex_index + 1) +
                                " but the file has " + std::to_string(position_count));
        }
    }

    // The face's triangles, as corner numbers within the face.
    std::vector<std::array<size_t, 3>> face_triangles(const tinyobj::mesh_t& m, size_t offset,
                                                      size_t count) const {
        std::vector<std::array<size_t, 3>> triangles;
        if (count == 3) {
            triangles.push_back({0, 1, 2});
        } else {
            std::vector<glm::dvec3> corners(count);
            for (size_t k = 0; k < count; ++k) {
                size_t v = static_cast<size_t>(m.indices[offset + k].vertex_index);
                corners[k] = {attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                              attrib.vertices[3 * v + 2]};
            }
            triangles = triangulate_polygon(corners);
        }
        return triangles;
    }

    PartBuilder& face_part(const tinyobj::mesh_t& m, size_t face) {
        int mat_id = face < m.material_ids.size() ? m.material_ids[face] : -1;
        uint32_t material = (mat_id >= 0 && static_cast<size_t>(mat_id) < default_material)
                                ? static_cast<uint32_t>(mat_id)
                                : default_material;
        used_default = used_default || material == default_material;
        PartBuilder& b = parts[material];
        b.part.material = material;
        return b;
    }

    void add_corner(PartBuilder& b, const tinyobj::index_t& idx) {
        int n = idx.normal_index;
        if (n >= 0 && static_cast<size_t>(n) >= normal_count) n = -1;
        int t = idx.texcoord_index;
        if (t >= 0 && static_cast<size_t>(t) >= uv_count) t = -1;
        if (n < 0) b.missing_normals = true;
        if (t >= 0) b.any_uv = true;
        auto key = std::make_tuple(idx.vertex_index, n, t);
        auto [it, added] = b.unique.emplace(key, static_cast<uint32_t>(b.part.positions.size()));
        if (added) {
            size_t v = static_cast<size_t>(idx.vertex_index);
            b.part.positions.push_back(
                {attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]});
            b.part.normals.push_back(n >= 0 ? glm::vec3(attrib.normals[3 * n],
                                                        attrib.normals[3 * n + 1],
                                                        attrib.normals[3 * n + 2])
                                            : glm::vec3(0));
            // OBJ puts v = 0 at the bottom of the image; facet samples from the top.
            b.part.uvs.push_back(
                t >= 0 ? glm::vec2(attrib.texcoords[2 * t], 1.0f - attrib.texcoords[2 * t + 1])
                       : glm::vec2(0));
        }
        b.part.indices.push_back(it->second);
    }
};

// Drops unused UVs, fills in missing normals, makes every normal unit length
// and checks the part.
void finish_part(PartBuilder& b, const std::string& path) {
    if (!b.any_uv) b.part.uvs.clear();
    if (b.missing_normals) compute_normals(b.part, kObjCreaseDegrees);
    for (auto& n : b.part.normals) {
        float len = glm::length(n);
        n = len > 0 ? n / len : glm::vec3(0, 1, 0);
    }
    validate_part(b.part, path);
}

}  // namespace

Mesh load_obj(const std::string& path, const AssetContext& context) {
    const ObjContents obj = read_obj(path, context);

    Mesh mesh;
    mesh.source = path;
    mesh.loader = "tinyobjloader";
    for (std::string& line : split_lines(obj.warn, ""))
        mesh.warnings.push_back(file_warning(path, line));

    TextureCache textures;
    for (const auto& m : obj.materials) {
        mesh.materials.push_back(obj_material(m, path, context, textures));
        warn_undrawn_mtl_terms(m, path, mesh.warnings);
    }

    PartAssembly assembly(obj.attrib, path, static_cast<uint32_t>(mesh.materials.size()));
    for (const auto& shape : obj.shapes) assembly.add_shape(shape);
    if (assembly.used_default) {
        Material fallback;
        fallback.name = "default";
        mesh.materials.push_back(fallback);
    }
    for (auto& [material, b] : assembly.parts) {
        finish_part(b, path);
        mesh.parts.push_back(std::move(b.part));
    }
    if (mesh.triangle_count() == 0)
        throw Error(ExitCode::invalid_input, path + ": the OBJ file has no faces");
    return mesh;
}

}  // namespace facet
