#include "assets/gltf_materials.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

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
        // NEAREST within the mipmaps is an exporter's default (OpenGL's
        // minFilter default, COLLADA2GLTF's output), not an author's choice:
        // taken at its word it point-samples every minified pixel into
        // stair steps. Unless the file magnifies by NEAREST too (pixel art),
        // the levels are read linearly, as Blender's importer and VTK read
        // them and as GPUs filter under anisotropic filtering.
        case kNearestMipmapNearest:
            s.min = s.mag, s.mip = Filter::nearest;
            break;
        case kLinearMipmapNearest:
            s.min = Filter::linear, s.mip = Filter::nearest;
            break;
        case kNearestMipmapLinear:
            s.min = s.mag, s.mip = Filter::linear;
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
                 TextureBudget* budget, bool basisu_required)
        : model_(model),
          path_(path),
          unread_(unread),
          budget_(budget),
          basisu_required_(basisu_required) {}

    // A texture as read: null with `lost` saying why, or drawn, `lost`
    // then saying why its preferred image gave way to a fallback (empty
    // when none did). Kept, so every material that reads it is told.
    // `refused`: a KTX2 texture without a fallback in a file that requires
    // KHR_texture_basisu, which a render refuses (check_basisu_fallbacks).
    struct Read {
        std::shared_ptr<const Texture> texture;
        std::string lost;
        bool refused = false;
    };
    const Read& texture(int index);
    // The same texture read as data (Texture::as_data): normal,
    // metallic-roughness and occlusion maps hold numbers, not colours.
    const Read& data_texture(int index);

  private:
    std::shared_ptr<const Texture> image(int index, std::string& lost);

    const tinygltf::Model& model_;
    const std::string& path_;
    const UnreadImages& unread_;
    TextureBudget* budget_;
    bool basisu_required_;
    std::map<int, std::shared_ptr<const Texture>> images_;
    std::map<int, Read> textures_;
    std::map<int, Read> data_textures_;
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
    if (choices.empty()) {
        const bool ktx2 = t.extensions.count("KHR_texture_basisu") > 0;
        read.lost = ktx2 ? "KTX2 (KHR_texture_basisu) is not supported, and the texture has no "
                           "PNG/JPEG fallback"
                         : "the texture has no image";
        read.refused = ktx2 && basisu_required_;
    }
    if (decoded) {
        auto copy = std::make_shared<Texture>(*decoded);  // shares the levels
        copy->sampler = sampler_of(model_, t.sampler, path_);
        read.texture = copy;
    }
    return textures_[index] = read;
}

const TextureCache::Read& TextureCache::data_texture(int index) {
    if (const auto it = data_textures_.find(index); it != data_textures_.end()) return it->second;
    Read read = texture(index);
    if (read.texture) read.texture = std::make_shared<const Texture>(read.texture->as_data());
    return data_textures_[index] = read;
}

// How a map's texels are read.
enum class TexelMeaning { colour, data };

