#pragma once
// Image files to textures: the format recognised by its first bytes (never
// by the file's name or a glTF mimeType), the size read from the header and
// checked before anything is decoded, then the decoder the format needs:
// stb_image (PNG, JPEG and the rest it reads), libwebp (WebP), libavif
// (AVIF). KTX2 is recognised only to say that it is not supported.
#include <cstddef>
#include <cstdint>
#include <string>

#include "assets/texture.hpp"
#include "core/error.hpp"

namespace facet {

enum class ImageFormat { png, jpeg, webp, avif, ktx2, other, unknown };

// The format the bytes start with; `other` is anything else stb_image
// reads (BMP, TGA, GIF, PSD, HDR, PNM).
ImageFormat sniff_image(const uint8_t* bytes, size_t size);

// "PNG", "JPEG", "WebP", "AVIF", "KTX2", ...: for messages.
std::string image_format_name(ImageFormat format);

// Bytes that are not an image facet decodes (an unknown or unsupported
// format, damaged data): the texture is lost, but the run need not be.
// Limits (size, budget) throw plain facet::Error.
class UndecodableImage : public Error {
  public:
    using Error::Error;
};

// Decodes an image file held in memory. `name` prefixes every message.
// Each side must be 1 to kMaxImageSide, checked from the header; the
// texture's bytes are charged to `budget` (when given) before decoding.
// Throws facet::Error (invalid_input) naming the format for bytes it cannot
// decode (UndecodableImage).
Texture decode_texture(const uint8_t* bytes, size_t size, const std::string& name,
                       TextureBudget* budget);

}  // namespace facet
