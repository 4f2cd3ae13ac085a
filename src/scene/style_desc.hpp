#pragma once
// A style as plain records (docs/styles.md): the shading model and the
// parameters of each look. Numbers and colours may be keyframed.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/error.hpp"
#include "scene/animated.hpp"

namespace facet {

// The shading models a style can select (docs/styles.md).
enum class ShadingModel {
    flat,
    gouraud,
    phong,
    blinn_phong,
    unlit,
    depth,
    normal,
    palette,  // the seed-000 method: two-colour diffuse, cels, hatching
    gooch,    // Gooch et al. 1998 warm/cool
    toon,     // bands, toon highlight, rim light
    pbr,      // glTF's metallic-roughness BRDF, lit by lights and an environment (docs/pbr.md)
};

struct ToonBandDesc {
    float threshold;  // in n.l, -1..1: the band starts here
    glm::vec3 value;  // light level (grey) or colour
};

struct ToonDesc {
    std::vector<ToonBandDesc> bands = {
        {-1.0f, glm::vec3(0.35f)}, {0.0f, glm::vec3(0.7f)}, {0.5f, glm::vec3(1.0f)}};
    bool ramp = false;                // blend between bands instead of stepping
    Animated<float> softness = 0.0f;  // width of a softened band edge in n.l
    Animated<glm::vec3> specular_color = glm::vec3(1);
    Animated<float> specular_threshold = 0.5f;  // hard highlight where (n.h)^s passes this
    float shininess = 32;
    Animated<glm::vec3> rim_color = glm::vec3(0);  // black: no rim light
    float rim_power = 2;
    Animated<float> rim_threshold = 0.5f;
};

// Strokes laid over the shading where it is dark (tonal art maps, Praun et
// al. 2001), in the object's UV space or in screen space.
// Where hatching strokes are laid out (docs/styles.md, "hatching").
enum class HatchSpace {
    object,  // planes of the object's own space, blended by the normal: no UVs needed
    uv,      // the texture coordinates (object space where a mesh has none)
    screen,  // the image: strokes stay put while the surface moves under them
};

// Which way the strokes run.
enum class HatchDirection {
    curvature,  // along the surface's least bend (along a tube); `uv`'s way where flat
    uv,         // along the texture's u, else along `axis`
    axis,       // along `axis`, in the object's own space
    fixed,      // at `angle` in the layout space alone
};

struct HatchingDesc {
    // Many levels: each adds few strokes, so a stroke fades in over a narrow
    // band of tone and reads as a line, not a fading hair.
    int levels = 24;
    HatchSpace space = HatchSpace::object;
    HatchDirection direction = HatchDirection::curvature;
    glm::vec3 axis{0, 1, 0};                 // the object's own axis
    float scale = 8;                         // object and uv space: tiles per unit
    float tile_pixels = 160;                 // the tile's size on screen, in output pixels
    float angle = 0;                         // degrees, from the direction
    float stroke_width = 1.5f;               // pixels
    std::optional<Animated<glm::vec3>> ink;  // unset: the object's colour, darkened
    Animated<float> strength = 1.0f;         // 0 no strokes .. 1 full
    // The lightness (CIE L*/100 of the shaded light) at and above which a
    // surface gets no strokes: the tone is that lightness over `white`, so
    // lit faces stay paper, as an illustrator leaves them.
    Animated<float> white = 1.0f;
    // Stops: the light is scaled by 2^exposure before the tone curve that
    // turns it into strokes (docs/styles.md, "hatching", "Tone").
    Animated<float> exposure = 0.0f;
    bool pencil = false;  // pencil strokes over paper grain
    // Set: the strokes go on a flat wash, the paper tinted by the object's
    // colour by this much (0 paper, 1 the full colour), and carry the tone
    // alone. Unset: they go over the shading.
    std::optional<Animated<float>> wash;
    Animated<glm::vec3> paper = glm::vec3(0.96f, 0.95f, 0.92f);
    int seed = 1;
    // How strokes meet the colour: `ink` blends towards the ink by the
    // stroke coverage; `add` adds ink x coverage, as seed 000's listing adds
    // its stroke texture (docs/references.md, seed 000).
    bool additive = false;
};

struct LineDesc {
    bool enabled = false;
    Animated<float> width = 1.0f;  // pixels of the output image
    Animated<glm::vec3> color = glm::vec3(0);
};

struct OutlinesDesc {
    LineDesc silhouette, crease, boundary, intersection;
    float crease_angle = 30;        // degrees between face normals
    float depth_threshold = 0.02f;  // relative jump in depth that makes a silhouette
    bool any() const {
        return silhouette.enabled || crease.enabled || boundary.enabled || intersection.enabled;
    }
};

// Screen-space ambient occlusion over the shading (post/ambient_occlusion.hpp):
// corners and contacts darken, which grounds a model on its floor.
struct OcclusionDesc {
    bool enabled = false;
    Animated<float> radius = 0.5f;    // scene units
    Animated<float> strength = 1.0f;  // 0 none, 1 the paper's
    int samples = 16;                 // taps per sample
    bool half_resolution = true;      // found per 2 x 2 pixels (`resolution: half`), or per pixel
};

struct WireframeDesc {
    bool enabled = false;
    Animated<float> width = 1.0f;
    Animated<glm::vec3> color = glm::vec3(0);
    bool hidden = false;  // also draw edges behind surfaces
    Animated<glm::vec3> hidden_color = glm::vec3(0.6f);
    // Which edges: the features an illustrator draws (silhouettes, creases
    // sharper than `crease_angle`, boundaries), or every triangle edge but
    // the diagonals inside flat polygons.
    bool all_edges = false;
    float crease_angle = 30.0f;  // degrees between the faces' normals
    // What the faces show: their shading, or one flat colour (wireframe "alone").
    bool fill_shading = true;
    Animated<glm::vec3> fill_color = glm::vec3(1);
};

struct StyleDesc {
    std::string name;         // preset name, file stem, or "inline"
    std::string description;  // one line, shown by `facet styles`
    ShadingModel shading = ShadingModel::blinn_phong;
    // Depth view range in scene units; unset means "fit the scene's bounds".
    std::optional<glm::vec2> depth_range;
    // Replaces every object's colour (e.g. clay); unset keeps materials.
    std::optional<Animated<glm::vec3>> base_color;
    // Replaces the scene's background colour.
    std::optional<glm::vec4> background;
    // Shadows of every light on (true) or off (false) whatever the lights
    // say; unset leaves each light's `shadows`. The seed-001 "lit" and
    // "lit with shadows" display modes differ only in this.
    std::optional<bool> shadows;

