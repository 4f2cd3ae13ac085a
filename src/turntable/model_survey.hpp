#pragma once
// What the built-in turntable scene needs to know of a model file before
// it can be written: the file's format, triangles and animations, which way
// is up, and where the model stands over every pose the turntable shows.
// A model with nothing to draw or no size to frame is refused here, with a
// message, before any camera could be computed from it.
#include <memory>
#include <optional>
#include <string>

#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "turntable/up_axis.hpp"

namespace facet {

struct SurveyRequest {
    std::string path;
    AssetContext assets;
    std::optional<UpAxis> up;  // --up; unset: choose_up_axis decides
    // The turntable's frames, numbered from 0, and their rate: the poses
    // of the file's animations that the turntable shows.
    int frames = 72;
    double fps = 24;
};

struct ModelSurvey {
    std::string path;
    MeshFormat format = MeshFormat::obj;
    std::string sha256;  // of exactly the bytes that were read and drawn
    size_t triangles = 0;
    int animations = 0;            // the file's (glTF), all of which play
    double animation_seconds = 0;  // the longest of them
    UpChoice up;
    // The model turned upright (Z-up files turned -90 degrees about X), over
    // every pose the turntable shows; before it is moved onto the ground.
    Bounds bounds;
    double size() const;  // the largest side of `bounds`
    // The mesh as read, so that the render need not read the file again
    // (model_turntable.hpp says when it may use it).
    std::shared_ptr<const Mesh> mesh;
    std::vector<TextureBudget::Charge> texture_charges;  // what its textures took
};

// The smallest and largest model facet frames, by its largest side: a
// turntable's ground is ten times larger, and scene lengths run from 1e-6
// to 1e7.
inline constexpr double kSmallestModel = 1e-5;
inline constexpr double kLargestModel = 1e6;

// Loads the model and surveys it. Throws facet::Error (invalid_input)
// naming the file for a file that cannot be read as a mesh, a mesh without
// triangles, one whose triangles have no area (every vertex on one line or
// at one point), and one too small or too large to frame.
ModelSurvey survey_model(const SurveyRequest& request);

}  // namespace facet
