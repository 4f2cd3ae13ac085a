// FFmpeg's libavcodec, libavformat and libswscale (API of FFmpeg 5.1, as
// in Debian 12). The muxer writes into memory through a seekable
// AVIOContext, so MP4 can put its index at the end as usual.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "video/gif_palette.hpp"
#include "video/video_encoder.hpp"

namespace facet {
namespace {

[[noreturn]] void fail(const std::string& what, int code = 0) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    if (code < 0) av_strerror(code, text, sizeof text);
    throw Error(ExitCode::runtime_failure,
                "video: " + what + (code < 0 ? std::string(": ") + text : std::string()));
}

// A growable file in memory with a position, for the muxer.
struct MemoryFile {
    std::vector<uint8_t> bytes;
    int64_t position = 0;
};

// FFmpeg 5.1 declares the write callback without const.
int memory_write(void* opaque, uint8_t* data, int size) {
    auto* f = static_cast<MemoryFile*>(opaque);
    const auto end = static_cast<size_t>(f->position) + static_cast<size_t>(size);
    if (end > f->bytes.size()) f->bytes.resize(end);
    std::memcpy(f->bytes.data() + f->position, data, static_cast<size_t>(size));
    f->position += size;
    return size;
}

int memory_read(void* opaque, uint8_t* data, int size) {
    auto* f = static_cast<MemoryFile*>(opaque);
    const int64_t left = static_cast<int64_t>(f->bytes.size()) - f->position;
    if (left <= 0) return AVERROR_EOF;
    const int n = static_cast<int>(std::min<int64_t>(left, size));
    std::memcpy(data, f->bytes.data() + f->position, static_cast<size_t>(n));
    f->position += n;
    return n;
}

int64_t memory_seek(void* opaque, int64_t offset, int whence) {
    auto* f = static_cast<MemoryFile*>(opaque);
    if (whence == AVSEEK_SIZE) return static_cast<int64_t>(f->bytes.size());
    whence &= ~AVSEEK_FORCE;
    const int64_t base = whence == SEEK_CUR   ? f->position
                         : whence == SEEK_END ? static_cast<int64_t>(f->bytes.size())
                                              : 0;
    if (base + offset < 0) return -1;
    f->position = base + offset;
    return f->position;
}

}  // namespace

std::optional<VideoFormat> video_format_for(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".mp4") return VideoFormat::mp4;
    if (ext == ".webm") return VideoFormat::webm;
    if (ext == ".gif") return VideoFormat::gif;
    return std::nullopt;
}

struct VideoEncoder::State {
    VideoFormat format;
    int width, height;     // of the frames given
    int coded_w, coded_h;  // even for 4:2:0
    AVRational rate;
    MemoryFile file;
    AVIOContext* io = nullptr;
    AVFormatContext* muxer = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scaler = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    int64_t next_pts = 0;
    std::vector<std::vector<uint8_t>> gif_frames;  // a GIF's palette needs them all

