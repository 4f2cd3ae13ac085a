#include "render/render_plan.hpp"

#include "render/alpha_coverage.hpp"
#include "render/transmission_stage.hpp"

namespace facet {

RenderPlan plan_render(const SceneDesc& scene, const World& world) {
    RenderPlan plan;
    plan.styles = plan_styles(scene);
    plan.targets = plan_frame_targets(plan.styles, scene.output.passes);
    plan.transmitting = transmitting_triangles(world, plan.styles);
    plan.alpha_tested = coverage_tested_triangles(world);
    plan.coverage_tested = plan.alpha_tested;
    if (!plan.transmitting.empty() && plan.coverage_tested.empty())
        plan.coverage_tested.assign(plan.transmitting.size(), 0);
    for (size_t t = 0; t < plan.transmitting.size(); ++t)
        plan.coverage_tested[t] |= plan.transmitting[t];
    return plan;
}

}  // namespace facet
