#pragma once
// Stage 8 of a frame: hidden edges of wireframe styles (`wireframe.hidden:
// true`), the feature edges behind surfaces, drawn after shading in their
// own colour. Visible edges are drawn by the shading stage itself.
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/image.hpp"
#include "render/frame_inputs.hpp"
#include "render/world.hpp"

namespace facet {

class HiddenEdgeStage {
  public:
    explicit HiddenEdgeStage(const World& world) : world_(world) {}

    // `clip` holds every world vertex in clip space; `edge_mask` the edges
    // to draw (render/feature_edge_stage.hpp); `depth` and `color` are
    // the shaded images at sample resolution (`samples_per_side` per pixel
    // side). `lines` holds the visible strokes the shading stage drew
    // (premultiplied RGBA, per sample): hidden edges go under them, so a
    // visible line always wins where the two meet, and are added to them.
    void draw(std::span<const glm::vec4> clip, const FrameInputs& frame, const StylePlan& plan,
              std::span<const uint8_t> edge_mask, int samples_per_side, const DepthImage& depth,
              ColorImage& color, ColorImage& lines);

  private:
    const World& world_;
    std::vector<float> coverage_;  // reused from frame to frame
    std::vector<glm::vec3> line_color_;
};

}  // namespace facet
