#pragma once
// Triangle meshes as loaded from files or built procedurally. A mesh is a list
// of parts; each part has one material and its own indexed vertices.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/mesh_format.hpp"
#include "assets/mesh_rig.hpp"
#include "assets/texture.hpp"
#include "core/diagnostics.hpp"
#include "core/exact_trig.hpp"
#include "core/input_file.hpp"

namespace facet {

class ThreadPool;

enum class AlphaMode { opaque, mask, blend };

// A material's highlight coefficient when neither the scene nor the file
// gives one. The stylised models' highlights are designed for it.
constexpr float kDefaultSpecular = 0.4f;

// The Blinn-Phong exponent of a metal-rough material's roughness: 2 /
// alpha^2 - 2 with alpha = roughness^2 (shade/metal_rough_phong.hpp says
// why), the roughness taken as at least 0.05 and the exponent kept within
// 1..2048, a mirror's highlight being smaller than any pixel.
inline float roughness_exponent(float roughness) {
    const float r = std::clamp(roughness, 0.05f, 1.0f);
    return std::max(std::min(2.0f / (r * r * r * r) - 2.0f, 2048.0f), 1.0f);
}

// The steps of the shading stage's surface path (render/shade_batch.cpp)
// that a material, a mesh part and a style may need beyond a material of
// constants: one bit each. A batch whose set is empty, under a Phong,
// Blinn-Phong or unlit style without layers, takes the path compiled
// without any of them.
enum MaterialFeature : uint32_t {
    kBaseColorMap = 1u << 0,  // the base colour map multiplies the albedo
    kVertexColors = 1u << 1,  // the part's vertex colours multiply it (a part's, not a material's)
    kPhysicalMaps =
        1u << 2,            // the `pbr` model's metal-rough, occlusion, specular, coat, sheen maps
    kNormalMaps = 1u << 3,  // the `pbr` model's normal maps (the base's, the coat's)
    kEmission = 1u << 4,    // unlit, or emission added to what the model made
    kShadowCatcher = 1u << 5,  // shows only the shadows on it
    kFade = 1u << 6,           // fades into the background with distance
    // `pbr`'s sheen, thin film, anisotropy, diffuse transmission or transmission
    kExtraLobes = 1u << 7,
    // A metallic-roughness material under a Phong-family model: its metal,
    // roughness and maps become the model's colours and highlight
    // (shade/metal_rough_phong.hpp)
    kMetalRough = 1u << 8,
};
constexpr int kMaterialFeatureCount = 9;

struct Material {
    std::string name;
    glm::vec3 color = {0.8f, 0.8f, 0.8f};  // linear base colour
    float ambient = 0.1f;
    float diffuse = 0.8f;
    float specular = kDefaultSpecular;
    float shininess = 32;
    TextureSlot base_color_map;  // multiplies color (and alpha)
    bool double_sided = false;
    // Light the surface gives off, linear RGB, added to the shaded colour
    // of the lit models: glTF emissiveFactor times emissiveStrength, times
    // the emissive map where there is one.
    glm::vec3 emissive = {0, 0, 0};
    TextureSlot emissive_map;
    // Shown as its colour alone, without lights (KHR_materials_unlit).
    bool unlit = false;
    // Shows only the shadows cast on it, over the background: a floor that
    // grounds a model on any backdrop or in a transparent render.
    bool shadow_catcher = false;
    // From fade_start to fade_end (model units from the object's origin;
    // off when end <= start) the surface fades into the background, so a
    // floor ends softly instead of at a hard horizon line.
    float fade_start = 0, fade_end = 0;
    // glTF alphaMode: opaque ignores alpha; mask keeps the samples whose
    // alpha (this times the texture's) reaches alpha_cutoff; blend keeps a
    // share of samples equal to the alpha, in an ordered pattern
    // (render/alpha_coverage.hpp).
    AlphaMode alpha_mode = AlphaMode::opaque;
    float alpha = 1;
    float alpha_cutoff = 0.5f;

