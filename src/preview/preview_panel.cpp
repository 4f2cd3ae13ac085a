#include "preview/preview_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace facet {
namespace {

// The passes with an 8-bit view (position and motion have none).
constexpr Pass kShownPasses[] = {Pass::color,     Pass::alpha,       Pass::depth, Pass::normal,
                                 Pass::object_id, Pass::material_id, Pass::uv,    Pass::lines};

// ImGui tells widgets apart by label; the key path after "##" keeps two
// sliders called "color" (two lights) apart without showing it. A value
// the scene keys is marked: the panel shows its first key, and a change
// replaces the keys with that one value.
std::string widget_id(const char* label, const std::string& path, bool keyed = false) {
    return std::string(label) + (keyed ? " (keyed)" : "") + "##" + path;
}

// A tweak's value while it is edited, else the scene's: the scene shows a
// new value only once the worker has reloaded it, and a slider must not
// jump back meanwhile.
template <typename T>
T shown(const PreviewState& state, const std::string& path, T scene_value) {
    auto it = state.tweaks.find(path);
    if (it != state.tweaks.end())
        if (const T* value = std::get_if<T>(&it->second)) return *value;
    return scene_value;
}

void edit_float(PreviewState& state, const char* label, const std::string& path, float scene_value,
                float min, float max, bool keyed = false) {
    float value = shown(state, path, scene_value);
    if (ImGui::SliderFloat(widget_id(label, path, keyed).c_str(), &value, min, max, "%.3g"))
        state.tweaks[path] = value;
}

void edit_float(PreviewState& state, const char* label, const std::string& path,
                const Animated<float>& scene_value, float min, float max) {
    edit_float(state, label, path, scene_value.value, min, max, scene_value.animated());
}

void edit_int(PreviewState& state, const char* label, const std::string& path, int scene_value,
              int min, int max) {
    int value = shown(state, path, scene_value);
    if (ImGui::SliderInt(widget_id(label, path).c_str(), &value, min, max))
        state.tweaks[path] = value;
}

void edit_color(PreviewState& state, const char* label, const std::string& path,
                const Animated<glm::vec3>& scene_value) {
    glm::vec3 value = shown(state, path, scene_value.value);
    if (ImGui::ColorEdit3(widget_id(label, path, scene_value.animated()).c_str(), &value.x,
                          ImGuiColorEditFlags_Float))
        state.tweaks[path] = value;
}

// A light's travel direction as the compass bearing and height it comes from.
void edit_direction(PreviewState& state, const std::string& path,
                    const Animated<glm::vec3>& scene_value) {
    const bool keyed = scene_value.animated();
    const glm::vec3 from = -glm::normalize(shown(state, path, scene_value.value));
    float azimuth = glm::degrees(std::atan2(from.x, from.z));
    float elevation = glm::degrees(std::asin(std::fmax(-1.0f, std::fmin(1.0f, from.y))));
    const bool a = ImGui::SliderFloat(widget_id("from azimuth", path, keyed).c_str(), &azimuth,
                                      -180, 180, "%.0f deg");
    const bool e = ImGui::SliderFloat(widget_id("from elevation", path, keyed).c_str(), &elevation,
                                      -89, 89, "%.0f deg");
    if (a || e) {
        const float az = glm::radians(azimuth), el = glm::radians(elevation);
        state.tweaks[path] =
            -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    }
}

void time_section(PreviewState& state) {
    if (state.frames.empty()) return;
    int index = static_cast<int>(state.frame_index);
    const int last = static_cast<int>(state.frames.size()) - 1;
    const std::string label = "frame " + std::to_string(state.frames[state.frame_index]);
    if (ImGui::SliderInt("##frame", &index, 0, last, label.c_str())) {
        state.frame_index = static_cast<size_t>(index);
        state.playing = false;
    }
    if (ImGui::Button("|<")) state.frame_index = 0, state.playing = false;
    ImGui::SameLine();
    if (ImGui::Button("<") && state.frame_index > 0) --state.frame_index, state.playing = false;
    ImGui::SameLine();
    if (ImGui::Button(state.playing ? "Pause" : "Play")) state.playing = !state.playing;
    ImGui::SameLine();
    if (ImGui::Button(">") && index < last) ++state.frame_index, state.playing = false;
    ImGui::SameLine();
    if (ImGui::Button(">|")) state.frame_index = static_cast<size_t>(last), state.playing = false;
}

void camera_section(PreviewState& state, PreviewAction& action) {
    const SceneDesc& scene = *state.scene;
    if (scene.cameras.size() > 1 &&
        ImGui::BeginCombo("camera", scene.cameras[state.camera_index].name.c_str())) {
        for (size_t i = 0; i < scene.cameras.size(); ++i)
            if (ImGui::Selectable(scene.cameras[i].name.c_str(), i == state.camera_index)) {
                state.camera_index = i;
                state.view.reset();
            }
        ImGui::EndCombo();
    }
    ImGui::TextUnformatted(state.view ? "camera moved (R returns)" : "the scene's camera");
    if (ImGui::Button("Print camera (C)")) action = PreviewAction::print_camera;
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) action = PreviewAction::reset_camera;
}

