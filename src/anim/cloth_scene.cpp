#include "anim/cloth_scene.hpp"

#include "anim/track.hpp"
#include "core/error.hpp"

namespace facet {

ClothParams cloth_params(const ObjectDesc& object, double fps, int first_frame) {
    ClothParams p = object.cloth->params;
    const glm::dquat to_local =
        glm::inverse(evaluate_rotation(object.rotate, {static_cast<double>(first_frame), 0.0}));
    p.gravity = glm::vec3(to_local * glm::dvec3(p.gravity));
    p.frame_seconds = 1.0 / fps;
    return p;
}

WindState cloth_wind(const ObjectDesc& object, int frame, int first_frame, double fps) {
    const ClothDesc& desc = *object.cloth;
    const FrameTime at{static_cast<double>(first_frame + frame), frame / fps};
    const glm::dquat to_local = glm::inverse(evaluate_rotation(object.rotate, at));
    WindState wind;
    wind.direction = glm::vec3(to_local * glm::dvec3(evaluate(desc.wind_direction, at)));
    wind.strength = evaluate(desc.wind_strength, at);
    wind.gust = evaluate(desc.gust, at);
    wind.seed = static_cast<uint32_t>(desc.seed);
    return wind;
}

std::shared_ptr<const ClothModel> build_scene_cloth(const ObjectDesc& object,
                                                    const OutputDesc& output) {
    const int first = output.frames.front();
    auto model = std::make_shared<const ClothModel>(
        build_cloth_model(cloth_params(object, output.fps, first), object.cloth->pins));
    // Every frame's wind must suit this cloth; checked here so a bad key
    // frame fails before anything is rendered.
    for (int f = 0; f <= output.frames.back() - first; ++f) {
        try {
            check_wind(cloth_wind(object, f, first, output.fps), model->params);
        } catch (const Error& e) {
            throw Error(ExitCode::invalid_input,
                        "frame " + std::to_string(first + f) + ": " + e.detail());
        }
    }
    return model;
}

}  // namespace facet
