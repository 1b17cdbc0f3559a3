#pragma once
// A fast DEFLATE (RFC 1951) compressor for filtered image rows: Huffman coding of the bytes plus
// runs of a repeated byte as matches at distance 1, the two things that pay on PNG-filtered
// renders (flat areas filter to runs of zeros). Like zlib's Z_RLE strategy, without a general
// match search; a piece of a stream can end byte-aligned so that pieces compressed in parallel
// are simply concatenated (zlib's Z_SYNC_FLUSH).

#include <cstdint>
#include <span>
#include <vector>

namespace hikari {

/// Appends `data` to `out` as one dynamic-Huffman DEFLATE block. With `last`, the block is the
/// stream's final one (BFINAL); otherwise an empty stored block follows, which ends the piece on
/// a byte boundary so that the next piece's blocks can be appended as they are. Runs refer only
/// to bytes of `data` itself, so pieces are independent.
void deflate_runs(std::span<const uint8_t> data, bool last, std::vector<uint8_t>& out);

}  // namespace hikari
