#pragma once
// facet's built-in turntable around a model (docs/turntables.md): the
// scene as commented YAML text, and the overrides the turntable's
// command-line options stand for. `facet render MODEL` reads the text with
// the options applied as overrides; `facet scene MODEL` writes the text
// with them written in, so the two give the same scene.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/enum_names.hpp"
#include "scene/scene_desc.hpp"
#include "turntable/model_survey.hpp"

namespace facet {

// What the turntable's frames and rate are: one turn in three seconds.
inline constexpr int kTurntableFrames = 72;
inline constexpr double kTurntableFps = 24;

// `--ground`: a ground that shows only the model's shadow and occlusion
// (the default), a grey floor that fades into the background, or none.
enum class GroundKind { shadow, floor, none };
inline constexpr EnumName<GroundKind> kGroundKinds[] = {
    {GroundKind::shadow, "shadow"}, {GroundKind::floor, "floor"}, {GroundKind::none, "none"}};

// The turntable's choices where an option is not given: what the scene's
// text writes, what the options' words for them mean, and what the
// manifest's `model` block records.
struct TurntableDefaults {
    double turns = 1;                          // turns of the camera over the frames
    double elevation = 20;                     // degrees above the model's centre
    std::string_view background = "gradient";  // the environment, shown blurred
    GroundKind ground = GroundKind::shadow;
    std::string_view environment = "studio";  // facet's own
};
inline constexpr TurntableDefaults kTurntableDefaults{};

// The scene keys the options set, as -D names them. The scene's text has
// every one (turntable_scene_yaml checks, each time it writes), so an
// option cannot set a key the text lacks.
inline constexpr const char* kTurnsKey = "camera.orbit.turns";
inline constexpr const char* kElevationKey = "camera.orbit.elevation";
inline constexpr const char* kBackgroundKey = "output.background";
inline constexpr const char* kEnvironmentShownKey = "environment.background";
inline constexpr const char* kEnvironmentFileKey = "environment.file";
inline constexpr const char* kGroundCatcherKey = "objects.ground.material.shadow_catcher";
inline constexpr const char* kGroundVisibleKey = "objects.ground.visible";
inline constexpr const char* kOptionKeys[] = {
    kTurnsKey,           kElevationKey,     kBackgroundKey,   kEnvironmentShownKey,
    kEnvironmentFileKey, kGroundCatcherKey, kGroundVisibleKey};

// The turntable's options as given on the command line; "" or unset: not
// given (the built-in scene's own value).
struct TurntableOptions {
    std::string turns;       // --turns N
    std::string elevation;   // --elevation DEG
    std::string background;  // --background transparent|gradient|COLOR, as typed
    std::optional<GroundKind> ground;
    std::string environment;  // --environment FILE, relative to where facet runs
    std::optional<UpAxis> up;
};

// The overrides the options are short for, in the order given above, each
// naming its option as its origin. `scene_dir` is the folder the scene's
// paths resolve against (the environment file is written relative to it).
std::vector<Override> turntable_overrides(const TurntableOptions& options,
                                          const std::string& scene_dir);

// The options as the manifest records them, every one with its value
// (defaults included) and the up axis with how it was chosen.
std::vector<std::pair<std::string, std::string>> turntable_option_record(
    const TurntableOptions& options, const ModelSurvey& survey);

// `file` as a scene in `scene_dir` names it: relative to that folder when
// both are on one root, else absolute; absolute for an empty `scene_dir`
// (text printed, with no folder of its own).
std::string path_from_scene(const std::string& scene_dir, const std::string& file);

// The scene's text around a surveyed model. `mesh_reference` is the model's
// path as the scene file names it. Each override in `written_in` is written
// in place of the value its key has (facet scene); those whose keys the
// text does not have are returned in `unused` (the caller refuses them).
std::string turntable_scene_yaml(const ModelSurvey& survey, const std::string& mesh_reference,
                                 const std::vector<Override>& written_in,
                                 std::vector<Override>& unused);

}  // namespace facet
