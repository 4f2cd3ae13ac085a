#include "render/outline_stage.hpp"

namespace facet {

OutlineBuffers& OutlineStage::gbuffer(int width, int height) {
    if (buffers_.width != width || buffers_.height != height) buffers_.reset(width, height);
    return buffers_;
}

void OutlineStage::draw(const OutlineStyle& style, ColorImage& color, ThreadPool& pool,
                        ColorImage* lines) {
    draw_outlines(buffers_, style, lines_, pool, scratch_);
    composite_lines(lines_, color, pool);
    if (lines) composite_lines_premultiplied(lines_, *lines, pool);
}

}  // namespace facet
