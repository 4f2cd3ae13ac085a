#pragma once
// The passes a render can write (docs/passes.md), named the same in scenes,
// on the command line, in file names and in the manifest.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string_view>

namespace facet {

// In the order a frame's files are written.
enum class Pass : uint8_t {
    color,
    alpha,
    depth,
    normal,
    object_id,
    material_id,
    uv,
    position,
    motion,
    lines,
};
inline constexpr int kPassCount = 10;

inline constexpr std::array<std::string_view, kPassCount> kPassNames = {
    "color",       "alpha", "depth",    "normal", "object_id",
    "material_id", "uv",    "position", "motion", "lines"};

// Every pass, in the enum's order.
inline constexpr Pass kAllPasses[] = {
    Pass::color,       Pass::alpha, Pass::depth,    Pass::normal, Pass::object_id,
    Pass::material_id, Pass::uv,    Pass::position, Pass::motion, Pass::lines};
static_assert(std::size(kAllPasses) == kPassCount);

constexpr std::string_view pass_name(Pass p) {
    return kPassNames[static_cast<size_t>(p)];
}

inline std::optional<Pass> pass_from_name(std::string_view name) {
    for (size_t i = 0; i < kPassNames.size(); ++i)
        if (kPassNames[i] == name) return static_cast<Pass>(i);
    return std::nullopt;
}

// Float-only passes: no 8-bit view would say what their values are.
constexpr bool pass_is_exr_only(Pass p) {
    return p == Pass::position || p == Pass::motion;
}

// A set of passes, one bit each.
struct PassSet {
    uint32_t bits = 0;

    constexpr bool has(Pass p) const { return (bits >> static_cast<int>(p)) & 1u; }
    constexpr void add(Pass p) { bits |= 1u << static_cast<int>(p); }
    constexpr bool empty() const { return bits == 0; }
    constexpr bool any_of(std::initializer_list<Pass> ps) const {
        for (Pass p : ps)
            if (has(p)) return true;
        return false;
    }
    friend constexpr bool operator==(PassSet, PassSet) = default;
};

}  // namespace facet
