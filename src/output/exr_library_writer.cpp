// EXR files whose compression facet does not do itself (RLE, PIZ, DWAA):
// written by OpenEXR's C++ library into memory, so the caller still hashes
// and writes the bytes atomically. The library compresses in the calling
// thread (its global thread count stays 0), and the chunks' order is fixed
// by the format, so the bytes depend only on the pixels.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstring>
#include <exception>

#include "core/error.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

// A file that grows in memory; the library seeks back to fill in the
// chunk offset table.
class MemoryStream : public Imf::OStream {
  public:
    // `expected`: the bytes reserved up front, so that growing the file
    // does not hold two copies of it (job/render_memory.cpp counts one).
    explicit MemoryStream(size_t expected) : Imf::OStream("memory") { bytes_.reserve(expected); }
    void write(const char c[], int n) override {
        const size_t end = position_ + static_cast<size_t>(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, static_cast<size_t>(n));
        position_ = end;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }
    std::vector<uint8_t> take() { return std::move(bytes_); }

  private:
    std::vector<uint8_t> bytes_;
    size_t position_ = 0;
};

Imf::PixelType pixel_type(ExrSample type) {
    switch (type) {
        case ExrSample::half:
            return Imf::HALF;
        case ExrSample::float32:
            return Imf::FLOAT;
        case ExrSample::uint32:
            return Imf::UINT;
    }
    return Imf::FLOAT;
}

Imf::Compression library_compression(ExrCompression compression) {
    switch (compression) {
        case ExrCompression::rle:
            return Imf::RLE_COMPRESSION;
        case ExrCompression::piz:
            return Imf::PIZ_COMPRESSION;
        case ExrCompression::dwaa:
            return Imf::DWAA_COMPRESSION;
        case ExrCompression::zips:
            return Imf::ZIPS_COMPRESSION;
        case ExrCompression::zip:
            return Imf::ZIP_COMPRESSION;
        case ExrCompression::none:
            break;
    }
    return Imf::NO_COMPRESSION;
}

}  // namespace

std::vector<uint8_t> encode_exr_with_library(int width, int height,
                                             const std::vector<ExrChannel>& channels,
                                             const std::vector<ExrAttribute>& attributes,
                                             ExrCompression compression) {
    try {
        Imf::Header header(width, height);
        header.compression() = library_compression(compression);
        for (const ExrAttribute& a : attributes)
            header.insert(a.name, Imf::StringAttribute(a.value));
        Imf::FrameBuffer frame;
        for (const ExrChannel& c : channels) {
            header.channels().insert(c.name, Imf::Channel(pixel_type(c.type)));
            // The library reads sample (x, y) at base + x * xStride + y * yStride.
            frame.insert(c.name, Imf::Slice(pixel_type(c.type),
                                            reinterpret_cast<char*>(const_cast<uint8_t*>(c.base)),
                                            c.x_stride, c.row_stride));
        }
        // Room for the samples as they are (most methods make them smaller),
        // the header and the offset table.
        MemoryStream stream(exr_raw_bytes(width, height, channels) + 65536);
        {
            Imf::OutputFile file(stream, header, 1);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        }  // the offset table is written when the file closes
        return stream.take();
    } catch (const std::exception& e) {
        throw Error(ExitCode::runtime_failure, "EXR encoding failed (" +
                                                   std::string(exr_compression_name(compression)) +
                                                   "): " + e.what());
    }
}

}  // namespace facet
