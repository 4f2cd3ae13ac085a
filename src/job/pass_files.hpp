#pragma once
// The files of a frame's passes (docs/passes.md): which pass goes into
// which format, with which EXR channels, in the order they are written.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "job/output_layout.hpp"
#include "output/encoders.hpp"
#include "output/manifest.hpp"
#include "render/frame_renderer.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// The files each frame gets from the scene's passes and formats: per pass
// in output/passes.hpp's order its PNG view (passes that have one), then its
// EXR; with `exr: multilayer` one EXR of every pass last instead.
std::vector<PassFile> frame_files(const OutputDesc& out);

// What one encoder holds while it writes the largest of a frame's files,
// for the memory estimate; the samples themselves are read where the frame
// keeps them. An EXR: the file (a multi-layer one holds every pass), as
// large as its samples from facet's writer (zip, zips, none), up to twice
// that from OpenEXR's (rle, piz, dwaa). A PNG: its view's samples (8-bit
// RGB or RGBA, 16-bit grey for depth), the filtered rows, the compressed
// bytes and the file, four times the view.
uint64_t encoding_bytes(const OutputDesc& out);

// What the files carry besides the pixels.
struct PassFileFacts {
    glm::vec2 depth_range;  // near..far of the depth PNG
    std::vector<PngText> png_text;
    std::vector<ExrAttribute> exr_attributes;
};

// Encodes the frame's files `files` (frame_files of `out`, as the job's
// layout keeps them), in order, handing each to `write`.
void encode_frame_files(
    const OutputDesc& out, std::span<const PassFile> files, const FrameImages& images,
    const PassFileFacts& facts,
    const std::function<void(const PassFile&, const std::vector<uint8_t>&)>& write);

// The samples of one pass's PNG view, as its file holds them, with depth
// mapped from `depth_range`; none for position and motion, which have no view.
std::optional<PngSamples> png_view_samples(Pass pass, const OutputDesc& out,
                                           const FrameImages& images, glm::vec2 depth_range);

// The PNG view of one pass: png_view_samples compressed (empty for a pass
// without a view).
std::vector<uint8_t> encode_png_view(Pass pass, const OutputDesc& out, const FrameImages& images,
                                     const PassFileFacts& facts);

// What each object and material id stands for, for the manifest: scene
// object i has id i + 1, World material i id i + 1 (0 is the background).
// Materials without a name in their file are named "OBJECT:N", N counting
// the object's materials from 0. Empty unless an id pass is written.
std::vector<ManifestId> pass_ids(const SceneDesc& scene, const World& world);

// The EXR channels of one pass, as they are named in its own file
// (`layered` false) or in a multilayer file.
std::vector<ExrChannel> exr_pass_channels(Pass pass, const FrameImages& images, bool layered);

}  // namespace facet
