// Shading stage: every visible pixel of a tile is shaded once (deferred),
// from the triangle id and depth the tile stage left in the visibility buffer.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/color.hpp"
#include "render/frame_renderer.hpp"
#include "shade/lighting_batch.hpp"

namespace facet {

namespace {

// Pixels waiting for lighting, gathered so eight are lit at once.
struct PendingPixels {
    SurfaceBatch surface;
    glm::vec3 albedo[simd::kLanes];
    float alpha[simd::kLanes];
    glm::vec4* target[simd::kLanes];
    int count = 0;
};

void flush(PendingPixels& pending, const glm::vec3& eye, std::span<const ShadeLight> lights,
           Highlight highlight) {
    if (pending.count == 0) return;
    pad_batch(pending.surface, pending.count);
    LightingBatch l = light_surface_batch(pending.surface, eye, lights, highlight);
    for (int i = 0; i < pending.count; ++i) {
        const glm::vec3& a = pending.albedo[i];
        *pending.target[i] = {a.x * l.dr[i] + l.sr[i], a.y * l.dg[i] + l.sg[i],
                              a.z * l.db[i] + l.sb[i], pending.alpha[i]};
    }
    pending.count = 0;
}

}  // namespace

void FrameRenderer::shade_tile(const TileVisibility& tile, const CameraMatrices& camera,
                               std::span<const ShadeLight> lights, glm::vec2 depth_range,
                               FrameImages& out) const {
    const ShadingModel model = scene_.style.shading;
    const glm::vec4 background = scene_.output.background;
    const float infinity = std::numeric_limits<float>::infinity();
    const Highlight highlight = model == ShadingModel::phong ? Highlight::phong : Highlight::blinn;
    PendingPixels pending;

    for (int ty = 0; ty < tile.height; ++ty) {
        const int y = tile.y0 + ty;
        glm::vec4* color_row = &out.color.at(tile.x0, y);
        float* depth_row = &out.depth.at(tile.x0, y);
        for (int tx = 0; tx < tile.width; ++tx) {
            const uint32_t id = tile.id[ty * kTileSize + tx];
            if (id == kNoTriangle) {
                color_row[tx] = background;
                depth_row[tx] = infinity;
                continue;
            }
            const ShadeSetup& s = rasterizer_.shade_setup(id);
            // Perspective-correct barycentrics of the source triangle: b/w and
            // 1/w are affine in screen space, b is not (Heckbert & Moreton 1991).
            const float fx = (static_cast<float>(tile.x0 + tx) + 0.5f) - s.x0;
            const float fy = (static_cast<float>(y) + 0.5f) - s.y0;
            const float inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
            const float w = 1.0f / inv_w;
            const float b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) * w;
            const float b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) * w;
            const float b0 = 1.0f - b1 - b2;
            depth_row[tx] = w;  // w_clip is the distance along the viewing axis

            const uint32_t tri = s.source_triangle;
            const uint32_t i0 = world_.indices[3 * tri], i1 = world_.indices[3 * tri + 1],
                           i2 = world_.indices[3 * tri + 2];
            const Draw& draw = world_.draws[world_.triangle_draw[tri]];
            const Material& mat = materials()[draw.material];
            const auto& wp = vertices_.world_position;

            glm::vec3 albedo = mat.color;
            float alpha = 1.0f;
            if (mat.texture) {
                const auto& uv = world_.uvs;
                const glm::vec2 uv0 = uv[i0] * mat.uv_scale;
                const glm::vec2 e1 = uv[i1] * mat.uv_scale - uv0, e2 = uv[i2] * mat.uv_scale - uv0;
                // Texels per pixel step, for the mip level: the screen-space
                // derivatives of b = (b/w) / (1/w) by the quotient rule.
                const float db1dx = (s.b1_w[1] - b1 * s.inv_w[1]) * w;
                const float db1dy = (s.b1_w[2] - b1 * s.inv_w[2]) * w;
                const float db2dx = (s.b2_w[1] - b2 * s.inv_w[1]) * w;
                const float db2dy = (s.b2_w[2] - b2 * s.inv_w[2]) * w;
                const glm::vec2 size(mat.texture->width, mat.texture->height);
                const glm::vec2 ddx = (e1 * db1dx + e2 * db2dx) * size;
                const glm::vec2 ddy = (e1 * db1dy + e2 * db2dy) * size;
                const float texels = std::max(glm::length(ddx), glm::length(ddy));
                const float lod = texels > 1.0f ? std::log2(texels) : 0.0f;
                albedo *= glm::vec3(mat.texture->sample(uv0 + e1 * b1 + e2 * b2, lod));
            }
            if (model == ShadingModel::unlit) {
                color_row[tx] = glm::vec4(albedo, alpha);
                continue;
            }
            if (model == ShadingModel::depth) {
                float t = (depth_range.y - w) / (depth_range.y - depth_range.x);
                color_row[tx] =
                    glm::vec4(glm::vec3(srgb_to_linear(std::clamp(t, 0.0f, 1.0f))), 1.0f);
                continue;
            }
            if (model == ShadingModel::gouraud) {
                const auto& lit = vertices_.lit;
                glm::vec3 diffuse =
                    b0 * lit[i0].diffuse + b1 * lit[i1].diffuse + b2 * lit[i2].diffuse;
                glm::vec3 specular =
                    b0 * lit[i0].specular + b1 * lit[i1].specular + b2 * lit[i2].specular;
                color_row[tx] = glm::vec4(albedo * diffuse + specular, alpha);
                continue;
            }

            glm::vec3 normal;
            if (model == ShadingModel::flat) {
                normal = glm::cross(wp[i1] - wp[i0], wp[i2] - wp[i0]);
            } else {
                const auto& wn = vertices_.world_normal;
                normal = b0 * wn[i0] + b1 * wn[i1] + b2 * wn[i2];
            }
            if (s.back_facing) normal = -normal;
            if (model == ShadingModel::normal) {
                float len = glm::length(normal);
                glm::vec3 n = (len > 0 ? normal / len : glm::vec3(0, 1, 0)) * 0.5f + 0.5f;
                // Shown as the stored bytes, so undo the sRGB encoding to come.
                color_row[tx] = {srgb_to_linear(n.x), srgb_to_linear(n.y), srgb_to_linear(n.z),
                                 1.0f};
                continue;
            }
            // flat, phong and blinn_phong: lit eight pixels at a time.
            const glm::vec3 position = b0 * wp[i0] + b1 * wp[i1] + b2 * wp[i2];
            const int lane = pending.count++;
            SurfaceBatch& sb = pending.surface;
            sb.px[lane] = position.x;
            sb.py[lane] = position.y;
            sb.pz[lane] = position.z;
            sb.nx[lane] = normal.x;
            sb.ny[lane] = normal.y;
            sb.nz[lane] = normal.z;
            sb.ambient[lane] = mat.ambient;
            sb.diffuse[lane] = mat.diffuse;
            sb.specular[lane] = mat.specular;
            sb.shininess[lane] = mat.shininess;
            pending.albedo[lane] = albedo;
            pending.alpha[lane] = alpha;
            pending.target[lane] = &color_row[tx];
            if (pending.count == simd::kLanes) flush(pending, camera.position, lights, highlight);
        }
    }
    flush(pending, camera.position, lights, highlight);
}

}  // namespace facet
