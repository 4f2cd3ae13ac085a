// Reading OpenEXR files (tests, comparisons) through OpenEXR's C++ API.
#include <cstdint>
#include <limits>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "core/error.hpp"
#include "output/encoders.hpp"

namespace facet {

DecodedExr read_exr_header(const std::string& path) {
    try {
        // Opening reads the header and the chunk offsets, not the pixels.
        Imf::InputFile file(path.c_str(), 1);
        const Imath::Box2i window = file.header().dataWindow();
        // In 64 bits: a damaged window's corners can be far enough apart
        // to overflow an int.
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
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ExitCode::invalid_input, path + ": cannot read EXR: " + e.what());
    }
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
