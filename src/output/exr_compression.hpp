#pragma once
// How an EXR file's chunks are compressed, as OpenEXR names the methods
// (and as `output.exr_compression` spells them, docs/scene-format.md).
#include <array>
#include <string_view>

namespace facet {

// All lossless but dwaa (lossy on half channels; float and uint channels
// it keeps exact). zip, zips and none are written by output/exr_writer.cpp
// with libdeflate; rle, piz and dwaa by OpenEXR's own compressors.
enum class ExrCompression { none, rle, zips, zip, piz, dwaa };

inline constexpr std::array<std::string_view, 6> kExrCompressionNames = {"none", "rle", "zips",
                                                                         "zip",  "piz", "dwaa"};

constexpr std::string_view exr_compression_name(ExrCompression c) {
    return kExrCompressionNames[static_cast<size_t>(c)];
}

// Whether output/exr_writer.cpp writes the method itself (else OpenEXR does).
constexpr bool written_by_facet(ExrCompression c) {
    return c == ExrCompression::zip || c == ExrCompression::zips || c == ExrCompression::none;
}

}  // namespace facet
