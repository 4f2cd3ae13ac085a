#pragma once
// Environment image files: reading and checking a Radiance .hdr or an
// OpenEXR .exr for the `pbr` model's environment. Here, not in shade/,
// because reading files takes both decoders: the .hdr one in assets/ and
// OpenEXR's in output/ (docs/architecture.md, "Modules").
#include <string>

#include "core/diagnostics.hpp"
#include "shade/environment_map.hpp"

namespace facet::pbr {

// Reads an equirectangular environment image: a Radiance .hdr (RGBE,
// stb_image) or an OpenEXR .exr (its R, G and B channels), told apart by
// their first bytes ("#?RADIANCE" or "#?RGBE"; 76 2f 31 01), never by the
// name. `path` is the resolved file: the scene's asset path policy is the
// caller's. Throws facet::Error (invalid_input) naming the path when the
// file cannot be read, is neither format, is damaged or cut short, is not
// equirectangular (its width must be exactly twice its height: anything
// else is a cube map, a mirror ball or a photograph, and would light the
// scene wrongly without a word), is wider than kMaxEnvironmentWidth
// (core/limits.hpp; checked from the header, before decoding), or holds a
// NaN or infinite texel (one would spread over every level). Negative
// texels, which resampling filters leave beside bright spots, are set to 0
// with one warning that counts them.
EquirectRadiance read_environment_image(const std::string& path, Warnings& warnings);

// build_environment(read_environment_image(path, warnings), threads).
SharedEnvironment load_environment(const std::string& path, Warnings& warnings,
                                   unsigned threads = 0);

}  // namespace facet::pbr