    // The physically based terms, read by the `pbr` shading model
    // (docs/pbr.md); the other models use the Phong terms above. glTF's
    // metallic-roughness material, with its defaults for a file's
    // materials; these are a scene's and an OBJ's (a grey dielectric).
    float metallic = 0.0f;   // 0 dielectric .. 1 metal
    float roughness = 0.5f;  // perceptual roughness, 0..1
    // Whether its author described it by metal and roughness (a glTF
    // file's; a scene's that gives `metallic` or `roughness` and neither
    // `specular` nor `shininess`): the Phong family then reads it through
    // shade/metal_rough_phong.hpp. An OBJ's is a Phong material (MTL's
    // Ka, Kd, Ks and Ns are the Phong family's own terms).
    bool metal_rough = false;
    // glTF metallicRoughnessTexture: G multiplies roughness, B metallic
    // (linear data, not colour).
    TextureSlot metal_rough_map;
    // Tangent-space normals (glTF normalTexture, OpenGL convention: +Y up
    // the texture's v), tilted by normal_scale in x and y.
    TextureSlot normal_map;
    float normal_scale = 1.0f;
    // Ambient occlusion of indirect light: R, blended by occlusion_strength.
    TextureSlot occlusion_map;
    float occlusion_strength = 1.0f;
    float ior = 1.5f;  // the dielectric's index of refraction (KHR_materials_ior)
    // KHR_materials_specular: the dielectric's reflectance, scaled by the
    // weight (times the map's A) and tinted by the colour (times its RGB).
    float specular_weight = 1.0f;
    glm::vec3 specular_color = {1, 1, 1};
    TextureSlot specular_weight_map, specular_color_map;
    // KHR_materials_clearcoat: a smooth dielectric layer (ior 1.5) over the
    // base, of this strength (times the map's R) and roughness (times G).
    float clearcoat = 0.0f;
    float clearcoat_roughness = 0.0f;
    TextureSlot clearcoat_map, clearcoat_roughness_map;
    // The coat's own tangent-space normals (clearcoatNormalTexture), tilted
    // by clearcoat_normal_scale. Without it the coat follows the surface's
    // normal before normal_map: smooth lacquer over the base's relief.
    TextureSlot clearcoat_normal_map;
    float clearcoat_normal_scale = 1.0f;
    // KHR_materials_sheen: the back-scattering of cloth's fibres, of this
    // linear colour (times the colour map's RGB; black: none) and roughness
    // (times the roughness map's A), over the base and under the coat.
    glm::vec3 sheen_color = {0, 0, 0};
    float sheen_roughness = 0.0f;
    TextureSlot sheen_color_map, sheen_roughness_map;
    // KHR_materials_pbrSpecularGlossiness (archived), drawn as the
    // dielectric it is: diffuse colour c, specular colour s (its f0) and
    // glossiness g give base c (1 - max(s)), f0 s and roughness 1 - g. A
    // file without this map has them folded into color, specular_color
    // and roughness when read; with it, RGB (sRGB) times specular_factor is
    // s and A times glossiness_factor is g, texel by texel.
    TextureSlot specular_glossiness_map;
    glm::vec3 specular_factor = {1, 1, 1};
    float glossiness_factor = 1.0f;
    // KHR_materials_iridescence: a thin film of this strength (times the
    // map's R; 0: none) and index of refraction, whose thickness in nm is
    // the maximum, or with the thickness map from the minimum (G = 0) to
    // the maximum (G = 1).
    float iridescence = 0.0f;
    float iridescence_ior = 1.3f;
    float iridescence_thickness_min = 100.0f, iridescence_thickness_max = 400.0f;
    TextureSlot iridescence_map, iridescence_thickness_map;
    // KHR_materials_anisotropy: the specular lobe stretched along a
    // direction of the tangent plane, of this strength (times the map's B;
    // 0: none). The direction is the tangent turned by the rotation
    // (counter-clockwise towards the bitangent), or the map's RG (a
    // direction in [-1, 1]^2 of the tangent frame) turned by it. The
    // rotation is kept as its cosine and sine (set_anisotropy_rotation),
    // worked out once when read rather than per pixel.
    float anisotropy = 0.0f;
    float anisotropy_cos = 1.0f, anisotropy_sin = 0.0f;
    TextureSlot anisotropy_map;
    // The cosine and sine of a rotation of `radians`, from exact series
    // (core/exact_trig.hpp), so that they do not depend on the CPU.
    static glm::vec2 rotation_cos_sin(double radians) {
        const double turns = radians / (2.0 * 3.14159265358979323846);
        return {static_cast<float>(cos_turns(turns)), static_cast<float>(sin_turns(turns))};
    }
    void set_anisotropy_rotation(double radians) {
        const glm::vec2 cs = rotation_cos_sin(radians);
        anisotropy_cos = cs.x, anisotropy_sin = cs.y;
    }
    // KHR_materials_diffuse_transmission: the share of the dielectric's
    // diffuse light that passes through the surface (times the map's A; 0:
    // none), lighting it from behind as a lampshade or a leaf is, in this
    // linear colour (times the colour map's RGB).
    float diffuse_transmission = 0.0f;
    glm::vec3 diffuse_transmission_color = {1, 1, 1};
    TextureSlot diffuse_transmission_map, diffuse_transmission_color_map;
    // KHR_materials_transmission: the share of the dielectric's diffuse
    // light replaced by light refracted through the surface (times the
    // map's R; 0: none), glass and clear plastic. Such surfaces are drawn
    // after the opaque ones, over what those left behind them
    // (render/transmission_stage.hpp).
    float transmission = 0.0f;
    TextureSlot transmission_map;
    // KHR_materials_volume: the thickness of the volume under the surface
    // in the mesh's units (times the map's G; 0: a thin wall, light passes
    // straight through), and its Beer-Lambert tint: light keeps
    // attenuation_color after attenuation_distance (infinite: no tint).
    float thickness = 0.0f;
    TextureSlot thickness_map;
    glm::vec3 attenuation_color = {1, 1, 1};
    float attenuation_distance = std::numeric_limits<float>::infinity();
    // KHR_materials_dispersion: the spread of the index of refraction over
    // the spectrum, as 20 / Abbe number (0: none).
    float dispersion = 0.0f;