// The slot a textureInfo fills: its texture, set and transform. A lost
// texture leaves the slot empty, with a warning naming the map and, in
// `without`, how the material is drawn then.
TextureSlot slot_of(const tinygltf::TextureInfo& info, TextureCache& cache, const std::string& path,
                    const std::string& what, Warnings& warnings,
                    const std::string& without = "drawn without it",
                    TexelMeaning meaning = TexelMeaning::colour) {
    TextureSlot slot;
    if (info.index < 0) return slot;
    const UvMapping mapping = texture_mapping(info, path, what);
    const TextureCache::Read& read =
        meaning == TexelMeaning::data ? cache.data_texture(info.index) : cache.texture(info.index);
    slot.texture = read.texture;
    if (!slot.texture) {
        // A refused texture is not drawn without: the file is not drawn.
        if (!read.refused)
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

// A textureInfo inside an extension (which tinygltf leaves as a Value):
// its index, texCoord and KHR_texture_transform. The field types were
// checked before (gltf_field_types.hpp).
tinygltf::TextureInfo texture_info_of(const tinygltf::Value& extension, const char* key) {
    tinygltf::TextureInfo info;
    if (!extension.Has(key)) return info;
    const tinygltf::Value& v = extension.Get(key);
    if (v.Has("index")) info.index = static_cast<int>(v.Get("index").GetNumberAsDouble());
    if (v.Has("texCoord")) info.texCoord = static_cast<int>(v.Get("texCoord").GetNumberAsDouble());
    if (v.Has("extensions") && v.Get("extensions").Has("KHR_texture_transform"))
        info.extensions["KHR_texture_transform"] = v.Get("extensions").Get("KHR_texture_transform");
    return info;
}

// An extension's map: its textureInfo at `key`, named in messages as the
// material's `key`.
TextureSlot extension_map(const tinygltf::Value& extension, const char* key, TextureCache& cache,
                          const std::string& path, const std::string& what, Warnings& warnings,
                          const std::string& without = "drawn without it",
                          TexelMeaning meaning = TexelMeaning::colour) {
    return slot_of(texture_info_of(extension, key), cache, path, what + " " + key, warnings,
                   without, meaning);
}

// A bound as a message writes it: 1, 10, 0.5 (std::to_string gives
// "10.000000", and cutting that short gave "10.").
std::string bound_text(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
}

// A number of an extension, `fallback` when absent; outside [low, high]
// (or not finite) it is an error naming the material and the field.
float extension_number(const tinygltf::Value& extension, const char* key, float fallback,
                       double low, double high, const std::string& path, const std::string& what) {
    if (!extension.Has(key)) return fallback;
    const double v = extension.Get(key).GetNumberAsDouble();
    if (!(v >= low && v <= high))
        bad(path,
            what + ": " + key + " must be from " + bound_text(low) + " to " + bound_text(high));
    return static_cast<float>(v);
}

// An extension's RGB factor (its fields' types are checked before, in
// gltf_field_types.cpp), each number from 0 to `high`.
glm::vec3 extension_color(const tinygltf::Value& extension, const char* key, glm::vec3 fallback,
                          double high, const std::string& path, const std::string& what) {
    if (!extension.Has(key)) return fallback;
    const tinygltf::Value& c = extension.Get(key);
    glm::vec3 color;
    for (int a = 0; a < 3; ++a) {
        const double v = c.Get(a).GetNumberAsDouble();
        if (!(v >= 0 && v <= high))
            bad(path, what + ": " + key + " must hold numbers from 0 to " + bound_text(high));
        color[a] = static_cast<float>(v);
    }
    return color;
}

// A normal or occlusion textureInfo as the plain one slot_of reads (the
// scale and strength are read apart).
template <typename Info>
tinygltf::TextureInfo plain_info(const Info& info) {
    tinygltf::TextureInfo plain;
    plain.index = info.index;
    plain.texCoord = info.texCoord;
    plain.extensions = info.extensions;
    return plain;
}

// glTF's metallic-roughness terms (§3.9.2) and its normal and occlusion
// maps (§3.9.3, §3.9.4), read as data.
// Marks the material as metallic-roughness (the Phong family reads it
// through shade/metal_rough_phong.hpp) and gives the stylised models'
// highlight: smoother surfaces get tighter, stronger highlights
// (documented in docs/scene-format.md).
void phong_from_roughness(double roughness_factor, Material& mat) {
    mat.metal_rough = true;
    const float roughness = static_cast<float>(std::clamp(roughness_factor, 0.05, 1.0));
    mat.shininess = roughness_exponent(roughness);
    mat.specular = 0.15f + 0.6f * (1.0f - roughness);
}

// The core material's pbrMetallicRoughness: base colour, metal and roughness.
void read_metal_rough(const tinygltf::Material& m, TextureCache& cache, const std::string& path,
                      const std::string& what, Warnings& warnings, Material& mat) {
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
        mat.color = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
    mat.base_color_map =
        slot_of(pbr.baseColorTexture, cache, path, what + " baseColorTexture", warnings);
    phong_from_roughness(pbr.roughnessFactor, mat);
    if (!(pbr.metallicFactor >= 0 && pbr.metallicFactor <= 1))
        bad(path, what + ": metallicFactor must be from 0 to 1");
    if (!(pbr.roughnessFactor >= 0 && pbr.roughnessFactor <= 1))
        bad(path, what + ": roughnessFactor must be from 0 to 1");
    mat.metallic = static_cast<float>(pbr.metallicFactor);
    mat.roughness = static_cast<float>(pbr.roughnessFactor);
    mat.metal_rough_map =
        slot_of(pbr.metallicRoughnessTexture, cache, path, what + " metallicRoughnessTexture",
                warnings, "drawn with its factors alone", TexelMeaning::data);
}

// KHR_materials_pbrSpecularGlossiness (archived), in place of
// pbrMetallicRoughness, which such a file gives only as a fallback: the
// dielectric it describes (Material::specular_glossiness_map says how).
// The `pbr` model's f0 is f0(ior) * specular_color, 0.04 * specular_color
// at the default ior of 1.5, so specular_color is s / 0.04.
void read_specular_glossiness(const tinygltf::Value& e, TextureCache& cache,
                              const std::string& path, const std::string& what, Warnings& warnings,
                              Material& mat) {
    if (e.Has("diffuseFactor")) {
        const tinygltf::Value& d = e.Get("diffuseFactor");
        for (int a = 0; a < 4; ++a) {
            const double v = d.Get(a).GetNumberAsDouble();
            if (!(v >= 0 && v <= 1))
                bad(path, what + ": diffuseFactor must hold numbers from 0 to 1");
            if (a < 3) mat.color[a] = static_cast<float>(v);
        }
        mat.alpha = static_cast<float>(d.Get(3).GetNumberAsDouble());
    } else {
        mat.color = glm::vec3(1.0f), mat.alpha = 1.0f;
    }
    mat.base_color_map = extension_map(e, "diffuseTexture", cache, path, what, warnings);
    mat.specular_factor = extension_color(e, "specularFactor", glm::vec3(1.0f), 1.0, path, what);
    mat.glossiness_factor = extension_number(e, "glossinessFactor", 1.0f, 0.0, 1.0, path, what);
    mat.specular_glossiness_map =
        extension_map(e, "specularGlossinessTexture", cache, path, what, warnings,
                      "drawn with its specularFactor and glossinessFactor");
    mat.metallic = 0.0f;
    mat.ior = 1.5f;
    mat.specular_weight = 1.0f;
    mat.specular_color = mat.specular_factor / 0.04f;
    mat.roughness = 1.0f - mat.glossiness_factor;
    phong_from_roughness(mat.roughness, mat);
    if (mat.specular_glossiness_map) return;  // the map's step applies the factors per texel
    const glm::vec3& s = mat.specular_factor;
    mat.color *= 1.0f - std::max({s.x, s.y, s.z});
}

// The maps every material has: normals and occlusion.
void read_normal_and_occlusion(const tinygltf::Material& m, TextureCache& cache,
                               const std::string& path, const std::string& what, Warnings& warnings,
                               Material& mat) {
    const TexelMeaning data = TexelMeaning::data;
    mat.normal_map = slot_of(plain_info(m.normalTexture), cache, path, what + " normalTexture",
                             warnings, "drawn with the mesh's normals", data);
    if (!std::isfinite(m.normalTexture.scale))
        bad(path, what + ": normalTexture.scale is not finite");
    mat.normal_scale = static_cast<float>(m.normalTexture.scale);
    mat.occlusion_map =
        slot_of(plain_info(m.occlusionTexture), cache, path, what + " occlusionTexture", warnings,
                "drawn without occlusion", data);
    if (!(m.occlusionTexture.strength >= 0 && m.occlusionTexture.strength <= 1))
        bad(path, what + ": occlusionTexture.strength must be from 0 to 1");
    mat.occlusion_strength = static_cast<float>(m.occlusionTexture.strength);
}

// clearcoatNormalTexture.scale (1 when absent; its type was checked).
float coat_normal_scale(const tinygltf::Value& coat, const std::string& path,
                        const std::string& what) {
    if (!coat.Has("clearcoatNormalTexture")) return 1.0f;
    const tinygltf::Value& info = coat.Get("clearcoatNormalTexture");
    if (!info.Has("scale")) return 1.0f;
    const double scale = info.Get("scale").GetNumberAsDouble();
    if (!std::isfinite(scale)) bad(path, what + ": clearcoatNormalTexture.scale is not finite");
    return static_cast<float>(scale);
}

// One tangent frame serves both normal maps, made along the base's map's
// coordinates: a coat map on another set would tilt the wrong way.
void warn_coat_normal_coordinates(Material& mat, const std::string& path, const std::string& what,
                                  Warnings& warnings) {
    if (!mat.normal_map || !mat.clearcoat_normal_map ||
        mat.normal_map.uv_set == mat.clearcoat_normal_map.uv_set)
        return;
    warnings.push_back(file_warning(
        path, what + " clearcoatNormalTexture reads TEXCOORD_" +
                  std::to_string(mat.clearcoat_normal_map.uv_set) + " but normalTexture TEXCOORD_" +
                  std::to_string(mat.normal_map.uv_set) +
                  ": the tangent frames follow one set, so the coat is drawn smooth"));
    mat.clearcoat_normal_map = {};
}

// KHR_materials_sheen: colour (sRGB map) and roughness (the A of a data map).
void read_sheen(const tinygltf::Value& e, TextureCache& cache, const std::string& path,
                const std::string& what, Warnings& warnings, Material& mat) {
    mat.sheen_color = extension_color(e, "sheenColorFactor", glm::vec3(0), 1.0, path, what);
    mat.sheen_roughness = extension_number(e, "sheenRoughnessFactor", 0.0f, 0.0, 1.0, path, what);
    if (mat.sheen_color == glm::vec3(0)) return;  // the layer is off: its maps show nothing
    mat.sheen_color_map = extension_map(e, "sheenColorTexture", cache, path, what, warnings,
                                        "drawn with its sheenColorFactor alone");
    mat.sheen_roughness_map =
        extension_map(e, "sheenRoughnessTexture", cache, path, what, warnings,
                      "drawn with its sheenRoughnessFactor alone", TexelMeaning::data);
}

// KHR_materials_iridescence: strength (R of a data map), the film's index,
// and its thickness range in nm (G of a data map picks within it; without
// the map the maximum).
void read_iridescence(const tinygltf::Value& e, TextureCache& cache, const std::string& path,
                      const std::string& what, Warnings& warnings, Material& mat) {
    mat.iridescence = extension_number(e, "iridescenceFactor", 0.0f, 0.0, 1.0, path, what);
    mat.iridescence_ior = extension_number(e, "iridescenceIor", 1.3f, 1.0, 10.0, path, what);
    mat.iridescence_thickness_min =
        extension_number(e, "iridescenceThicknessMinimum", 100.0f, 0.0, 1e5, path, what);
    mat.iridescence_thickness_max =
        extension_number(e, "iridescenceThicknessMaximum", 400.0f, 0.0, 1e5, path, what);
    if (mat.iridescence == 0.0f) return;  // no film: its maps show nothing
    mat.iridescence_map =
        extension_map(e, "iridescenceTexture", cache, path, what, warnings,
                      "drawn with its iridescenceFactor alone", TexelMeaning::data);
    mat.iridescence_thickness_map =
        extension_map(e, "iridescenceThicknessTexture", cache, path, what, warnings,
                      "drawn at its iridescenceThicknessMaximum alone", TexelMeaning::data);
}

// KHR_materials_anisotropy: strength, rotation (radians) and a data map
// (RG direction, B strength).
void read_anisotropy(const tinygltf::Value& e, TextureCache& cache, const std::string& path,
                     const std::string& what, Warnings& warnings, Material& mat) {
    mat.anisotropy = extension_number(e, "anisotropyStrength", 0.0f, 0.0, 1.0, path, what);
    mat.set_anisotropy_rotation(
        extension_number(e, "anisotropyRotation", 0.0f, -1e6, 1e6, path, what));
    if (mat.anisotropy == 0.0f) return;  // isotropic: the map shows nothing
    mat.anisotropy_map =
        extension_map(e, "anisotropyTexture", cache, path, what, warnings,
                      "drawn along its anisotropyRotation alone", TexelMeaning::data);
    // Its directions are read in the tangent frames, which follow the
    // normal maps' coordinates (Material::tangent_uv_set).
    const int frames = *mat.tangent_uv_set();
    if (!mat.anisotropy_map || mat.anisotropy_map.uv_set == frames) return;
    warnings.push_back(file_warning(
        path, what + " anisotropyTexture reads TEXCOORD_" +
                  std::to_string(mat.anisotropy_map.uv_set) +
                  " but the tangent frames follow the normal map's TEXCOORD_" +
                  std::to_string(frames) + ": drawn along its anisotropyRotation alone"));
    mat.anisotropy_map = {};
}

// KHR_materials_diffuse_transmission: strength (A of a data map) and
// colour (sRGB map).
void read_diffuse_transmission(const tinygltf::Value& e, TextureCache& cache,
                               const std::string& path, const std::string& what, Warnings& warnings,
                               Material& mat) {
    mat.diffuse_transmission =
        extension_number(e, "diffuseTransmissionFactor", 0.0f, 0.0, 1.0, path, what);
    mat.diffuse_transmission_color =
        extension_color(e, "diffuseTransmissionColorFactor", glm::vec3(1.0f), 1.0, path, what);
    if (mat.diffuse_transmission == 0.0f) return;  // nothing passes: the maps show nothing
    mat.diffuse_transmission_map =
        extension_map(e, "diffuseTransmissionTexture", cache, path, what, warnings,
                      "drawn with its diffuseTransmissionFactor alone", TexelMeaning::data);
    mat.diffuse_transmission_color_map =
        extension_map(e, "diffuseTransmissionColorTexture", cache, path, what, warnings,
                      "drawn with its diffuseTransmissionColorFactor alone");
}

// KHR_materials_transmission (R of a data map), _volume (thickness: G of
// a data map; the attenuation) and _dispersion.
void read_transmission(const tinygltf::Material& m, TextureCache& cache, const std::string& path,
                       const std::string& what, Warnings& warnings, Material& mat) {
    const auto transmission = m.extensions.find("KHR_materials_transmission");
    if (transmission != m.extensions.end()) {
        const tinygltf::Value& e = transmission->second;
        mat.transmission = extension_number(e, "transmissionFactor", 0.0f, 0.0, 1.0, path, what);
        if (mat.transmission > 0.0f)
            mat.transmission_map =
                extension_map(e, "transmissionTexture", cache, path, what, warnings,
                              "drawn with its transmissionFactor alone", TexelMeaning::data);
    }
    if (const auto it = m.extensions.find("KHR_materials_volume"); it != m.extensions.end()) {
        const tinygltf::Value& e = it->second;
        mat.thickness = extension_number(e, "thicknessFactor", 0.0f, 0.0, 1e30, path, what);
        mat.attenuation_color =
            extension_color(e, "attenuationColor", glm::vec3(1.0f), 1.0, path, what);
        constexpr float kInfinite = std::numeric_limits<float>::infinity();
        mat.attenuation_distance =
            extension_number(e, "attenuationDistance", kInfinite, 1e-30, 1e30, path, what);
        if (mat.transmission > 0.0f && mat.thickness > 0.0f)
            mat.thickness_map =
                extension_map(e, "thicknessTexture", cache, path, what, warnings,
                              "drawn with its thicknessFactor alone", TexelMeaning::data);
    }
    if (const auto it = m.extensions.find("KHR_materials_dispersion"); it != m.extensions.end())
        mat.dispersion = extension_number(it->second, "dispersion", 0.0f, 0.0, 1e3, path, what);
    // Its back faces are drawn as layers of their own (docs/pbr.md,
    // "Transmission"): the view crosses the volume twice.
    if (mat.transmission > 0.0f && mat.thickness > 0.0f && mat.double_sided)
        warnings.push_back(file_warning(
            path, what + " is double-sided glass with a volume: its tint and refraction are "
                         "applied at its front and again at its back faces, darker than the "
                         "one crossing authored"));
}

// KHR_materials_ior, _specular, _clearcoat, _sheen, _iridescence, _anisotropy,
// _diffuse_transmission and the glass's (read_transmission).
void read_layer_extensions(const tinygltf::Material& m, TextureCache& cache,
                           const std::string& path, const std::string& what, Warnings& warnings,
                           Material& mat) {
    if (const auto it = m.extensions.find("KHR_materials_ior"); it != m.extensions.end()) {
        // 0 is not an index of refraction; the extension's schema allows
        // it, but no renderer agrees on its meaning.
        mat.ior = extension_number(it->second, "ior", 1.5f, 1.0, 10.0, path, what);
    }
    if (const auto it = m.extensions.find("KHR_materials_specular"); it != m.extensions.end()) {
        const tinygltf::Value& e = it->second;
        mat.specular_weight = extension_number(e, "specularFactor", 1.0f, 0.0, 1.0, path, what);
        mat.specular_color =
            extension_color(e, "specularColorFactor", mat.specular_color, 1e3, path, what);
        mat.specular_weight_map =
            extension_map(e, "specularTexture", cache, path, what, warnings,
                          "drawn with its specularFactor alone", TexelMeaning::data);
        mat.specular_color_map =
            extension_map(e, "specularColorTexture", cache, path, what, warnings,
                          "drawn with its specularColorFactor alone");
    }
    if (const auto it = m.extensions.find("KHR_materials_clearcoat"); it != m.extensions.end()) {
        const tinygltf::Value& e = it->second;
        mat.clearcoat = extension_number(e, "clearcoatFactor", 0.0f, 0.0, 1.0, path, what);
        mat.clearcoat_roughness =
            extension_number(e, "clearcoatRoughnessFactor", 0.0f, 0.0, 1.0, path, what);
        mat.clearcoat_map =
            extension_map(e, "clearcoatTexture", cache, path, what, warnings,
                          "drawn with its clearcoatFactor alone", TexelMeaning::data);
        mat.clearcoat_roughness_map =
            extension_map(e, "clearcoatRoughnessTexture", cache, path, what, warnings,
                          "drawn with its clearcoatRoughnessFactor alone", TexelMeaning::data);
        mat.clearcoat_normal_map =
            extension_map(e, "clearcoatNormalTexture", cache, path, what, warnings,
                          "drawn with a smooth coat", TexelMeaning::data);
        mat.clearcoat_normal_scale = coat_normal_scale(e, path, what);
        warn_coat_normal_coordinates(mat, path, what, warnings);
    }
    if (const auto it = m.extensions.find("KHR_materials_sheen"); it != m.extensions.end())
        read_sheen(it->second, cache, path, what, warnings, mat);
    if (const auto it = m.extensions.find("KHR_materials_iridescence"); it != m.extensions.end())
        read_iridescence(it->second, cache, path, what, warnings, mat);
    if (const auto it = m.extensions.find("KHR_materials_anisotropy"); it != m.extensions.end())
        read_anisotropy(it->second, cache, path, what, warnings, mat);
    if (const auto it = m.extensions.find("KHR_materials_diffuse_transmission");
        it != m.extensions.end())
        read_diffuse_transmission(it->second, cache, path, what, warnings, mat);
    read_transmission(m, cache, path, what, warnings, mat);
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
    const auto spec_gloss = m.extensions.find("KHR_materials_pbrSpecularGlossiness");
    if (spec_gloss != m.extensions.end())
        read_specular_glossiness(spec_gloss->second, cache, path, what, warnings, mat);
    else
        read_metal_rough(m, cache, path, what, warnings, mat);
    read_normal_and_occlusion(m, cache, path, what, warnings, mat);
    read_layer_extensions(m, cache, path, what, warnings, mat);
    return mat;
}

}  // namespace

std::vector<Material> read_materials(const tinygltf::Model& model, const std::string& path,
                                     const UnreadImages& unread, TextureBudget* budget,
                                     bool basisu_required, Warnings& warnings) {
    TextureCache cache(model, path, unread, budget, basisu_required);
    std::vector<Material> materials;
    for (size_t i = 0; i < model.materials.size(); ++i)
        materials.push_back(read_material(model.materials[i], i, cache, path, warnings));
    return materials;
}

void check_basisu_fallbacks(const tinygltf::Model& model, const std::string& path, bool required,
                            Warnings& warnings, std::vector<Error>* refusals) {
    size_t ktx2 = 0;
    for (size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& t = model.textures[i];
        if (!t.extensions.count("KHR_texture_basisu")) continue;
        ++ktx2;
        if (!required || !image_choices(t).empty()) continue;
        const Error refusal(ExitCode::invalid_input,
                            path + ": texture " + std::to_string(i) +
                                ": KTX2 (KHR_texture_basisu) is not supported; the file has no "
                                "PNG/JPEG fallback");
        if (!refusals) throw refusal;
        if (refusals->empty() || refusals->back().what() != std::string(refusal.what()))
            refusals->push_back(refusal);
    }
    if (ktx2 > 0)
        warnings.push_back(
            file_warning(path, "uses KHR_texture_basisu: KTX2 images are not supported, so " +
                                   std::to_string(ktx2) + " texture" + (ktx2 == 1 ? "" : "s") +
                                   " are drawn from their PNG/JPEG fallback where they have one"));
}

}  // namespace facet::gltf_detail
