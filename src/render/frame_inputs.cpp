#include "render/frame_inputs.hpp"

#include "core/exact_trig.hpp"
#include "render/framing_shapes.hpp"
#include "shade/shading_models.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet {
namespace {

// The world's materials with this frame's animated values applied.
std::vector<Material> frame_materials(const World& world, const FrameState& state) {
    std::vector<Material> materials = world.materials;
    for (size_t m = 0; m < materials.size(); ++m) {
        const MaterialState& s = state.objects[world.material_object[m]].material;
        Material& mat = materials[m];
        if (s.color) mat.color = *s.color;
        if (s.ambient) mat.ambient = *s.ambient;
        if (s.diffuse) mat.diffuse = *s.diffuse;
        if (s.specular) mat.specular = *s.specular;
        if (s.shininess) mat.shininess = *s.shininess;
        if (s.metallic) mat.metallic = *s.metallic;
        if (s.roughness) mat.roughness = *s.roughness;
    }
    return materials;
}

// FrameInputs::draw_features.
std::vector<uint32_t> settle_draw_features(const World& world,
                                           const std::vector<Material>& materials,
                                           const std::vector<StyleState>& styles) {
    std::vector<uint32_t> features;
    features.reserve(styles.size() * world.draws.size());
    for (const StyleState& style : styles)
        for (const Draw& draw : world.draws)
            features.push_back(
                drawn_features(style, materials[draw.material].features() |
                                          (draw.has_colors ? uint32_t{kVertexColors} : 0u)));
    return features;
}

}  // namespace

float camera_heading_degrees(const CameraMatrices& camera) {
    const glm::vec3& f = camera.forward;
    // Straight up or down has no heading: 0, rather than noise.
    if (f.x * f.x + f.z * f.z < 1e-8f) return 0.0f;
    // The exact series (core/exact_trig.hpp), as the rotation's cosine and
    // sine are: the same bits on every CPU and C library.
    return static_cast<float>(360.0 * atan2_turns(-f.x, -f.z));
}

StylePlan plan_styles(const SceneDesc& scene) {
    StylePlan plan;
    plan.styles.push_back(&scene.style);
    for (const ObjectDesc& obj : scene.objects) {
        plan.object_style.push_back(obj.style ? static_cast<uint32_t>(plan.styles.size()) : 0);
        if (obj.style) plan.styles.push_back(&*obj.style);
    }
    for (const uint32_t style : plan.object_style)
        plan.object_normal_mapped.push_back(plan.styles[style]->shading == ShadingModel::pbr);
    for (const StyleDesc* style : plan.styles) {
        plan.any_gouraud = plan.any_gouraud || style->shading == ShadingModel::gouraud;
        plan.hidden_edges =
            plan.hidden_edges || (style->wireframe.enabled && style->wireframe.hidden);
    }
    plan.outlines = scene.style.outlines.any();
    plan.occlusion = scene.style.occlusion.enabled;
    return plan;
}

glm::vec2 fit_depth_view_range(const World& world, const FrameState& state,
                               const CameraMatrices& camera) {
    // Fit the bounding sphere of everything visible; for an orbiting camera
    // it stays constant, so animations do not flicker.
    Bounds all;
    for (const Draw& d : world.draws) {
        const Bounds& b = world.object_bounds[d.object];
        const glm::mat4& m = state.objects[d.object].transform;
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                        (corner & 4) ? b.max.z : b.min.z);
            all.add(glm::vec3(m * glm::vec4(p, 1.0f)));
        }
    }
    if (all.empty()) return {camera.near, camera.far};
    glm::vec3 centre = (all.min + all.max) * 0.5f;
    float radius = glm::length(all.max - centre);
    float d = glm::dot(centre - camera.position, camera.forward);
    float near = std::max(camera.near, d - radius);
    float far = std::max(near + 1e-3f, d + radius);
    return {near, far};
}

FrameEvaluator::FrameEvaluator(const SceneDesc& scene, const World& world, const StylePlan& plan,
                               int samples_per_side)
    : scene_(scene),
      world_(world),
      samples_per_side_(samples_per_side),
      plan_(plan),
      framing_(framing_shapes(scene, world)) {}

FrameInputs FrameEvaluator::evaluate(int frame, size_t camera_index) {
    FrameInputs in;
    in.state = evaluate_frame(scene_, world_.object_bounds, frame, camera_index,
                              FrameAssets{framing_, world_.file_cameras, world_.object_lights});
    const FrameTime at{static_cast<double>(in.state.frame), in.state.time};
    const float aspect =
        static_cast<float>(scene_.output.width) / static_cast<float>(scene_.output.height);
    in.camera = make_camera(in.state.camera, aspect);
    in.materials = frame_materials(world_, in.state);
    for (const ObjectState& object : in.state.objects)
        in.object_scales.push_back(object_scale(object.transform));
    for (const StyleDesc* style : plan_.styles)
        in.styles.push_back(evaluate_style(*style, at, tams_));
    in.draw_features = settle_draw_features(world_, in.materials, in.styles);
    for (const StyleState& style : in.styles) {
        in.style_needs.push_back(needs_of(style.model));
        in.style_plain.push_back(plain_style(style) ? 1 : 0);
    }
    if (plan_.outlines)
        in.outlines =
            evaluate_outlines(scene_.style.outlines, at, static_cast<float>(samples_per_side_));
    if (plan_.occlusion) {
        const OcclusionDesc& o = scene_.style.occlusion;
        in.occlusion = {facet::evaluate(o.radius, at), facet::evaluate(o.strength, at), o.samples,
                        o.half_resolution ? 2 : 1};
    }
    // Given straight, used premultiplied like every colour in the frame.
    const glm::vec4 background = scene_.style.background.value_or(scene_.output.background);
    in.background = glm::vec4(glm::vec3(background) * background.a, background.a);
    if (world_.environment) {
        const std::optional<EnvironmentDesc>& e = scene_.environment;
        float rotation = e ? facet::evaluate(e->rotation, at) : 0.0f;
        if (e && e->follow_camera) rotation += camera_heading_degrees(in.camera);
        in.environment = environment_at(world_.environment.get(),
                                        e ? facet::evaluate(e->intensity, at) : 1.0f, rotation);
        in.environment_background = e && e->background;
        in.environment_blur = e ? e->background_blur : 0.0f;
        if (in.environment_background) in.background = glm::vec4(0.0f);
    }
    in.depth_view_range = fit_depth_view_range(world_, in.state, in.camera);
    in.style_depth_range = scene_.style.depth_range.value_or(in.depth_view_range);
    return in;
}

}  // namespace facet