    // The texture coordinate set the tangent frames follow, or none when
    // nothing needs them: the base's normal map's, else the coat's (glTF
    // gives both one tangent frame), else the anisotropy map's, else set 0
    // for an anisotropy without a map.
    std::optional<int> tangent_uv_set() const {
        for (const TextureSlot* map : {&normal_map, &clearcoat_normal_map, &anisotropy_map})
            if (*map) return map->uv_set;
        if (anisotropy > 0.0f) return 0;
        return std::nullopt;
    }

    // Every texture slot, for what applies to all maps alike (a scene's
    // uv_scale and wrap, render/world.cpp). A new map adds itself here.
    std::array<TextureSlot*, 20> texture_slots() {
        return {&base_color_map,
                &normal_map,
                &occlusion_map,
                &metal_rough_map,
                &emissive_map,
                &specular_weight_map,
                &specular_color_map,
                &clearcoat_map,
                &clearcoat_roughness_map,
                &clearcoat_normal_map,
                &sheen_color_map,
                &sheen_roughness_map,
                &specular_glossiness_map,
                &iridescence_map,
                &iridescence_thickness_map,
                &anisotropy_map,
                &diffuse_transmission_map,
                &diffuse_transmission_color_map,
                &transmission_map,
                &thickness_map};
    }

    // What shading must do for this material beyond its constants
    // (MaterialFeature): the single source of it, read once per frame for
    // the frame's values. A new key that needs a step of its own adds its
    // bit here.
    uint32_t features() const {
        uint32_t f = 0;
        if (base_color_map) f |= kBaseColorMap;
        if (metal_rough_map || occlusion_map || specular_weight_map || specular_color_map ||
            clearcoat_map || clearcoat_roughness_map || sheen_color_map || sheen_roughness_map ||
            specular_glossiness_map || iridescence_map || iridescence_thickness_map ||
            diffuse_transmission_map || diffuse_transmission_color_map || transmission_map ||
            thickness_map)
            f |= kPhysicalMaps;
        if (normal_map || clearcoat_normal_map) f |= kNormalMaps;
        if (unlit || emissive != glm::vec3(0)) f |= kEmission;
        if (shadow_catcher) f |= kShadowCatcher;
        if (fade_end > fade_start) f |= kFade;
        if (sheen_color != glm::vec3(0) || iridescence > 0.0f || anisotropy > 0.0f ||
            diffuse_transmission > 0.0f || transmission > 0.0f)
            f |= kExtraLobes;
        if (metal_rough && !unlit) f |= kMetalRough;  // an unlit material shows its colour
        return f;
    }
};

struct Bounds {
    glm::vec3 min = glm::vec3(std::numeric_limits<float>::infinity());
    glm::vec3 max = glm::vec3(-std::numeric_limits<float>::infinity());
    bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p);
    void add(const Bounds& b);
};

