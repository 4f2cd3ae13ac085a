// Reading OpenEXR files (environments, comparisons, movies) through
// OpenEXR's C++ API, from a file whose header was checked first.
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "output/encoders.hpp"

namespace facet {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw Error(ExitCode::invalid_input, path + ": cannot read EXR: " + why);
}

// A null-terminated name at `at` of at most `longest` characters; `at`
// moves past its null. "" for the null byte that ends a header.
std::string read_name(const InputFileReader& file, uint64_t& at, size_t longest) {
    const size_t window = static_cast<size_t>(std::min<uint64_t>(longest + 1, file.size() - at));
    std::string bytes(window, '\0');
    file.read_at(at, bytes.data(), window);
    const size_t end = bytes.find('\0');
    if (end == std::string::npos)
        refuse(file.path(), "a header name at byte " + std::to_string(at) + " is longer than " +
                                std::to_string(longest) + " characters or runs past the end");
    at += end + 1;
    return bytes.substr(0, end);
}

// Walks the file's headers (the OpenEXR file layout: magic number, version
// field, then per part a list of attributes, each a name, a type name, a
// 32-bit size and that many bytes, ended by an empty name; a multi-part
// file ends its list of headers with an empty header) and refuses a size
// past the end of the file. OpenEXR allocates an attribute's declared size
// before it reads it: a 29-byte file could declare 2 GB.
void check_headers(const InputFileReader& file) {
    if (file.size() < 8) refuse(file.path(), "the file is too short to be an EXR");
    unsigned char start[8];
    file.read_at(0, reinterpret_cast<char*>(start), 8);
    if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01)
        refuse(file.path(), "no OpenEXR magic number");
    const uint32_t flags = start[5] | (uint32_t(start[6]) << 8) | (uint32_t(start[7]) << 16);
    const size_t longest = (flags & 0x4) ? 255 : 31;  // bit 10 of the field: long names
    const bool multipart = flags & 0x10;              // bit 12
    uint64_t at = 8;
    for (int part = 0;; ++part) {
        if (at >= file.size()) refuse(file.path(), "the header runs past the end of the file");
        if (multipart && part > 0) {
            char end = 0;
            file.read_at(at, &end, 1);
            if (end == '\0') return;  // the empty header after the last part
        }
        for (;;) {
            if (at >= file.size()) refuse(file.path(), "the header runs past the end of the file");
            const std::string name = read_name(file, at, longest);
            if (name.empty()) break;
            const std::string type = read_name(file, at, longest);
            if (file.size() - at < 4) refuse(file.path(), "attribute '" + name + "' has no size");
            unsigned char size_bytes[4];
            file.read_at(at, reinterpret_cast<char*>(size_bytes), 4);
            at += 4;
            const int32_t size = static_cast<int32_t>(
                size_bytes[0] | (uint32_t(size_bytes[1]) << 8) | (uint32_t(size_bytes[2]) << 16) |
                (uint32_t(size_bytes[3]) << 24));
            if (size < 0 || static_cast<uint64_t>(size) > file.size() - at)
                refuse(file.path(), "attribute '" + name + "' (" + type + ") declares " +
                                        std::to_string(size) + " bytes, but the file has " +
                                        std::to_string(file.size() - at) + " after it");
            at += static_cast<uint64_t>(size);
        }
        if (!multipart) return;
    }
}

// The checked file as OpenEXR's input: reads by ranges from the file that
// was opened and checked, and refuses to read past its end.
class CheckedStream : public Imf::IStream {
  public:
    explicit CheckedStream(const InputFileReader& file)
        : Imf::IStream(file.path().c_str()), file_(file) {}
    bool read(char out[], int count) override {
        if (count < 0 || static_cast<uint64_t>(count) > file_.size() - at_)
            refuse(file_.path(), "a read past the end of the file");
        file_.read_at(at_, out, static_cast<size_t>(count));
        at_ += static_cast<uint64_t>(count);
        return at_ < file_.size();
    }
    uint64_t tellg() override { return at_; }
    void seekg(uint64_t position) override { at_ = position; }

  private:
    const InputFileReader& file_;
    uint64_t at_ = 0;
};

// Opens the file, checks its headers, and hands OpenEXR's input file to
// `use`; OpenEXR's exceptions become invalid_input naming the file.
template <typename Use>
DecodedExr with_exr_file(const std::string& path, Use&& use) {
    const InputFileReader file(path, "EXR");
    check_headers(file);
    CheckedStream stream(file);
    try {
        Imf::InputFile exr(stream, 1);
        return use(exr);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        refuse(path, e.what());
    }
}

// The data window's size and the channel names.
DecodedExr shape_of(const Imf::InputFile& file, const std::string& path) {
    const Imath::Box2i window = file.header().dataWindow();
    // In 64 bits: a damaged window's corners can be far enough apart to
    // overflow an int.
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    if (width < 1 || height < 1 || width > std::numeric_limits<int>::max() ||
        height > std::numeric_limits<int>::max())
        throw Error(ExitCode::invalid_input, path + ": the EXR's data window is " +
                                                 std::to_string(width) + "x" +
                                                 std::to_string(height) + " pixels");
    DecodedExr out;
    out.width = static_cast<int>(width);
    out.height = static_cast<int>(height);
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
        out.channel_names.push_back(it.name());
    return out;
}

}  // namespace

DecodedExr read_exr_header(const std::string& path) {
    // Opening reads the header and the chunk offsets, not the pixels.
    return with_exr_file(path, [&](Imf::InputFile& file) { return shape_of(file, path); });
}

DecodedExr read_exr(const std::string& path) {
    return with_exr_file(path, [&](Imf::InputFile& file) {
        DecodedExr out = shape_of(file, path);
        const Imath::Box2i window = file.header().dataWindow();
        Imf::FrameBuffer fb;
        const size_t count = static_cast<size_t>(out.width) * out.height;
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
    });
}

}  // namespace facet
