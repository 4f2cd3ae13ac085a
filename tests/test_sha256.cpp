// facet::sha256_hex against the FIPS 180-4 examples (NIST CSRC "Example
// Algorithms", SHA-256) and against lengths around the 64-byte block and
// its 55-byte padding boundary.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "core/sha256.hpp"

namespace {

std::string sha(const std::string& text) {
    return facet::sha256_hex(text.data(), text.size());
}

}  // namespace

TEST_CASE("SHA-256 of the FIPS 180-4 example messages", "[sha256]") {
    // Digests as published by NIST for FIPS 180-4.
    CHECK(sha("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // 448 bits: two blocks after padding.
    CHECK(sha("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    // 896 bits.
    CHECK(sha("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmn"
              "opqrlmnopqrsmnopqrstnopqrstu") ==
          "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
}

TEST_CASE("SHA-256 of one million 'a'", "[sha256]") {
    std::string million(1000000, 'a');
    CHECK(sha(million) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    // The vector overload hashes the same bytes.
    std::vector<uint8_t> bytes(million.begin(), million.end());
    CHECK(facet::sha256_hex(bytes) ==
          "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("SHA-256 around the block and padding boundaries", "[sha256]") {
    // Expected digests computed on this machine with coreutils:
    //   head -c N /dev/zero | tr '\0' a | sha256sum
    // 55 bytes is the longest message whose length still fits in its own
    // block; 56 needs a second block; 63/64/65 straddle one full block.
    struct Case {
        size_t length;
        const char* digest;
    };
    auto c = GENERATE(Case{55, "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318"},
                      Case{56, "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a"},
                      Case{63, "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34"},
                      Case{64, "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb"},
                      Case{65, "635361c48bb9eab14198e76ea8ab7f1a41685d6ad62aa9146d301d4f17eb0ae0"});
    CAPTURE(c.length);
    CHECK(sha(std::string(c.length, 'a')) == c.digest);
}

TEST_CASE("SHA-256 hashes every byte value, including zero", "[sha256]") {
    // Expected digest computed on this machine with:
    //   python3 -c "import sys; sys.stdout.buffer.write(bytes(range(256)))" | sha256sum
    std::vector<uint8_t> all(256);
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<uint8_t>(i);
    CHECK(facet::sha256_hex(all) ==
          "40aff2e9d2d8922e47afd4648e6967497158785fbd1da870e7110266bf944880");
}

TEST_CASE("SHA-256 digests are 64 lower-case hex digits and depend on every byte", "[sha256]") {
    std::string a = sha("facet");
    REQUIRE(a.size() == 64);
    for (char ch : a) CHECK(((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f')));
    CHECK(sha("facet") == a);  // deterministic
    CHECK(sha("facee") != a);
    CHECK(sha("facet ") != a);
    // A pointer into the middle of a buffer hashes only the given range.
    std::string padded = "xxabcyy";
    CHECK(facet::sha256_hex(padded.data() + 2, 3) == sha("abc"));
}
