// Deflate blocks with dynamic Huffman codes (RFC 1951, 3.2.7), written in two
// passes over each block: the first counts the bytes and finds the runs, the
// second writes them. A run is at least kMinRun bytes that repeat the bytes
// a fixed distance before them; it is written as copies of length 3..258
// from that distance, every other byte as a literal.
#include "output/fast_deflate.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <queue>

namespace facet {
namespace {

constexpr size_t kBlockBytes = size_t(1) << 18;  // each block's codes fit its own bytes
constexpr size_t kMinRun = 4;     // shorter runs cost about as much as their literals
constexpr size_t kMaxCopy = 258;  // the longest copy deflate has
constexpr int kLiteralSymbols = 286, kCodeLengthSymbols = 19;
constexpr int kEndOfBlock = 256;
// A block header: 17 bits, 19 3-bit lengths, and at most 288 coded lengths
// of up to 7 + 7 bits; rounded up.
constexpr size_t kMaxHeaderBytes = 600;

// Length symbols 257..285: the first length of each and its extra bits.
constexpr std::array<uint16_t, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                                  15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                                  67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                  2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
// The order in which the code-length code's lengths are stored.
constexpr std::array<uint8_t, 19> kCodeLengthOrder = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                                      11, 4,  12, 3, 13, 2, 14, 1, 15};

// The length symbol (0-based, from 257) of a copy of `length` bytes.
int length_slot(size_t length) {
    int slot = 0;
    while (slot + 1 < 29 && kLengthBase[slot + 1] <= length) ++slot;
    return slot;
}

// Bits go out least significant first, as deflate packs them, into a
// buffer the caller sized for the worst case.
class BitWriter {
  public:
    explicit BitWriter(uint8_t* out) : start_(out), at_(out) {}
    void put(uint32_t bits, int count) {
        buffer_ |= static_cast<uint64_t>(bits) << filled_;
        filled_ += count;
        if (filled_ >= 32) {
            for (int i = 0; i < 4; ++i) at_[i] = static_cast<uint8_t>(buffer_ >> (8 * i));
            at_ += 4;
            buffer_ >>= 32;
            filled_ -= 32;
        }
    }
    // Pads with zero bits to the next byte; the bytes written.
    size_t flush() {
        for (; filled_ > 0; filled_ -= 8) {
            *at_++ = static_cast<uint8_t>(buffer_);
            buffer_ >>= 8;
        }
        filled_ = 0;
        return static_cast<size_t>(at_ - start_);
    }

