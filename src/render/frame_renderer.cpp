// One frame: evaluate the scene, then run the stages in order (vertex,
// primitive, tile + shading, resolve). The stages themselves live in the
// files named after them.
#include <algorithm>

#include <glm/geometric.hpp>

#include "post/resolve.hpp"
#include "render/frame_renderer.hpp"

namespace facet {

std::vector<ShadeLight> make_shade_lights(const std::vector<LightState>& lights,
                                          std::span<const ShadowMap* const> shadow_maps) {
    std::vector<ShadeLight> out, ambient;
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightState& l = lights[i];
        ShadeLight s;
        s.radiance = l.color * l.intensity;
        if (l.type == LightType::ambient) {
            s.is_ambient = true;
            ambient.push_back(s);
            continue;
        }
        s.is_point = l.type == LightType::point || l.type == LightType::spot;
        s.direction = l.type == LightType::point ? glm::vec3(0) : -glm::normalize(l.direction);
        s.position = l.position;
        if (l.type == LightType::spot) set_spot_cone(s, l.inner_angle, l.outer_angle);
        if (s.is_point && l.range > 0) s.inv_range = 1.0f / l.range;
        if (i < shadow_maps.size()) s.shadow = shadow_maps[i];
        out.push_back(s);
    }
    out.insert(out.end(), ambient.begin(), ambient.end());
    return out;
}

glm::vec2 FrameRenderer::depth_view_range(const FrameState& state,
                                          const CameraMatrices& camera) const {
    // Fit the bounding sphere of everything visible; for an orbiting camera
    // it stays constant, so animations do not flicker.
    Bounds all;
    for (const Draw& d : world_.draws) {
        const Bounds& b = world_.object_bounds[d.object];
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

FrameRenderer::FrameRenderer(const SceneDesc& scene, const World& world, ThreadPool& pool)
    : scene_(scene),
      world_(world),
      pool_(pool),
      side_(scene.output.samples_per_side()),
      rasterizer_(scene.output.width * side_, scene.output.height * side_),
      shadows_(scene, world) {
    style_descs_.push_back(&scene.style);
    for (const ObjectDesc& obj : scene.objects) {
        object_style_.push_back(obj.style ? static_cast<uint32_t>(style_descs_.size()) : 0);
        if (obj.style) style_descs_.push_back(&*obj.style);
    }
    for (const StyleDesc* style : style_descs_) {
        any_gouraud_ = any_gouraud_ || style->shading == ShadingModel::gouraud;
        hidden_edges_on_ =
            hidden_edges_on_ || (style->wireframe.enabled && style->wireframe.hidden);
    }
    outlines_on_ = scene.style.outlines.any();
    make_cloth_simulations();
}

void FrameRenderer::update_styles(const FrameState& state) {
    const FrameTime at{static_cast<double>(state.frame), state.time};
    styles_.clear();
    for (const StyleDesc* style : style_descs_)
        styles_.push_back(evaluate_style(*style, at, tams_));
}

// The world's materials with this frame's animated values applied; the
// world's own list when nothing is animated.
void FrameRenderer::update_materials(const FrameState& state) {
    materials_ = &world_.materials;
    bool animated = false;
    for (const ObjectState& o : state.objects) animated = animated || o.material.any();
    if (!animated) return;
    frame_materials_ = world_.materials;
    for (size_t m = 0; m < frame_materials_.size(); ++m) {
        const MaterialState& s = state.objects[world_.material_object[m]].material;
        Material& mat = frame_materials_[m];
        if (s.color) mat.color = *s.color;
        if (s.ambient) mat.ambient = *s.ambient;
        if (s.diffuse) mat.diffuse = *s.diffuse;
        if (s.specular) mat.specular = *s.specular;
        if (s.shininess) mat.shininess = *s.shininess;
    }
    materials_ = &frame_materials_;
}

void FrameRenderer::render(int frame, size_t camera_index, FrameImages& out) {
    const FrameState state = evaluate_frame(scene_, world_.object_bounds, frame, camera_index);
    update_materials(state);
    update_styles(state);
    const float aspect =
        static_cast<float>(scene_.output.width) / static_cast<float>(scene_.output.height);
    const CameraMatrices camera = make_camera(state.camera, aspect);
    // Animated meshes and cloth take this frame's pose first: the shadow
    // maps and the image are both drawn from it.
    const bool posed = world_.deforms();
    if (posed) deform_meshes(state);
    shadows_.render(state, posed ? posed_positions_ : world_.positions, pool_);
    const std::vector<ShadeLight> lights = make_shade_lights(state.lights, shadows_.maps());

    vertex_stage(state, camera, lights);
    RasterInput input;
    input.clip = vertices_.clip.data();
    input.vertex_count = vertices_.clip.size();
    input.indices = world_.indices.data();
    input.triangle_count = world_.triangle_count();
    input.cull_back = world_.cull_back.data();
    rasterizer_.set_geometry(input, pool_);

    // Every pixel is written by shading (background included), so reused
    // buffers need no clearing.
    auto fit = [](FrameImages& images, int width, int height) {
        if (images.color.width != width || images.color.height != height)
            images.color = ColorImage(width, height);
        if (images.depth.width != width || images.depth.height != height)
            images.depth = DepthImage(width, height);
    };
    fit(out, scene_.output.width, scene_.output.height);
    out.depth_view_range = depth_view_range(state, camera);
    const glm::vec2 style_range = scene_.style.depth_range.value_or(out.depth_view_range);
    // With supersampling, shade at side x side the size, then resolve (post/).
    FrameImages& target = side_ == 1 ? out : supersampled_;
    if (side_ > 1) fit(supersampled_, rasterizer_.width(), rasterizer_.height());
    if (outlines_on_ && (outline_buffers_.width != rasterizer_.width() ||
                         outline_buffers_.height != rasterizer_.height()))
        outline_buffers_.reset(rasterizer_.width(), rasterizer_.height());
    rasterizer_.draw_tiles(pool_, [&](const TileVisibility& tile) {
        shade_tile(tile, camera, lights, style_range, target);
    });
    if (hidden_edges_on_ && !world_.edge_mask.empty()) draw_hidden_edges(target);
    // Outlines at the sample resolution, widths scaled to match, so the
    // resolve anti-aliases them like the surfaces.
    if (outlines_on_) {
        const FrameTime at{static_cast<double>(frame), state.time};
        const OutlineStyle lines =
            evaluate_outlines(scene_.style.outlines, at, static_cast<float>(side_));
        draw_outlines(outline_buffers_, lines, outline_lines_, pool_, outline_scratch_);
        composite_lines(outline_lines_, target.color, pool_);
    }
    if (side_ > 1)
        resolve_supersampled(supersampled_.color, supersampled_.depth, side_, out.color, out.depth,
                             pool_);
}

}  // namespace facet
