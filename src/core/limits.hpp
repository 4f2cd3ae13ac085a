#pragma once
// Limits on values users give, named once for every module that checks them.
#include <cstdint>

namespace facet {

// Largest image side, for output, sample grids and textures alike: keeps
// tile and pixel indices well inside int32 (raster/raster_limits.hpp).
constexpr int kMaxImageSide = 16384;

// Largest coordinate or length a scene may hold, in scene units: far inside
// float range, so products of two of them stay finite.
constexpr double kMaxCoordinate = 1e7;

}  // namespace facet
