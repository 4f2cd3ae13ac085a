#include "anim/cloth_scene.hpp"

#include "anim/track.hpp"
#include "core/error.hpp"

namespace facet {

ClothParams cloth_params(const ObjectDesc& object, double fps, int first_frame, int frame) {
    const ClothDesc& desc = *object.cloth;
    ClothParams p = desc.params;
    const glm::dquat to_local =
        glm::inverse(evaluate_rotation(object.rotate, {static_cast<double>(first_frame), 0.0}));
    p.gravity = glm::vec3(to_local * glm::dvec3(p.gravity));
    p.frame_seconds = 1.0 / fps;
    const FrameTime at{static_cast<double>(first_frame + frame), frame / fps};
    p.mass = evaluate(desc.mass, at);
    p.stiffness = evaluate(desc.stiffness, at);
    p.friction = evaluate(desc.friction, at);
    p.damping = evaluate(desc.damping, at);
    return p;
}

bool cloth_values_keyed(const ObjectDesc& object) {
    const ClothDesc& d = *object.cloth;
    return d.mass.animated() || d.stiffness.animated() || d.friction.animated() ||
           d.damping.animated();
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
    const int count = output.frames.back() - first + 1;
    const bool keyed = cloth_values_keyed(object);
    auto at_frame = [&](int f, auto&& check) {
        try {
            check();
        } catch (const Error& e) {
            throw Error(ExitCode::invalid_input,
                        "frame " + std::to_string(first + f) + ": " + e.detail());
        }
    };
    ClothParams base = cloth_params(object, output.fps, first, 0);
    if (keyed && base.substeps == 0) {
        // One step size for the whole run (the frames must not depend on
        // which are rendered): the most substeps any frame's values need.
        int substeps = 1;
        for (int f = 0; f < count; ++f)
            at_frame(f, [&] {
                const ClothParams p = cloth_params(object, output.fps, first, f);
                check_cloth_params(p, object.cloth->pins);
                substeps = std::max(substeps, cloth_substeps(p));
            });
        base.substeps = substeps;
    }
    std::shared_ptr<const ClothModel> model;
    auto build = [&] {
        model = std::make_shared<const ClothModel>(build_cloth_model(base, object.cloth->pins));
    };
    if (keyed)
        at_frame(0, build);  // the first frame's values are the model's
    else
        build();
    // Every frame's keyed values and wind must suit this cloth at its step;
    // checked here so a bad key frame fails before anything is rendered.
    for (int f = 0; f < count; ++f)
        at_frame(f, [&] {
            ClothParams p =
                with_keyed_values(model->params, cloth_params(object, output.fps, first, f));
            if (keyed) check_cloth_params(p, object.cloth->pins);
            check_wind(cloth_wind(object, f, first, output.fps), p);
        });
    return model;
}

std::unique_ptr<ClothSimulation> scene_cloth_simulation(const ObjectDesc& object,
                                                        const OutputDesc& output,
                                                        std::shared_ptr<const ClothModel> model) {
    const int first = output.frames.front();
    const double fps = output.fps;
    auto wind_at = [&object, first, fps](int frame) {
        return cloth_wind(object, frame, first, fps);
    };
    ClothSimulation::ParamsAt params_at;
    if (cloth_values_keyed(object))
        params_at = [&object, first, fps](int frame) {
            return cloth_params(object, fps, first, frame);
        };
    return std::make_unique<ClothSimulation>(std::move(model), wind_at, params_at);
}

}  // namespace facet
