// Shading stage: every visible pixel of a tile is shaded once (deferred),
// from the triangle id and depth the tile stage left in the visibility
// buffer, by the style of the object it shows (docs/styles.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/color.hpp"
#include "render/frame_renderer.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

namespace {

// What is left to do to a pixel after its lighting: hatching strokes and
// wireframe lines (docs/styles.md, "Layers").
struct PixelFinish {
    const StyleState* style = nullptr;  // null when the style has no layers
    glm::vec3 albedo{0};
    glm::vec2 hatch_uv{0};
    float hatch_lod = 0;
    float wire = 0;  // wireframe line coverage
};

float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;  // Rec. 709, linear
}

glm::vec3 finish_pixel(glm::vec3 color, const PixelFinish& f, float palette_tone = -1) {
    if (!f.style) return color;  // no layers: most pixels
    const StyleState& style = *f.style;
    if (style.hatching) {
        const HatchingState& h = *style.hatching;
        // The palette model hatches its own dark cels (seed 000); other
        // models hatch by how much light the surface gets, the brightness
        // relative to its own colour's, so dark colours are not all ink.
        const float lit = luminance(color) / std::max(luminance(f.albedo), 1e-4f);
        const float tone = palette_tone >= 0 ? palette_hatch_tone(style.palette, palette_tone)
                                             : std::clamp(lit, 0.0f, 1.0f);
        const float coverage = tam_coverage(*h.tam, tone, f.hatch_uv, f.hatch_lod) * h.strength;
        if (h.pencil) color *= tam_paper_shade(*h.tam, f.hatch_uv, f.hatch_lod);
        const glm::vec3 ink = h.ink ? *h.ink : palette_ink(style.palette, f.albedo);
        color = apply_hatching(color, ink, coverage);
    }
    if (f.wire > 0) color += (style.wire.color - color) * f.wire;
    return color;
}

// Pixels waiting for Phong lighting, gathered so eight are lit at once.
struct PendingPixels {
    SurfaceBatch surface;
    Highlight highlight = Highlight::blinn;
    glm::vec3 albedo[simd::kLanes];
    PixelFinish finish[simd::kLanes];
    glm::vec4* target[simd::kLanes];
    int count = 0;
};

void flush(PendingPixels& pending, const glm::vec3& eye, std::span<const ShadeLight> lights) {
    if (pending.count == 0) return;
    pad_batch(pending.surface, pending.count);
    LightingBatch l = light_surface_batch(pending.surface, eye, lights, pending.highlight);
    for (int i = 0; i < pending.count; ++i) {
        const glm::vec3& a = pending.albedo[i];
        const glm::vec3 c(a.x * l.dr[i] + l.sr[i], a.y * l.dg[i] + l.sg[i],
                          a.z * l.db[i] + l.sb[i]);
        *pending.target[i] = glm::vec4(finish_pixel(c, pending.finish[i]), 1.0f);
    }
    pending.count = 0;
}

// The stylised models, one pixel at a time. n and v unit; the key light
// (lights[0]) drives the palette, Gooch and toon terms, its shadow taken in
// by darkening its n.l towards -1 (so toon styles get a hard shadow band).
glm::vec3 shade_stylised(const StyleState& style, const glm::vec3& k, const glm::vec3& position,
                         const glm::vec3& n, const glm::vec3& v, std::span<const ShadeLight> lights,
                         bool receives_shadows, float& palette_tone) {
    auto visibility_of = [&](const ShadeLight& light) {
        return receives_shadows ? light_visibility(light, position, n) : 1.0f;
    };
    float n_dot_l = 0;  // no lights: the middle of the palette
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        const LightSample key = sample_light(light, position);
        const float visibility = visibility_of(light);
        n_dot_l = dot3(n, key.to_light);
        n_dot_l = -1.0f + (n_dot_l + 1.0f) * visibility;
        break;
    }
    glm::vec3 c(0);
    switch (style.model) {
        case ShadingModel::palette: {
            const PaletteShading p = seed_palette(style.palette, k, n_dot_l);
            c = p.color;
            palette_tone = p.tone;
            break;
        }
        case ShadingModel::gooch: {
            // Gooch 1998 is the palette blend without ambient or cels.
            PaletteStyle g = style.palette;
            g.ambient = 0;
            g.cels = 0;
            c = seed_palette(g, k, n_dot_l).color;
            break;
        }
        default:
            c = toon_diffuse(style.toon, k, n_dot_l) + toon_rim(style.toon, n, v);
            break;
    }
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        const LightSample l = sample_light(light, position);
        if (!(l.radiance.x > 0 || l.radiance.y > 0 || l.radiance.z > 0)) continue;
        LightSample seen = l;
        seen.radiance *= visibility_of(light);
        if (style.model == ShadingModel::palette)
            c += seed_specular(style.palette, k, n, v, seen);
        else if (style.model == ShadingModel::gooch)
            c += gooch_highlight(style.gooch, n, v, seen);
        else
            c += toon_specular(style.toon, n, v, seen);
    }
    return c;
}

}  // namespace

