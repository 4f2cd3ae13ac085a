#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cstring>

#include "core/error.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

// OpenEXR writes through a seekable stream; this one collects bytes in memory.
class MemoryStream : public Imf::OStream {
  public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + n > bytes_.size()) bytes_.resize(position_ + n);
        std::memcpy(bytes_.data() + position_, c, static_cast<size_t>(n));
        position_ += static_cast<uint64_t>(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t pos) override { position_ = pos; }
    std::vector<uint8_t> take() { return std::move(bytes_); }

  private:
    std::vector<uint8_t> bytes_;
    uint64_t position_ = 0;
};

// ZIP at zlib level 1: on half and float data, higher levels save only a
// few percent and take several times longer (measured in docs/performance.md).
constexpr int kExrZipLevel = 1;

// Writes the frame buffer's channels (already listed in the header) to bytes.
std::vector<uint8_t> write_exr(const Imf::Header& header, const Imf::FrameBuffer& fb, int height) {
    MemoryStream stream;
    try {
        Imf::OutputFile file(stream, header, 1);
        file.setFrameBuffer(fb);
        file.writePixels(height);
    } catch (const std::exception& e) {
        throw Error(ExitCode::runtime_failure, std::string("EXR encoding failed: ") + e.what());
    }
    return stream.take();
}

Imf::Header make_header(int width, int height) {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.zipCompressionLevel() = kExrZipLevel;
    return header;
}

}  // namespace

std::vector<uint8_t> encode_exr_color(const HalfColorImage& image) {
    Imf::Header header = make_header(image.width, image.height);
    const char* names[4] = {"R", "G", "B", "A"};
    Imf::FrameBuffer fb;
    // The frame's own half floats, straight from the interleaved pixels.
    char* base = reinterpret_cast<char*>(const_cast<Rgba16F*>(image.pixels.data()));
    for (int c = 0; c < 4; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::HALF));
        fb.insert(names[c], Imf::Slice(Imf::HALF, base + c * sizeof(uint16_t), sizeof(Rgba16F),
                                       sizeof(Rgba16F) * static_cast<size_t>(image.width)));
    }
    return write_exr(header, fb, image.height);
}

std::vector<uint8_t> encode_exr_depth(const DepthImage& depth) {
    Imf::Header header = make_header(depth.width, depth.height);
    header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    Imf::FrameBuffer fb;
    fb.insert("Z", Imf::Slice(Imf::FLOAT,
                              reinterpret_cast<char*>(const_cast<float*>(depth.pixels.data())),
                              sizeof(float), sizeof(float) * depth.width));
    return write_exr(header, fb, depth.height);
}

DecodedExr read_exr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str(), 1);
        const Imath::Box2i window = file.header().dataWindow();
        DecodedExr out;
        out.width = window.max.x - window.min.x + 1;
        out.height = window.max.y - window.min.y + 1;
        Imf::FrameBuffer fb;
        const size_t count = static_cast<size_t>(out.width) * out.height;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
            out.channel_names.push_back(it.name());
        out.channels.resize(out.channel_names.size(), std::vector<float>(count));
        for (size_t c = 0; c < out.channel_names.size(); ++c) {
            char* base = reinterpret_cast<char*>(out.channels[c].data()) -
                         (static_cast<ptrdiff_t>(window.min.x) +
                          static_cast<ptrdiff_t>(window.min.y) * out.width) *
                             sizeof(float);
            fb.insert(out.channel_names[c],
                      Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * out.width));
        }
        file.setFrameBuffer(fb);
        file.readPixels(window.min.y, window.max.y);
        return out;
    } catch (const std::exception& e) {
        throw Error(ExitCode::invalid_input, path + ": cannot read EXR: " + e.what());
    }
}

}  // namespace facet
