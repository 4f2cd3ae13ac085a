#include "assets/gltf_materials.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>

#include "assets/gltf_accessors.hpp"
#include "assets/gltf_extensions.hpp"
#include "assets/image_decode.hpp"

namespace facet::gltf_detail {
namespace {

// glTF sampler enums (§5.26, the OpenGL values).
constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kNearestMipmapNearest = 9984, kLinearMipmapNearest = 9985;
constexpr int kNearestMipmapLinear = 9986, kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071, kMirroredRepeat = 33648, kRepeat = 10497;

Wrap wrap_of(int mode, const std::string& path, const std::string& what) {
    if (mode == kClampToEdge) return Wrap::clamp;
    if (mode == kMirroredRepeat) return Wrap::mirror;
    if (mode == kRepeat || mode == -1) return Wrap::repeat;
    bad(path, what + ": wrap mode " + std::to_string(mode) +
                  " is not 33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 (REPEAT)");
}

// The sampler as the file gives it; what it leaves out keeps facet's
// defaults (linear filters, trilinear minification).
Sampler sampler_of(const tinygltf::Model& model, int index, const std::string& path) {
    Sampler s;
    if (index < 0) return s;
    if (static_cast<size_t>(index) >= model.samplers.size())
        bad(path, "texture refers to missing sampler " + std::to_string(index));
    const tinygltf::Sampler& g = model.samplers[static_cast<size_t>(index)];
    const std::string what = "sampler " + std::to_string(index);
    s.wrap_s = wrap_of(g.wrapS, path, what + " wrapS");
    s.wrap_t = wrap_of(g.wrapT, path, what + " wrapT");
    if (g.magFilter == kNearest) s.mag = Filter::nearest;
    switch (g.minFilter) {
        case kNearest:
            s.min = Filter::nearest, s.mipmaps = false;
            break;
        case kLinear:
            s.min = Filter::linear, s.mipmaps = false;
            break;
        case kNearestMipmapNearest:
            s.min = Filter::nearest, s.mip = Filter::nearest;
            break;
        case kLinearMipmapNearest:
            s.min = Filter::linear, s.mip = Filter::nearest;
            break;
        case kNearestMipmapLinear:
            s.min = Filter::nearest, s.mip = Filter::linear;
            break;
        case kLinearMipmapLinear:
        default:
            break;
    }
    return s;
}

// The image an extension of a texture names as its source (-1 when none).
int extension_source(const tinygltf::Texture& t, const char* extension) {
    const auto it = t.extensions.find(extension);
    if (it == t.extensions.end() || !it->second.Has("source")) return -1;
    const tinygltf::Value& v = it->second.Get("source");
    return v.IsNumber() ? static_cast<int>(v.GetNumberAsDouble()) : -1;
}

// A texture's images in the order facet tries them: the formats the
// extensions add first (what a reader that has them is meant to show),
// then the core PNG/JPEG `source`, their fallback.
std::vector<int> image_choices(const tinygltf::Texture& t) {
    std::vector<int> choices;
    for (const char* extension : {"EXT_texture_avif", "EXT_texture_webp"})
        if (const int image = extension_source(t, extension); image >= 0) choices.push_back(image);
    if (t.source >= 0) choices.push_back(t.source);
    return choices;
}

// Decodes each image once, and each texture (an image with a sampler)
// once; failures are kept as reasons, so each is reported per map.
class TextureCache {
  public:
    TextureCache(const tinygltf::Model& model, const std::string& path, const UnreadImages& unread,
                 TextureBudget* budget)
        : model_(model), path_(path), unread_(unread), budget_(budget) {}

    // A texture as read: null with `lost` saying why, or drawn, `lost`
    // then saying why its preferred image gave way to a fallback (empty
    // when none did). Kept, so every material that reads it is told.
    struct Read {
        std::shared_ptr<const Texture> texture;
        std::string lost;
    };
    const Read& texture(int index);

  private:
    std::shared_ptr<const Texture> image(int index, std::string& lost);