void FrameRenderer::shade_tile(const TileVisibility& tile, const CameraMatrices& camera,
                               std::span<const ShadeLight> lights, glm::vec2 depth_range,
                               FrameImages& out) {
    const glm::vec4 background = scene_.style.background.value_or(scene_.output.background);
    const float infinity = std::numeric_limits<float>::infinity();
    const bool outlines = outlines_on_;
    PendingPixels pending;

    for (int ty = 0; ty < tile.height; ++ty) {
        const int y = tile.y0 + ty;
        glm::vec4* color_row = &out.color.at(tile.x0, y);
        float* depth_row = &out.depth.at(tile.x0, y);
        for (int tx = 0; tx < tile.width; ++tx) {
            const int x = tile.x0 + tx;
            const uint32_t id = tile.id[ty * kTileSize + tx];
            const size_t outline_at = outlines ? outline_buffers_.index(x, y) : 0;
            if (id == kNoTriangle) {
                color_row[tx] = background;
                depth_row[tx] = infinity;
                if (outlines) {
                    outline_buffers_.depth[outline_at] = infinity;
                    outline_buffers_.object_id[outline_at] = kNoObject;
                }
                continue;
            }
            const ShadeSetup& s = rasterizer_.shade_setup(id);
            // Perspective-correct barycentrics of the source triangle: b/w and
            // 1/w are affine in screen space, b is not (Heckbert & Moreton 1991).
            const float fx = (static_cast<float>(x) + 0.5f) - s.x0;
            const float fy = (static_cast<float>(y) + 0.5f) - s.y0;
            const float inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
            const float w = 1.0f / inv_w;
            const float b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) * w;
            const float b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) * w;
            const float b0 = 1.0f - b1 - b2;
            depth_row[tx] = w;  // w_clip is the distance along the viewing axis
            // Screen-space derivatives of b = (b/w) / (1/w), by the quotient
            // rule: for texture and stroke levels of detail, and wire widths.
            const float db1dx = (s.b1_w[1] - b1 * s.inv_w[1]) * w;
            const float db1dy = (s.b1_w[2] - b1 * s.inv_w[2]) * w;
            const float db2dx = (s.b2_w[1] - b2 * s.inv_w[1]) * w;
            const float db2dy = (s.b2_w[2] - b2 * s.inv_w[2]) * w;

            const uint32_t tri = s.source_triangle;
            const uint32_t i0 = world_.indices[3 * tri], i1 = world_.indices[3 * tri + 1],
                           i2 = world_.indices[3 * tri + 2];
            const Draw& draw = world_.draws[world_.triangle_draw[tri]];
            const Material& mat = materials()[draw.material];
            const StyleState& style = styles_[object_style_[draw.object]];
            const ShadingModel model = style.model;
            const auto& wp = vertices_.world_position;

            auto uv_at = [&](float scale, glm::vec2 size, float& lod) {
                const auto& uv = world_.uvs;
                const glm::vec2 uv0 = uv[i0] * scale;
                const glm::vec2 e1 = uv[i1] * scale - uv0, e2 = uv[i2] * scale - uv0;
                const glm::vec2 ddx = (e1 * db1dx + e2 * db2dx) * size;
                const glm::vec2 ddy = (e1 * db1dy + e2 * db2dy) * size;
                const float texels = std::max(glm::length(ddx), glm::length(ddy));
                lod = texels > 1.0f ? std::log2(texels) : 0.0f;
                return uv0 + e1 * b1 + e2 * b2;
            };

            glm::vec3 albedo = style.base_color.value_or(mat.color);
            if (mat.texture && !style.base_color) {
                const auto& uv = world_.uvs;
                const glm::vec2 uv0 = uv[i0] * mat.uv_scale;
                const glm::vec2 e1 = uv[i1] * mat.uv_scale - uv0, e2 = uv[i2] * mat.uv_scale - uv0;
                const glm::vec2 size(mat.texture->width, mat.texture->height);
                const glm::vec2 ddx = (e1 * db1dx + e2 * db2dx) * size;
                const glm::vec2 ddy = (e1 * db1dy + e2 * db2dy) * size;
                const float texels = std::max(glm::length(ddx), glm::length(ddy));
                const float lod = texels > 1.0f ? std::log2(texels) : 0.0f;
                albedo *= glm::vec3(mat.texture->sample(uv0 + e1 * b1 + e2 * b2, lod));
            }

            glm::vec3 normal;
            if (model == ShadingModel::flat) {
                normal = glm::cross(wp[i1] - wp[i0], wp[i2] - wp[i0]);
            } else {
                const auto& wn = vertices_.world_normal;
                normal = b0 * wn[i0] + b1 * wn[i1] + b2 * wn[i2];
            }
            if (s.back_facing) normal = -normal;
            if (outlines) {
                outline_buffers_.depth[outline_at] = w;
                outline_buffers_.normal[outline_at] = normal;
                outline_buffers_.object_id[outline_at] = draw.object;
            }

            PixelFinish finish;
            if (style.hatching || style.wireframe) {
                finish.style = &style;
                finish.albedo = albedo;
            }
            if (style.wireframe && !world_.edge_mask.empty()) {
                const glm::vec3 bary(b0, b1, b2);
                const glm::vec3 ddx(-db1dx - db2dx, db1dx, db2dx);
                const glm::vec3 ddy(-db1dy - db2dy, db1dy, db2dy);
                finish.wire = wire_coverage(edge_distances(bary, ddx, ddy),
                                            style.wire.width * static_cast<float>(side_),
                                            world_.edge_mask[tri]);
                if (!style.wire_fill_shading) {
                    color_row[tx] = glm::vec4(
                        style.wire_fill + (style.wire.color - style.wire_fill) * finish.wire, 1.0f);
                    continue;
                }
            }
            if (style.hatching) {
                const HatchingState& h = *style.hatching;
                const float size = static_cast<float>(h.tam->params.size);
                if (h.screen_space || !draw.has_uvs) {
                    const float tile_samples = h.tile_pixels * static_cast<float>(side_);
                    finish.hatch_uv =
                        glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) /
                        tile_samples;
                    finish.hatch_lod = std::max(0.0f, std::log2(size / tile_samples));
                } else {
                    finish.hatch_uv = uv_at(h.scale, glm::vec2(size), finish.hatch_lod);
                }
            }

            switch (model) {
                case ShadingModel::unlit:
                    color_row[tx] = glm::vec4(finish_pixel(albedo, finish), 1.0f);
                    continue;
                case ShadingModel::depth: {
                    float t = (depth_range.y - w) / (depth_range.y - depth_range.x);
                    color_row[tx] =
                        glm::vec4(glm::vec3(srgb_to_linear(std::clamp(t, 0.0f, 1.0f))), 1.0f);
                    continue;
                }
                case ShadingModel::gouraud: {
                    const auto& lit = vertices_.lit;
                    glm::vec3 diffuse =
                        b0 * lit[i0].diffuse + b1 * lit[i1].diffuse + b2 * lit[i2].diffuse;
                    glm::vec3 specular =
                        b0 * lit[i0].specular + b1 * lit[i1].specular + b2 * lit[i2].specular;
                    color_row[tx] =
                        glm::vec4(finish_pixel(albedo * diffuse + specular, finish), 1.0f);
                    continue;
                }
                case ShadingModel::normal: {
                    float len = glm::length(normal);
                    glm::vec3 n = (len > 0 ? normal / len : glm::vec3(0, 1, 0)) * 0.5f + 0.5f;
                    // Shown as the stored bytes, so undo the sRGB encoding to come.
                    color_row[tx] = {srgb_to_linear(n.x), srgb_to_linear(n.y), srgb_to_linear(n.z),
                                     1.0f};
                    continue;
                }
                case ShadingModel::palette:
                case ShadingModel::gooch:
                case ShadingModel::toon: {
                    const glm::vec3 position = b0 * wp[i0] + b1 * wp[i1] + b2 * wp[i2];
                    const glm::vec3 n = normalise_or(normal, glm::vec3(0, 1, 0));
                    const glm::vec3 v = normalise_or(camera.position - position, n);
                    float palette_tone = -1;
                    const glm::vec3 c =
                        shade_stylised(style, albedo, position, n, v, lights,
                                       world_.receives_shadows[draw.object] > 0, palette_tone);
                    color_row[tx] = glm::vec4(finish_pixel(c, finish, palette_tone), 1.0f);
                    continue;
                }
                default:
                    break;
            }
            // flat, phong and blinn_phong: lit eight pixels at a time.
            const Highlight highlight =
                model == ShadingModel::phong ? Highlight::phong : Highlight::blinn;
            if (pending.count > 0 && pending.highlight != highlight)
                flush(pending, camera.position, lights);
            pending.highlight = highlight;
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
            sb.receives_shadow[lane] = world_.receives_shadows[draw.object];
            pending.albedo[lane] = albedo;
            pending.finish[lane] = finish;
            pending.target[lane] = &color_row[tx];
            if (pending.count == simd::kLanes) flush(pending, camera.position, lights);
        }
    }
    flush(pending, camera.position, lights);
}

}  // namespace facet
