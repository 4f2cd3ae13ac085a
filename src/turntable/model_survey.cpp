#include "turntable/model_survey.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "assets/gltf_pose.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"

namespace facet {
namespace {

// Poses sampled for an animated model's bounds: every frame of a short
// turntable, evenly spread frames of a long one (as camera framing does).
constexpr int kMaxPosedFrames = 256;

// A Z-up point as the scene's `rotate: [-90, 0, 0]` turns it: Z becomes up
// and -Y (a Z-up model's front) faces +Z, the camera's side at the start.
glm::vec3 upright(const glm::vec3& p, UpAxis up) {
    return up == UpAxis::y ? p : glm::vec3(p.x, p.z, -p.y);
}

double triangle_area(const MeshPart& part) {
    double area = 0;
    for (size_t t = 0; t < part.triangle_count(); ++t) {
        const glm::dvec3 a = part.positions[part.indices[3 * t]];
        const glm::dvec3 b = part.positions[part.indices[3 * t + 1]];
        const glm::dvec3 c = part.positions[part.indices[3 * t + 2]];
        area += glm::length(glm::cross(b - a, c - a)) / 2;
    }
    return area;
}

// The mesh must have something to draw and a size to frame.
void check_drawable(const Mesh& mesh, const std::string& path) {
    // (The loaders refuse most files without triangles themselves.)
    if (mesh.triangle_count() == 0)
        throw Error(ExitCode::invalid_input,
                    path + ": the mesh has no triangles: there is nothing to show on a turntable");
    const double area =
        std::accumulate(mesh.parts.begin(), mesh.parts.end(), 0.0,
                        [](double sum, const MeshPart& part) { return sum + triangle_area(part); });
    if (!(area > 0))
        throw Error(ExitCode::invalid_input,
                    path + ": " +
                        (mesh.triangle_count() == 1
                             ? std::string("its one triangle has")
                             : "all " + std::to_string(mesh.triangle_count()) + " triangles have") +
                        " no area (every vertex lies on one line or at one point): there is "
                        "nothing to show on a turntable");
}

// The bounds of every pose the turntable shows, upright.
Bounds posed_bounds(const Mesh& mesh, const SurveyRequest& request, UpAxis up, double duration) {
    Bounds bounds;
    auto add = [&](const std::vector<glm::vec3>& points) {
        for (const glm::vec3& p : points) bounds.add(upright(p, up));
    };
    const int animations = animation_count(mesh);
    if (animations == 0) {
        for (const MeshPart& part : mesh.parts) add(part.positions);
        return bounds;
    }
    // Only the poses shown: the rest pose of an animated file may lie
    // below them all, and the model would float.
    std::vector<int> all(static_cast<size_t>(animations));
    std::iota(all.begin(), all.end(), 0);
    const int step = std::max(1, (request.frames + kMaxPosedFrames - 1) / kMaxPosedFrames);
    std::vector<PosedPart> posed;
    for (int frame = 0; frame < request.frames; frame += step) {
        // The clock of `animation: all` at this frame: looping, from 0 at the
        // first frame (render/world.cpp, animation_clock).
        const double seconds = duration > 0 ? std::fmod(frame / request.fps, duration) : 0.0;
        pose_mesh(mesh, all, seconds, posed);
        for (const PosedPart& part : posed) add(part.positions);
    }
    return bounds;
}

void check_size(const ModelSurvey& survey) {
    const double size = survey.size();
    if (size < kSmallestModel || size > kLargestModel) {
        char text[256];
        std::snprintf(text, sizeof text,
                      ": the model is %g units across, too %s to frame (a turntable takes "
                      "models from %g to %g units): scale it in a scene of your own",
                      size, size < kSmallestModel ? "small" : "large", kSmallestModel,
                      kLargestModel);
        throw Error(ExitCode::invalid_input, survey.path + text);
    }
}

}  // namespace

double ModelSurvey::size() const {
    if (bounds.empty()) return 0;
    const glm::vec3 extent = bounds.max - bounds.min;
    return std::max({extent.x, extent.y, extent.z});
}

ModelSurvey survey_model(const SurveyRequest& request) {
    // Read once: the bytes drawn are the bytes hashed, and the format is
    // told once.
    const MeshFile file = read_mesh_file(request.path, request.assets);
    auto read = std::make_shared<const Mesh>(load_mesh(file, request.assets));
    const Mesh& mesh = *read;
    check_drawable(mesh, request.path);
    ModelSurvey survey;
    survey.mesh = read;
    survey.path = request.path;
    survey.format = file.format;
    survey.sha256 = sha256_hex(file.bytes);
    survey.triangles = mesh.triangle_count();
    survey.animations = animation_count(mesh);
    for (int a = 0; a < survey.animations; ++a)
        survey.animation_seconds = std::max(survey.animation_seconds, animation_duration(mesh, a));
    survey.up = choose_up_axis(mesh, survey.format);
    if (request.up) {
        const bool same = *request.up == survey.up.axis;
        survey.up = {*request.up, false,
                     std::string("--up ") + std::string(name_of(kUpAxes, *request.up)) +
                         (same ? ""
                               : " (the file alone would be read " +
                                     std::string(name_of(kUpAxes, survey.up.axis)) + "-up)")};
    }
    survey.bounds = posed_bounds(mesh, request, survey.up.axis, survey.animation_seconds);
    check_size(survey);
    return survey;
}

}  // namespace facet
