#include "turntable/model_turntable.hpp"

#include <filesystem>

#include "assets/texture.hpp"
#include "core/input_file.hpp"
#include "core/sha256.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The asset settings the model is surveyed under: a scene's defaults, with
// the command line's --allow-asset-paths-outside.
AssetSettings survey_settings(const TurntableRequest& request) {
    AssetSettings settings;
    settings.allow_paths_outside = request.allow_asset_paths_outside;
    return settings;
}

ModelSurvey survey_of(const TurntableRequest& request) {
    // The model is read as a scene's mesh is: its paths kept to its folder
    // and its textures to the default budget.
    const AssetSettings settings = survey_settings(request);
    TextureBudget textures(settings.texture_budget_bytes);
    SurveyRequest survey;
    survey.path = request.model;
    survey.assets = asset_context(settings, textures, request.threads);
    survey.up = request.options.up;
    survey.frames = kTurntableFrames;
    survey.fps = kTurntableFps;
    ModelSurvey surveyed = survey_model(survey);
    // What the model's textures took, for the world's budget to take too
    // when it uses the surveyed mesh.
    surveyed.texture_charges = textures.charges();
    return surveyed;
}

// Where errors in the scene's own text point (none should: its values
// are facet's, and the user's come with their options as origin).
std::string text_name(const std::string& model) {
    return model + " (facet's turntable scene)";
}

// The options' overrides, then the user's: -D has the last word.
std::vector<Override> all_overrides(const TurntableRequest& request, const std::string& scene_dir) {
    std::vector<Override> overrides = turntable_overrides(request.options, scene_dir);
    overrides.insert(overrides.end(), request.scene_options.overrides.begin(),
                     request.scene_options.overrides.end());
    return overrides;
}

SceneDesc read_scene(const std::string& text, const std::string& name, const std::string& path,
                     const SceneOptions& base, std::vector<Override> overrides) {
    SceneOptions options = base;
    options.overrides = std::move(overrides);
    return load_scene_text(text, name, path, options);
}

// The surveyed mesh, offered to the world under each path of the scene
// that names the model, when the survey read it as the scene would.
LoadedMeshes surveyed_meshes(const TurntableRequest& request, const SceneDesc& scene,
                             const ModelSurvey& survey) {
    LoadedMeshes meshes;
    if (scene.assets != survey_settings(request) || !survey.mesh) return meshes;
    // The same path, not merely the same file: a link elsewhere would
    // resolve the model's own references (mtllib, textures) from its folder.
    const fs::path model = fs::absolute(request.model).lexically_normal();
    for (const ObjectDesc& object : scene.objects)
        if (!object.mesh.empty() && fs::absolute(object.mesh).lexically_normal() == model)
            meshes[object.mesh] = {survey.mesh, survey.texture_charges};
    return meshes;
}

}  // namespace

Turntable load_turntable(const TurntableRequest& request) {
    Turntable turntable;
    turntable.survey = survey_of(request);
    const fs::path parent = fs::path(request.model).parent_path();
    const std::string folder = parent.empty() ? std::string(".") : parent.string();
    std::vector<Override> unused;
    const std::string text = turntable_scene_yaml(
        turntable.survey, fs::path(request.model).filename().string(), {}, unused);
    turntable.overrides = all_overrides(request, folder);
    turntable.scene = read_scene(text, text_name(request.model), request.model,
                                 request.scene_options, turntable.overrides);
    turntable.scene.built =
        BuiltScene{sha256_hex(text.data(), text.size()), turntable.survey.sha256,
                   turntable_option_record(request.options, turntable.survey)};
    turntable.meshes = surveyed_meshes(request, turntable.scene, turntable.survey);
    return turntable;
}

TurntableFile turntable_scene_file(const TurntableRequest& request, const std::string& scene_dir) {
    const ModelSurvey survey = survey_of(request);
    const std::string reference = path_from_scene(scene_dir, request.model);
    const std::vector<Override> overrides = all_overrides(request, scene_dir);
    // A scene file in scene_dir named after the model: how render reads it.
    const std::string as_file =
        (fs::path(scene_dir) / (fs::path(request.model).stem().string() + ".yaml")).string();
    // Every value is checked first as -D would check it, so that an error
    // names the option that gave it.
    std::vector<Override> unused;
    const SceneDesc checked =
        read_scene(turntable_scene_yaml(survey, reference, {}, unused), text_name(request.model),
                   as_file, request.scene_options, overrides);
    check_variant(checked, survey.mesh->variants, false);
    const std::string text = turntable_scene_yaml(survey, reference, overrides, unused);
    if (!unused.empty())
        fail_input({"", 0, 0, unused.front().origin}, unused.front().path,
                   "facet scene writes only the keys its file has, and this is not one of "
                   "them: write the file, then add the key to it");
    // The text as written must read back as the scene just checked.
    read_scene(text, "the scene facet scene wrote for " + request.model, as_file,
               request.scene_options, {});
    return {text, survey};
}

}  // namespace facet
