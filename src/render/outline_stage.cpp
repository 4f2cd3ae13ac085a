#include "render/outline_stage.hpp"

namespace facet {

void OutlineStage::draw(const OutlineStyle& style, const OutlineBuffers& gbuffer,
                        CrossingPairs crossing, ColorImage& color, ThreadPool& pool,
                        ColorImage* lines) {
    draw_outlines(gbuffer, style, lines_, pool, scratch_, crossing);
    composite_lines(lines_, color, pool);
    if (lines) composite_lines_premultiplied(lines_, *lines, pool);
}

}  // namespace facet
