#pragma once
// Stage 9 of a frame: outlines (post/outlines.hpp) from the G-buffer the
// shading stage filled, drawn over the colour at the sample resolution so
// that the resolve anti-aliases them like the surfaces.
#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "post/outlines.hpp"

namespace facet {

class OutlineStage {
  public:
    // Lines from the G-buffer over `color` (the same size), and over
    // `lines` (premultiplied strokes alone, the lines pass) when given;
    // intersection lines only between `crossing`'s pairs when given.
    void draw(const OutlineStyle& style, const OutlineBuffers& gbuffer, CrossingPairs crossing,
              ColorImage& color, ThreadPool& pool, ColorImage* lines = nullptr);

  private:
    OutlineScratch scratch_;
    ColorImage lines_;
};

}  // namespace facet