struct MeshPart {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // one per position, unit length
    std::vector<glm::vec2> uvs;      // texture coordinate set 0: one per position, or empty
    std::vector<glm::vec2> uvs1;     // set 1 (glTF TEXCOORD_1), or empty
    // One per position, or empty: xyz the unit tangent (along +u), w = +1
    // or -1 the sign of the bitangent, b = w (n x t) (glTF TANGENT). Made
    // for the parts whose material has a normal map (assets/tangent_frames.hpp).
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec3>
        colors;  // one per position (linear RGB, multiplies the material's), or empty
    std::vector<uint32_t> indices;  // three per triangle
    uint32_t material = 0;
    // KHR_materials_variants: empty, or one per Mesh::variants, the material
    // the part is drawn in under that variant (`material` where the file
    // maps none to it).
    std::vector<uint32_t> variant_materials;
    size_t triangle_count() const { return indices.size() / 3; }
};

// A camera of a glTF file (§3.10), on the node that carries it. It looks
// down the node's -Z with +Y up.
struct GltfCamera {
    std::string name;           // the camera's name, else its node's
    int node = -1;              // index into the rig's nodes
    bool orthographic = false;  // listed, but facet renders perspective only
    double yfov_degrees = 45;
    double znear = 0.1;
    double zfar = 0;  // 0: infinite
};

// facet's light intensity for 1 lux (directional) or 1 candela (point,
// spot) of a KHR_lights_punctual light: 1/π, the normalisation of the
// Lambertian diffuse, so that a white diffuse surface under E lux shows
// E/π, as the glTF Sample Viewer and other physically based viewers show it
// (docs/scene-format.md, "lights").
constexpr float kGltfLightUnit = 0.318309886183790671538f;

// A light of KHR_lights_punctual, placed by its node's rest transform in
// the file's world space; it shines down the node's -Z.
struct GltfLight {
    enum class Type { directional, point, spot };
    std::string name;
    Type type = Type::point;
    glm::vec3 color = {1, 1, 1};                  // linear
    float intensity = 1;                          // the file's: lux (directional) or candela
    float range = 0;                              // 0: no limit
    float inner_degrees = 0, outer_degrees = 45;  // spot cone half-angles
    glm::vec3 position = {0, 0, 0};
    glm::vec3 direction = {0, 0, -1};  // unit length
};

struct Mesh {
    std::string source;  // file it came from, or the primitive's description
    std::string loader;  // what read it: "tinygltf", "assimp" or "facet" (OBJ and primitives)
    std::vector<MeshPart> parts;
    std::vector<Material> materials;
    Warnings warnings;  // non-fatal problems found while loading, each naming the file
    // glTF nodes, skins, morph targets and animations, for posing the parts
    // (assets/gltf_pose.hpp); null when the file has none of them. The parts
    // above are always the static rest pose.
    std::shared_ptr<const MeshRig> rig;
    std::vector<GltfCamera> cameras;  // a glTF file's, for `facet info`
    std::vector<GltfLight> lights;    // a glTF file's KHR_lights_punctual lights
    // A glTF file's KHR_materials_variants, in its order: the names of a
    // product's colourways, which MeshPart::variant_materials map.
    std::vector<std::string> variants;
    // A glTF file's extension lists, and those of them facet does not read.
    struct Extensions {
        std::vector<std::string> used, required, ignored;
    } extensions;
    // Read for inspection (AssetContext::inspect_only): the errors a render
    // of the file stops with, each as render words it; empty otherwise.
    std::vector<Error> refusals;

    size_t triangle_count() const;
    size_t vertex_count() const;
    Bounds bounds() const;
};

// The cameras of a glTF file, with its nodes and animations to place them
// at any time (assets/gltf_pose.hpp, node_world_matrix).
struct GltfCameras {
    std::vector<GltfCamera> cameras;
    std::shared_ptr<const MeshRig> rig;
    Warnings warnings;
};

// What loading may touch besides the file itself: the policy for paths
// named inside it (mtllib, map_Kd, glTF URIs) and the run's texture budget.
struct AssetContext {
    AssetPathPolicy paths;
    TextureBudget* textures = nullptr;  // when set, charged before each texture is decoded
    // `facet info`: a file that requires an extension facet does not read
    // is still loaded as far as it can be, the refusal kept in
    // Mesh::refusals instead of thrown.
    bool inspect_only = false;
    // Threads that may read one big file (OBJ): 0 uses every core the
    // process may run on (available_cores). The mesh is the same for any
    // count.
    unsigned threads = 0;
};

