#pragma once
// Stage 5c of a frame, for wireframe styles: which triangle edges to draw
// this frame. An illustrator draws features, not the tessellation:
// - silhouettes: edges between a triangle facing the camera and one facing
//   away, found again each frame since they move with the view;
// - creases: folds sharper than the style's `crease_angle`;
// - boundaries: edges with no face across them.
// `wireframe.edges: all` draws every edge but the diagonals inside flat
// polygons instead. A shadow catcher's triangles have none. The result is
// a plain per-triangle mask the shading and hidden-edge stages read (bit i:
// the edge opposite vertex i).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "render/frame_inputs.hpp"
#include "render/world.hpp"

namespace facet {

class FeatureEdgeStage {
  public:
    explicit FeatureEdgeStage(const World& world) : world_(world) {}

    // `clip` holds every world vertex in clip space, this frame. Returns
    // the masks, empty when the world has no edge adjacency (no wireframe).
    std::span<const uint8_t> classify(std::span<const glm::vec4> clip, const FrameInputs& frame,
                                      const StylePlan& plan);

  private:
    const World& world_;
    std::vector<uint8_t> front_facing_;  // per triangle, reused from frame to frame
    std::vector<uint8_t> masks_;
};

}  // namespace facet
