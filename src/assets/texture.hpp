#pragma once
// Decoded textures with a mipmap chain, sampled trilinearly (Williams 1983,
// "Pyramidal Parametrics"). Texels keep the precision their image had:
// 8-bit images stay 8-bit sRGB (4 bytes a texel, decoded through a table
// when sampled), 16-bit ones become half-float linear RGBA (8 bytes). The
// levels are shared between copies, so a copy that only changes `wrap`
// costs nothing.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/half.hpp"

namespace facet {

enum class Wrap { repeat, clamp };

// One level: exactly one of the two vectors holds its width x height texels,
// rows top to bottom.
struct TextureLevel {
    int width = 0;
    int height = 0;
    std::vector<uint32_t> srgb8;  // R, G, B as sRGB bytes, A linear; R in the low byte
    std::vector<Rgba16F> half;    // linear RGBA
};

class TextureBudget;

struct Texture {
    enum class Format { srgb8, half };

    int width = 0;
    int height = 0;
    Wrap wrap = Wrap::repeat;

    // From linear RGBA texels (row by row), stored in `format`.
    static Texture from_linear(int width, int height, const std::vector<glm::vec4>& texels,
                               Format format);

    Format format() const { return format_; }
    int level_count() const { return levels_ ? static_cast<int>(levels_->size()) : 0; }
    const TextureLevel& level(int i) const { return (*levels_)[static_cast<size_t>(i)]; }
    // Linear RGBA of one texel of one level.
    glm::vec4 texel(int level, int x, int y) const;
    // Bytes the texels of every level take.
    uint64_t bytes() const;

    // Bilinear lookup in level 0. uv (0,0) is the top-left corner of the
    // image, as in glTF and as OBJ files are commonly authored after their v flip.
    glm::vec4 sample(glm::vec2 uv) const;

    // Trilinear lookup: `lod` is log2 of the texels one pixel step covers;
    // 0 or less is level 0, and each step up halves the resolution.
    glm::vec4 sample(glm::vec2 uv, float lod) const;

  private:
    // Level 0 given; the mipmaps are added here.
    static Texture from_base_level(Format format, TextureLevel base);

    Format format_ = Format::srgb8;
    std::shared_ptr<const std::vector<TextureLevel>> levels_;
    friend Texture texture_from_pixels(int, int, int, int, const uint8_t*);
};

// Bytes a texture of this size and bit depth takes with its mipmaps, known
// before decoding, for budgets.
uint64_t texture_bytes(int width, int height, int bits);

// Reads PNG or JPEG (8 or 16 bit, grey, grey+alpha, RGB, RGBA). Colour
// channels are taken as sRGB; alpha is linear. The image's size is read
// first and charged to `budget` (when given) before anything is decoded.
Texture load_texture(const std::string& path, TextureBudget* budget = nullptr);
Texture texture_from_pixels(int width, int height, int channels, int bits, const uint8_t* data);

// The memory all textures of one run may take together; every texture is
// charged before it is decoded. Thread-safe.
class TextureBudget {
  public:
    explicit TextureBudget(uint64_t limit_bytes);
    ~TextureBudget();
    // Records `bytes` for `name`; throws facet::Error (invalid_input) that
    // names it, its size and the largest textures charged so far when the
    // total would pass the limit.
    void charge(const std::string& name, int width, int height, uint64_t bytes);
    uint64_t used() const;
    uint64_t limit() const { return limit_; }

  private:
    struct State;
    uint64_t limit_;
    std::unique_ptr<State> state_;
};

constexpr uint64_t kDefaultTextureBudget = uint64_t(1) << 30;

}  // namespace facet
