#pragma once
// Movies of a sequence's colour frames through FFmpeg's libraries (the
// only module that uses them): H.264 in MP4, VP9 in WebM, or an animated
// GIF with one palette made from all its frames (docs/video.md). The whole
// file is built in memory and returned, so the caller writes it atomically
// and an interrupted run never leaves a broken movie in place.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace facet {

enum class VideoFormat { mp4, webm, gif };

// From the file name's extension (.mp4, .webm, .gif, any case).
std::optional<VideoFormat> video_format_for(const std::string& path);

class VideoEncoder {
  public:
    // Throws facet::Error (runtime_failure) when FFmpeg lacks the codec.
    VideoEncoder(VideoFormat format, int width, int height, double fps);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // One frame: 8-bit sRGB, R, G, B per pixel, row by row.
    void add_frame(std::span<const uint8_t> rgb);

    // Flushes the encoder and returns the whole file.
    std::vector<uint8_t> finish();

  private:
    struct State;
    std::unique_ptr<State> state_;
};

// A JPEG (JFIF) of one 8-bit sRGB RGB image, for stills such as contact
// sheets: full-range 4:4:4 at high quality.
std::vector<uint8_t> encode_jpeg(int width, int height, std::span<const uint8_t> rgb);

}  // namespace facet
