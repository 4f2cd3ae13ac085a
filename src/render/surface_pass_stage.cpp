#include "render/surface_pass_stage.hpp"

#include "render/normal_map_lookup.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "raster/surface_sample.hpp"
#include "render/tile_fragments.hpp"

namespace facet {
namespace {

template <typename Pixel>
void fit(Image<Pixel>& image, bool wanted, int width, int height) {
    if (!wanted) return;
    if (image.width != width || image.height != height)
        image = Image<Pixel>::uninitialized(width, height);
}

// What one fragment shows.
struct FragmentValues {
    glm::vec3 normal{0.0f}, position{0.0f};
    glm::vec2 uv{0.0f}, motion{0.0f};
    uint32_t object_id = 0, material_id = 0;
    float depth = 0;  // linear view depth, for ties
};

// Where a clip-space point lands, in output pixels with y down.
glm::vec2 to_pixels(const glm::vec4& clip, int width, int height) {
    return {(clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width),
            (0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(height)};
}

template <typename T, typename Array>
T interpolate(const Array& values, const uint32_t* corners, const glm::vec3& bary) {
    return values[corners[0]] * bary[0] + values[corners[1]] * bary[1] +
           values[corners[2]] * bary[2];
}

FragmentValues fragment_values(const SurfacePassInputs& in, const Rasterizer& raster, uint32_t id,
                               float x, float y) {
    const ShadeSetup& setup = raster.shade_setup(id);
    const SurfaceSamples lanes =
        reconstruct_surfaces(splat_setup(setup), simd::splat(x), simd::splat(y));
    const SurfaceSample s = surface_lane(lanes, 0, setup);
    const World& world = in.world;
    const uint32_t* corners = &world.indices[3 * static_cast<size_t>(s.triangle)];
    const Draw& draw = world.draws[world.triangle_draw[s.triangle]];
    FragmentValues v;
    v.depth = s.w;
    v.object_id = draw.object + 1;
    v.material_id = draw.material + 1;
    const PassSet passes = in.passes;
    if (passes.has(Pass::normal)) {
        glm::vec3 n = interpolate<glm::vec3>(in.vertices.world_normal, corners, s.bary);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f);
        // A `pbr` style draws the normal map: the pass shows what it shades with.
        const Material& m = in.frame.materials[draw.material];
        if (in.normal_mapped[draw.object] &&
            draws_normal_map(world, in.vertices, m.normal_map, s.triangle) && length > 0.0f) {
            SurfaceSample pixel = s;
            pixel.ddx *= static_cast<float>(in.samples_per_side);
            pixel.ddy *= static_cast<float>(in.samples_per_side);
            n = normal_from_map(world, in.vertices, m.normal_map, m.normal_scale, pixel, n);
        } else if (s.back_facing) {
            n = -n;  // the side the camera sees, as shading uses
        }
        if (in.normals_in_camera_space) n = glm::mat3(in.frame.camera.view) * n;
        v.normal = n;
    }
    if (passes.has(Pass::position))
        v.position = interpolate<glm::vec3>(in.vertices.world_position, corners, s.bary);
    if (passes.has(Pass::uv) && draw.has_uvs) {
        // The coordinates the base colour texture reads (set and transform).
        const std::array<glm::vec2, 3> c =
            world.corner_uvs(s.triangle, in.frame.materials[draw.material].base_color_map);
        v.uv = s.bary[0] * c[0] + s.bary[1] * c[1] + s.bary[2] * c[2];
    }
    if (passes.has(Pass::motion)) {
        // Both ends through the same interpolation of clip positions, so a
        // still point moves by exactly zero.
        const glm::vec4 now = interpolate<glm::vec4>(in.vertices.clip, corners, s.bary);
        const glm::vec4 before = interpolate<glm::vec4>(in.previous_clip, corners, s.bary);
        if (before.w > 0.0f && now.w > 0.0f) {
            const glm::vec2 d =
                to_pixels(before, in.width, in.height) - to_pixels(now, in.width, in.height);
            v.motion = {d.x, -d.y};
        }
    }
    return v;
}

}  // namespace

void fit_surface_passes(const SurfacePassInputs& in, SurfacePassImages& images) {
    const PassSet p = in.passes;
    fit(images.normal, p.has(Pass::normal), in.width, in.height);
    fit(images.object_id, p.has(Pass::object_id), in.width, in.height);
    fit(images.material_id, p.has(Pass::material_id), in.width, in.height);
    fit(images.uv, p.has(Pass::uv), in.width, in.height);
    fit(images.position, p.has(Pass::position), in.width, in.height);
    fit(images.motion, p.has(Pass::motion), in.width, in.height);
}

uint64_t surface_pass_pixel_bytes(Pass pass) {
    switch (pass) {
        case Pass::normal:
            return decltype(SurfacePassImages::normal)::kPixelBytes;
        case Pass::object_id:
            return decltype(SurfacePassImages::object_id)::kPixelBytes;
        case Pass::material_id:
            return decltype(SurfacePassImages::material_id)::kPixelBytes;
        case Pass::uv:
            return decltype(SurfacePassImages::uv)::kPixelBytes;
        case Pass::position:
            return decltype(SurfacePassImages::position)::kPixelBytes;
        case Pass::motion:
            return decltype(SurfacePassImages::motion)::kPixelBytes;
        default:
            return 0;
    }
}

void write_surface_passes(const TileVisibility& tile, const Rasterizer& raster,
                          const SurfacePassInputs& in, SurfacePassImages& out) {
    const int side = in.samples_per_side;
    const PassSet p = in.passes;
    TileFragments f;
    build_tile_fragments(tile, side, false, f);
    const float per_sample = 1.0f / static_cast<float>(side * side);
    int at = 0;
    for (int py = 0; py < f.pixels_y; ++py)
        for (int px = 0; px < f.pixels_x; ++px) {
            const int pixel = py * f.pixels_x + px;
            // The pixel's fragments follow one another in the list.
            FragmentValues sum, chosen;
            int chosen_samples = f.empty[pixel];  // the background's claim
            for (; at < f.count && f.pixel[at] == pixel; ++at) {
                const FragmentValues v = fragment_values(in, raster, f.id[at], f.x[at], f.y[at]);
                const float weight = static_cast<float>(f.samples[at]) * per_sample;
                sum.normal += v.normal * weight;
                sum.uv += v.uv * weight;
                sum.position += v.position * weight;
                const int samples = f.samples[at];
                // A surface wins a tie with the background, the nearer a tie with another.
                if (samples > chosen_samples ||
                    (samples == chosen_samples &&
                     (chosen.object_id == 0 || v.depth < chosen.depth))) {
                    chosen = v;
                    chosen_samples = samples;
                }
            }
            const int x = tile.x0 / side + px, y = tile.y0 / side + py;
            if (p.has(Pass::normal)) out.normal.at(x, y) = sum.normal;
            if (p.has(Pass::uv)) out.uv.at(x, y) = sum.uv;
            if (p.has(Pass::position)) out.position.at(x, y) = sum.position;
            if (p.has(Pass::object_id)) out.object_id.at(x, y) = chosen.object_id;
            if (p.has(Pass::material_id)) out.material_id.at(x, y) = chosen.material_id;
            if (p.has(Pass::motion)) out.motion.at(x, y) = chosen.motion;
        }
}

}  // namespace facet
