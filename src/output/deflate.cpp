#include "output/deflate.hpp"

#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>

#include <algorithm>

#include "core/error.hpp"

namespace facet {
namespace {

size_t level_buffer_size(int level) {
    switch (level) {
        case 0:
            return ISAL_DEF_LVL0_DEFAULT;
        case 1:
            return ISAL_DEF_LVL1_DEFAULT;
        case 2:
            return ISAL_DEF_LVL2_DEFAULT;
        default:
            return ISAL_DEF_LVL3_DEFAULT;
    }
}

}  // namespace

void zlib_compress(const uint8_t* data, size_t size, int level, std::vector<uint8_t>& out) {
    level = std::clamp(level, 0, kMaxDeflateLevel);
    std::vector<uint8_t> level_buffer(level_buffer_size(level));
    isal_zstream stream;
    isal_deflate_init(&stream);
    stream.level = static_cast<uint32_t>(level);
    stream.level_buf = level_buffer.data();
    stream.level_buf_size = static_cast<uint32_t>(level_buffer.size());
    stream.gzip_flag = IGZIP_ZLIB;
    stream.end_of_stream = 1;
    stream.flush = NO_FLUSH;
    stream.next_in = const_cast<uint8_t*>(data);
    stream.avail_in = static_cast<uint32_t>(size);
    if (size > UINT32_MAX) throw Error(ExitCode::runtime_failure, "deflate: input over 4 GiB");
    // Stored blocks bound the output: a little over the input.
    const size_t start = out.size();
    out.resize(start + size + size / 64 + 1024);
    stream.next_out = out.data() + start;
    stream.avail_out = static_cast<uint32_t>(out.size() - start);
    while (true) {
        if (isal_deflate(&stream) != COMP_OK)
            throw Error(ExitCode::runtime_failure, "deflate failed (ISA-L)");
        if (stream.internal_state.state == ZSTATE_END) break;
        const size_t used = out.size() - stream.avail_out;
        out.resize(out.size() + size / 4 + 4096);
        stream.next_out = out.data() + used;
        stream.avail_out = static_cast<uint32_t>(out.size() - used);
    }
    out.resize(out.size() - stream.avail_out);
}

uint32_t crc32(uint32_t crc, const uint8_t* data, size_t size) {
    return crc32_gzip_refl(crc, data, size);
}

}  // namespace facet
