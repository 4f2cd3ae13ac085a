#pragma once
// Radiance RGBE (.hdr) images, decoded to linear float RGB: the high
// dynamic range format that environment maps come in beside OpenEXR
// (shade/environment_map.hpp reads them through here, since stb_image is
// linked in this module only). Ward's format: a text header, then each
// texel as an 8-bit mantissa per channel and a shared exponent, by rows,
// usually run-length encoded.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// Texels as linear RGB floats, row by row from the top.
struct RgbFloatImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3
};

// Whether the bytes begin as a Radiance file does: "#?RADIANCE" or "#?RGBE".
bool is_radiance_hdr(const uint8_t* bytes, size_t size);

// The size that a Radiance file's header gives, read without decoding the
// texels, so that the caller can refuse a size before paying for it.
// Throws facet::Error (invalid_input) "NAME: ..." when the header is
// damaged or lays the texels out other than "-Y height +X width" (rows from
// the top, each from the left: the layout every tool writes).
struct RadianceHdrSize {
    int width = 0, height = 0;
};
RadianceHdrSize radiance_hdr_size(const uint8_t* bytes, size_t size, const std::string& name);

// The texels, by stb_image, which expands each RGBE texel to
// mantissa * 2^(exponent - 136). stb reads zeros past the end of the data
// without a word (and a zero run length would hang it), so the bytes are
// fed to it through a reader that notices a read past the end and keeps
// stb moving, and a file that ends early is refused. Throws facet::Error
// (invalid_input) "NAME: ..." for damaged data.
RgbFloatImage decode_radiance_hdr(const uint8_t* bytes, size_t size, const std::string& name);

}  // namespace facet
