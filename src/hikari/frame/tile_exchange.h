#pragma once
// A framebuffer's tiles as bytes, for processes that share one image (frame/tile_share.h): each
// sends the pixels of its tiles, and the one that writes the file puts them into its own
// framebuffer. Every buffer the framebuffer holds travels (colour, linear or 8-bit, then depth,
// ids and normals), so the gathered image and AOVs are those of one process.

#include <cstddef>
#include <span>
#include <vector>

#include "hikari/frame/framebuffer.h"

namespace hikari {

/// The pixels of every buffer of `fb` in the tiles that process `part` of `parts` renders, buffer
/// by buffer, tile by tile (row-major), row by row: what unpack_tiles reads.
std::vector<std::byte> pack_tiles(const Framebuffer& fb, int part, int parts);

/// Writes `bytes`, packed by pack_tiles from a framebuffer of the same size and buffers, into the
/// same tiles of `fb`. Throws std::invalid_argument when `bytes` is not that many bytes.
void unpack_tiles(Framebuffer& fb, std::span<const std::byte> bytes, int part, int parts);

}  // namespace hikari
