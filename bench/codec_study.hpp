#pragma once
// What each file encoder costs on a rendered frame: MB of samples per
// second on one thread and the compression ratio, per codec and pass
// (docs/performance.md, "Encoding (issue 36)").
#include <string>

#include "render/frame_renderer.hpp"

namespace facet_bench {

// Markdown rows `| scene | file | codec | raw MB | ms | MB/s | ratio |`
// for the colour and depth of one frame, every codec timed `repeats`
// times on the calling thread (medians).
std::string codec_rows(const std::string& scene_name, const facet::FrameImages& images,
                       int repeats);

// The table's header, to go before the rows of every scene.
std::string codec_table_header();

}  // namespace facet_bench
