#pragma once
// The masks of a comparison as one value per pixel (0 = left out), for one
// camera and kind of image (compare/thresholds.hpp, CompareMask). Mask
// images are read once.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "compare/thresholds.hpp"
#include "output/encoders.hpp"

namespace facet {

class MaskBuilder {
  public:
    explicit MaskBuilder(const CompareThresholds& thresholds) : thresholds_(thresholds) {}

    // Empty when no mask applies. A mask image of another size than the
    // images throws Error(invalid_input).
    std::vector<uint8_t> build(const std::string& camera, ImageKind kind, int width, int height);

  private:
    const DecodedPng& mask_image(const std::string& path);

    const CompareThresholds& thresholds_;
    std::map<std::string, DecodedPng> images_;
};

}  // namespace facet
