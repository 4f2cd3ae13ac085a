#pragma once
// SHA-256 (FIPS 180-4) for the manifest's file digests, as lower-case hex.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

std::string sha256_hex(const void* data, size_t size);
inline std::string sha256_hex(const std::vector<uint8_t>& bytes) {
    return sha256_hex(bytes.data(), bytes.size());
}

}  // namespace facet
