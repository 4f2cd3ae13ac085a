#include "assets/gltf_field_types.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <nlohmann/json.hpp>

#include "assets/gltf_accessors.hpp"
#include "core/plain_text.hpp"

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
                if (const json* extensions = object_if_present(primitive, "extensions", p))
                    if (const json* variants = object_if_present(
                            *extensions, "KHR_materials_variants", p + ".extensions"))
                        variant_mappings(*variants, p + ".extensions.KHR_materials_variants");
            });
        });
        variant_names(doc);
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
            if (const json* extensions = object_if_present(texture, "extensions", at))
                for (const auto& [name, extension] : extensions->items())
                    if (extension.is_object())
                        index_if_present(extension, "source", at + ".extensions." + name);
        });
        for_each_item(doc, "samplers", "", [&](const json& sampler, const std::string& at) {
            for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"})
                whole_if_present(sampler, key, at);
        });
        references(doc);
    }

    // Every other field that refers to an item by its index: the nodes,
    // scenes, accessors, buffer views, skins, animations and morph targets.
    void references(const json& doc) {
        index_if_present(doc, "scene", "");
        for_each_item(doc, "scenes", "", [&](const json& scene, const std::string& at) {
            index_list_if_present(scene, "nodes", at);
        });
        for_each_item(doc, "nodes", "", [&](const json& node, const std::string& at) {
            for (const char* key : {"camera", "skin", "mesh"}) index_if_present(node, key, at);
            index_list_if_present(node, "children", at);
            if (const json* extensions = object_if_present(node, "extensions", at)) {
                const std::string p = at + ".extensions";
                if (const json* light = object_if_present(*extensions, "KHR_lights_punctual", p))
                    index_if_present(*light, "light", p + ".KHR_lights_punctual");
                if (const json* instancing =
                        object_if_present(*extensions, "EXT_mesh_gpu_instancing", p))
                    index_map_if_present(*instancing, "attributes", p + ".EXT_mesh_gpu_instancing");
            }
        });
        for_each_item(doc, "meshes", "", [&](const json& mesh, const std::string& at) {
            for_each_item(mesh, "primitives", at, [&](const json& primitive, const std::string& p) {
                index_map_if_present(primitive, "attributes", p);
                for_each_item(primitive, "targets", p,
                              [&](const json& target, const std::string& t) {
                                  for (const auto& [name, value] : target.items())
                                      index_value(value, t + "." + name);
                              });
            });
        });
        for_each_item(doc, "accessors", "", [&](const json& accessor, const std::string& at) {
            index_if_present(accessor, "bufferView", at);
            if (const json* sparse = object_if_present(accessor, "sparse", at))
                sparse_accessor(accessor, *sparse, at + ".sparse");
        });
        for_each_item(doc, "bufferViews", "", [&](const json& view, const std::string& at) {
            index_if_present(view, "buffer", at);
        });
        for_each_item(doc, "skins", "", [&](const json& skin, const std::string& at) {
            index_if_present(skin, "inverseBindMatrices", at);
            index_if_present(skin, "skeleton", at);
            index_list_if_present(skin, "joints", at);
        });
        for_each_item(doc, "animations", "", [&](const json& animation, const std::string& at) {
            for_each_item(animation, "channels", at,
                          [&](const json& channel, const std::string& c) {
                              index_if_present(channel, "sampler", c);
                              if (const json* target = object_if_present(channel, "target", c))
                                  index_if_present(*target, "node", c + ".target");
                          });
            for_each_item(animation, "samplers", at,
                          [&](const json& sampler, const std::string& s) {
                              index_if_present(sampler, "input", s);
                              index_if_present(sampler, "output", s);
                          });
        });
    }

    // A sparse accessor: its count a whole number from 1 to the accessor's
    // count, and its indices and values in buffer views.
    void sparse_accessor(const json& accessor, const json& sparse, const std::string& at) {
        const auto count = sparse.find("count");
        if (count == sparse.end()) wrong(at + ".count", "present");
        index_value(*count, at + ".count");
        const auto total = accessor.find("count");
        if (total != accessor.end() && total->is_number_unsigned() &&
            (count->get<uint64_t>() < 1 || count->get<uint64_t>() > total->get<uint64_t>()))
            wrong(at + ".count",
                  "from 1 to the accessor's count (" + total->dump() + "), not " + count->dump());
        for (const char* part : {"indices", "values"}) {
            const json* p = object_if_present(sparse, part, at);
            if (!p) wrong(at + "." + part, "present");
            if (!p->contains("bufferView")) wrong(at + "." + part + ".bufferView", "present");
            index_if_present(*p, "bufferView", at + "." + part);
        }
    }

    // KHR_materials_variants at the file's root: a list of variants, each
    // with a name.
    void variant_names(const json& doc) {
        const auto extensions = doc.find("extensions");
        if (extensions == doc.end()) return;
        if (!extensions->is_object()) wrong("extensions", "an object");
        const json* root = object_if_present(*extensions, "KHR_materials_variants", "extensions");
        if (!root) return;
        const std::string at = "extensions.KHR_materials_variants";
        if (!root->contains("variants")) wrong(at + ".variants", "present");
        for_each_item(*root, "variants", at, [&](const json& variant, const std::string& v) {
            const auto name = variant.find("name");
            if (name == variant.end() || !name->is_string()) wrong(v + ".name", "a string");
        });
    }

    // A primitive's KHR_materials_variants: mappings, each of a material to
    // a list of variants.
    void variant_mappings(const json& extension, const std::string& at) {
        if (!extension.contains("mappings")) wrong(at + ".mappings", "present");
        for_each_item(extension, "mappings", at, [&](const json& mapping, const std::string& m) {
            for (const char* key : {"material", "variants"})
                if (!mapping.contains(key)) wrong(m + "." + key, "present");
            index_if_present(mapping, "material", m);
            index_list_if_present(mapping, "variants", m);
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

    // An index: a whole number from 0 to the largest tinygltf keeps
    // (2^31 - 1). A larger one would wrap to a valid index.
    void index_value(const json& value, const std::string& field) {
        if (!value.is_number_unsigned() ||
            value.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int32_t>::max()))
            wrong(field, "an index (a whole number from 0 to 2147483647), not " +
                             text_for_message(value.dump()));
    }

    void index_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it != parent.end()) index_value(*it, (at.empty() ? "" : at + ".") + key);
    }

    void index_list_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it == parent.end()) return;
        const std::string field = (at.empty() ? "" : at + ".") + key;
        if (!it->is_array()) wrong(field, "a list of indices");
        for (size_t i = 0; i < it->size(); ++i)
            index_value((*it)[i], field + "[" + std::to_string(i) + "]");
    }

    // A mapping of names to indices (a primitive's attributes).
    void index_map_if_present(const json& parent, const char* key, const std::string& at) {
        const json* map = object_if_present(parent, key, at);
        if (!map) return;
        for (const auto& [name, value] : map->items())
            index_value(value, at + "." + key + "." + name);
    }

    // A whole number (an enum such as a sampler's filter): tinygltf drops
    // a value of another type without a word.
    void whole_if_present(const json& parent, const char* key, const std::string& at) {
        const auto it = parent.find(key);
        if (it != parent.end() && !it->is_number_integer())
            wrong(at + "." + key, "a whole number, not " + text_for_message(it->dump()));
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
            color_if_present(*specular, "specularColorFactor", p);
        }
        if (const json* coat = object_if_present(extensions, "KHR_materials_clearcoat", at)) {
            const std::string p = at + ".KHR_materials_clearcoat";
            number_if_present(*coat, "clearcoatFactor", p);
            number_if_present(*coat, "clearcoatRoughnessFactor", p);
            texture_info(*coat, "clearcoatTexture", p);
            texture_info(*coat, "clearcoatRoughnessTexture", p);
            texture_info(*coat, "clearcoatNormalTexture", p, "scale");
        }
        if (const json* gloss =
                object_if_present(extensions, "KHR_materials_pbrSpecularGlossiness", at)) {
            const std::string p = at + ".KHR_materials_pbrSpecularGlossiness";
            color_if_present(*gloss, "diffuseFactor", p, 4);
            color_if_present(*gloss, "specularFactor", p);
            number_if_present(*gloss, "glossinessFactor", p);
            texture_info(*gloss, "diffuseTexture", p);
            texture_info(*gloss, "specularGlossinessTexture", p);
        }
        if (const json* film = object_if_present(extensions, "KHR_materials_iridescence", at)) {
            const std::string p = at + ".KHR_materials_iridescence";
            for (const char* key : {"iridescenceFactor", "iridescenceIor",
                                    "iridescenceThicknessMinimum", "iridescenceThicknessMaximum"})
                number_if_present(*film, key, p);
            texture_info(*film, "iridescenceTexture", p);
            texture_info(*film, "iridescenceThicknessTexture", p);
        }
        if (const json* sheen = object_if_present(extensions, "KHR_materials_sheen", at)) {
            const std::string p = at + ".KHR_materials_sheen";
            color_if_present(*sheen, "sheenColorFactor", p);
            number_if_present(*sheen, "sheenRoughnessFactor", p);
            texture_info(*sheen, "sheenColorTexture", p);
            texture_info(*sheen, "sheenRoughnessTexture", p);
        }
        number_and_map_extensions(extensions, at);
    }

    // The layers read by numbers, colours and maps alone:
    // KHR_materials_transmission, _volume, _dispersion, _anisotropy and
    // _diffuse_transmission.
    void number_and_map_extensions(const json& extensions, const std::string& at) {
        struct Fields {
            const char* extension;
            std::initializer_list<const char*> numbers, colors, maps;
        };
        const Fields all[] = {
            {"KHR_materials_transmission", {"transmissionFactor"}, {}, {"transmissionTexture"}},
            {"KHR_materials_volume",
             {"thicknessFactor", "attenuationDistance"},
             {"attenuationColor"},
             {"thicknessTexture"}},
            {"KHR_materials_dispersion", {"dispersion"}, {}, {}},
            {"KHR_materials_anisotropy",
             {"anisotropyStrength", "anisotropyRotation"},
             {},
             {"anisotropyTexture"}},
            {"KHR_materials_diffuse_transmission",
             {"diffuseTransmissionFactor"},
             {"diffuseTransmissionColorFactor"},
             {"diffuseTransmissionTexture", "diffuseTransmissionColorTexture"}},
        };
        for (const Fields& f : all) {
            const json* e = object_if_present(extensions, f.extension, at);
            if (!e) continue;
            const std::string p = at + "." + f.extension;
            for (const char* key : f.numbers) number_if_present(*e, key, p);
            for (const char* key : f.colors) color_if_present(*e, key, p);
            for (const char* key : f.maps) texture_info(*e, key, p);
        }
    }

    // An RGB (or, with `count` 4, RGBA) factor: a list of numbers.
    void color_if_present(const json& object, const char* key, const std::string& at,
                          size_t count = 3) {
        const auto color = object.find(key);
        if (color != object.end() && !(color->is_array() && color->size() == count &&
                                       std::all_of(color->begin(), color->end(),
                                                   [](const json& c) { return c.is_number(); })))
            wrong(at + "." + key, "a list of " + std::to_string(count) + " numbers");
    }

    const std::string& path_;
};

}  // namespace

void check_field_types(const json& doc, const std::string& path) {
    if (doc.is_object()) FieldTypes(path).document(doc);
}

}  // namespace facet::gltf_detail