void style_values(PreviewState& state, const StyleDesc& style) {
    const bool palette = style.shading == ShadingModel::palette;
    if (palette || style.shading == ShadingModel::gooch) {
        edit_color(state, "cool", "style.cool", style.cool);
        edit_color(state, "warm", "style.warm", style.warm);
        edit_float(state, "alpha", "style.alpha", style.alpha, 0, 1);
        edit_float(state, "beta", "style.beta", style.beta, 0, 1);
    }
    if (palette) {
        edit_float(state, "ambient", "style.ambient", style.ambient, 0, 1);
        edit_int(state, "cels", "style.cels", static_cast<int>(std::lround(style.cels.value)), 0,
                 8);
    }
    if (style.shading == ShadingModel::toon)
        edit_float(state, "softness", "style.toon.softness", style.toon.softness, 0, 0.5f);
    if (style.outlines.silhouette.enabled) {
        edit_float(state, "outline width", "style.outlines.silhouette.width",
                   style.outlines.silhouette.width, 0.25f, 8);
        edit_color(state, "outline colour", "style.outlines.silhouette.color",
                   style.outlines.silhouette.color);
    }
    if (style.outlines.crease.enabled)
        edit_float(state, "crease width", "style.outlines.crease.width",
                   style.outlines.crease.width, 0.25f, 8);
    if (style.hatching) {
        edit_float(state, "hatch strength", "style.hatching.strength", style.hatching->strength, 0,
                   1);
        edit_float(state, "stroke width", "style.hatching.stroke_width",
                   style.hatching->stroke_width, 0.25f, 4);
        edit_float(state, "tile pixels", "style.hatching.tile_pixels", style.hatching->tile_pixels,
                   32, 512);
        edit_float(state, "stroke angle", "style.hatching.angle", style.hatching->angle, -90, 90);
    }
}

void style_section(PreviewState& state) {
    const StyleDesc& style = state.scene->style;
    const std::string preset = shown(state, "style", std::string(style.name));
    if (ImGui::BeginCombo("style", preset.c_str())) {
        for (const std::string& name : state.presets)
            if (ImGui::Selectable(name.c_str(), name == preset)) {
                // The values belong to the old preset; the new one starts as it is.
                std::erase_if(state.tweaks,
                              [](const auto& t) { return t.first.rfind("style", 0) == 0; });
                state.tweaks["style"] = name;
            }
        ImGui::EndCombo();
    }
    ImGui::Text("shading: %s", shading_model_name(style.shading));
    style_values(state, style);
}

void lights_section(PreviewState& state) {
    const SceneDesc& scene = *state.scene;
    if (scene.lights.empty()) {
        ImGui::TextWrapped("The scene has no lights (lights: []).");
        return;
    }
    // Only the light a scene without `lights:` gets follows the camera; it
    // has no key to override.
    if (scene.lights.front().camera_relative) {
        ImGui::TextWrapped(
            "The scene's default key light, which follows the camera: give the scene lights: "
            "to change them here.");
        return;
    }
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LightDesc& light = scene.lights[i];
        const std::string key = "lights." + std::to_string(i);
        ImGui::Text("light %zu", i);
        if (!light.kelvin) edit_color(state, "colour", key + ".color", light.color);
        edit_float(state, "intensity", key + ".intensity", light.intensity, 0, 10);
        if (light.type == LightType::directional || light.type == LightType::spot)
            edit_direction(state, key + ".direction", light.direction);
    }
}

// `environment.background`: a checkbox, and the blur when it shows. A blur
// makes the key a mapping ({blur: b}), so the two tweaks never stand together.
void environment_background(PreviewState& state, const EnvironmentDesc& scene_desc) {
    const std::string flag_key = "environment.background", blur_key = "environment.background.blur";
    const bool blur_tweaked = state.tweaks.count(blur_key) > 0;
    const std::string flag =
        shown(state, flag_key, std::string(scene_desc.background ? "true" : "false"));
    bool show = blur_tweaked || flag == "true";
    if (ImGui::Checkbox("show behind the scene##environment.background", &show)) {
        state.tweaks.erase(blur_key);
        state.tweaks[flag_key] = std::string(show ? "true" : "false");
    }
    if (!show) return;
    float blur = shown(state, blur_key, scene_desc.background_blur);
    if (ImGui::SliderFloat("blur##environment.background.blur", &blur, 0.0f, 1.0f, "%.3g")) {
        state.tweaks.erase(flag_key);
        state.tweaks[blur_key] = blur;
    }
}

