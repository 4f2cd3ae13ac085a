// The built-in studio environment (shade/environment_map.hpp): what
// `style: pbr` lights a model with when the scene names no environment, so
// that facet ships no third-party HDR file. docs/pbr.md, "The built-in
// studio", draws the layout.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

#include "core/exact_trig.hpp"
#include "shade/environment_map.hpp"

namespace facet::pbr {

namespace {

constexpr int kStudioWidth = 512;
constexpr int kStudioHeight = 256;

// The grey of the floor straight down, at the horizon and straight up:
// darker below than above, as in a photographic studio whose floor is lit
// from above, and neutral, so that a product's colours come out as authored.
constexpr double kFloorRadiance = 0.12;
constexpr double kHorizonRadiance = 0.26;
constexpr double kZenithRadiance = 0.36;

// A rectangular softbox facing the subject: its centre at `elevation` above
// the horizon and `azimuth` about +Y from +Z (where the default camera
// stands; positive towards +X, the image's right), its half sizes as
// tangents of the angles they subtend, and an edge `softness` (in the same
// tangent units) over which it fades, as a diffuser's rim does.
struct Softbox {
    double elevation_degrees, azimuth_degrees;
    double half_width, half_height, softness;
    double radiance;
};

// Key: large, high, at the camera's front left. Fill: dimmer and lower, at
// the front right, to open the key's shadows. Rim: small and bright,
// high behind the subject, to draw its outline against the background.
constexpr Softbox kKey{35.0, -40.0, 0.55, 0.40, 0.12, 3.0};
constexpr Softbox kFill{12.0, 60.0, 0.40, 0.35, 0.12, 1.2};
constexpr Softbox kRim{40.0, 165.0, 0.25, 0.15, 0.06, 4.0};

// 0 at or below edge0, 1 at or above edge1, the cubic 3x^2 - 2x^3 between.
double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// The grey gradient: the floor brightens towards the horizon over its top
// quarter or so ((1 + y)^4), as light falls on a cove, and the sky rises
// from the horizon to the zenith, eased out (y (2 - y)).
double background(const glm::dvec3& d) {
    if (d.y < 0.0) {
        const double rise = (1.0 + d.y) * (1.0 + d.y);
        return kFloorRadiance + (kHorizonRadiance - kFloorRadiance) * rise * rise;
    }
    return kHorizonRadiance + (kZenithRadiance - kHorizonRadiance) * d.y * (2.0 - d.y);
}

// The softbox's radiance towards d: a rectangle in the plane facing the
// subject, found by projecting d onto that plane (the gnomonic projection
// x / z, y / z in the box's frame), faded over `softness` at its edges.
double softbox(const Softbox& box, const glm::dvec3& d) {
    const double elevation = box.elevation_degrees / 360.0, azimuth = box.azimuth_degrees / 360.0;
    const glm::dvec3 centre(cos_turns(elevation) * sin_turns(azimuth), sin_turns(elevation),
                            cos_turns(elevation) * cos_turns(azimuth));
    const double facing = glm::dot(d, centre);
    if (!(facing > 0.0)) return 0.0;
    // The box's up is the world's +Y made perpendicular to its centre.
    const glm::dvec3 up = glm::normalize(glm::dvec3(0.0, 1.0, 0.0) - centre * centre.y);
    const glm::dvec3 across = glm::cross(up, centre);
    const double x = std::abs(glm::dot(d, across)) / facing;
    const double y = std::abs(glm::dot(d, up)) / facing;
    const double fade_x =
        smoothstep(box.half_width + box.softness, box.half_width - box.softness, x);
    const double fade_y =
        smoothstep(box.half_height + box.softness, box.half_height - box.softness, y);
    return box.radiance * fade_x * fade_y;
}

}  // namespace

EquirectRadiance studio_image() {
    EquirectRadiance image{
        kStudioWidth, kStudioHeight,
        std::vector<float>(static_cast<size_t>(kStudioWidth) * kStudioHeight * 3)};
    for (int row = 0; row < kStudioHeight; ++row)
        for (int column = 0; column < kStudioWidth; ++column) {
            const glm::dvec3 d =
                equirect_direction((column + 0.5) / kStudioWidth, (row + 0.5) / kStudioHeight);
            const double light = std::max({softbox(kKey, d), softbox(kFill, d), softbox(kRim, d)});
            const float grey = static_cast<float>(std::max(background(d), light));
            float* texel = &image.rgb[(static_cast<size_t>(row) * kStudioWidth + column) * 3];
            texel[0] = texel[1] = texel[2] = grey;
        }
    return image;
}

SharedEnvironment studio_environment(unsigned threads) {
    return build_environment(studio_image(), threads);
}

SharedEnvironment shared_studio_environment() {
    static const SharedEnvironment studio = studio_environment();
    return studio;
}

}  // namespace facet::pbr
