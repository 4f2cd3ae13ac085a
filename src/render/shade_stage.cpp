#include "render/shade_stage.hpp"

#include <limits>

#include <glm/geometric.hpp>

#include "raster/surface_sample.hpp"
#include "shade/layers.hpp"
#include "shade/shading_models.hpp"
#include "shade/texture_lod.hpp"
#include "shade/wireframe.hpp"

namespace facet {
namespace {

// Everything shading needs about one visible pixel, gathered from the
// surface sample, the triangle's vertices, its material and its style.
struct VisiblePoint {
    uint32_t style;  // index into FrameInputs::styles
    uint32_t object;
    glm::vec3 position, normal;  // world space; normal facing the viewer, any length
    glm::vec3 albedo;
    const Material* material;
    float receives_shadow;
    float depth;
    LightingResult vertex_light;  // Gouraud only
    LayerInputs layers;
};

// The texture coordinates of a triangle's corners, times `scale`.
struct CornerUvs {
    glm::vec2 uv[3];
};

CornerUvs corner_uvs(const World& world, const uint32_t* corners, glm::vec2 scale) {
    return {{world.uvs[corners[0]] * scale, world.uvs[corners[1]] * scale,
             world.uvs[corners[2]] * scale}};
}

TextureLookup lookup(const CornerUvs& c, const SurfaceSample& s, glm::vec2 texels) {
    return texture_lookup(c.uv[0], c.uv[1], c.uv[2], s, texels);
}

// Hatching coordinates: the object's UVs, or the screen for screen-space
// strokes and objects without UVs.
void hatch_coordinates(const HatchingState& h, const Draw& draw, const World& world,
                       const uint32_t* corners, const SurfaceSample& s, int x, int y,
                       int samples_per_side, LayerInputs& out) {
    const float size = static_cast<float>(h.tam->params.size);
    if (h.screen_space || !draw.has_uvs) {
        const float tile_samples = h.tile_pixels * static_cast<float>(samples_per_side);
        out.hatch_uv =
            glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) / tile_samples;
        out.hatch_lod = std::max(0.0f, std::log2(size / tile_samples));
        return;
    }
    const TextureLookup t =
        lookup(corner_uvs(world, corners, glm::vec2(h.scale)), s, glm::vec2(size));
    out.hatch_uv = t.uv;
    out.hatch_lod = t.lod;
}

VisiblePoint gather_point(const SurfaceSample& s, int x, int y, const ShadeInputs& in) {
    const World& world = in.world;
    const uint32_t tri = s.triangle;
    const uint32_t* corners = &world.indices[3 * static_cast<size_t>(tri)];
    const uint32_t i0 = corners[0], i1 = corners[1], i2 = corners[2];
    const Draw& draw = world.draws[world.triangle_draw[tri]];
    VisiblePoint p;
    p.object = draw.object;
    p.style = in.plan.object_style[draw.object];
    const StyleState& style = in.frame.styles[p.style];
    p.material = &in.frame.materials[draw.material];
    const Material& mat = *p.material;
    const float b0 = s.bary.x, b1 = s.bary.y, b2 = s.bary.z;
    const auto& wp = in.vertices.world_position;

    p.albedo = style.base_color.value_or(mat.color);
    if (mat.texture && !style.base_color) {
        const glm::vec2 texels(mat.texture->width, mat.texture->height);
        const TextureLookup t = lookup(corner_uvs(world, corners, mat.uv_scale), s, texels);
        p.albedo *= glm::vec3(mat.texture->sample(t.uv, t.lod));
    }
    if (style.model == ShadingModel::flat) {
        p.normal = glm::cross(wp[i1] - wp[i0], wp[i2] - wp[i0]);
    } else {
        const auto& wn = in.vertices.world_normal;
        p.normal = b0 * wn[i0] + b1 * wn[i1] + b2 * wn[i2];
    }
    if (s.back_facing) p.normal = -p.normal;
    p.position = b0 * wp[i0] + b1 * wp[i1] + b2 * wp[i2];
    p.receives_shadow = world.receives_shadows[draw.object];
    p.depth = s.w;
    if (style.model == ShadingModel::gouraud) {
        const auto& lit = in.vertices.lit;
        p.vertex_light.diffuse = b0 * lit[i0].diffuse + b1 * lit[i1].diffuse + b2 * lit[i2].diffuse;
        p.vertex_light.specular =
            b0 * lit[i0].specular + b1 * lit[i1].specular + b2 * lit[i2].specular;
    }
    p.layers.albedo = p.albedo;
    if (style.wireframe && !world.edge_mask.empty())
        p.layers.wire = wire_coverage(edge_distances(s.bary, s.ddx, s.ddy),
                                      style.wire.width * static_cast<float>(in.samples_per_side),
                                      world.edge_mask[tri]);
    if (style.hatching)
        hatch_coordinates(*style.hatching, draw, world, corners, s, x, y, in.samples_per_side,
                          p.layers);
    return p;
}

// Visible points waiting to be shaded, all of one style, at most eight.
class PendingPoints {
  public:
    PendingPoints(const ShadeInputs& in, const ShadingContext& context)
        : in_(in), context_(context) {}

