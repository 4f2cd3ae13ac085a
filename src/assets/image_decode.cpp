#include "assets/image_decode.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

#include <avif/avif.h>
#include <stb/stb_image.h>
#include <webp/decode.h>

#include "core/enum_names.hpp"
#include "core/error.hpp"
#include "core/limits.hpp"

namespace facet {
namespace {

bool starts_with(const uint8_t* bytes, size_t size, const char* magic, size_t length,
                 size_t at = 0) {
    return size >= at + length && std::memcmp(bytes + at, magic, length) == 0;
}

uint32_t big_endian(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// ISO BMFF: the first box is `ftyp`, whose major or compatible brands name
// AVIF (still "avif" or sequence "avis").
bool is_avif(const uint8_t* bytes, size_t size) {
    if (!starts_with(bytes, size, "ftyp", 4, 4)) return false;
    const size_t box = std::min<size_t>(big_endian(bytes), size);
    for (size_t at = 8; at + 4 <= box; at += 4) {
        if (at == 12) continue;  // the minor version, not a brand
        if (starts_with(bytes, size, "avif", 4, at) || starts_with(bytes, size, "avis", 4, at))
            return true;
    }
    return false;
}

struct Size {
    int width = 0, height = 0;
};

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
    throw Error(ExitCode::invalid_input, name + ": " + why);
}

[[noreturn]] void undecodable(const std::string& name, const std::string& why) {
    throw UndecodableImage(ExitCode::invalid_input, name + ": " + why);
}

// A charge to the texture budget, given back when this goes out of scope
// unless kept. The texture's own bytes are kept once it is decoded (a
// decoder that fails gives them back); what a decoder holds only while it
// runs (its output buffer, stb's inflated PNG rows, AVIF's planes, the
// file's bytes) is always given back, so the budget bounds the peak, not
// only what stays.
class BudgetCharge {
  public:
    BudgetCharge(TextureBudget* budget, std::string name, Size size, uint64_t bytes)
        : budget_(budget), name_(std::move(name)) {
        if (budget_) budget_->charge(name_, size.width, size.height, bytes);
    }
    BudgetCharge(BudgetCharge&& other) noexcept
        : budget_(std::exchange(other.budget_, nullptr)), name_(std::move(other.name_)) {}
    BudgetCharge(const BudgetCharge&) = delete;
    BudgetCharge& operator=(const BudgetCharge&) = delete;
    BudgetCharge& operator=(BudgetCharge&&) = delete;
    ~BudgetCharge() {
        if (budget_) budget_->release(name_);
    }
    void keep() { budget_ = nullptr; }

