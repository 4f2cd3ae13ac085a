#include "assets/gltf_extensions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "assets/gltf_accessors.hpp"
#include "assets/gltf_field_types.hpp"

namespace facet::gltf_detail {
namespace {

// What facet reads, and what it does with each.
const std::map<std::string, std::string>& supported_extensions() {
    static const std::map<std::string, std::string> supported = {
        {"KHR_mesh_quantization", "integer vertex attributes"},
        {"EXT_meshopt_compression",
         "geometry compressed by gltfpack -cc, decoded by libmeshoptimizer"},
        {"KHR_texture_transform", "texture offset, rotation, scale and texCoord"},
        {"KHR_draco_mesh_compression", "compressed geometry, decoded by libdraco"},
        {"KHR_materials_emissive_strength", "emission brighter than 1"},
        {"KHR_materials_unlit", "materials shown without lights"},
        {"KHR_materials_ior", "the dielectric's index of refraction (style pbr)"},
        {"KHR_materials_specular", "the dielectric's reflectance and its tint (style pbr)"},
        {"KHR_materials_clearcoat", "a clear lacquer over the material (style pbr)"},
        {"KHR_materials_sheen", "the sheen of cloth and velvet (style pbr)"},
        {"KHR_materials_iridescence", "the colours of thin films (style pbr)"},
        {"KHR_materials_anisotropy", "highlights stretched along brushed metal (style pbr)"},
        {"KHR_materials_diffuse_transmission",
         "light through lampshades, leaves and paper (style pbr)"},
        {"KHR_materials_transmission",
         "glass and clear plastic, refracting what lies behind them (style pbr)"},
        {"KHR_materials_volume",
         "the thickness and Beer-Lambert tint of transmitting volumes (style pbr)"},
        {"KHR_materials_dispersion",
         "the spread of colours through refraction, one index per channel (style pbr)"},
        {"KHR_materials_pbrSpecularGlossiness",
         "the older specular-glossiness material, drawn as the dielectric it describes"},
        {"KHR_lights_punctual", "the file's lights, for objects with `lights: true`"},
        {"EXT_texture_webp", "WebP textures, decoded by libwebp"},
        {"EXT_texture_avif", "AVIF textures, decoded by libavif"},
        {"EXT_mesh_gpu_instancing", "copies of a mesh, each with its own transform"},
        {"KHR_materials_variants",
         "a product's colourways, listed by `facet info` and chosen by `variant:` or --variant"},
    };
    return supported;
}

// What is lost when an extension is ignored, for the ones files often use.
std::string what_is_lost(const std::string& extension) {
    static const std::map<std::string, std::string> effects = {
        {"KHR_texture_basisu", "its KTX2 textures are not read"},
        {"KHR_animation_pointer", "its animations of materials, lights and cameras do not play"},
    };
    const auto it = effects.find(extension);
    return it == effects.end() ? "what it adds is not drawn" : it->second;
}

uint32_t little_endian(const char* bytes) {
    uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[i]);
    return value;
}

// The JSON text of a .gltf, or of a .glb's first chunk; "" when there is none.
std::string json_text(std::span<const uint8_t> bytes, const std::string& path) {
    const char* data = reinterpret_cast<const char*>(bytes.data());
    if (bytes.size() < 20 || std::memcmp(data, "glTF", 4) != 0)
        return std::string(data, bytes.size());  // a .gltf is JSON from its first byte
    // GLB: 12-byte header (magic, version, length), then a chunk: length,
    // type "JSON", data.
    if (little_endian(data + 4) == 1)
        bad(path, "is a glTF 1.0 binary (version 1 in its header); facet reads glTF 2.0 files");
    const uint32_t length = little_endian(data + 12);
    if (std::memcmp(data + 16, "JSON", 4) != 0 || length > bytes.size() - 20) return "";
    return std::string(data + 20, length);
}

std::vector<std::string> names(const nlohmann::json& doc, const char* key) {
    std::vector<std::string> list;
    if (!doc.contains(key) || !doc[key].is_array()) return list;
    for (const auto& item : doc[key])
        if (item.is_string()) list.push_back(item.get<std::string>());
    return list;
}

double finite_number(const tinygltf::Value& v, const std::string& path, const std::string& what) {
    if (!v.IsNumber()) bad(path, what + " is not a number");
    const double number = v.GetNumberAsDouble();
    if (!std::isfinite(number)) bad(path, what + " is not finite");
    return number;
}

glm::dvec2 pair_of(const tinygltf::Value& v, const std::string& path, const std::string& what) {
    if (!v.IsArray() || v.ArrayLen() != 2) bad(path, what + " must be an array of 2 numbers");
    return {finite_number(v.Get(0), path, what), finite_number(v.Get(1), path, what)};
}

}  // namespace

