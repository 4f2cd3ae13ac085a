#include "assets/gltf_field_types.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "assets/gltf_accessors.hpp"

namespace facet::gltf_detail {
namespace {

using nlohmann::json;

// The checks of one file: each names the field by its path in the JSON.
class FieldTypes {
  public:
    explicit FieldTypes(const std::string& path) : path_(path) {}

    void document(const json& doc) {
        // glTF 1.0 keeps its meshes and materials in mappings by name.
        const auto asset = doc.find("asset");
        if (asset != doc.end() && asset->is_object()) {
            const auto version = asset->find("version");
            if (version != asset->end() && version->is_string() &&
                version->get<std::string>().rfind("1.", 0) == 0)
                bad(path_, "is glTF " + version->get<std::string>() +
                               " (asset.version); facet reads glTF 2.0 files");
        }
        const auto meshes = doc.find("meshes");
        if (meshes != doc.end() && meshes->is_object())
            bad(path_,
                "keeps its meshes in a mapping by name, as glTF 1.0 did; facet reads "
                "glTF 2.0 files");
        for_each_item(doc, "meshes", "", [&](const json& mesh, const std::string& at) {
            for_each_item(mesh, "primitives", at, [&](const json& primitive, const std::string& p) {
                object_if_present(primitive, "attributes", p);
                index_if_present(primitive, "indices", p);
                index_if_present(primitive, "material", p);
            });
        });
        for_each_item(doc, "materials", "", [&](const json& material, const std::string& at) {
            if (const json* pbr = object_if_present(material, "pbrMetallicRoughness", at)) {
                const std::string p = at + ".pbrMetallicRoughness";
                texture_info(*pbr, "baseColorTexture", p);
                texture_info(*pbr, "metallicRoughnessTexture", p);
                number_if_present(*pbr, "metallicFactor", p);
                number_if_present(*pbr, "roughnessFactor", p);
            }
            texture_info(material, "normalTexture", at, "scale");
            texture_info(material, "occlusionTexture", at, "strength");
            texture_info(material, "emissiveTexture", at);
            if (const json* extensions = object_if_present(material, "extensions", at))
                material_extensions(*extensions, at + ".extensions");
        });
        for_each_item(doc, "textures", "", [&](const json& texture, const std::string& at) {
            index_if_present(texture, "source", at);
            index_if_present(texture, "sampler", at);
        });
    }

  private:
    [[noreturn]] void wrong(const std::string& field, const std::string& should) const {
        bad(path_, field + " must be " + should);
    }

    // Calls visit(item, "key[i]") for every item of an optional list.
    template <typename Visit>
    void for_each_item(const json& parent, const char* key, const std::string& at, Visit&& visit) {
        const auto it = parent.find(key);
        if (it == parent.end()) return;
        const std::string field = (at.empty() ? "" : at + ".") + key;
        if (!it->is_array()) wrong(field, "a list");
        for (size_t i = 0; i < it->size(); ++i) {
            const std::string item = field + "[" + std::to_string(i) + "]";
            if (!(*it)[i].is_object()) wrong(item, "an object");
            visit((*it)[i], item);
        }
    }

    const json* object_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it == parent.end()) return nullptr;
        if (!it->is_object()) wrong(at + "." + key, "an object");
        return &*it;
    }

    void index_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it != parent.end() && !it->is_number_unsigned())
            wrong(at + "." + key, "an index (a whole number from 0), not " + it->dump());
    }

    void number_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it != parent.end() && !it->is_number()) wrong(at + "." + key, "a number");
    }

    // A textureInfo: its index, texCoord, scale or strength, and
    // KHR_texture_transform, which facet reads.
    void texture_info(const json& parent, const char* key, const std::string& at,
                      const char* factor = nullptr) {
        const json* info = object_if_present(parent, key, at);
        if (!info) return;
        const std::string p = at + "." + key;
        if (!info->contains("index")) wrong(p + ".index", "present");
        index_if_present(*info, "index", p);
        index_if_present(*info, "texCoord", p);
        if (factor) number_if_present(*info, factor, p);
        if (const json* extensions = object_if_present(*info, "extensions", p))
            object_if_present(*extensions, "KHR_texture_transform", p + ".extensions");
    }

    // The material extensions whose fields facet draws from.
    void material_extensions(const json& extensions, const std::string& at) {
        if (const json* ior = object_if_present(extensions, "KHR_materials_ior", at))
            number_if_present(*ior, "ior", at + ".KHR_materials_ior");
        if (const json* specular = object_if_present(extensions, "KHR_materials_specular", at)) {
            const std::string p = at + ".KHR_materials_specular";
            number_if_present(*specular, "specularFactor", p);
            texture_info(*specular, "specularTexture", p);
            texture_info(*specular, "specularColorTexture", p);
            const auto color = specular->find("specularColorFactor");
            if (color != specular->end() &&
                !(color->is_array() && color->size() == 3 &&
                  std::all_of(color->begin(), color->end(),
                              [](const json& c) { return c.is_number(); })))
                wrong(p + ".specularColorFactor", "a list of 3 numbers");
        }
        if (const json* coat = object_if_present(extensions, "KHR_materials_clearcoat", at)) {
            const std::string p = at + ".KHR_materials_clearcoat";
            number_if_present(*coat, "clearcoatFactor", p);
            number_if_present(*coat, "clearcoatRoughnessFactor", p);
            texture_info(*coat, "clearcoatTexture", p);
            texture_info(*coat, "clearcoatRoughnessTexture", p);
            texture_info(*coat, "clearcoatNormalTexture", p, "scale");
        }
    }

    const std::string& path_;
};

}  // namespace

void check_field_types(const json& doc, const std::string& path) {
    if (doc.is_object()) FieldTypes(path).document(doc);
}

}  // namespace facet::gltf_detail
