#include "hikari/io/images/deflate_runs.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <memory>

#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/thread_scratch.h"

namespace hikari {

namespace {

constexpr int k_max_code_bits = 15;  // RFC 1951 §3.2.7: code lengths 0..15
constexpr int k_end_of_block = 256;
constexpr int k_litlen_symbols = 286;  // literals, end of block, length codes 257..285
constexpr int k_min_run = 3, k_max_run = 258;

/// Length code, extra-bit count and extra-bit value of a match length 3..258 (RFC 1951 §3.2.5).
struct LengthCode {
    uint16_t symbol;
    uint8_t extra_bits;
    uint8_t extra;
};

constexpr std::array<LengthCode, k_max_run + 1> make_length_codes() {
    // The first length of each of the codes 257..284; 285 alone stands for 258.
    constexpr std::array<int, 28> base = {3,  4,  5,  6,   7,   8,   9,   10, 11, 13,
                                          15, 17, 19, 23,  27,  31,  35,  43, 51, 59,
                                          67, 83, 99, 115, 131, 163, 195, 227};
    std::array<LengthCode, k_max_run + 1> table{};
    for (int code = 0; code < 28; ++code) {
        const int extra_bits = code < 8 ? 0 : code / 4 - 1;
        for (int extra = 0; extra < (1 << extra_bits); ++extra) {
            const int length = base[code] + extra;
            if (length < k_max_run)
                table[length] = {static_cast<uint16_t>(257 + code),
                                 static_cast<uint8_t>(extra_bits), static_cast<uint8_t>(extra)};
        }
    }
    table[k_max_run] = {285, 0, 0};
    return table;
}

constexpr std::array<LengthCode, k_max_run + 1> k_length_codes = make_length_codes();

/// Calls literal(byte) and run(length) for `data` read as literals and runs: a byte repeated
/// after itself becomes one match of distance 1 per 258 repeats (shorter leftovers stay literals).
template <class Literal, class Run>
void tokenize(std::span<const uint8_t> data, Literal&& literal, Run&& run) {
    const size_t n = data.size();
    const uint8_t* d = data.data();
    size_t i = 0;
    while (i < n) {
        const uint8_t b = d[i];
        literal(b);
        if (i + 1 < n && d[i + 1] != b) {  // no run: the common case, one comparison
            ++i;
            continue;
        }
        // Measure the run of b after d[i], eight bytes at a time: the first byte that differs
        // is the lowest non-zero byte of word ^ all_b (a little-endian load, as BitWriter
        // assumes too); the last few bytes one at a time.
        const uint64_t all_b = 0x0101010101010101ULL * b;
        size_t j = i + 1;
        bool ended = false;
        for (uint64_t word; !ended && j + 8 <= n;) {
            std::memcpy(&word, d + j, 8);
            const uint64_t differ = word ^ all_b;
            ended = differ != 0;
            j += ended ? static_cast<size_t>(std::countr_zero(differ) / 8) : 8;
        }
        while (!ended && j < n && d[j] == b) ++j;
        size_t repeats = j - i - 1;
        for (; repeats >= k_min_run; repeats -= std::min<size_t>(repeats, k_max_run))
            run(static_cast<int>(std::min<size_t>(repeats, k_max_run)));
        for (; repeats > 0; --repeats) literal(b);
        i = j;
    }
}

/// Huffman code lengths of at most `max_bits` for the symbol frequencies `freq` (0: unused).
/// Huffman's merge with two queues over the sorted leaves; when the tree is too deep the
/// frequencies are halved (keeping them non-zero), which flattens it, and the merge rerun.
template <size_t N>
std::array<uint8_t, N> huffman_lengths(std::array<uint32_t, N> freq, int max_bits) {
    std::array<uint8_t, N> lengths{};
    std::vector<int> leaves;
    for (size_t s = 0; s < N; ++s)
        if (freq[s] > 0) leaves.push_back(static_cast<int>(s));
    if (leaves.size() == 1) lengths[leaves[0]] = 1;
    if (leaves.size() <= 1) return lengths;

    const size_t count = leaves.size();
    std::vector<uint64_t> weight(2 * count - 1);
    std::vector<size_t> parent(2 * count - 1);
    std::vector<int> depth(2 * count - 1);
    for (;;) {
        std::stable_sort(leaves.begin(), leaves.end(),
                         [&](int a, int b) { return freq[a] < freq[b]; });
        for (size_t k = 0; k < count; ++k) weight[k] = freq[leaves[k]];
        // Nodes 0..count-1 are the leaves, ascending; internal nodes follow in the order made,
        // which is also ascending, so the two lightest are at the front of one queue or the other.
        size_t next_leaf = 0, next_node = count;
        auto take_lightest = [&](size_t made) {
            if (next_leaf < count && (next_node == made || weight[next_leaf] <= weight[next_node]))
                return next_leaf++;
            return next_node++;
        };
        for (size_t made = count; made < 2 * count - 1; ++made) {
            const size_t a = take_lightest(made), b = take_lightest(made);
            weight[made] = weight[a] + weight[b];
            parent[a] = parent[b] = made;
        }
        // Parents come after their children, so one backward sweep gives every depth.
        depth[2 * count - 2] = 0;
        int deepest = 0;
        for (size_t k = 2 * count - 2; k-- > 0;) {
            depth[k] = depth[parent[k]] + 1;
            deepest = std::max(deepest, depth[k]);
        }
        if (deepest <= max_bits) break;
        for (uint32_t& f : freq)
            if (f > 0) f = (f + 1) / 2;
    }
    for (size_t k = 0; k < count; ++k) lengths[leaves[k]] = static_cast<uint8_t>(depth[k]);
    return lengths;
}

uint32_t reverse_bits(uint32_t code, int bits) {
    uint32_t out = 0;
    for (int i = 0; i < bits; ++i) out |= ((code >> i) & 1u) << (bits - 1 - i);
    return out;
}

/// Canonical Huffman codes for `lengths` (RFC 1951 §3.2.2), bit-reversed because DEFLATE sends
/// codes from their most significant bit while the bit writer fills bytes from the least.
template <size_t N>
std::array<uint16_t, N> canonical_codes(const std::array<uint8_t, N>& lengths) {
    std::array<int, k_max_code_bits + 1> length_count{};
    for (uint8_t l : lengths) ++length_count[l];
    length_count[0] = 0;
    std::array<uint32_t, k_max_code_bits + 2> next{};
    for (int bits = 1, code = 0; bits <= k_max_code_bits; ++bits) {
        code = (code + length_count[bits - 1]) << 1;
        next[bits] = static_cast<uint32_t>(code);
    }
    std::array<uint16_t, N> codes{};
    for (size_t s = 0; s < N; ++s)
        if (lengths[s] > 0)
            codes[s] = static_cast<uint16_t>(reverse_bits(next[lengths[s]]++, lengths[s]));
    return codes;
}

/// Writes bits least significant first into a buffer sized in advance, with at least 8 bytes
/// to spare after the last byte written. Each put stores the whole 64-bit accumulator and moves
/// on by the bytes it completed: no branch on whether a word is full, which a stream of codes of
/// random lengths mispredicts every few codes.
class BitWriter {
  public:
    explicit BitWriter(uint8_t* out) : m_out(out) {}