    void add(const VisiblePoint& p, glm::vec4* target) {
        if (lanes_.count > 0 && p.style != style_) flush();
        style_ = p.style;
        const int i = lanes_.count++;
        SurfaceBatch& s = lanes_.surface;
        s.px[i] = p.position.x, s.py[i] = p.position.y, s.pz[i] = p.position.z;
        s.nx[i] = p.normal.x, s.ny[i] = p.normal.y, s.nz[i] = p.normal.z;
        s.ambient[i] = p.material->ambient, s.diffuse[i] = p.material->diffuse;
        s.specular[i] = p.material->specular, s.shininess[i] = p.material->shininess;
        s.receives_shadow[i] = p.receives_shadow;
        lanes_.albedo[i] = p.albedo;
        lanes_.depth[i] = p.depth;
        lanes_.vertex_light[i] = p.vertex_light;
        layers_[i] = p.layers;
        targets_[i] = target;
        if (lanes_.count == simd::kLanes) flush();
    }

    void flush() {
        if (lanes_.count == 0) return;
        const StyleState& style = in_.frame.styles[style_];
        ShadedLanes shaded;
        shade_lanes(style, context_, lanes_, shaded);
        const bool layers = has_layers(style);
        for (int i = 0; i < lanes_.count; ++i) {
            const glm::vec3 c =
                layers ? apply_layers(style, shaded.color[i], layers_[i], shaded.palette_tone[i])
                       : shaded.color[i];
            *targets_[i] = glm::vec4(c, 1.0f);
        }
        lanes_.count = 0;
    }

  private:
    const ShadeInputs& in_;
    const ShadingContext& context_;
    uint32_t style_ = 0;
    SurfaceLanes lanes_;
    LayerInputs layers_[simd::kLanes];
    glm::vec4* targets_[simd::kLanes];
};

void write_gbuffer(OutlineBuffers& g, int x, int y, float depth, const glm::vec3& normal,
                   uint32_t object) {
    const size_t at = g.index(x, y);
    g.depth[at] = depth;
    g.normal[at] = normal;
    g.object_id[at] = object;
}

}  // namespace

void shade_tile(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                const ShadeTarget& out) {
    const float infinity = std::numeric_limits<float>::infinity();
    const ShadingContext context{in.frame.camera.position, in.lights, in.frame.style_depth_range};
    PendingPoints pending(in, context);
    for (int ty = 0; ty < tile.height; ++ty) {
        const int y = tile.y0 + ty;
        glm::vec4* color_row = &out.color.at(tile.x0, y);
        float* depth_row = &out.depth.at(tile.x0, y);
        for (int tx = 0; tx < tile.width; ++tx) {
            const int x = tile.x0 + tx;
            const uint32_t id = tile.id[ty * kTileSize + tx];
            if (id == kNoTriangle) {
                color_row[tx] = in.frame.background;
                depth_row[tx] = infinity;
                if (out.gbuffer)
                    write_gbuffer(*out.gbuffer, x, y, infinity, glm::vec3(0), kNoObject);
                continue;
            }
            const SurfaceSample s = reconstruct_surface(raster.shade_setup(id), x, y);
            const VisiblePoint p = gather_point(s, x, y, in);
            depth_row[tx] = p.depth;
            if (out.gbuffer) write_gbuffer(*out.gbuffer, x, y, p.depth, p.normal, p.object);
            const StyleState& style = in.frame.styles[p.style];
            if (style.wireframe && !style.wire_fill_shading) {  // lines alone, on a flat fill
                color_row[tx] = glm::vec4(
                    style.wire_fill + (style.wire.color - style.wire_fill) * p.layers.wire, 1.0f);
                continue;
            }
            pending.add(p, &color_row[tx]);
        }
    }
    pending.flush();
}

}  // namespace facet
