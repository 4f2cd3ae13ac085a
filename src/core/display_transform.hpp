#pragma once
// Display transform: exposure and tone mapping for the files people look
// at (PNG, video, contact sheets). EXR files stay scene-linear.
#include <cstdint>
#include <string_view>

#include <glm/vec4.hpp>

#include "core/enum_names.hpp"
#include "core/half.hpp"
#include "core/image.hpp"

namespace facet {

enum class Tonemap { none, aces, filmic, neutral, agx };

struct DisplayTransform {
    float exposure = 0;  // stops: each one doubles the linear values
    Tonemap tonemap = Tonemap::none;

    bool is_identity() const { return exposure == 0 && tonemap == Tonemap::none; }
};

// The curves' names, as scenes and manifests write them.
inline constexpr EnumName<Tonemap> kTonemaps[] = {{Tonemap::none, "none"},
                                                  {Tonemap::aces, "aces"},
                                                  {Tonemap::filmic, "filmic"},
                                                  {Tonemap::neutral, "neutral"},
                                                  {Tonemap::agx, "agx"}};

// One premultiplied linear colour, exposed and tone-mapped; alpha kept.
// The curve applies to the straight colour, so a half-covered edge pixel
// gets the same tone as the surface it belongs to.
glm::vec4 display_color(const glm::vec4& premultiplied, const DisplayTransform& transform);
// The same with the exposure's factor computed once for many pixels.
float exposure_gain(const DisplayTransform& transform);
glm::vec4 display_color(const glm::vec4& premultiplied, const DisplayTransform& transform,
                        float gain);

// A linear value as the 8-bit sRGB code of the images people look at
// (PNG, contact-sheet JPEG, movie frames, the preview): 0 and below, and
// NaN, are black; 1 and above, +inf included, white; rounded to nearest.
// Every 8-bit display image goes through it, so they agree code for code.
uint8_t display_byte(double linear);

// A 16-bit sample (a 16-bit PNG's) as an 8-bit one, rounded to nearest:
// v * 255 / 65535.
uint8_t narrow_to_byte(uint16_t v);

// The whole image, pixel by pixel. Callers skip the copy when the
// transform is the identity.
ColorImage apply_display_transform(const ColorImage& image, const DisplayTransform& transform);
HalfColorImage apply_display_transform(const HalfColorImage& image,
                                       const DisplayTransform& transform);

}  // namespace facet
