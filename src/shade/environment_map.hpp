#pragma once
// Light from an environment for the physically based shading model: an
// image of the radiance arriving from every direction, prepared once so
// that a shading point reads its diffuse and specular light in a few
// arithmetic operations. docs/pbr.md, "Environment lighting: the
// prefiltered maps", gives every formula and its source.
//
//   diffuse:  9 spherical-harmonic coefficients of the radiance
//             (shade/spherical_harmonics.hpp, Ramamoorthi & Hanrahan 2001)
//   specular: Karis 2013's split sum. The radiance convolved with the GGX
//             lobe of perceptual roughness r_k = k / (kEnvironmentLevels - 1)
//             is level k of a chain of octahedral maps (shade/octahedral_map.hpp,
//             Cigolle et al. 2014); level 0 is the sharp image. The shading
//             model multiplies a lookup by the DFG table's f0 * scale + bias
//             (shade/brdf.hpp).
//   filtering: GGX importance sampling with Hammersley points, each sample
//             read from the mip level its density asks for (filtered
//             importance sampling, Krivanek & Colbert 2008).
//
// Once per run and file:
//   const std::shared_ptr<const PrefilteredEnvironment> env = load_environment(path, warnings);
//   (render/environment_file.hpp reads the file)
// per shading point (n, r and v unit, in the environment's frame):
//   colour += albedo * env->diffuse(n) + dfg * env->specular(r, roughness);
//
// Directions are in world space, right-handed, +Y up (docs/scene-format.md).
// The source image's mapping is EquirectRadiance's: its centre is -Z.
//
// Rotation and intensity belong to the caller, and nothing here knows of
// them: the maps are prefiltered once per run and file, and a keyed
// rotation or intensity costs nothing per frame. An environment turned by
// the angle a about +Y (right-handed, +X towards -Z) gives in direction d
// what this one gives in R_y(-a) d, so the caller turns d by -a before the
// lookup, and multiplies the result by the intensity.
//
// A PrefilteredEnvironment never changes once built: share it read-only
// across threads and frames through std::shared_ptr<const ...>. Lookups are
// pure arithmetic (adds, multiplies, a division, bilinear taps; no
// trigonometry), and prefiltering sums every texel on its own in a fixed
// order, so the maps and every lookup have the same bits for any thread
// count and on every CPU. No global mutable state.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/diagnostics.hpp"
#include "shade/octahedral_map.hpp"
#include "shade/spherical_harmonics.hpp"

namespace facet::pbr {

// Levels of the specular chain: perceptual roughness 0, 1/7, ..., 1,
// evenly spaced in the roughness that glTF calls perceptually linear.
// Between two levels a lookup blends them: from roughness 3/14 on, within
// 2.5 % rms of the lobe in between; below 1/7 it mixes the sharp image with
// a blur rather than blurring slightly (docs/pbr.md has the figures).
constexpr int kEnvironmentLevels = 8;

class PrefilteredEnvironment {
  public:
    // From the parts, as the builders below make them: kEnvironmentLevels
    // maps, level k filtered for roughness level_roughness(k).
    // std::invalid_argument for another count.
    PrefilteredEnvironment(const RadianceSh& sh, std::vector<OctahedralMap> levels);

    // The radiance a white Lambertian surface of unit normal n reflects:
    // diffuse_radiance of the coefficients (irradiance / pi), each channel
    // clamped at 0. Nine terms ring: opposite a small bright light they go
    // slightly negative (docs/pbr.md, "Error of 9 terms"), and light is
    // never negative, so the clamp removes what is an error anyway.
    glm::vec3 diffuse(const glm::vec3& n) const;

    // The prefiltered radiance around the reflected direction (any
    // length) for GGX of the given perceptual roughness, clamped to
    // [0, 1]: the two levels on either side, each filtered bilinearly,
    // blended linearly in roughness. The split sum's first factor: the
    // shading model multiplies it by the DFG table's terms. A NaN
    // roughness reads level 0, and a zero, infinite or NaN direction +Y,
    // rather than memory beyond the maps.
    glm::vec3 specular(const glm::vec3& reflected, float perceptual_roughness) const;

    // diffuse and specular for eight points at once, to the bit: the
    // shading model's form.
    void diffuse(const simd::vf (&n)[3], simd::vf (&radiance)[3]) const;
    void specular(const simd::vf (&reflected)[3], simd::vf perceptual_roughness,
                  simd::vf (&radiance)[3]) const;

    // The environment as a background in the unit direction d: blur 0 is
    // the sharp image (level 0), blur b in (0, 1] the image as a mirror of
    // roughness b reflects it. specular(d, blur), named for its use.
    glm::vec3 radiance(const glm::vec3& d, float blur) const { return specular(d, blur); }

    const RadianceSh& sh() const { return sh_; }
    // Level k, 0 <= k < kEnvironmentLevels: for tests, and for a peer
    // renderer that uploads the maps as textures.
    const OctahedralMap& level(int k) const { return levels_[static_cast<size_t>(k)]; }
    // k / (kEnvironmentLevels - 1).
    static float level_roughness(int k);

  private:
    RadianceSh sh_;
    std::vector<OctahedralMap> levels_;
};

using SharedEnvironment = std::shared_ptr<const PrefilteredEnvironment>;

// Prefilters an equirectangular image (width * height * 3 finite,
// non-negative floats; read_environment_image checks a file's). The sharp
// level (0) is an octahedral map as many texels tall as the image, rounded
// up to a power of two, 32 to 2048; each texel is the mean of 2 x 2
// bilinear reads of the image. Levels 1 to 7 are 256 texels a side or
// fewer, as their lobes allow (docs/pbr.md gives the sizes). `threads` as
// ThreadPool counts them (0: every core this process may use); the result
// has the same bits for any count. 2048 x 1024 takes about 0.5 s on the
// 2-core development machine, 0.9 s on one core (docs/pbr.md).
// std::invalid_argument when the sizes do not match the data.
SharedEnvironment build_environment(const EquirectRadiance& image, unsigned threads = 0);

// An environment of the same radiance in every direction, exactly: every
// specular and radiance lookup returns `radiance` to the bit, and diffuse
// returns it to float rounding (the white furnace). Nothing is filtered:
// the convolution of a constant is the constant.
SharedEnvironment uniform_environment(const glm::vec3& radiance);

// The built-in studio, made in code (no file): a neutral grey gradient from
// a darker floor to a lighter sky, a large soft key softbox high at the
// camera's front left, a dimmer fill at its right and a rim light behind.
// A white diffuse surface facing the key reflects about 0.9. 512 x 256,
// the same bits on every machine; docs/pbr.md gives the layout.
EquirectRadiance studio_image();
// build_environment(studio_image(), threads).
SharedEnvironment studio_environment(unsigned threads = 0);
// The studio, prefiltered on first use and then shared (a function-local
// static const, like the DFG table): the preview rebuilds its world on
// every edit, and the studio is the same each time.
SharedEnvironment shared_studio_environment();

}  // namespace facet::pbr