  private:
    uint8_t* start_;
    uint8_t* at_;
    uint64_t buffer_ = 0;
    int filled_ = 0;
};

// Huffman code lengths for `freq` (at least two symbols used), none longer
// than `limit`: a Huffman tree, with the counts halved and rebuilt while
// it is too deep. Ties break on the node's index, so the lengths depend
// only on the counts.
template <size_t N>
std::array<uint8_t, N> code_lengths(std::array<uint32_t, N> freq, int limit) {
    for (;;) {
        using Node = std::pair<uint64_t, int>;  // weight, index
        std::priority_queue<Node, std::vector<Node>, std::greater<>> queue;
        std::vector<int> parent(2 * N, -1);
        int next = static_cast<int>(N);
        for (size_t s = 0; s < N; ++s)
            if (freq[s]) queue.push({freq[s], static_cast<int>(s)});
        while (queue.size() > 1) {
            const Node a = queue.top();
            queue.pop();
            const Node b = queue.top();
            queue.pop();
            parent[static_cast<size_t>(a.second)] = parent[static_cast<size_t>(b.second)] = next;
            queue.push({a.first + b.first, next++});
        }
        std::array<uint8_t, N> lengths{};
        int deepest = 0;
        for (size_t s = 0; s < N; ++s) {
            if (!freq[s]) continue;
            int depth = 0;
            for (int p = parent[s]; p >= 0; p = parent[static_cast<size_t>(p)]) ++depth;
            lengths[s] = static_cast<uint8_t>(depth);
            deepest = std::max(deepest, depth);
        }
        if (deepest <= limit) return lengths;
        for (uint32_t& f : freq)
            if (f) f = (f >> 1) | 1;
    }
}

// Canonical codes (RFC 1951, 3.2.2), bit-reversed for writing LSB first.
template <size_t N>
std::array<uint16_t, N> canonical_codes(const std::array<uint8_t, N>& lengths) {
    std::array<uint16_t, 16> count{}, next{};
    for (uint8_t l : lengths) ++count[l];
    count[0] = 0;
    uint16_t code = 0;
    for (int bits = 1; bits < 16; ++bits) {
        code = static_cast<uint16_t>((code + count[bits - 1]) << 1);
        next[bits] = code;
    }
    std::array<uint16_t, N> codes{};
    for (size_t s = 0; s < N; ++s) {
        const int l = lengths[s];
        if (!l) continue;
        const uint16_t c = next[l]++;
        uint16_t reversed = 0;
        for (int i = 0; i < l; ++i)
            reversed |= static_cast<uint16_t>(((c >> i) & 1) << (l - 1 - i));
        codes[s] = reversed;
    }
    return codes;
}

// A symbol of the code-length alphabet and its extra bits.
struct LengthToken {
    uint8_t symbol, extra;
};

// The literal/length and distance code lengths, run-length coded with
// symbols 16 (repeat the previous 3-6 times), 17 (3-10 zeros), 18 (11-138 zeros).
std::vector<LengthToken> code_length_tokens(const std::vector<uint8_t>& lengths) {
    std::vector<LengthToken> tokens;
    for (size_t i = 0; i < lengths.size();) {
        const uint8_t l = lengths[i];
        size_t run = 1;
        while (i + run < lengths.size() && lengths[i + run] == l) ++run;
        if (l == 0 && run >= 3) {
            const size_t n = std::min<size_t>(run, 138);
            tokens.push_back(n >= 11 ? LengthToken{18, static_cast<uint8_t>(n - 11)}
                                     : LengthToken{17, static_cast<uint8_t>(n - 3)});
            i += n;
        } else if (l != 0 && run >= 4) {
            const size_t n = std::min<size_t>(run - 1, 6);
            tokens.push_back({l, 0});
            tokens.push_back({16, static_cast<uint8_t>(n - 3)});
            i += n + 1;
        } else {
            tokens.push_back({l, 0});
            ++i;
        }
    }
    return tokens;
}

// Where the runs of a block are: bytes [start, start + length) repeat the
// ones `distance` before them.
struct Run {
    size_t start, length;
};

// How many bytes from `at` on repeat the bytes `distance` before them, up to `end`.
size_t run_length(const uint8_t* data, size_t at, size_t end, size_t distance) {
    size_t n = 0;
    while (at + n + 8 <= end) {
        uint64_t here, back;
        std::memcpy(&here, data + at + n, 8);
        std::memcpy(&back, data + at + n - distance, 8);
        if (here != back) break;
        n += 8;
    }
    while (at + n < end && data[at + n] == data[at + n - distance]) ++n;
    return n;
}

// The bytes a run leaves over after its copies: none, or one or two
// (shorter than any copy), at its end.
size_t run_leftover(size_t length) {
    const size_t tail = length % kMaxCopy;
    return tail < 3 ? tail : 0;
}

// Counts the literals and copies of data[begin, end) and finds its runs.
void count_block(const uint8_t* data, size_t begin, size_t end, size_t distance,
                 std::vector<Run>& runs, std::array<uint32_t, kLiteralSymbols>& freq) {
    size_t i = begin;
    while (i < end) {
        if (i >= distance && i + kMinRun <= end && data[i] == data[i - distance]) {
            const size_t n = run_length(data, i, end, distance);
            if (n >= kMinRun) {
                runs.push_back({i, n});
                const size_t leftover = run_leftover(n);
                for (size_t left = n - leftover; left > 0;) {
                    const size_t copy = std::min(left, kMaxCopy);
                    ++freq[static_cast<size_t>(257 + length_slot(copy))];
                    left -= copy;
                }
                for (size_t k = i + n - leftover; k < i + n; ++k) ++freq[data[k]];
                i += n;
                continue;
            }
        }
        ++freq[data[i]];
        ++i;
    }
}

}  // namespace