    ~State() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        sws_freeContext(scaler);
        avcodec_free_context(&codec);
        if (muxer) avformat_free_context(muxer);
        if (io) {
            av_freep(&io->buffer);
            avio_context_free(&io);
        }
    }

    void open() {
        const char* muxer_name = format == VideoFormat::mp4    ? "mp4"
                                 : format == VideoFormat::webm ? "webm"
                                                               : "gif";
        if (avformat_alloc_output_context2(&muxer, nullptr, muxer_name, nullptr) < 0 || !muxer)
            fail(std::string("FFmpeg has no ") + muxer_name + " muxer");
        const AVCodec* encoder =
            format == VideoFormat::mp4    ? avcodec_find_encoder_by_name("libx264")
            : format == VideoFormat::webm ? avcodec_find_encoder_by_name("libvpx-vp9")
                                          : avcodec_find_encoder(AV_CODEC_ID_GIF);
        if (!encoder) fail(std::string("FFmpeg has no encoder for ") + muxer_name);
        codec = avcodec_alloc_context3(encoder);
        stream = avformat_new_stream(muxer, nullptr);
        packet = av_packet_alloc();
        frame = av_frame_alloc();
        if (!codec || !stream || !packet || !frame) fail("out of memory");
        const bool yuv = format != VideoFormat::gif;
        coded_w = yuv ? (width + 1) / 2 * 2 : width;
        coded_h = yuv ? (height + 1) / 2 * 2 : height;
        codec->width = coded_w;
        codec->height = coded_h;
        codec->time_base = av_inv_q(rate);
        codec->framerate = rate;
        codec->pix_fmt = yuv ? AV_PIX_FMT_YUV420P : AV_PIX_FMT_PAL8;
        // No library versions in the file: the same frames, the same bytes.
        codec->flags |= AV_CODEC_FLAG_BITEXACT;
        muxer->flags |= AVFMT_FLAG_BITEXACT;
        if (muxer->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        if (yuv) {
            codec->color_primaries = AVCOL_PRI_BT709;
            codec->color_trc = AVCOL_TRC_BT709;
            codec->colorspace = AVCOL_SPC_BT709;
            codec->color_range = AVCOL_RANGE_MPEG;
            codec->gop_size = 48;
        }
        AVDictionary* options = nullptr;
        if (format == VideoFormat::mp4) {
            av_dict_set(&options, "crf", "18", 0);  // visually lossless for renders
            av_dict_set(&options, "preset", "medium", 0);
        } else if (format == VideoFormat::webm) {
            av_dict_set(&options, "crf", "30", 0);  // constant quality: with b:v 0
            av_dict_set(&options, "b", "0", 0);
            av_dict_set(&options, "row-mt", "1", 0);
        }
        const int opened = avcodec_open2(codec, encoder, &options);
        av_dict_free(&options);
        if (opened < 0) fail("cannot open the encoder", opened);
        if (avcodec_parameters_from_context(stream->codecpar, codec) < 0) fail("codec parameters");
        stream->time_base = codec->time_base;
        stream->avg_frame_rate = rate;
        constexpr int kBuffer = 1 << 16;
        auto* buffer = static_cast<uint8_t*>(av_malloc(kBuffer));
        io = avio_alloc_context(buffer, kBuffer, 1, &file, memory_read, memory_write, memory_seek);
        if (!io) fail("out of memory");
        muxer->pb = io;
        AVDictionary* mux_options = nullptr;
        if (format == VideoFormat::gif) av_dict_set(&mux_options, "loop", "0", 0);  // forever
        const int header = avformat_write_header(muxer, &mux_options);
        av_dict_free(&mux_options);
        if (header < 0) fail("cannot write the header", header);
        frame->format = codec->pix_fmt;
        frame->width = coded_w;
        frame->height = coded_h;
        if (av_frame_get_buffer(frame, 0) < 0) fail("out of memory");
        if (yuv) {
            scaler = sws_getContext(
                coded_w, coded_h, AV_PIX_FMT_RGB24, coded_w, coded_h, AV_PIX_FMT_YUV420P,
                SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
            if (!scaler) fail("no RGB to YUV converter");
            // sRGB (full range) in, BT.709 limited range out, as players expect.
            const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
            sws_setColorspaceDetails(scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
        }
    }

    void drain() {
        for (;;) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            if (r < 0) fail("encoding failed", r);
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            const int w = av_interleaved_write_frame(muxer, packet);
            if (w < 0) fail("writing failed", w);
        }
    }

    void send(AVFrame* f) {
        const int r = avcodec_send_frame(codec, f);
        if (r < 0) fail("encoding failed", r);
        drain();
    }

    // The frame padded to even sides by repeating its last column and row.
    std::vector<uint8_t> padded(std::span<const uint8_t> rgb) const {
        std::vector<uint8_t> out(static_cast<size_t>(coded_w) * coded_h * 3);
        for (int y = 0; y < coded_h; ++y)
            for (int x = 0; x < coded_w; ++x) {
                const size_t from = (static_cast<size_t>(std::min(y, height - 1)) * width +
                                     std::min(x, width - 1)) *
                                    3;
                std::copy_n(&rgb[from], 3, &out[(static_cast<size_t>(y) * coded_w + x) * 3]);
            }
        return out;
    }

    void encode_yuv(std::span<const uint8_t> rgb) {
        const std::vector<uint8_t> even = padded(rgb);
        if (av_frame_make_writable(frame) < 0) fail("out of memory");
        const uint8_t* source[1] = {even.data()};
        const int stride[1] = {coded_w * 3};
        sws_scale(scaler, source, stride, 0, coded_h, frame->data, frame->linesize);
        frame->pts = next_pts++;
        send(frame);
    }

    void encode_gif() {
        const GifPalette palette = make_gif_palette(gif_frames);
        for (const auto& rgb : gif_frames) {
            if (av_frame_make_writable(frame) < 0) fail("out of memory");
            const std::vector<uint8_t> indices = map_to_palette(palette, rgb);
            for (int y = 0; y < coded_h; ++y)
                std::copy_n(&indices[static_cast<size_t>(y) * width], width,
                            frame->data[0] + static_cast<ptrdiff_t>(y) * frame->linesize[0]);
            auto* colours = reinterpret_cast<uint32_t*>(frame->data[1]);
            for (size_t i = 0; i < 256; ++i) {
                const auto& c = palette.colors[std::min(i, palette.colors.size() - 1)];
                colours[i] = 0xff000000u | (uint32_t(c[0]) << 16) | (uint32_t(c[1]) << 8) | c[2];
            }
            frame->pts = next_pts++;
            send(frame);
        }
    }
};

VideoEncoder::VideoEncoder(VideoFormat format, int width, int height, double fps)
    : state_(std::make_unique<State>()) {
    // FFmpeg's encoders report statistics on stderr by default; facet's
    // output is its own (errors still come through, as facet::Error).
    av_log_set_level(AV_LOG_ERROR);
    if (width < 1 || height < 1) fail("empty frames");
    if (!(fps > 0) || fps > 1000) fail("fps must be between 0 and 1000");
    state_->format = format;
    state_->width = width;
    state_->height = height;
    state_->rate = av_d2q(fps, 100000);
    state_->open();
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add_frame(std::span<const uint8_t> rgb) {
    if (rgb.size() != static_cast<size_t>(state_->width) * state_->height * 3)
        fail("a frame of another size");
    if (state_->format == VideoFormat::gif)
        state_->gif_frames.emplace_back(rgb.begin(), rgb.end());
    else
        state_->encode_yuv(rgb);
}

std::vector<uint8_t> VideoEncoder::finish() {
    if (state_->format == VideoFormat::gif) state_->encode_gif();
    state_->send(nullptr);  // flush
    const int r = av_write_trailer(state_->muxer);
    if (r < 0) fail("cannot finish the file", r);
    avio_flush(state_->io);
    return std::move(state_->file.bytes);
}

}  // namespace facet
