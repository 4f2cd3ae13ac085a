#include "assets/gltf_variants.hpp"

#include <algorithm>

#include "assets/gltf_accessors.hpp"
#include "core/plain_text.hpp"

namespace facet::gltf_detail {
namespace {

constexpr const char* kVariants = "KHR_materials_variants";

// "the file declares 3 variants: midnight, beach, street", for messages.
std::string declared(const std::vector<std::string>& names) {
    if (names.empty()) return "the file declares no variants";
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "'" : ", '") + name + "'";
    return "the file declares " + count_of(names.size(), "variant", "variants") + ": " + list;
}

}  // namespace

std::vector<std::string> read_variant_names(const tinygltf::Model& model, const std::string& path,
                                            Warnings* warnings) {
    std::vector<std::string> names;
    const auto extension = model.extensions.find(kVariants);
    if (extension == model.extensions.end() || !extension->second.Has("variants")) return names;
    const tinygltf::Value& variants = extension->second.Get("variants");
    for (size_t i = 0; i < variants.ArrayLen(); ++i) {
        const std::string name = variants.Get(static_cast<int>(i)).Get("name").Get<std::string>();
        if (warnings && std::find(names.begin(), names.end(), name) != names.end())
            warnings->push_back(file_warning(
                path, "extensions." + std::string(kVariants) + ".variants[" + std::to_string(i) +
                          "]: the variant '" + name +
                          "' is named twice: a variant is chosen by its name, so this one is "
                          "never drawn"));
        names.push_back(name);
    }
    return names;
}

std::vector<uint32_t> read_variant_materials(const tinygltf::Model& model,
                                             const tinygltf::Primitive& primitive,
                                             uint32_t material, const std::string& path,
                                             const std::string& what) {
    const auto extension = primitive.extensions.find(kVariants);
    if (extension == primitive.extensions.end()) return {};
    const std::vector<std::string> names = read_variant_names(model, path);
    std::vector<uint32_t> materials(names.size(), material);
    std::vector<bool> mapped(names.size(), false);
    const tinygltf::Value& mappings = extension->second.Get("mappings");
    for (size_t m = 0; m < mappings.ArrayLen(); ++m) {
        const tinygltf::Value& mapping = mappings.Get(static_cast<int>(m));
        const std::string key =
            what + ": extensions." + kVariants + ".mappings[" + std::to_string(m) + "]";
        const int mapped_material = mapping.Get("material").GetNumberAsInt();
        if (mapped_material < 0 || static_cast<size_t>(mapped_material) >= model.materials.size())
            bad(path, key + ".material refers to missing material " +
                          std::to_string(mapped_material) + " (the file has " +
                          count_of(model.materials.size(), "material", "materials") + ")");
        const tinygltf::Value& variants = mapping.Get("variants");
        for (size_t v = 0; v < variants.ArrayLen(); ++v) {
            const int variant = variants.Get(static_cast<int>(v)).GetNumberAsInt();
            const std::string at = key + ".variants[" + std::to_string(v) + "]";
            if (variant < 0 || static_cast<size_t>(variant) >= names.size())
                bad(path, at + " refers to missing variant " + std::to_string(variant) + " (" +
                              declared(names) + ")");
            const size_t index = static_cast<size_t>(variant);
            if (mapped[index])
                bad(path, at + ": the variant '" + names[index] +
                              "' is mapped a second time; a primitive maps each variant to one "
                              "material");
            mapped[index] = true;
            materials[index] = static_cast<uint32_t>(mapped_material);
        }
    }
    return materials;
}

}  // namespace facet::gltf_detail
