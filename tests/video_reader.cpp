#include "video_reader.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "core/error.hpp"

namespace facet {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw Error(ExitCode::io_failure, path + ": cannot read video: " + what);
}

}  // namespace

VideoSummary read_video(const std::string& path) {
    AVFormatContext* input = nullptr;
    if (avformat_open_input(&input, path.c_str(), nullptr, nullptr) < 0) fail(path, "not a movie");
    struct Closer {
        AVFormatContext** input;
        AVCodecContext* codec = nullptr;
        AVFrame* frame = nullptr;
        AVPacket* packet = nullptr;
        ~Closer() {
            av_packet_free(&packet);
            av_frame_free(&frame);
            avcodec_free_context(&codec);
            avformat_close_input(input);
        }
    } closer{&input};
    if (avformat_find_stream_info(input, nullptr) < 0) fail(path, "no stream information");
    const int index = av_find_best_stream(input, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) fail(path, "no video stream");
    const AVStream* stream = input->streams[index];
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    if (!decoder) fail(path, "no decoder");
    closer.codec = avcodec_alloc_context3(decoder);
    closer.frame = av_frame_alloc();
    closer.packet = av_packet_alloc();
    avcodec_parameters_to_context(closer.codec, stream->codecpar);
    if (avcodec_open2(closer.codec, decoder, nullptr) < 0) fail(path, "cannot open the decoder");
    VideoSummary summary;
    summary.codec = decoder->name;
    summary.width = closer.codec->width;
    summary.height = closer.codec->height;
    summary.fps = av_q2d(stream->avg_frame_rate);
    auto receive = [&] {
        while (avcodec_receive_frame(closer.codec, closer.frame) == 0) {
            if (summary.frames++ == 0) {
                SwsContext* to_rgb =
                    sws_getContext(closer.frame->width, closer.frame->height,
                                   static_cast<AVPixelFormat>(closer.frame->format),
                                   closer.frame->width, closer.frame->height, AV_PIX_FMT_RGB24,
                                   SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
                if (!to_rgb) fail(path, "no converter to RGB");
                const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
                sws_setColorspaceDetails(to_rgb, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
                summary.first_frame_rgb.resize(static_cast<size_t>(closer.frame->width) *
                                               closer.frame->height * 3);
                uint8_t* out[1] = {summary.first_frame_rgb.data()};
                const int stride[1] = {closer.frame->width * 3};
                sws_scale(to_rgb, closer.frame->data, closer.frame->linesize, 0,
                          closer.frame->height, out, stride);
                sws_freeContext(to_rgb);
            }
            av_frame_unref(closer.frame);
        }
    };
    while (av_read_frame(input, closer.packet) >= 0) {
        if (closer.packet->stream_index == index) {
            avcodec_send_packet(closer.codec, closer.packet);
            receive();
        }
        av_packet_unref(closer.packet);
    }
    avcodec_send_packet(closer.codec, nullptr);
    receive();
    return summary;
}

}  // namespace facet