std::vector<uint8_t> with_json_rewritten(
    const std::vector<uint8_t>& file,
    const std::function<std::string(const std::string&)>& rewrite) {
    auto u32 = [&](size_t at) {
        uint32_t v = 0;
        for (int i = 3; i >= 0; --i) v = (v << 8) | file[at + static_cast<size_t>(i)];
        return v;
    };
    const bool glb = file.size() >= 20 && std::equal(file.begin(), file.begin() + 4, "glTF");
    if (!glb) {
        const std::string json = rewrite(std::string(file.begin(), file.end()));
        return std::vector<uint8_t>(json.begin(), json.end());
    }
    // GLB: a 12-byte header, then chunks of (length, type, data); the first is JSON.
    const uint32_t json_length = u32(12);
    if (!std::equal(file.begin() + 16, file.begin() + 20, "JSON") ||
        20 + static_cast<uint64_t>(json_length) > file.size())
        return file;  // tinygltf reports what is wrong
    std::string json = rewrite(std::string(file.begin() + 20, file.begin() + 20 + json_length));
    while (json.size() % 4) json += ' ';  // chunks stay 4-byte aligned
    std::vector<uint8_t> out(file.begin(), file.begin() + 12);
    auto put = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
    };
    put(static_cast<uint32_t>(json.size()));
    out.insert(out.end(), {'J', 'S', 'O', 'N'});
    out.insert(out.end(), json.begin(), json.end());
    out.insert(out.end(), file.begin() + 20 + json_length, file.end());
    const uint32_t total = static_cast<uint32_t>(out.size());
    for (int i = 0; i < 4; ++i)
        out[8 + static_cast<size_t>(i)] = static_cast<uint8_t>(total >> (8 * i));
    return out;
}

bool ExtensionLists::lists(const std::string& extension) const {
    return std::find(required.begin(), required.end(), extension) != required.end() ||
           std::find(used.begin(), used.end(), extension) != used.end();
}

ExtensionLists read_extension_lists(std::span<const uint8_t> bytes, const std::string& path) {
    const nlohmann::json doc = nlohmann::json::parse(json_text(bytes, path), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return {};
    check_field_types(doc, path);
    return {names(doc, "extensionsRequired"), names(doc, "extensionsUsed")};
}

ExtensionCheck check_extensions(const ExtensionLists& lists, const std::string& path,
                                std::vector<Error>* refusals) {
    const auto& supported = supported_extensions();
    ExtensionCheck check;
    auto required = [&](const std::string& name) {
        return std::find(lists.required.begin(), lists.required.end(), name) !=
               lists.required.end();
    };
    for (const std::string& name : lists.required) {
        if (supported.count(name)) continue;
        check.ignored.push_back(name);
        // KTX2 textures with PNG/JPEG fallbacks can still be drawn; that is
        // checked texture by texture once the file is parsed.
        if (name == "KHR_texture_basisu") continue;
        const Error refusal(ExitCode::invalid_input, path + ": requires the glTF extension " +
                                                         name + ", which facet does not support (" +
                                                         what_is_lost(name) + ")");
        if (!refusals) throw refusal;
        refusals->push_back(refusal);
    }
    for (const std::string& name : lists.used) {
        if (supported.count(name) || required(name)) continue;
        check.ignored.push_back(name);
        if (name == "KHR_texture_basisu") continue;
        check.warnings.push_back(file_warning(
            path,
            "uses the glTF extension " + name + ", which facet ignores: " + what_is_lost(name)));
    }
    return check;
}

UvMapping texture_mapping(const tinygltf::TextureInfo& info, const std::string& path,
                          const std::string& what) {
    UvMapping mapping;
    mapping.tex_coord = info.texCoord;
    const auto it = info.extensions.find("KHR_texture_transform");
    if (it == info.extensions.end()) return mapping;
    const tinygltf::Value& e = it->second;
    const std::string where = what + " KHR_texture_transform";
    if (!e.IsObject()) bad(path, where + " is not an object");
    glm::dvec2 offset(0.0), scale(1.0);
    double rotation = 0;
    if (e.Has("offset")) offset = pair_of(e.Get("offset"), path, where + " offset");
    if (e.Has("rotation")) rotation = finite_number(e.Get("rotation"), path, where + " rotation");
    if (e.Has("scale")) scale = pair_of(e.Get("scale"), path, where + " scale");
    mapping.transform = UvTransform::from_trs(offset, rotation, scale);
    if (e.Has("texCoord")) {
        const double set = finite_number(e.Get("texCoord"), path, where + " texCoord");
        if (set < 0 || set > 31 || set != std::floor(set))
            bad(path, where + " texCoord must be a whole number from 0 to 31");
        mapping.tex_coord = static_cast<int>(set);
    }
    return mapping;
}

}  // namespace facet::gltf_detail
