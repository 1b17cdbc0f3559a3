#pragma once
// What an image file's header promises, checked against the bytes the file holds before a
// decoder allocates anything: a JPEG with headers but no scan data, more scans than any encoder
// writes, or fewer entropy-coded bytes than its blocks need, and a Radiance HDR whose scanlines
// stop short, are refused naming the file (stb_image would read zeros past the end and decode a
// picture of any claimed size from a few bytes).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace hikari {

/// The most scans a JPEG may have (libjpeg-turbo's documentation suggests 500 as the limit for
/// untrusted progressive files; encoders write about 10).
inline constexpr int k_max_jpeg_scans = 500;

/// The most 8×8 blocks all of a JPEG's scans may walk together: a progressive decoder visits
/// every block of a scan's components, even for a scan of a few bytes, so 100 empty scans of a
/// large image take minutes. 2^27 is 32 passes over the largest image read_image() accepts.
inline constexpr double k_max_jpeg_scan_blocks = double(1 << 27);

/// Walks the markers of the JPEG `bytes` (ITU T.81, Annex B) and throws InputError naming
/// `path` when the frame header (SOF) has no scan after it, a scan has fewer entropy-coded bits
/// than one a block of its DC coefficients (T.81 F.1.2.1: every Huffman code is at least one
/// bit), a segment runs past the end of the file, a Huffman table holds more than 256 codes, or
/// the scans exceed the limits above. Files without an SOF are otherwise left to the decoder's
/// own error. Call it before stb_image sees the bytes.
void check_jpeg_data(const std::filesystem::path& path, std::string_view bytes);

/// The PNG `bytes` without their empty IDAT chunks, or nothing when it has none (PNG 11.2.4: the
/// image data is the concatenation of the IDAT chunks, so an empty one adds nothing). stb_image
/// copies a first, empty IDAT into a buffer it has not yet allocated (found by
/// fuzz/image_fuzz.cpp). Chunks past the end of the file are left to the decoder.
std::optional<std::string> png_without_empty_data_chunks(std::string_view bytes);

/// Walks the scanlines of the Radiance HDR `bytes` of `width` × `height` pixels (read from its
/// header) as stb_image reads them (flat RGBE, or the run-length encoded scanlines of Ward's
/// format), and throws InputError naming `path` when the pixel data ends before the last one.
void check_hdr_data(const std::filesystem::path& path, std::string_view bytes, int width,
                    int height);

}  // namespace hikari
