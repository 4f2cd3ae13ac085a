// SHA-256 through OpenSSL's libcrypto, which uses the processor's SHA
// instructions where it has them (several times faster than portable code).
#include "core/sha256.hpp"

#include <openssl/evp.h>

#include "core/error.hpp"

namespace facet {

std::string sha256_hex(const void* data, size_t size) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_Digest(data, size, digest, &length, EVP_sha256(), nullptr) != 1 || length != 32)
        throw Error(ExitCode::runtime_failure, "SHA-256 failed (OpenSSL)");
    static const char kHex[] = "0123456789abcdef";
    std::string hex(64, '0');
    for (unsigned i = 0; i < 32; ++i) {
        hex[2 * i] = kHex[digest[i] >> 4];
        hex[2 * i + 1] = kHex[digest[i] & 15];
    }
    return hex;
}

}  // namespace facet
