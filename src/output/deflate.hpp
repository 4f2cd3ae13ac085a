#pragma once
// zlib streams and CRC-32 through Intel's ISA-L (igzip), the fastest deflate
// Debian packages: a 1080p frame in a few milliseconds where zlib takes tens.
// The only ISA-L user; PNG and EXR writers call it.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

// ISA-L's levels: 0 (fastest) to 3 (smallest). Every level writes a valid
// zlib stream that any inflater reads back to the same bytes.
constexpr int kMaxDeflateLevel = 3;

// Appends the zlib stream (header, deflate data, Adler-32) of `data` to `out`.
void zlib_compress(const uint8_t* data, size_t size, int level, std::vector<uint8_t>& out);

// The CRC-32 of ISO 3309 / ITU-T V.42 (as PNG and gzip use), continuing
// from `crc` (0 to start).
uint32_t crc32(uint32_t crc, const uint8_t* data, size_t size);

}  // namespace facet