    /// Appends the low `count` bits of `bits` (count ≤ 56, and no higher bit set); with the
    /// fewer than 8 bits pending, at most 63 are then held.
    void put(uint64_t bits, int count) {
        m_acc |= bits << m_count;
        m_count += count;
        std::memcpy(m_out, &m_acc, 8);  // little-endian host: bytes in stream order
        const int whole_bytes = m_count >> 3;
        m_out += whole_bytes;
        m_acc >>= 8 * whole_bytes;  // at most 56: m_count stays under 64
        m_count &= 7;
    }

    /// Pads with zero bits to a byte boundary and returns the end of the written bytes.
    uint8_t* finish() {
        if (m_count > 0) *m_out++ = static_cast<uint8_t>(m_acc);
        m_count = 0;
        m_acc = 0;
        return m_out;
    }

  private:
    uint8_t* m_out;
    uint64_t m_acc = 0;  ///< bits not yet in a whole byte: fewer than 8 between puts
    int m_count = 0;
};

// thread_scratch buffers of deflate_runs.
struct TokensTag {};
struct CodedBitsTag {};

}  // namespace

void deflate_runs(std::span<const uint8_t> data, bool last, std::vector<uint8_t>& out) {
    // Pass 1: the data as tokens (a literal byte b as b, a run of r repeats as 256 + r), and the
    // symbol frequencies, from which the literal/length code follows. Pass 2 then codes the
    // tokens without scanning the data again.
    uint16_t* const tokens = thread_scratch<uint16_t, TokensTag>(data.size());
    size_t token_count = 0;
    std::array<uint32_t, k_litlen_symbols> freq{};
    tokenize(
        data,
        [&](uint8_t b) {
            ++freq[b];
            tokens[token_count++] = b;
        },
        [&](int run) {
            ++freq[k_length_codes[run].symbol];
            tokens[token_count++] = static_cast<uint16_t>(256 + run);
        });
    freq[k_end_of_block] = 1;
    const auto lengths = huffman_lengths(freq, k_max_code_bits);
    const auto codes = canonical_codes(lengths);
    // Each token's bits and bit count: a literal's code, or a run's length code, its extra bits
    // and distance code 0 (one 0 bit), sent together.
    std::array<uint32_t, 256 + k_max_run + 1> token_bits{};
    std::array<uint8_t, 256 + k_max_run + 1> token_count_bits{};
    for (int b = 0; b < 256; ++b) token_bits[b] = codes[b], token_count_bits[b] = lengths[b];
    for (int run = k_min_run; run <= k_max_run; ++run) {
        const LengthCode& lc = k_length_codes[run];
        token_bits[256 + run] = codes[lc.symbol] | uint32_t{lc.extra} << lengths[lc.symbol];
        token_count_bits[256 + run] = static_cast<uint8_t>(lengths[lc.symbol] + lc.extra_bits + 1);
    }

    // Worst case: 15 bits per byte, plus the header (under 200 bytes) and the flush. The
    // scratch is left uninitialised: only what is written is touched.
    uint8_t* const scratch = thread_scratch<uint8_t, CodedBitsTag>(data.size() * 2 + 256);
    BitWriter bits(scratch);

    // Block header (RFC 1951 §3.2.7): BFINAL, BTYPE = 2 (dynamic), HLIT, HDIST, HCLEN. The
    // code-length code gives the lengths 0..15 four bits each (16 codes of 4 bits: complete);
    // its repeat codes 16..18 are not used. Two distance codes of one bit; only code 0 is sent.
    int litlen_count = k_litlen_symbols;
    while (litlen_count > 257 && lengths[litlen_count - 1] == 0) --litlen_count;
    bits.put(last ? 1 : 0, 1);
    bits.put(2, 2);
    bits.put(static_cast<uint64_t>(litlen_count - 257), 5);
    bits.put(2 - 1, 5);
    bits.put(19 - 4, 4);
    constexpr std::array<int, 19> k_code_length_order = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                                         11, 4,  12, 3, 13, 2, 14, 1, 15};
    for (int symbol : k_code_length_order) bits.put(symbol >= 16 ? 0 : 4, 3);
    for (int s = 0; s < litlen_count; ++s) bits.put(reverse_bits(lengths[s], 4), 4);
    for (int s = 0; s < 2; ++s) bits.put(reverse_bits(1, 4), 4);

    // Pass 2: the tokens.
    for (size_t t = 0; t < token_count; ++t)
        bits.put(token_bits[tokens[t]], token_count_bits[tokens[t]]);
    bits.put(codes[k_end_of_block], lengths[k_end_of_block]);
    if (!last) bits.put(0, 3);  // an empty stored block: BFINAL 0, BTYPE 0, ...
    uint8_t* end = bits.finish();
    if (!last) {
        // ... padded to a byte, then LEN 0 and NLEN 0xFFFF.
        const std::array<uint8_t, 4> empty_stored = {0x00, 0x00, 0xFF, 0xFF};
        end = std::copy(empty_stored.begin(), empty_stored.end(), end);
    }
    // Room for the piece, mapped in one call (populate_pages), growing geometrically when a
    // caller appends piece after piece.
    const auto coded = static_cast<size_t>(end - scratch);
    if (out.capacity() - out.size() < coded)
        out.reserve(std::max(out.size() + coded, 2 * out.capacity()));
    populate_pages(out.data() + out.size(), coded);
    out.insert(out.end(), scratch, end);
}

}  // namespace hikari
