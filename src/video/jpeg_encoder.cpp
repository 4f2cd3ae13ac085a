// JPEG stills (contact sheets) through FFmpeg's MJPEG encoder: one frame
// of MJPEG is a JFIF file. Full-range 4:4:4, so thin labels keep their
// colour.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libswscale/swscale.h>
}

#include "core/error.hpp"
#include "video/video_encoder.hpp"

namespace facet {

std::vector<uint8_t> encode_jpeg(int width, int height, std::span<const uint8_t> rgb) {
    auto fail = [](const std::string& what) -> void {
        throw Error(ExitCode::runtime_failure, "JPEG: " + what);
    };
    const AVCodec* encoder = avcodec_find_encoder(AV_CODEC_ID_MJPEG);
    if (!encoder) fail("FFmpeg has no MJPEG encoder");
    struct Parts {
        AVCodecContext* codec = nullptr;
        AVFrame* frame = nullptr;
        AVPacket* packet = nullptr;
        SwsContext* scaler = nullptr;
        ~Parts() {
            sws_freeContext(scaler);
            av_packet_free(&packet);
            av_frame_free(&frame);
            avcodec_free_context(&codec);
        }
    } p;
    av_log_set_level(AV_LOG_ERROR);
    p.codec = avcodec_alloc_context3(encoder);
    p.frame = av_frame_alloc();
    p.packet = av_packet_alloc();
    if (!p.codec || !p.frame || !p.packet) fail("out of memory");
    p.codec->width = width;
    p.codec->height = height;
    p.codec->pix_fmt = AV_PIX_FMT_YUVJ444P;
    p.codec->color_range = AVCOL_RANGE_JPEG;
    p.codec->time_base = {1, 25};
    p.codec->flags |= AV_CODEC_FLAG_QSCALE | AV_CODEC_FLAG_BITEXACT;
    p.codec->global_quality = FF_QP2LAMBDA * 2;  // quantiser 2: near the best MJPEG gives
    if (avcodec_open2(p.codec, encoder, nullptr) < 0) fail("cannot open the encoder");
    p.frame->format = p.codec->pix_fmt;
    p.frame->width = width;
    p.frame->height = height;
    p.frame->quality = p.codec->global_quality;
    if (av_frame_get_buffer(p.frame, 0) < 0) fail("out of memory");
    p.scaler =
        sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUVJ444P,
                       SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
    if (!p.scaler) fail("no RGB to YUV converter");
    const uint8_t* source[1] = {rgb.data()};
    const int stride[1] = {width * 3};
    sws_scale(p.scaler, source, stride, 0, height, p.frame->data, p.frame->linesize);
    p.frame->pts = 0;
    if (avcodec_send_frame(p.codec, p.frame) < 0 || avcodec_send_frame(p.codec, nullptr) < 0)
        fail("encoding failed");
    if (avcodec_receive_packet(p.codec, p.packet) < 0) fail("encoding failed");
    return std::vector<uint8_t>(p.packet->data, p.packet->data + p.packet->size);
}

}  // namespace facet
