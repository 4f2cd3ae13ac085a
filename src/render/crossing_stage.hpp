#pragma once
// Stage 8b of a frame, for styles with intersection outlines: which pairs
// of objects really pass through each other this frame. The outlines
// (post/outlines.hpp) find intersection lines in the image, where two
// objects meet without a jump in depth; an image cannot tell an object
// resting flush on a floor from one sunk into it by less than a pixel, so
// they draw intersection lines only between the pairs found here.
#include <cstdint>
#include <vector>

#include "render/vertex_stage.hpp"
#include "render/world.hpp"

namespace facet {

// Object pair key: the smaller scene object index in the high half.
inline uint64_t object_pair_key(uint32_t a, uint32_t b) {
    return a < b ? (static_cast<uint64_t>(a) << 32) | b : (static_cast<uint64_t>(b) << 32) | a;
}

// Sorted keys of the object pairs with at least one pair of triangles that
// cross: each passes through the other's plane, with vertices strictly on
// both sides (beyond a ten-thousandth of the smaller object's size), and
// the two crossing segments overlap (Möller 1997, "A Fast Triangle-Triangle
// Intersection Test"). Triangles that only touch (a cube's base on the
// floor, a pyramid standing on it) do not cross. World positions of this
// frame; serial, and the same for any thread count.
std::vector<uint64_t> crossing_object_pairs(const World& world,
                                            const TransformedVertices& vertices);

}  // namespace facet
