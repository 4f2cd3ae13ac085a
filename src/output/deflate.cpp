#include "output/deflate.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <memory>

#include "core/error.hpp"
#include "output/fast_deflate.hpp"

namespace facet {

void zlib_compress(const uint8_t* data, size_t size, int level, std::vector<uint8_t>& out,
                   size_t repeat_distance) {
    level = std::clamp(level, 0, kMaxDeflateLevel);
    if (level == kRunsDeflateLevel) {
        zlib_compress_runs(data, size, repeat_distance, out);
        return;
    }
    const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
        libdeflate_alloc_compressor(level), &libdeflate_free_compressor);
    if (!compressor) throw Error(ExitCode::runtime_failure, "deflate: out of memory");
    const size_t start = out.size();
    out.resize(start + libdeflate_zlib_compress_bound(compressor.get(), size));
    const size_t written = libdeflate_zlib_compress(compressor.get(), data, size,
                                                    out.data() + start, out.size() - start);
    // The bound is an upper bound for any input: 0 ("did not fit") cannot happen.
    if (written == 0) throw Error(ExitCode::runtime_failure, "deflate failed (libdeflate)");
    out.resize(start + written);
}

uint32_t crc32(uint32_t crc, const uint8_t* data, size_t size) {
    return libdeflate_crc32(crc, data, size);
}

}  // namespace facet