    const tinygltf::Model& model_;
    const std::string& path_;
    const UnreadImages& unread_;
    TextureBudget* budget_;
    std::map<int, std::shared_ptr<const Texture>> images_;
    std::map<int, Read> textures_;
    std::map<int, std::string> image_errors_;
};

std::shared_ptr<const Texture> TextureCache::image(int index, std::string& lost) {
    if (index < 0 || static_cast<size_t>(index) >= model_.images.size())
        bad(path_, "texture refers to missing image " + std::to_string(index));
    if (const auto it = images_.find(index); it != images_.end()) return it->second;
    if (const auto it = image_errors_.find(index); it != image_errors_.end()) {
        lost = it->second;
        return nullptr;
    }
    const tinygltf::Image& img = model_.images[static_cast<size_t>(index)];
    const std::string name =
        "image " + std::to_string(index) + (img.uri.empty() ? std::string() : " '" + img.uri + "'");
    if (img.image.empty()) {
        const auto reason = unread_.find(img.uri);
        lost = reason != unread_.end() ? reason->second : name + " has no data";
        image_errors_[index] = lost;
        return nullptr;
    }
    try {
        auto texture = std::make_shared<const Texture>(
            decode_texture(img.image.data(), img.image.size(), path_ + " " + name, budget_));
        images_[index] = texture;
        return texture;
    } catch (const UndecodableImage& e) {
        // Limits (size, budget) protect the run: they stay errors.
        lost = e.what();
        image_errors_[index] = lost;
        return nullptr;
    }
}

const TextureCache::Read& TextureCache::texture(int index) {
    if (index < 0 || static_cast<size_t>(index) >= model_.textures.size())
        bad(path_, "material refers to missing texture " + std::to_string(index));
    if (const auto it = textures_.find(index); it != textures_.end()) return it->second;
    const tinygltf::Texture& t = model_.textures[static_cast<size_t>(index)];
    const std::vector<int> choices = image_choices(t);
    Read read;
    std::shared_ptr<const Texture> decoded;
    for (const int choice : choices) {
        std::string why;
        decoded = image(choice, why);
        if (decoded) break;
        read.lost += (read.lost.empty() ? "" : "; ") + why;
    }
    if (choices.empty())
        read.lost = t.extensions.count("KHR_texture_basisu")
                        ? "KTX2 (KHR_texture_basisu) is not supported, and the texture has no "
                          "PNG/JPEG fallback"
                        : "the texture has no image";
    if (decoded) {
        auto copy = std::make_shared<Texture>(*decoded);  // shares the levels
        copy->sampler = sampler_of(model_, t.sampler, path_);
        read.texture = copy;
    }
    return textures_[index] = read;
}

// The slot a textureInfo fills: its texture, set and transform. A lost
// texture leaves the slot empty, with a warning naming the map and, in
// `without`, how the material is drawn then.
TextureSlot slot_of(const tinygltf::TextureInfo& info, TextureCache& cache, const std::string& path,
                    const std::string& what, Warnings& warnings,
                    const std::string& without = "drawn without it") {
    TextureSlot slot;
    if (info.index < 0) return slot;
    const UvMapping mapping = texture_mapping(info, path, what);
    const TextureCache::Read& read = cache.texture(info.index);
    slot.texture = read.texture;
    if (!slot.texture) {
        warnings.push_back(file_warning(path, what + ": " + read.lost + "; " + without));
        return slot;
    }
    if (!read.lost.empty())
        warnings.push_back(
            file_warning(path, what + ": " + read.lost + "; its fallback image is drawn instead"));
    slot.transform = mapping.transform;
    slot.uv_set = mapping.tex_coord;
    if (slot.uv_set > 1) {
        warnings.push_back(file_warning(path, what + " reads TEXCOORD_" +
                                                  std::to_string(slot.uv_set) +
                                                  "; facet reads sets 0 and 1, so set 0 is used"));
        slot.uv_set = 0;
    }
    return slot;
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

// A Phong reading of metal/roughness: smoother surfaces get tighter,
// stronger highlights (documented in docs/scene-format.md).
void phong_from_roughness(double roughness_factor, Material& mat) {
    const float roughness = static_cast<float>(std::clamp(roughness_factor, 0.05, 1.0));
    mat.shininess =
        std::min(2.0f / (roughness * roughness * roughness * roughness) - 2.0f, 2048.0f);
    mat.shininess = std::max(mat.shininess, 1.0f);
    mat.specular = 0.15f + 0.6f * (1.0f - roughness);
}

void read_alpha(const tinygltf::Material& m, const std::string& path, Material& mat) {
    const auto& pbr = m.pbrMetallicRoughness;
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
}

Material read_material(const tinygltf::Material& m, size_t index, TextureCache& cache,
                       const std::string& path, Warnings& warnings) {
    Material mat;
    mat.name = m.name;
    const std::string what =
        "material " + (m.name.empty() ? std::to_string(index) : "'" + m.name + "'");
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
        mat.color = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
    mat.base_color_map =
        slot_of(pbr.baseColorTexture, cache, path, what + " baseColorTexture", warnings);
    phong_from_roughness(pbr.roughnessFactor, mat);
    mat.double_sided = m.doubleSided;
    mat.emissive = emission(m, path);
    // A map under a zero factor shows nothing: it is not decoded. Without
    // its map, the factor alone would glow all over (a white silhouette
    // where the map lit a few lamps), so a lost map takes the emission.
    if (mat.emissive != glm::vec3(0) && m.emissiveTexture.index >= 0) {
        mat.emissive_map = slot_of(m.emissiveTexture, cache, path, what + " emissiveTexture",
                                   warnings, "its emission is not drawn");
        if (!mat.emissive_map) mat.emissive = glm::vec3(0);
    }
    read_alpha(m, path, mat);
    mat.unlit = m.extensions.count("KHR_materials_unlit") > 0;
    return mat;
}

// The maps a material has that facet's shading does not draw.
std::vector<std::string> undrawn_maps(const tinygltf::Material& m) {
    std::vector<std::string> maps;
    if (m.normalTexture.index >= 0) maps.push_back("normalTexture");
    if (m.occlusionTexture.index >= 0) maps.push_back("occlusionTexture");
    if (m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
        maps.push_back("metallicRoughnessTexture");
    return maps;
}

}  // namespace

std::vector<Material> read_materials(const tinygltf::Model& model, const std::string& path,
                                     const UnreadImages& unread, TextureBudget* budget,
                                     Warnings& warnings) {
    TextureCache cache(model, path, unread, budget);
    std::vector<Material> materials;
    std::set<std::string> undrawn;
    std::vector<std::string> with_undrawn;
    for (size_t i = 0; i < model.materials.size(); ++i) {
        materials.push_back(read_material(model.materials[i], i, cache, path, warnings));
        const std::vector<std::string> maps = undrawn_maps(model.materials[i]);
        undrawn.insert(maps.begin(), maps.end());
        if (!maps.empty())
            with_undrawn.push_back(model.materials[i].name.empty()
                                       ? std::to_string(i)
                                       : "'" + model.materials[i].name + "'");
    }
    if (!undrawn.empty()) {
        std::string maps, names;
        for (const std::string& map : undrawn) maps += (maps.empty() ? "" : ", ") + map;
        for (size_t i = 0; i < with_undrawn.size() && i < 3; ++i)
            names += (i ? ", " : "") + with_undrawn[i];
        if (with_undrawn.size() > 3)
            names += " and " + std::to_string(with_undrawn.size() - 3) + " more";
        warnings.push_back(file_warning(
            path, std::string(with_undrawn.size() == 1 ? "material " : "materials ") + names +
                      " have maps facet does not draw (" + maps +
                      "; their files are not read): surface detail, occlusion and metal are "
                      "lost, and metal and roughness factors become a Phong highlight"));
    }
    return materials;
}

void check_basisu_fallbacks(const tinygltf::Model& model, const std::string& path, bool required,
                            Warnings& warnings) {
    size_t ktx2 = 0;
    for (size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& t = model.textures[i];
        if (!t.extensions.count("KHR_texture_basisu")) continue;
        ++ktx2;
        if (required && image_choices(t).empty())
            bad(path, "texture " + std::to_string(i) +
                          ": KTX2 (KHR_texture_basisu) is not supported; the file has no "
                          "PNG/JPEG fallback");
    }
    if (ktx2 > 0)
        warnings.push_back(
            file_warning(path, "uses KHR_texture_basisu: KTX2 images are not supported, so " +
                                   std::to_string(ktx2) + " texture" + (ktx2 == 1 ? "" : "s") +
                                   " are drawn from their PNG/JPEG fallback where they have one"));
}

}  // namespace facet::gltf_detail