    // The seed-000 palette method (docs/references.md, seed 000) and Gooch 1998.
    Animated<glm::vec3> cool = glm::vec3(0, 0, 0.4f);     // c_shadow; Gooch's blue
    Animated<glm::vec3> warm = glm::vec3(0.4f, 0.4f, 0);  // c_lit; Gooch's yellow
    Animated<float> alpha = 0.2f, beta = 0.6f;
    Animated<float> ambient = 0.2f;  // a in ambient = a.k (palette)
    Animated<float> cels = 4.0f;     // 0: no quantisation; rounded to a whole number
    // Seed 000's c' = c.q (false), or c' = c.q/|c|, which keeps |c'| = q
    // and the hue (true; `cel_color: keep_hue`).
    bool cels_keep_hue = false;
    // The tone q/√3 under which the palette model hatches (the seed: 0.5).
    Animated<float> hatch_below = 0.5f;
    Animated<float> specular = 1.0f;
    Animated<float> shininess = 32.0f;

    ToonDesc toon;
    std::optional<HatchingDesc> hatching;
    OutlinesDesc outlines;
    OcclusionDesc occlusion;
    WireframeDesc wireframe;

    std::vector<std::string> chain;  // the presets it extends, nearest last
    std::vector<std::string> files;  // the preset files read: the chain's, then its own
    SourceLocation where;  // its own mapping: a preset file's root, or the scene's inline style
};

const char* shading_model_name(ShadingModel model);

}  // namespace facet
