// `material:` of an object -> MaterialDesc (docs/scene-format.md,
// "Materials"; the physically based keys in docs/pbr.md).
#include <cmath>
#include <map>

#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace {

constexpr EnumName<Wrap> kWraps[] = {
    {Wrap::repeat, "repeat"}, {Wrap::clamp, "clamp"}, {Wrap::mirror, "mirror"}};

// A map's file, where the scene names it and its key.
MaterialDesc::Map map_of(const Field& f, const std::string& base_dir) {
    return {existing_file(f, base_dir), f.where(), f.path()};
}

// A material's number keys that do not animate: the scene's name, the
// field of Material it sets and its range. A new key of this kind is one
// line here (docs/architecture.md, "Adding a material key").
struct NumberKey {
    const char* name;
    float Material::*field;
    double low, high;
};
constexpr NumberKey kNumberKeys[] = {
    {"normal_scale", &Material::normal_scale, -10, 10},
    {"occlusion_strength", &Material::occlusion_strength, 0, 1},
    {"ior", &Material::ior, 1, 10},
    {"clearcoat", &Material::clearcoat, 0, 1},
    {"clearcoat_roughness", &Material::clearcoat_roughness, 0, 1},
    {"sheen_roughness", &Material::sheen_roughness, 0, 1},
    {"iridescence", &Material::iridescence, 0, 1},
    {"iridescence_ior", &Material::iridescence_ior, 1, 10},
    {"iridescence_thickness", &Material::iridescence_thickness_max, 0, 5000},
    {"anisotropy", &Material::anisotropy, 0, 1},
    {"diffuse_transmission", &Material::diffuse_transmission, 0, 1},
    {"transmission", &Material::transmission, 0, 1},
    {"thickness", &Material::thickness, 0, 1e6},
    {"attenuation_distance", &Material::attenuation_distance, 1e-6, 1e9},
    {"dispersion", &Material::dispersion, 0, 100},
};

// The same for colours (linear RGB, each channel from 0 to 1).
struct ColorKey {
    const char* name;
    glm::vec3 Material::*field;
};
constexpr ColorKey kColorKeys[] = {
    {"sheen_color", &Material::sheen_color},
    {"diffuse_transmission_color", &Material::diffuse_transmission_color},
    {"attenuation_color", &Material::attenuation_color},
};

// The keys of the `pbr` model (docs/pbr.md, "Material keys").
void parse_physical_terms(const Field& f, const std::string& base_dir, MaterialDesc& m) {
    if (f.has("metallic")) m.metallic = f["metallic"].animated_number(0, 1);
    if (f.has("roughness")) m.roughness = f["roughness"].animated_number(0, 1);
    for (const NumberKey& key : kNumberKeys)
        if (f.has(key.name))
            m.constants.push_back(
                {key.field, static_cast<float>(f[key.name].number(key.low, key.high))});
    for (const ColorKey& key : kColorKeys)
        if (f.has(key.name)) m.colors.push_back({key.field, f[key.name].color3()});
    // Degrees, as every angle of a scene; Material keeps its cosine and sine.
    if (f.has("anisotropy_rotation")) {
        const glm::vec2 cs = Material::rotation_cos_sin(f["anisotropy_rotation"].number(-360, 360) *
                                                        (3.14159265358979323846 / 180.0));
        m.constants.push_back({&Material::anisotropy_cos, cs.x});
        m.constants.push_back({&Material::anisotropy_sin, cs.y});
    }
    auto map = [&](const char* key, std::optional<MaterialDesc::Map>& out) {
        if (f.has(key)) out = map_of(f[key], base_dir);
    };
    map("normal_map", m.normal_map);
    map("occlusion_map", m.occlusion_map);
    map("metal_rough_map", m.metal_rough_map);
    map("emissive_map", m.emissive_map);
    if (f.has("normal_scale") && !f.has("normal_map"))
        f["normal_scale"].fail("scales the normal map; give `normal_map:` too");
}

}  // namespace

MaterialDesc parse_material(const Field& f, const std::string& base_dir) {
    MaterialDesc m;
    std::vector<const char*> keys = {"color",
                                     "ambient",
                                     "diffuse",
                                     "specular",
                                     "ka",
                                     "kd",
                                     "ks",
                                     "shininess",
                                     "texture",
                                     "wrap",
                                     "uv_scale",
                                     "double_sided",
                                     "emissive",
                                     "unlit",
                                     "shadow_catcher",
                                     "fade",
                                     "metallic",
                                     "roughness",
                                     "normal_map",
                                     "occlusion_map",
                                     "metal_rough_map",
                                     "emissive_map",
                                     "anisotropy_rotation"};
    for (const NumberKey& key : kNumberKeys) keys.push_back(key.name);
    for (const ColorKey& key : kColorKeys) keys.push_back(key.name);
    f.check_keys(keys);
    if (f.has("color")) m.color = f["color"].animated_color3();
    // Seed 001 names the Phong coefficients ka, kd and ks; either name works, not both.
    auto coefficient = [&](const char* name, const char* alias) -> std::optional<Field> {
        if (f.has(name) && f.has(alias))
            f[alias].fail("'" + std::string(alias) + "' and '" + name +
                          "' are the same value; give only one of them");
        if (f.has(name)) return f[name];
        if (f.has(alias)) return f[alias];
        return std::nullopt;
    };
    if (auto v = coefficient("ambient", "ka")) m.ambient = v->animated_number(0, 1000);
    if (auto v = coefficient("diffuse", "kd")) m.diffuse = v->animated_number(0, 1000);
    if (auto v = coefficient("specular", "ks")) m.specular = v->animated_number(0, 1000);
    if (f.has("shininess")) m.shininess = f["shininess"].animated_number(0, 100000);
    if (f.has("texture")) m.texture = map_of(f["texture"], base_dir);
    if (f.has("wrap")) m.wrap = f["wrap"].choice_of(kWraps);
    if (f.has("uv_scale")) {
        Field s = f["uv_scale"];
        m.uv_scale = s.is_scalar() ? glm::vec2(static_cast<float>(s.number(-1e6, 1e6))) : s.vec2();
    }
    if (f.has("double_sided")) m.double_sided = f["double_sided"].boolean();
    if (f.has("emissive")) m.emissive = f["emissive"].color3();
    if (f.has("unlit")) m.unlit = f["unlit"].boolean();
    if (f.has("shadow_catcher")) m.shadow_catcher = f["shadow_catcher"].boolean();
    if (f.has("fade")) {
        const glm::vec2 fade = f["fade"].vec2();
        if (!(fade.x >= 0.0f && fade.y > fade.x && std::isfinite(fade.y)))
            f["fade"].fail("must be [start, end] with 0 <= start < end");
        m.fade = fade;
    }
    parse_physical_terms(f, base_dir, m);
    return m;
}

}  // namespace facet