// The environment of the `pbr` model (docs/pbr.md): a file, its
// intensity and rotation, and whether it shows behind the scene.
void environment_section(PreviewState& state) {
    const std::optional<EnvironmentDesc>& e = state.scene->environment;
    const EnvironmentDesc shown_desc = e.value_or(EnvironmentDesc{});
    std::string file = shown(state, "environment.file", shown_desc.file);
    if (ImGui::InputText("file (.hdr, .exr)##environment.file", &file,
                         ImGuiInputTextFlags_EnterReturnsTrue))
        state.tweaks["environment.file"] = file;
    if (!e || e->source == EnvironmentDesc::Source::studio)
        ImGui::TextUnformatted("the built-in studio (no file)");
    edit_float(state, "intensity", "environment.intensity", shown_desc.intensity, 0, 4);
    edit_float(state, "rotation", "environment.rotation", shown_desc.rotation, -180, 180);
    environment_background(state, shown_desc);
}

// Metallic and roughness of each object's materials, for `pbr` styles.
void materials_section(PreviewState& state) {
    const SceneDesc& scene = *state.scene;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectDesc& object = scene.objects[i];
        const std::string key = "objects." + std::to_string(i) + ".material";
        ImGui::TextUnformatted(object.name.c_str());
        const MaterialDesc& m = object.material;
        edit_float(state, "metallic", key + ".metallic", m.metallic.value_or(0.0f), 0, 1);
        edit_float(state, "roughness", key + ".roughness", m.roughness.value_or(0.5f), 0, 1);
    }
}

void wind_section(PreviewState& state) {
    const SceneDesc& scene = *state.scene;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectDesc& object = scene.objects[i];
        if (!object.cloth) continue;
        const std::string key = "objects." + std::to_string(i) + ".cloth.wind";
        ImGui::TextUnformatted(object.name.empty() ? ("objects." + std::to_string(i)).c_str()
                                                   : object.name.c_str());
        edit_float(state, "wind m/s", key + ".strength", object.cloth->wind_strength, 0, 30);
        edit_direction(state, key + ".direction", object.cloth->wind_direction);
    }
}

void pass_section(PreviewState& state) {
    if (ImGui::BeginCombo("pass", std::string(pass_name(state.pass)).c_str())) {
        for (Pass pass : kShownPasses)
            if (ImGui::Selectable(std::string(pass_name(pass)).c_str(), pass == state.pass))
                state.pass = pass;
        ImGui::EndCombo();
    }
}

void output_section(PreviewState& state, PreviewAction& action) {
    if (ImGui::Button("Snapshot (S)")) action = PreviewAction::snapshot;
    ImGui::SameLine();
    if (ImGui::Button("Print -D (D)")) action = PreviewAction::print_defines;
    ImGui::SameLine();
    if (ImGui::Button("Revert")) action = PreviewAction::revert_tweaks;
    ImGui::InputText("##style file", &state.style_file);
    ImGui::SameLine();
    if (ImGui::Button("Write style")) action = PreviewAction::write_style;
}

}  // namespace

PreviewAction draw_preview_panel(PreviewState& state, float x, float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(x, 0));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("##panel", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    PreviewAction action = PreviewAction::none;
    ImGui::PushItemWidth(width * 0.55f);
    time_section(state);
    if (state.scene) {
        if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
            camera_section(state, action);
        if (ImGui::CollapsingHeader("Style", ImGuiTreeNodeFlags_DefaultOpen)) style_section(state);
        if (ImGui::CollapsingHeader("Lights")) lights_section(state);
        if (state.scene->style.shading == ShadingModel::pbr) {
            if (ImGui::CollapsingHeader("Environment")) environment_section(state);
            if (ImGui::CollapsingHeader("Materials")) materials_section(state);
        }
        const bool cloth = std::any_of(state.scene->objects.begin(), state.scene->objects.end(),
                                       [](const ObjectDesc& o) { return o.cloth.has_value(); });
        if (cloth && ImGui::CollapsingHeader("Wind", ImGuiTreeNodeFlags_DefaultOpen))
            wind_section(state);
    }
    pass_section(state);
    ImGui::Separator();
    output_section(state, action);
    ImGui::PopItemWidth();
    ImGui::End();
    return action;
}

}  // namespace facet
