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

#include "core/simd_math.hpp"

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

// The length symbol (0-based, from 257) of a copy of each length 3..258.
constexpr std::array<uint8_t, 259> kLengthSlot = [] {
    std::array<uint8_t, 259> slots{};
    for (size_t length = 3, slot = 0; length <= 258; ++length) {
        while (slot + 1 < kLengthBase.size() && kLengthBase[slot + 1] <= length) ++slot;
        slots[length] = static_cast<uint8_t>(slot);
    }
    return slots;
}();
int length_slot(size_t length) {
    return kLengthSlot[length];
}

// Bits go out least significant first, as deflate packs them, into a
// buffer the caller sized for the worst case plus kBitWriterSlack bytes:
// each put stores eight bytes and keeps fewer than eight bits back, so it
// takes up to 56 bits with no branch.
constexpr size_t kBitWriterSlack = 8;
class BitWriter {
  public:
    explicit BitWriter(uint8_t* out) : start_(out), at_(out) {}
    void put(uint64_t bits, int count) {
        buffer_ |= bits << filled_;
        filled_ += count;
        std::memcpy(at_, &buffer_, 8);  // little-endian: the first bits first
        at_ += filled_ >> 3;
        buffer_ >>= filled_ & ~7;
        filled_ &= 7;
    }
    // Pads with zero bits to the next byte; the bytes written.
    size_t flush() {
        if (filled_ > 0) *at_++ = static_cast<uint8_t>(buffer_);
        buffer_ = 0;
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
// it is too deep. The tree is built with two queues (van Leeuwen, 1976):
// the leaves sorted by (count, symbol), and the inner nodes, which are
// made in order of weight. Taking the smaller front by (weight, index),
// inner nodes numbered from N on, joins the same pairs as a priority
// queue would, without a heap; the lengths depend only on the counts.
template <size_t N>
std::array<uint8_t, N> code_lengths(std::array<uint32_t, N> freq, int limit) {
    for (;;) {
        std::array<uint16_t, N> leaves;
        size_t leaf_count = 0;
        for (size_t s = 0; s < N; ++s)
            if (freq[s]) leaves[leaf_count++] = static_cast<uint16_t>(s);
        std::sort(leaves.begin(), leaves.begin() + leaf_count, [&](uint16_t a, uint16_t b) {
            return freq[a] != freq[b] ? freq[a] < freq[b] : a < b;
        });
        std::array<uint64_t, N> inner_weight;
        std::array<int, 2 * N> parent;
        parent.fill(-1);
        size_t next_leaf = 0, next_inner = 0, inner_count = 0;
        // The lighter front of the two queues, as (weight, node index).
        auto take = [&]() -> std::pair<uint64_t, int> {
            const bool leaf =
                next_leaf < leaf_count &&
                (next_inner == inner_count || freq[leaves[next_leaf]] <= inner_weight[next_inner]);
            if (leaf) {
                const uint16_t symbol = leaves[next_leaf++];
                return {freq[symbol], symbol};
            }
            const size_t i = next_inner++;
            return {inner_weight[i], static_cast<int>(N + i)};
        };
        for (size_t joined = 1; joined < leaf_count; ++joined) {
            const auto a = take(), b = take();
            parent[static_cast<size_t>(a.second)] = parent[static_cast<size_t>(b.second)] =
                static_cast<int>(N + inner_count);
            inner_weight[inner_count++] = a.first + b.first;
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

// Which of the 16 bytes from `at` on equal the byte `distance` before
// each, one bit each; `at` >= `distance`, and 16 bytes from `at` readable.
unsigned repeat_mask16(const uint8_t* data, size_t at, size_t distance) {
    return simd::equal_bytes16(data + at, data + at - distance);
}

// How many bytes from `at` on repeat the bytes `distance` before them, up to `end`.
size_t run_length(const uint8_t* data, size_t at, size_t end, size_t distance) {
    size_t n = 0;
    while (at + n + 16 <= end) {
        const unsigned mask = repeat_mask16(data, at + n, distance);
        if (mask != 0xffff) return n + static_cast<size_t>(__builtin_ctz(~mask));
        n += 16;
    }
    while (at + n < end && data[at + n] == data[at + n - distance]) ++n;
    return n;
}

// The first position in [at, end) where kMinRun bytes in a row repeat the
// bytes `distance` before them, or `end`. Sixteen positions a step: most
// of a rendered image's bytes are literals, and a test per byte
// mispredicted often enough to be the coder's largest cost.
size_t next_run_start(const uint8_t* data, size_t at, size_t end, size_t distance) {
    static_assert(kMinRun == 4, "the masks below test four positions in a row");
    at = std::max(at, distance);
    // Two masks give 32 positions; a run can start at the first 29 of them.
    for (; at + 32 <= end; at += 29) {
        const unsigned m =
            repeat_mask16(data, at, distance) | repeat_mask16(data, at + 16, distance) << 16;
        const unsigned starts = m & m >> 1 & m >> 2 & m >> 3 & 0x1fffffffu;
        if (starts) return at + static_cast<size_t>(__builtin_ctz(starts));
    }
    for (; at + kMinRun <= end; ++at)
        if (run_length(data, at, at + kMinRun, distance) == kMinRun) return at;
    return end;
}

// The bytes a run leaves over after its copies: none, or one or two
// (shorter than any copy), at its end.
size_t run_leftover(size_t length) {
    const size_t tail = length % kMaxCopy;
    return tail < 3 ? tail : 0;
}

// Byte counts kept in four tables, each byte's table by its position:
// with one, a byte equal to the one before waits for that one's count to
// be stored, and images have many such bytes.
struct ByteCounts {
    std::array<std::array<uint32_t, 256>, 4> tables{};
    void add(const uint8_t* data, size_t begin, size_t end) {
        size_t i = begin;
        for (; i + 4 <= end; i += 4)
            for (size_t t = 0; t < 4; ++t) ++tables[t][data[i + t]];
        for (; i < end; ++i) ++tables[0][data[i]];
    }
    void add_to(std::array<uint32_t, kLiteralSymbols>& freq) const {
        for (const auto& table : tables)
            for (size_t b = 0; b < 256; ++b) freq[b] += table[b];
    }
};

// Counts the literals and copies of data[begin, end) and finds its runs.
void count_block(const uint8_t* data, size_t begin, size_t end, size_t distance,
                 std::vector<Run>& runs, std::array<uint32_t, kLiteralSymbols>& freq) {
    ByteCounts literals;
    for (size_t i = begin; i < end;) {
        const size_t start = next_run_start(data, i, end, distance);
        literals.add(data, i, start);
        i = start;
        if (start == end) break;
        const size_t n = run_length(data, start, end, distance);
        runs.push_back({start, n});
        const size_t leftover = run_leftover(n);
        for (size_t left = n - leftover; left > 0;) {
            const size_t copy = std::min(left, kMaxCopy);
            ++freq[static_cast<size_t>(257 + length_slot(copy))];
            left -= copy;
        }
        literals.add(data, start + n - leftover, start + n);
        i = start + n;
    }
    literals.add_to(freq);
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

// Three literals at a time (at most 45 bits), one table load each: the
// hottest loop, as most bytes of an image's busy parts are literals.
void write_literals(BitWriter& bits, const std::array<uint32_t, 256>& code_and_length,
                    const uint8_t* data, size_t begin, size_t end) {
    size_t i = begin;
    for (; i + 3 <= end; i += 3) {
        const uint32_t a = code_and_length[data[i]], b = code_and_length[data[i + 1]],
                       c = code_and_length[data[i + 2]];
        const int a_bits = static_cast<int>(a >> 16), b_bits = static_cast<int>(b >> 16);
        bits.put(uint64_t{a & 0xffff} | uint64_t{b & 0xffff} << a_bits |
                     uint64_t{c & 0xffff} << (a_bits + b_bits),
                 a_bits + b_bits + static_cast<int>(c >> 16));
    }
    for (; i < end; ++i)
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
        // Length code, its extra bits, distance code and its extra bit: at
        // most 15 + 5 + 1 + 1 bits, in one put.
        uint64_t word = c.codes[symbol];
        int count = c.lengths[symbol];
        word |= uint64_t{copy - kLengthBase[static_cast<size_t>(slot)]} << count;
        count += kLengthExtra[static_cast<size_t>(slot)];
        word |= uint64_t{distance.symbol == 0 ? 0u : 1u} << count;
        count += 1;
        word |= uint64_t{distance.extra} << count;
        bits.put(word, count + distance.extra_bits);
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
    const size_t bound = size / 8 * 15 + 15 + blocks * kMaxHeaderBytes + kBitWriterSlack;
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
