#pragma once
// A model file made into facet's built-in turntable scene: the scene that
// `facet render MODEL` renders, and the file `facet scene MODEL` writes
// (docs/turntables.md). Both survey the model, write the scene's text and
// read it back through the scene reader, so every value, the options' and
// -D's included, is checked as a scene file's are.
#include <string>

#include "scene/scene_desc.hpp"
#include "turntable/model_survey.hpp"
#include "turntable/turntable_scene.hpp"

namespace facet {

struct TurntableRequest {
    std::string model;  // the mesh file, as given
    TurntableOptions options;
    // The user's own settings (--size, --style, -D, ...), applied after
    // the options' overrides, and the style folders.
    SceneOptions scene_options;
    bool allow_asset_paths_outside = false;
    // Threads that may read the model (--threads; 0: one per core): its
    // survey is the only time the file is parsed.
    unsigned threads = 0;
};

struct Turntable {
    SceneDesc scene;
    ModelSurvey survey;
    // Every override applied, the options' first, as the manifest lists them.
    std::vector<Override> overrides;
    // The surveyed model under its scene path, for build_world: empty when
    // the scene's asset settings (-D assets.*) differ from the survey's, so
    // that the file is read again under the user's.
    LoadedMeshes meshes;
};

// `facet render MODEL`: the scene, named after the model and resolving its
// paths in the model's folder, with `built` recording the model's SHA-256,
// the scene text's and the options.
Turntable load_turntable(const TurntableRequest& request);

// `facet scene MODEL`: the scene's text for a file in `scene_dir`, every
// override written in. An override of a key the text does not have is an
// error (invalid_input) naming it: the file is the place to add it.
struct TurntableFile {
    std::string text;
    ModelSurvey survey;
};
TurntableFile turntable_scene_file(const TurntableRequest& request, const std::string& scene_dir);

}  // namespace facet
