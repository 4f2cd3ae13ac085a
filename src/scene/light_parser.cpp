// `lights:` entries -> LightDesc (docs/scene-format.md, "Lights" and "Shadows").
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "scene/color_temperature.hpp"
#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace {

constexpr double kMaxIntensity = 1e9;
constexpr int kMinShadowResolution = 16;
constexpr int kMaxShadowResolution = 8192;
constexpr double kMaxShadowSoftness = 8;  // texels; the filter reads (2 * 8 + 2)^2 texels at most
constexpr double kMaxShadowBias = 100;

// Default map sizes: one map for the sun, one for a spot, six faces for a point light.
constexpr int kDefaultSunResolution = 2048;
constexpr int kDefaultSpotResolution = 1024;
constexpr int kDefaultPointResolution = 512;

struct LightKeys {
    const char* type;
    LightType value;
    std::vector<std::string> keys;  // besides `type`
};

const std::vector<std::string> kShadowKeys = {"shadows", "shadow_resolution", "shadow_softness",
                                              "shadow_bias"};

std::vector<std::string> with_shadow_keys(std::vector<std::string> keys) {
    keys.insert(keys.end(), kShadowKeys.begin(), kShadowKeys.end());
    return keys;
}

const std::vector<LightKeys> kLightKeys = {
    {"directional", LightType::directional, with_shadow_keys({"direction", "color", "intensity"})},
    {"point", LightType::point, with_shadow_keys({"position", "range", "color", "intensity"})},
    {"spot", LightType::spot,
     with_shadow_keys(
         {"position", "direction", "inner_angle", "outer_angle", "range", "color", "intensity"})},
    {"ambient", LightType::ambient, {"color", "intensity"}},
};

const LightKeys& light_type(const Field& f) {
    const std::string type = f.text();
    std::vector<std::string_view> names;
    for (const LightKeys& entry : kLightKeys) {
        if (type == entry.type) return entry;
        names.push_back(entry.type);
    }
    f.fail_not_one_of(type, names);
}

// `color: [r, g, b]`, `"#rrggbb"`, a keyed colour, or `{ kelvin: K }` with K
// a number or a keyed number.
void parse_light_color(const Field& f, LightDesc& light) {
    if (f.is_map() && !f.is_track()) {
        f.check_keys({"kelvin"});
        light.kelvin = f.require("kelvin").animated_number(kMinKelvin, kMaxKelvin);
        return;
    }
    light.color = f.animated_color3();
}

}  // namespace

LightDesc parse_light(const Field& f) {
    LightDesc light;
    light.where = f.where();
    f.check_keys({"type", "direction", "position", "color", "intensity", "range", "inner_angle",
                  "outer_angle", "shadows", "shadow_resolution", "shadow_softness", "shadow_bias"});
    const LightKeys& type = light_type(f.require("type"));
    light.type = type.value;
    for (const std::string& key : f.keys()) {
        if (key == "type" || std::find(type.keys.begin(), type.keys.end(), key) != type.keys.end())
            continue;
        std::string list = "type";
        for (const std::string& k : type.keys) list += ", " + k;
        std::string hint;
        if (key == "position" && light.type == LightType::directional)
            hint = "; a directional light shines from infinitely far along its direction";
        if (key == "direction" && light.type == LightType::point)
            hint = "; a point light shines every way from its position (a spot has a direction)";
        f[key].fail("'" + key + "' does not apply to a" +
                    (light.type == LightType::ambient ? "n " : " ") + type.type +
                    " light (its keys are: " + list + ")" + hint);
    }

    if (light.type == LightType::directional || light.type == LightType::spot)
        light.direction = f.require("direction").animated_direction();
    if (light.type == LightType::point || light.type == LightType::spot)
        light.position = f.require("position").animated_vec3();
    if (f.has("color")) parse_light_color(f["color"], light);
    if (f.has("intensity")) light.intensity = f["intensity"].animated_number(0, kMaxIntensity);
    if (f.has("range")) light.range = f["range"].animated_number(1e-6, kMaxCoordinate);
    if (f.has("outer_angle")) light.outer_angle = f["outer_angle"].animated_number(0.01, 90);
    if (f.has("inner_angle")) light.inner_angle = f["inner_angle"].animated_number(0, 90);
    // Keyed angles are kept apart when the frame is evaluated (inner <= outer).
    if (!light.inner_angle.animated() && !light.outer_angle.animated() &&
        light.inner_angle.value > light.outer_angle.value)
        f["inner_angle"].fail("must not be larger than outer_angle (" +
                              format_number(light.outer_angle.value) + "), got " +
                              format_number(light.inner_angle.value));

    // Shadows are off unless asked for: by `shadows: true`, or by setting
    // any other shadow key without `shadows: false`.
    bool shadow_keys = false;
    for (const std::string& key : kShadowKeys) shadow_keys = shadow_keys || f.has(key);
    light.shadows = f.has("shadows") ? f["shadows"].boolean() : shadow_keys;
    light.shadow_resolution = light.type == LightType::directional ? kDefaultSunResolution
                              : light.type == LightType::spot      ? kDefaultSpotResolution
                                                                   : kDefaultPointResolution;
    if (f.has("shadow_resolution"))
        light.shadow_resolution =
            f["shadow_resolution"].integer(kMinShadowResolution, kMaxShadowResolution);
    if (f.has("shadow_softness"))
        light.shadow_softness = f["shadow_softness"].animated_number(0, kMaxShadowSoftness);
    if (f.has("shadow_bias"))
        light.shadow_bias = f["shadow_bias"].animated_number(0, kMaxShadowBias);
    return light;
}

LightDesc default_key_light() {
    LightDesc light;
    light.type = LightType::directional;
    // About 27 degrees left of and 35 degrees above the line of sight: the
    // usual key light, so that no face turned to the camera is left unlit.
    light.direction = glm::normalize(glm::vec3(0.5f, -0.7f, -1.0f));
    light.camera_relative = true;
    // A style with `shadows: true` turns its shadows on: the map needs the
    // size a scene's sun gets.
    light.shadow_resolution = kDefaultSunResolution;
    return light;
}

}  // namespace facet
