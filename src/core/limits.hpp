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

// The widest equirectangular environment image (shade/environment_map.hpp),
// and so the tallest, half of it: 8192 x 4096 texels are 400 MB as float
// RGB while they are filtered, and as large as published maps come. Its
// spherical harmonics alone take about 2 s.
constexpr int kMaxEnvironmentWidth = 8192;

// Scene and style files: far beyond any hand-written scene.
constexpr uint64_t kMaxYamlFileBytes = uint64_t(64) << 20;
// How deep yaml-cpp lets a document nest before it stops (its parser counts
// 2000 recursive calls, about four a level).
constexpr int kMaxYamlNesting = 500;

}  // namespace facet
