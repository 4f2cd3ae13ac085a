#pragma once
// What each image file says about itself (PNG tEXt chunks, EXR header
// attributes): facet's version, the scene, the camera with its matrices,
// and the frame, so a file found alone can be traced and reprojected.
// Only facts that are the same on every machine: no paths, times or hosts,
// so files stay bit-identical across runs.
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "output/encoders.hpp"

namespace facet {

struct FileFacts {
    std::string scene;  // the scene's name (file name without .yaml)
    std::string camera;
    int frame = 0;
    std::string style;
    glm::mat4 view{1.0f}, projection{1.0f};
};

// The keys, the same in both formats: "Software", "facet:scene",
// "facet:camera", "facet:frame", "facet:style", "facet:view" and
// "facet:projection" (16 numbers each, column by column, as glm stores
// them).
std::vector<PngText> png_metadata(const FileFacts& facts);
std::vector<ExrAttribute> exr_metadata(const FileFacts& facts);

}  // namespace facet
