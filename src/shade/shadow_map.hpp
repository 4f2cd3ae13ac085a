#pragma once
// Shadow maps (Williams 1978, "Casting curved shadows on curved surfaces"):
// for each texel of a view from the light, the depth of the nearest caster.
// A point is in shadow where something is nearer the light than it is. The
// maps are rendered by render/shadow_stage.cpp through the raster core; this
// file holds their layout, their projections and the lookup.
//
// Lookup: percentage-closer filtering (Reeves, Salesin & Cook 1987, "Rendering
// antialiased shadows with depth maps"): the fraction of the texels under a
// box filter of radius `softness` whose caster is not nearer than the point.
// Against acne, each texel is compared with the depth the receiving surface
// has under that texel, from the plane through the point with its normal
// (receiver plane depth bias, Isidoro 2006, "Shadow mapping: GPU-based tips
// and techniques"), plus a small bias that grows with the slope, and the
// point is first moved off the surface along its normal by about a texel
// (normal offset, Holbein 2011), more where the light grazes the surface.
// All offsets are in texels at the point, so they scale with the map.
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/simd_math.hpp"
#include "shade/lighting.hpp"

namespace facet {

// The side, in texels, of the blocks whose nearest caster a map keeps
// beside its texels (ShadowMap::block_nearest).
inline constexpr int kShadowBlock = 8;

enum class ShadowProjection {
    orthographic,  // directional lights: parallel rays
    perspective,   // spot lights: one frustum round the cone
    cube,          // point lights (and very wide spots): six 90-degree faces
};

struct ShadowMap {
    ShadowProjection projection = ShadowProjection::orthographic;
    int size = 0;   // texels per side of each face; 0 means no map: everything is lit
    int faces = 1;  // 6 for a cube, in the order +x, -x, +y, -y, +z, -z
    // faces * size * size depths, row 0 at the top (+y of the face's view).
    // Each is the distance along the face's viewing axis to the nearest
    // caster at the texel's centre; +infinity where nothing casts.
    std::vector<float> depth;
    // Per face, the smallest depth in each kShadowBlock x kShadowBlock
    // block of texels, `blocks` x `blocks` of them row by row (the last
    // ones cut at the map's edge). A lookup whose filter lies wholly in
    // blocks whose nearest caster is farther than the point can be is lit
    // without reading the texels. Empty: every lookup reads its texels.
    std::vector<float> block_nearest;
    int blocks = 0;
    glm::mat4 view[6];               // world -> face view space (right-handed, looking down -z)
    glm::mat4 clip[6];               // world -> the raster core's clip space (reversed-Z)
    glm::vec3 light_position{0.0f};  // perspective and cube maps: the eye
    // orthographic: NDC units per scene unit (1 / half the map's width);
    // perspective and cube: 1 / tan(half the field of view).
    float scale = 1.0f;
    float near = 0.0f, far = 1.0f;  // depth range along the viewing axis
    float softness = 1.0f;          // filter radius in texels; 0 gives a bilinear-like edge
    float bias = 1.0f;              // scales the depth bias and the normal offset
    // Glass (KHR_materials_transmission under `pbr`) casts apart from what
    // blocks all light, laid out as `depth` and `block_nearest`: per texel
    // the depth of the nearest transmitting caster (+infinity: none) and
    // the share of light it lets through. The filter weighs a texel whose
    // glass is nearer than the point by that share, so glass casts a
    // lighter shadow. Empty when no glass casts.
    struct Glass {
        std::vector<float> depth, passes, block_nearest;
    } glass;
};

// How much of the light reaches `position`, in [0, 1]: 0 in full shadow.
// `normal` is the surface normal on the side the light is on (any length;
// a zero one turns the normal offset and receiver plane off).
float shadow_visibility(const ShadowMap& map, const glm::vec3& position, const glm::vec3& normal);

// The same for eight points at once, in the lanes set in `lanes` (the
// others get 1): the bits the one-point version gives each. The placing in
// the map runs over the lanes; the filter, one lane at a time.
struct ShadowPoints {
    simd::vf px, py, pz;  // positions
    simd::vf nx, ny, nz;  // normals, as for shadow_visibility
};
simd::vf shadow_visibility(const ShadowMap& map, const ShadowPoints& points, unsigned lanes);

// The same for a shading light: 1 when it has no shadow map. For shading
// models that light one point at a time (the stylised styles); the
// batched Phong lighting calls shadow_visibility itself.
inline float light_visibility(const ShadeLight& light, const glm::vec3& position,
                              const glm::vec3& normal) {
    return light.shadow ? shadow_visibility(*light.shadow, position, normal) : 1.0f;
}

// A right-handed frame looking along `forward` (unit): the view matrix's
// rows are right, up and -forward. Up is as close to +Y as it can be (+Z
// when looking straight up or down), so it stays put while the light turns.
struct ShadowBasis {
    glm::vec3 right, up, forward;
};
ShadowBasis shadow_basis(const glm::vec3& forward);

// The view matrix of a basis with its eye at `eye`.
glm::mat4 shadow_view(const ShadowBasis& basis, const glm::vec3& eye);

// Projections. Each sets view, clip, scale, near and far of every face,
// and sizes `depth` for `size` texels a side.
void set_orthographic(ShadowMap& map, int size, const glm::mat4& view, float half_width, float near,
                      float far);
void set_perspective(ShadowMap& map, int size, const glm::vec3& position, const glm::vec3& forward,
                     float tan_half_fov, float near, float far);
// Each face looks along one axis; tan_half_fov >= 1 widens the faces past
// 90 degrees, so a filter near a face's edge still finds texels.
void set_cube(ShadowMap& map, int size, const glm::vec3& position, float tan_half_fov, float near,
              float far);

// Linear depth along the viewing axis from the raster core's reversed-Z depth.
float shadow_depth_from_raster(const ShadowMap& map, float z);

}  // namespace facet
