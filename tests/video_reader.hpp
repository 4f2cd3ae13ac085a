#pragma once
// The tests' check of what the video encoder wrote: the movie decoded again
// by FFmpeg's libraries, independently of src/video.
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

struct VideoSummary {
    std::string codec;
    int width = 0, height = 0;
    int frames = 0;
    double fps = 0;
    std::vector<uint8_t> first_frame_rgb;  // width * height * 3
};
VideoSummary read_video(const std::string& path);

}  // namespace facet
