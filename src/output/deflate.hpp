#pragma once
// zlib streams and CRC-32 through libdeflate (and, at level 1, facet's own
// run and Huffman coder): whole-buffer compression, two
// to three times faster than zlib at the same size, and the same bytes for
// the same input every time. (ISA-L's igzip is faster still, but on the
// machine this was measured on it now and then wrote different bytes for
// the same input when other threads were busy; docs/performance.md.)
// The only libdeflate user; PNG and EXR writers call it.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

// zlib's scale: 0 (stored) to 9 (smallest); libdeflate goes on to 12, which
// facet does not offer. Every level writes a valid zlib stream that any
// inflater reads back to the same bytes.
constexpr int kMaxDeflateLevel = 9;
// The fastest level that searches for nothing but runs of a byte
// (output/fast_deflate.hpp): several times libdeflate's level 1 on
// rendered images, a little larger. The other levels are libdeflate's.
constexpr int kRunsDeflateLevel = 1;

// Appends the zlib stream (header, deflate data, Adler-32) of `data` to
// `out`. `repeat_distance` (1..8) tells level 1 how far back the data
// repeats where it is flat: a PNG's bytes per pixel, 1 for EXR's bytes.
void zlib_compress(const uint8_t* data, size_t size, int level, std::vector<uint8_t>& out,
                   size_t repeat_distance = 1);

// The CRC-32 of ISO 3309 / ITU-T V.42 (as PNG and gzip use), continuing
// from `crc` (0 to start).
uint32_t crc32(uint32_t crc, const uint8_t* data, size_t size);

}  // namespace facet
