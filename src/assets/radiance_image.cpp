#include "assets/radiance_image.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <memory>

#include <stb/stb_image.h>

#include "core/error.hpp"

namespace facet {
namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
    throw Error(ExitCode::invalid_input, name + ": " + why);
}

int length_for_stb(size_t size, const std::string& name) {
    if (size > static_cast<size_t>(std::numeric_limits<int>::max()))
        refuse(name, "the Radiance .hdr file is too large (over 2 GB)");
    return static_cast<int>(size);
}

// The bytes as stb_image's reader callbacks see them. stb asks for more
// only when it needs more, so a request at the end means that the data
// stopped before the image did. stb itself would then read zeros, and a
// zero run length makes its decoder loop for ever (it checks only for runs
// too long); past the end this reader hands it newlines instead, which end
// a header line and count as a run of 10, so stb always gets to the end of
// the image, and the result is refused.
struct BoundedReader {
    static constexpr char kFiller = '\n';

    const uint8_t* bytes;
    size_t size;
    size_t position = 0;
    bool read_past_end = false;

    static int read(void* user, char* out, int wanted) {
        auto& self = *static_cast<BoundedReader*>(user);
        if (wanted <= 0) return 0;
        if (self.position >= self.size) {
            self.read_past_end = true;
            std::memset(out, kFiller, static_cast<size_t>(wanted));
            return wanted;
        }
        const size_t count = std::min(static_cast<size_t>(wanted), self.size - self.position);
        std::memcpy(out, self.bytes + self.position, count);
        self.position += count;
        return static_cast<int>(count);
    }
    static void skip(void* user, int n) {
        auto& self = *static_cast<BoundedReader*>(user);
        self.position += std::min(static_cast<size_t>(std::max(n, 0)), self.size - self.position);
    }
    static int eof(void* user) {
        const auto& self = *static_cast<const BoundedReader*>(user);
        return self.position >= self.size ? 1 : 0;
    }
};

}  // namespace

bool is_radiance_hdr(const uint8_t* bytes, size_t size) {
    const auto starts = [&](const char* magic) {
        const size_t length = std::strlen(magic);
        return size >= length && std::memcmp(bytes, magic, length) == 0;
    };
    return starts("#?RADIANCE") || starts("#?RGBE");
}

RadianceHdrSize radiance_hdr_size(const uint8_t* bytes, size_t size, const std::string& name) {
    RadianceHdrSize header;
    int channels = 0;
    if (!is_radiance_hdr(bytes, size) ||
        !stbi_info_from_memory(bytes, length_for_stb(size, name), &header.width, &header.height,
                               &channels))
        refuse(name,
               "cannot read the Radiance .hdr header (it must say FORMAT=32-bit_rle_rgbe and "
               "give the size as \"-Y height +X width\")");
    if (header.width <= 0 || header.height <= 0)
        refuse(name, "the Radiance .hdr header gives a size of " + std::to_string(header.width) +
                         "x" + std::to_string(header.height) + " texels");
    return header;
}

RgbFloatImage decode_radiance_hdr(const uint8_t* bytes, size_t size, const std::string& name) {
    const RadianceHdrSize header = radiance_hdr_size(bytes, size, name);
    BoundedReader reader{bytes, size};
    const stbi_io_callbacks callbacks{&BoundedReader::read, &BoundedReader::skip,
                                      &BoundedReader::eof};
    int width = 0, height = 0, channels = 0;
    float* data = stbi_loadf_from_callbacks(&callbacks, &reader, &width, &height, &channels, 3);
    const std::unique_ptr<float, void (*)(void*)> owned(data, stbi_image_free);
    // First: past the end, stb's own complaint is about the filler.
    if (reader.read_past_end) refuse(name, "the Radiance .hdr file ends before its last texel");
    if (!data)
        refuse(name, std::string("cannot decode the Radiance .hdr texels (") +
                         stbi_failure_reason() + ")");
    if (width != header.width || height != header.height)
        refuse(name, "the Radiance .hdr texels do not match the header's size");
    RgbFloatImage image{width, height, {}};
    image.rgb.assign(data, data + static_cast<size_t>(width) * height * 3);
    return image;
}

}  // namespace facet