  private:
    TextureBudget* budget_;
    std::string name_;
};

// Checks the header's size and charges the texture before decoding.
[[nodiscard]] BudgetCharge admit(const std::string& name, Size size, int bits,
                                 TextureBudget* budget) {
    if (size.width <= 0 || size.height <= 0 || size.width > kMaxImageSide ||
        size.height > kMaxImageSide)
        refuse(name, std::to_string(size.width) + "x" + std::to_string(size.height) +
                         " pixels (each side must be 1 to " + std::to_string(kMaxImageSide) + ")");
    return BudgetCharge(budget, name, size, texture_bytes(size.width, size.height, bits));
}

// The charge for what the decoder holds while it runs.
[[nodiscard]] BudgetCharge while_decoding(const std::string& name, Size size, uint64_t bytes,
                                          TextureBudget* budget) {
    return BudgetCharge(budget, name + std::string(kWhileDecoding), size, bytes);
}

uint64_t pixels_of(Size size) {
    return static_cast<uint64_t>(size.width) * static_cast<uint64_t>(size.height);
}

Texture decode_with_stb(const uint8_t* bytes, size_t size, ImageFormat format,
                        const std::string& name, TextureBudget* budget) {
    if (size > static_cast<size_t>(std::numeric_limits<int>::max()))
        refuse(name, "the file is too large");
    const int length = static_cast<int>(size);
    Size header;
    int channels = 0;
    if (format == ImageFormat::png && size >= 24) {
        // IHDR holds the size at bytes 16..23. Read here, not by stb, which
        // refuses very large images with a message that names no size.
        header = {static_cast<int>(std::min<uint32_t>(big_endian(bytes + 16), 1u << 30)),
                  static_cast<int>(std::min<uint32_t>(big_endian(bytes + 20), 1u << 30))};
    } else if (!stbi_info_from_memory(bytes, length, &header.width, &header.height, &channels)) {
        undecodable(name, "cannot decode " + image_format_name(format) + " image (" +
                              stbi_failure_reason() + ")");
    }
    const bool is16 = stbi_is_16_bit_from_memory(bytes, length);
    BudgetCharge texture = admit(name, header, is16 ? 16 : 8, budget);
    // stb inflates a PNG's rows whole, then unfilters them into its output:
    // two images of the file's channels (four at most), and the file.
    const BudgetCharge decoding =
        while_decoding(name, header, 2 * pixels_of(header) * 4 * (is16 ? 2 : 1) + size, budget);
    int w = 0, h = 0;
    void* data =
        is16 ? static_cast<void*>(stbi_load_16_from_memory(bytes, length, &w, &h, &channels, 0))
             : static_cast<void*>(stbi_load_from_memory(bytes, length, &w, &h, &channels, 0));
    if (!data)
        undecodable(name, "cannot decode " + image_format_name(format) + " image (" +
                              stbi_failure_reason() + ")");
    std::unique_ptr<void, void (*)(void*)> owned(data, stbi_image_free);
    Texture decoded =
        texture_from_pixels(w, h, channels, is16 ? 16 : 8, static_cast<const uint8_t*>(data));
    texture.keep();
    return decoded;
}

Texture decode_webp(const uint8_t* bytes, size_t size, const std::string& name,
                    TextureBudget* budget) {
    WebPBitstreamFeatures features;
    if (WebPGetFeatures(bytes, size, &features) != VP8_STATUS_OK)
        undecodable(name, "cannot decode WebP image (damaged header)");
    if (features.has_animation) undecodable(name, "animated WebP images are not supported");
    const Size header{features.width, features.height};
    BudgetCharge texture = admit(name, header, 8, budget);
    const BudgetCharge decoding =
        while_decoding(name, header, pixels_of(header) * 4 + size, budget);
    const int channels = features.has_alpha ? 4 : 3;
    int w = 0, h = 0;
    uint8_t* data = features.has_alpha ? WebPDecodeRGBA(bytes, size, &w, &h)
                                       : WebPDecodeRGB(bytes, size, &w, &h);
    if (!data) undecodable(name, "cannot decode WebP image (damaged data)");
    std::unique_ptr<uint8_t, void (*)(void*)> owned(data, WebPFree);
    Texture decoded = texture_from_pixels(w, h, channels, 8, data);
    texture.keep();
    return decoded;
}

Texture decode_avif(const uint8_t* bytes, size_t size, const std::string& name,
                    TextureBudget* budget) {
    std::unique_ptr<avifDecoder, void (*)(avifDecoder*)> decoder(avifDecoderCreate(),
                                                                 avifDecoderDestroy);
    if (!decoder) throw Error(ExitCode::runtime_failure, name + ": cannot start the AVIF decoder");
    decoder->maxThreads = 1;  // called from one thread per texture already
    decoder->imageDimensionLimit = kMaxImageSide;
    decoder->ignoreExif = decoder->ignoreXMP = AVIF_TRUE;
    avifResult result = avifDecoderSetIOMemory(decoder.get(), bytes, size);
    if (result == AVIF_RESULT_OK) result = avifDecoderParse(decoder.get());
    if (result != AVIF_RESULT_OK)
        undecodable(name,
                    std::string("cannot decode AVIF image (") + avifResultToString(result) + ")");
    const avifImage* header = decoder->image;
    const int bits = header->depth > 8 ? 16 : 8;
    const Size header_size{static_cast<int>(header->width), static_cast<int>(header->height)};
    BudgetCharge texture = admit(name, header_size, bits, budget);
    // The YUV and alpha planes, the RGBA image and its packed copy.
    const BudgetCharge decoding = while_decoding(
        name, header_size, pixels_of(header_size) * (4 + 4 + 4) * (bits / 8) + size, budget);
    result = avifDecoderNextImage(decoder.get());
    if (result != AVIF_RESULT_OK)
        undecodable(name,
                    std::string("cannot decode AVIF image (") + avifResultToString(result) + ")");
    avifRGBImage rgb;
    avifRGBImageSetDefaults(&rgb, decoder->image);
    rgb.format = AVIF_RGB_FORMAT_RGBA;
    rgb.depth = static_cast<uint32_t>(bits);
    avifRGBImageAllocatePixels(&rgb);
    std::unique_ptr<avifRGBImage, void (*)(avifRGBImage*)> owned(&rgb, avifRGBImageFreePixels);
    result = avifImageYUVToRGB(decoder->image, &rgb);
    if (result != AVIF_RESULT_OK)
        undecodable(name,
                    std::string("cannot convert AVIF image (") + avifResultToString(result) + ")");
    // Rows may be padded; texture_from_pixels wants them packed.
    const size_t row = static_cast<size_t>(rgb.width) * 4 * (bits / 8);
    std::vector<uint8_t> packed(row * rgb.height);
    for (uint32_t y = 0; y < rgb.height; ++y)
        std::memcpy(packed.data() + y * row, rgb.pixels + static_cast<size_t>(y) * rgb.rowBytes,
                    row);
    Texture decoded = texture_from_pixels(static_cast<int>(rgb.width), static_cast<int>(rgb.height),
                                          4, bits, packed.data());
    texture.keep();
    return decoded;
}

}  // namespace

ImageFormat sniff_image(const uint8_t* bytes, size_t size) {
    if (starts_with(bytes, size, "\x89PNG\r\n\x1a\n", 8)) return ImageFormat::png;
    if (starts_with(bytes, size, "\xff\xd8\xff", 3)) return ImageFormat::jpeg;
    if (starts_with(bytes, size, "RIFF", 4) && starts_with(bytes, size, "WEBP", 4, 8))
        return ImageFormat::webp;
    if (is_avif(bytes, size)) return ImageFormat::avif;
    if (starts_with(bytes, size, "\xabKTX 20\xbb\r\n\x1a\n", 12)) return ImageFormat::ktx2;
    if (size <= static_cast<size_t>(std::numeric_limits<int>::max())) {
        int w = 0, h = 0, channels = 0;
        if (stbi_info_from_memory(bytes, static_cast<int>(size), &w, &h, &channels))
            return ImageFormat::other;
    }
    return ImageFormat::unknown;
}

std::string image_format_name(ImageFormat format) {
    constexpr EnumName<ImageFormat> kNames[] = {
        {ImageFormat::png, "PNG"},        {ImageFormat::jpeg, "JPEG"},
        {ImageFormat::webp, "WebP"},      {ImageFormat::avif, "AVIF"},
        {ImageFormat::ktx2, "KTX2"},      {ImageFormat::other, "image"},
        {ImageFormat::unknown, "unknown"}};
    return std::string(name_of(kNames, format));
}

Texture decode_texture(const uint8_t* bytes, size_t size, const std::string& name,
                       TextureBudget* budget) {
    const ImageFormat format = sniff_image(bytes, size);
    try {
        switch (format) {
            case ImageFormat::webp:
                return decode_webp(bytes, size, name, budget);
            case ImageFormat::avif:
                return decode_avif(bytes, size, name, budget);
            case ImageFormat::ktx2:
                undecodable(name, "KTX2 (KHR_texture_basisu) images are not supported");
            case ImageFormat::unknown:
                undecodable(name,
                            "not an image facet reads (PNG, JPEG, WebP, AVIF, BMP, TGA, GIF)");
            default:
                return decode_with_stb(bytes, size, format, name, budget);
        }
    } catch (const UndecodableImage&) {
        throw;
    } catch (const Error& e) {
        const std::string what = e.what();
        // texture_from_pixels does not know the name.
        if (what.compare(0, name.size(), name) == 0) throw;
        throw Error(e.code(), name + ": " + what);
    }
}

}  // namespace facet
