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

// Largest image file facet decodes (compressed bytes); the decoded size is
// bounded separately, by kMaxImageSide and the texture budget.
constexpr uint64_t kMaxImageFileBytes = uint64_t(1) << 30;

// Scene and style files: far beyond any hand-written scene.
constexpr uint64_t kMaxYamlFileBytes = uint64_t(64) << 20;
// How deep yaml-cpp lets a document nest before it stops (its parser counts
// 2000 recursive calls, about four a level).
constexpr int kMaxYamlNesting = 500;

}  // namespace facet
