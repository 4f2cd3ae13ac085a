// Base64 through OpenSSL's libcrypto (as SHA-256 in sha256.cpp).
#include "core/base64.hpp"

#include <openssl/evp.h>

namespace facet {

std::string base64_encode(std::span<const uint8_t> bytes) {
    // EVP_EncodeBlock writes 4 characters per 3 bytes and a terminating NUL.
    std::string text(4 * ((bytes.size() + 2) / 3) + 1, '\0');
    const int written = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(text.data()), bytes.data(),
                                        static_cast<int>(bytes.size()));
    text.resize(static_cast<size_t>(written));
    return text;
}

}  // namespace facet
