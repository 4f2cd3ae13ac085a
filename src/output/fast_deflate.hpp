#pragma once
// A fast zlib stream for rendered images (RFC 1950 and 1951): no search for
// repeated strings, only Huffman codes fitted to each block's bytes and runs
// that repeat the bytes a fixed distance back (a flat area, a constant
// slope). Filtered or predicted
// image rows are mostly small differences and flat runs, so this keeps most
// of what a string search finds at several times its speed. The bytes
// depend only on the input. Any inflater reads the stream.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

// The farthest back a run may repeat: a pixel of up to 8 bytes.
constexpr size_t kMaxRunDistance = 8;

// Appends the zlib stream (header, deflate blocks, Adler-32) of `data` to
// `out`. Runs are bytes that repeat those `distance` (1..8) before them: 1
// for predicted EXR bytes, a PNG's bytes per pixel for its filtered rows
// (a flat area, or a constant slope).
void zlib_compress_runs(const uint8_t* data, size_t size, size_t distance,
                        std::vector<uint8_t>& out);

}  // namespace facet