namespace {

// A Huffman code needs two symbols to be complete: a block of one byte
// value (or one code length) gets a second symbol it does not use.
template <size_t N>
void at_least_two_symbols(std::array<uint32_t, N>& freq) {
    if (std::count_if(freq.begin(), freq.end(), [](uint32_t f) { return f != 0; }) >= 2) return;
    freq[0] = std::max<uint32_t>(freq[0], 1);
    freq[1] = std::max<uint32_t>(freq[1], 1);
}

struct BlockCodes {
    std::array<uint8_t, kLiteralSymbols> lengths;
    std::array<uint16_t, kLiteralSymbols> codes;
};

// The block's header: its type and the code lengths, themselves coded.
BlockCodes write_block_header(BitWriter& bits, std::array<uint32_t, kLiteralSymbols> freq,
                              int distance_symbol, bool last) {
    freq[kEndOfBlock] = 1;
    at_least_two_symbols(freq);
    BlockCodes codes{code_lengths(freq, 15), {}};
    codes.codes = canonical_codes(codes.lengths);
    int literal_count = kLiteralSymbols;
    while (literal_count > 257 && codes.lengths[static_cast<size_t>(literal_count - 1)] == 0)
        --literal_count;
    // Two distance codes of one bit each, a complete code: code 0 and the
    // one in use (or code 1, unused, when that is code 0).
    std::vector<uint8_t> all(codes.lengths.begin(), codes.lengths.begin() + literal_count);
    const int distance_count = std::max(2, distance_symbol + 1);
    for (int d = 0; d < distance_count; ++d)
        all.push_back(d == 0 || d == distance_count - 1 ? 1 : 0);
    const std::vector<LengthToken> tokens = code_length_tokens(all);
    std::array<uint32_t, kCodeLengthSymbols> length_freq{};
    for (const LengthToken& t : tokens) ++length_freq[t.symbol];
    at_least_two_symbols(length_freq);
    const auto length_lengths = code_lengths(length_freq, 7);
    const auto length_codes = canonical_codes(length_lengths);
    int stored = kCodeLengthSymbols;
    while (stored > 4 && length_lengths[kCodeLengthOrder[static_cast<size_t>(stored - 1)]] == 0)
        --stored;
    bits.put(last ? 1 : 0, 1);
    bits.put(2, 2);  // dynamic Huffman codes
    bits.put(static_cast<uint32_t>(literal_count - 257), 5);
    bits.put(static_cast<uint32_t>(distance_count - 1), 5);
    bits.put(static_cast<uint32_t>(stored - 4), 4);
    for (int i = 0; i < stored; ++i)
        bits.put(length_lengths[kCodeLengthOrder[static_cast<size_t>(i)]], 3);
    for (const LengthToken& t : tokens) {
        bits.put(length_codes[t.symbol], length_lengths[t.symbol]);
        if (t.symbol == 16) bits.put(t.extra, 2);
        if (t.symbol == 17) bits.put(t.extra, 3);
        if (t.symbol == 18) bits.put(t.extra, 7);
    }
    return codes;
}

// Two literals at a time (at most 30 bits), one table load each: the
// hottest loop, as most bytes of an image's busy parts are literals.
void write_literals(BitWriter& bits, const std::array<uint32_t, 256>& code_and_length,
                    const uint8_t* data, size_t begin, size_t end) {
    size_t i = begin;
    for (; i + 2 <= end; i += 2) {
        const uint32_t a = code_and_length[data[i]], b = code_and_length[data[i + 1]];
        const int a_bits = static_cast<int>(a >> 16);
        bits.put((a & 0xffff) | (b & 0xffff) << a_bits, a_bits + static_cast<int>(b >> 16));
    }
    if (i < end)
        bits.put(code_and_length[data[i]] & 0xffff,
                 static_cast<int>(code_and_length[data[i]] >> 16));
}

// The distance code of a copy from `distance` (1..8) back, and its extra bits.
struct DistanceCode {
    int symbol, extra_bits;
    uint32_t extra;
};
DistanceCode distance_code(size_t distance) {
    if (distance <= 4) return {static_cast<int>(distance) - 1, 0, 0};
    if (distance <= 6) return {4, 1, static_cast<uint32_t>(distance - 5)};
    return {5, 1, static_cast<uint32_t>(distance - 7)};
}

// A run as copies, its last one or two bytes as literals when no copy is
// that short. The distance code in use is the one-bit code 1 beside an
// unused code 0, or itself code 0 for distance 1 (write_block_header).
void write_run(BitWriter& bits, const BlockCodes& c, const uint8_t* data, const Run& run,
               const DistanceCode& distance) {
    const size_t leftover = run_leftover(run.length);
    for (size_t left = run.length - leftover; left > 0;) {
        const size_t copy = std::min(left, kMaxCopy);
        const int slot = length_slot(copy);
        const size_t symbol = static_cast<size_t>(257 + slot);
        bits.put(c.codes[symbol], c.lengths[symbol]);
        bits.put(static_cast<uint32_t>(copy - kLengthBase[static_cast<size_t>(slot)]),
                 kLengthExtra[static_cast<size_t>(slot)]);
        bits.put(distance.symbol == 0 ? 0 : 1, 1);
        bits.put(distance.extra, distance.extra_bits);
        left -= copy;
    }
    for (size_t k = run.start + run.length - leftover; k < run.start + run.length; ++k)
        bits.put(c.codes[data[k]], c.lengths[data[k]]);
}

}  // namespace