// Meshes already read, by the path a scene's `mesh:` gives, each read
// under the scene's own asset settings, with what its textures were
// charged: `facet render MODEL` surveys the model before its scene exists,
// and the world takes that mesh, and charges its budget the same, instead
// of reading the file again.
struct LoadedMesh {
    std::shared_ptr<const Mesh> mesh;
    std::vector<TextureBudget::Charge> texture_charges;
};
using LoadedMeshes = std::map<std::string, LoadedMesh>;

// A mesh file read once: every loader parses these bytes from memory, so
// that what is drawn and what a manifest hashes (a model's turntable) are
// the same bytes, and its format is told once.
struct MeshFile {
    std::string path;
    std::vector<uint8_t> bytes;
    MeshFormat format = MeshFormat::obj;  // by its bytes, else by its name
};

// Reads the file once (within the context's size limit) and tells its
// format by its bytes, else its name (assets/mesh_format.hpp). Throws
// facet::Error (invalid_input) naming the file when it cannot be read or
// neither tells a format facet reads.
MeshFile read_mesh_file(const std::string& path, const AssetContext& context = {});

// Loads a mesh file by the loader its format calls for: .obj (facet's own
// reader; .mtl through tinyobjloader), .gltf or .glb (through tinygltf), or
// .stl, .ply, .fbx, .dae or .3ds (through libassimp, told the format its
// bytes show, whatever the file's name). Throws facet::Error
// (invalid_input) with the file name and what is wrong.
Mesh load_mesh(const MeshFile& file, const AssetContext& context = {});
Mesh load_mesh(const std::string& path, const AssetContext& context = {});
// One loader, of a file read already or of a path (read first).
Mesh load_obj(const MeshFile& file, const AssetContext& context = {});
Mesh load_gltf(const MeshFile& file, const AssetContext& context = {});
Mesh load_assimp(const MeshFile& file, const AssetContext& context = {});
Mesh load_obj(const std::string& path, const AssetContext& context = {});
Mesh load_gltf(const std::string& path, const AssetContext& context = {});
Mesh load_assimp(const std::string& path, const AssetContext& context = {});
// The cameras of a .gltf or .glb, which need hold no triangles. Throws
// invalid_input naming the file for a file that cannot be read.
GltfCameras load_gltf_cameras(const std::string& path, const AssetContext& context = {});

// Normals for a part from its triangles: per vertex, area weighted, over
// the fan of faces round the vertex joined by edges whose faces meet within
// `crease_degrees` of each other (so cubes stay sharp). Vertices are split
// where faces meeting at one position disagree. When `source_vertex` is
// given, it receives for each new vertex the index of the old vertex it was
// copied from. O(n log n) in the corners for any input; when `work` is
// given, the count of steps taken besides sorting is added to it (tests
// bound it). With a pool, the vertices are smoothed on its threads; the
// normals are the same without one.
void compute_normals(MeshPart& part, float crease_degrees,
                     std::vector<uint32_t>* source_vertex = nullptr, uint64_t* work = nullptr,
                     ThreadPool* pool = nullptr);

// What loading one part of `vertices` and `indices` takes, for the
// loaders' memory checks before they place each instance of a mesh: its
// vertex and index arrays and what builds them (64 and 16 bytes each), and
// the part itself, its arrays' allocations and the list of parts growing
// (measured: a million one-triangle instances took 450 MB).
inline uint64_t planned_part_bytes(uint64_t vertices, uint64_t indices) {
    constexpr uint64_t kPerVertex = 64, kPerIndex = 16;
    constexpr uint64_t kPerPart = 2 * sizeof(MeshPart) + 3 * 32;
    return vertices * kPerVertex + indices * kPerIndex + kPerPart;
}

// Checks indices against vertex counts and drops degenerate index triples;
// throws if an index is out of range.
void validate_part(const MeshPart& part, const std::string& source);

// `mesh` with each part in its material under the variant named `variant`
// (KHR_materials_variants): the mesh itself when it declares no variant of
// that name (its parts keep their default materials, as the specification
// says) or when the variant changes no part's material, else a copy.
std::shared_ptr<const Mesh> with_variant(std::shared_ptr<const Mesh> mesh,
                                         const std::string& variant);

}  // namespace facet
