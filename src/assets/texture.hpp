#pragma once
// Decoded textures with a mipmap chain, sampled trilinearly (Williams 1983,
// "Pyramidal Parametrics"). Texels keep the precision their image had:
// 8-bit images stay 8-bit sRGB (4 bytes a texel, decoded through a table
// when sampled), 16-bit ones become half-float linear RGBA (8 bytes). The
// levels are shared between copies, so a copy that only changes its
// sampler costs nothing.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/ext/matrix_double2x2.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/half.hpp"
#include "core/simd_math.hpp"

namespace facet {

// What lies past the image's edge, per axis (glTF samplers: REPEAT,
// CLAMP_TO_EDGE, MIRRORED_REPEAT).
enum class Wrap { repeat, clamp, mirror };
enum class Filter { nearest, linear };

// How a texture is read, as a glTF sampler says (§5.26). The defaults are
// facet's own: repeat, bilinear within a level, linear between levels.
struct Sampler {
    Wrap wrap_s = Wrap::repeat;  // along u (image columns)
    Wrap wrap_t = Wrap::repeat;  // along v (image rows)
    Filter mag = Filter::linear;
    Filter min = Filter::linear;  // within a level, when minifying
    bool mipmaps = true;          // minifying reads the mip chain
    Filter mip = Filter::linear;  // between two levels of the chain
    // A footprint longer one way than the other (a surface seen at a
    // slant) is read by up to this many lookups along its longer axis, at
    // the level of its shorter one, as GPUs' anisotropic filtering does
    // (EXT_texture_filter_anisotropic); 1 reads it by its longer axis alone
    // (trilinear), which blurs it.
    int max_anisotropy = 16;
};

// A pixel's footprint in a texture: where its centre falls, and its steps
// along the two screen axes turned into the texture, as the lengths of the
// longer and the shorter (in texels) and the longer one as a step of
// texture coordinates (shade/texture_lod.hpp computes it).
struct TextureFootprint {
    glm::vec2 uv;
    glm::vec2 major_axis;  // texture coordinates per pixel along the longer step
    float major = 0.0f, minor = 0.0f;
};

// One level: exactly one of the two vectors holds its width x height texels,
// rows top to bottom.
struct TextureLevel {
    int width = 0;
    int height = 0;
    // R, G, B, A bytes, R in the low byte: colour as sRGB and alpha linear
    // (Format::srgb8), or all four linear (Format::data8).
    std::vector<uint32_t> bytes8;
    std::vector<Rgba16F> half;  // linear RGBA
};

// What a decoder holds while it runs is charged as the texture's name with
// this after it, and given back when it is done.
inline constexpr std::string_view kWhileDecoding = " (while decoding)";

class TextureBudget;

// An affine map of texture coordinates, uv' = offset + linear·uv: glTF's
// KHR_texture_transform (translation · rotation · scale), then a scene
// material's uv_scale. Double, like the file's numbers; the result is
// rounded to float once.
struct UvTransform {
    glm::dvec2 offset = {0, 0};
    glm::dmat2 linear = glm::dmat2(1.0);
    // KHR_texture_transform's T·R·S: a positive rotation (radians) turns
    // the UVs counter-clockwise, the image clockwise.
    static UvTransform from_trs(glm::dvec2 offset, double rotation, glm::dvec2 scale);
    // This map followed by a scale of its result.
    UvTransform scaled(glm::dvec2 scale) const;
    bool identity() const { return offset == glm::dvec2(0) && linear == glm::dmat2(1.0); }
    glm::vec2 apply(glm::vec2 uv) const;
    // apply() on eight lanes in place: the same bits in each.
    void apply(simd::vf& u, simd::vf& v) const;
};

struct Texture {
    // data8: 8-bit texels that are numbers, not colours (normal, metal-rough
    // and occlusion maps): read as byte / 255, and averaged as such in the
    // mipmaps.
    enum class Format { srgb8, data8, half };

    int width = 0;
    int height = 0;
    Sampler sampler;

    // From linear RGBA texels (row by row), stored in `format`.
    static Texture from_linear(int width, int height, const std::vector<glm::vec4>& texels,
                               Format format);

    Format format() const { return format_; }
    int level_count() const { return levels_ ? static_cast<int>(levels_->size()) : 0; }
    const TextureLevel& level(int i) const { return (*levels_)[static_cast<size_t>(i)]; }
    // Linear RGBA of one texel of one level.
    glm::vec4 texel(int level, int x, int y) const;
    // The same image read as data rather than colour (glTF's normal,
    // metallic-roughness and occlusion maps are linear): level 0 keeps its
    // values as stored in the file, and the mipmaps average those. A copy
    // of an 8-bit image keeps its bytes exactly.
    Texture as_data() const;
    // Bytes the texels of every level take.
    uint64_t bytes() const;

    // Lookup in level 0 with the magnification filter. uv (0,0) is the
    // top-left corner of the image, as in glTF and as OBJ files are
    // commonly authored after their v flip.
    glm::vec4 sample(glm::vec2 uv) const;

    // Lookup as the sampler says: `lod` is log2 of the texels one pixel
    // step covers. 0 or less magnifies level 0; above it minifies, by
    // default trilinearly, each step up halving the resolution.
    glm::vec4 sample(glm::vec2 uv, float lod) const;

    // Lookup of a pixel's footprint as the sampler says. With
    // max_anisotropy 1, or a footprint no longer than wide, it is
    // sample(uv, log2 major); else N = min(ceil(major / minor),
    // max_anisotropy) lookups at level log2(max(major / N, minor)), spread
    // evenly along the longer axis, averaged.
    glm::vec4 sample(const TextureFootprint& footprint) const;

  private:
    // Level 0 given; the mipmaps are added here.
    static Texture from_base_level(Format format, TextureLevel base);

    Format format_ = Format::srgb8;
    std::shared_ptr<const std::vector<TextureLevel>> levels_;
    friend Texture texture_from_pixels(int, int, int, int, const uint8_t*);
};

// How a material reads one of its textures: which of a part's texture
// coordinate sets (glTF texCoord), mapped by `transform`.
struct TextureSlot {
    std::shared_ptr<const Texture> texture;
    int uv_set = 0;  // 0: MeshPart::uvs, 1: MeshPart::uvs1
    UvTransform transform;
    explicit operator bool() const { return texture != nullptr; }
    glm::vec2 map(glm::vec2 uv) const { return transform.identity() ? uv : transform.apply(uv); }
};

// Bytes a texture of this size and bit depth takes with its mipmaps, known
// before decoding, for budgets.
uint64_t texture_bytes(int width, int height, int bits);

// Reads an image file (PNG, JPEG, WebP, AVIF and the rest that
// assets/image_decode.hpp reads; 8 or 16 bit, grey, grey+alpha, RGB, RGBA).
// Colour channels are taken as sRGB; alpha is linear. The image's size is
// read first and charged to `budget` (when given) before anything is decoded.
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
    // Gives back what a charge of `name` took: memory a decoder held only
    // while it ran.
    void release(const std::string& name);
    uint64_t used() const;
    // What is charged now, in the order it was charged.
    struct Charge {
        std::string name;
        int width = 0, height = 0;
        uint64_t bytes = 0;
    };
    std::vector<Charge> charges() const;
    uint64_t limit() const { return limit_; }

  private:
    struct State;
    uint64_t limit_;
    std::unique_ptr<State> state_;
};

constexpr uint64_t kDefaultTextureBudget = uint64_t(1) << 30;

}  // namespace facet