void zlib_compress_runs(const uint8_t* data, size_t size, size_t distance,
                        std::vector<uint8_t>& out) {
    distance = std::clamp<size_t>(distance, 1, kMaxRunDistance);
    const DistanceCode code = distance_code(distance);
    // No code is longer than 15 bits and a copy's bits are fewer than its
    // bytes', so a block takes at most 15/8 of its bytes plus its header.
    const size_t blocks = size / kBlockBytes + 1;
    const size_t bound = size / 8 * 15 + 15 + blocks * kMaxHeaderBytes;
    const std::unique_ptr<uint8_t[]> scratch(new uint8_t[bound]);  // not cleared: written first
    BitWriter bits(scratch.get());
    std::vector<Run> runs;
    size_t begin = 0;
    do {
        const size_t end = std::min(size, begin + kBlockBytes);
        std::array<uint32_t, kLiteralSymbols> freq{};
        runs.clear();
        count_block(data, begin, end, distance, runs, freq);
        const BlockCodes codes = write_block_header(bits, freq, code.symbol, end == size);
        std::array<uint32_t, 256> literal_codes;
        for (size_t b = 0; b < 256; ++b)
            literal_codes[b] = codes.codes[b] | static_cast<uint32_t>(codes.lengths[b]) << 16;
        size_t at = begin;
        for (const Run& run : runs) {
            write_literals(bits, literal_codes, data, at, run.start);
            write_run(bits, codes, data, run, code);
            at = run.start + run.length;
        }
        write_literals(bits, literal_codes, data, at, end);
        bits.put(codes.codes[kEndOfBlock], codes.lengths[kEndOfBlock]);
        begin = end;
    } while (begin < size);
    const size_t written = bits.flush();
    out.push_back(0x78);  // deflate, 32 KiB window
    out.push_back(0x01);  // fastest, and a multiple of 31 with the byte before
    out.insert(out.end(), scratch.get(), scratch.get() + written);
    const uint32_t adler = libdeflate_adler32(1, data, size);
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<uint8_t>(adler >> shift));
}

}  // namespace facet
