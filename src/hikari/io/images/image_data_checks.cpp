#include "hikari/io/images/image_data_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"

namespace hikari {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw InputError(printable_text(path.string() + ": " + reason));
}

unsigned byte_at(std::string_view bytes, size_t i) { return static_cast<unsigned char>(bytes[i]); }

// --- JPEG (ITU T.81) ----------------------------------------------------------------------------

/// One component of the frame: its sampling factors (T.81 B.2.2).
struct JpegComponent {
    int id = 0, h = 1, v = 1;
};

struct JpegFrame {
    long long width = 0, height = 0;
    std::array<JpegComponent, 4> components{};
    int component_count = 0;
    int h_max = 1, v_max = 1;

    /// The 8×8 blocks of component `id` (T.81 A.1.1: its size is the image's scaled by its
    /// sampling factors), without the padding to whole MCUs: a lower bound.
    double blocks_of(int id) const {
        for (int c = 0; c < component_count; ++c) {
            if (components[c].id != id) continue;
            const double w = std::ceil(double(width) * components[c].h / h_max);
            const double h = std::ceil(double(height) * components[c].v / v_max);
            return std::ceil(w / 8) * std::ceil(h / 8);
        }
        return 0;
    }
};

bool is_sof(unsigned marker) {
    return marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
}

JpegFrame parse_sof(const std::filesystem::path& path, std::string_view segment) {
    if (segment.size() < 6) fail(path, "truncated JPEG frame header");
    JpegFrame frame;
    frame.height = byte_at(segment, 1) << 8 | byte_at(segment, 2);
    frame.width = byte_at(segment, 3) << 8 | byte_at(segment, 4);
    frame.component_count = std::min<int>(byte_at(segment, 5), 4);
    if (segment.size() < 6 + 3 * size_t(frame.component_count))
        fail(path, "truncated JPEG frame header");
    for (int c = 0; c < frame.component_count; ++c) {
        const unsigned sampling = byte_at(segment, 7 + 3 * c);
        frame.components[c] = {static_cast<int>(byte_at(segment, 6 + 3 * c)),
                               std::max(1, int(sampling >> 4)), std::max(1, int(sampling & 15))};
        frame.h_max = std::max(frame.h_max, frame.components[c].h);
        frame.v_max = std::max(frame.v_max, frame.components[c].v);
    }
    return frame;
}

/// The bytes of entropy-coded data from `pos` up to the next marker that is not a stuffed 0xFF00
/// or a restart marker RSTn (T.81 B.1.1.5); `pos` is left on that marker (or at the end).
size_t skip_entropy_coded(std::string_view bytes, size_t& pos) {
    const size_t begin = pos;
    while (pos < bytes.size()) {
        if (byte_at(bytes, pos) == 0xff && pos + 1 < bytes.size()) {
            const unsigned next = byte_at(bytes, pos + 1);
            if (next != 0x00 && !(next >= 0xd0 && next <= 0xd7) && next != 0xff) break;
        }
        ++pos;
    }
    return pos - begin;
}

/// Reads the Huffman tables of a DHT segment starting at `pos` as stb_image reads them (T.81
/// B.2.4.2: Tc/Th, 16 code counts, then the values) and throws when a table holds more than 256
/// codes: Debian's stb_image writes past its 257-entry code-size list before it looks at the
/// count (found by fuzz/jpeg_fuzz.cpp). Like stb_image, the tables may read past the segment's
/// length; that mismatch is stb_image's own "Corrupt JPEG" afterwards.
void check_huffman_tables(const std::filesystem::path& path, std::string_view bytes, size_t pos,
                          size_t length) {
    long long left = static_cast<long long>(length) - 2;
    while (left > 0 && pos + 17 <= bytes.size()) {
        const unsigned class_and_id = byte_at(bytes, pos);
        if (class_and_id >> 4 > 1 || (class_and_id & 15) > 3) return;  // stb_image refuses it
        int codes = 0;
        for (int i = 1; i <= 16; ++i) codes += static_cast<int>(byte_at(bytes, pos + i));
        if (codes > 256) {
            fail(path, fmt::format("corrupt JPEG: a Huffman table at byte {} has {} codes (at "
                                   "most 256)",
                                   pos, codes));
        }
        pos += 17 + static_cast<size_t>(codes);
        left -= 17 + codes;
    }
}

}  // namespace

void check_jpeg_data(const std::filesystem::path& path, std::string_view bytes) {
    size_t pos = 2;  // after SOI
    JpegFrame frame;
    bool have_frame = false;
    int scans = 0;
    double scan_blocks = 0;
    while (pos + 1 < bytes.size()) {
        if (byte_at(bytes, pos) != 0xff) {  // garbage between segments: the decoder's to judge
            ++pos;
            continue;
        }
        const unsigned marker = byte_at(bytes, pos + 1);
        if (marker == 0xff) {  // fill byte
            ++pos;
            continue;
        }
        pos += 2;
        if (marker == 0xd9) break;                                           // EOI
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd8)) continue;  // no length
        if (pos + 2 > bytes.size()) fail(path, "truncated JPEG: a segment ends the file");
        const size_t length = byte_at(bytes, pos) << 8 | byte_at(bytes, pos + 1);
        if (length < 2 || pos + length > bytes.size())
            fail(path, fmt::format("truncated JPEG: a segment of {} bytes at byte {} runs past the "
                                   "end of the file",
                                   length, pos - 2));
        const std::string_view segment = bytes.substr(pos + 2, length - 2);
        if (marker == 0xc4) check_huffman_tables(path, bytes, pos + 2, length);
        pos += length;
        if (is_sof(marker)) {
            frame = parse_sof(path, segment);
            have_frame = true;
        } else if (marker == 0xda && have_frame) {
            // T.81 B.2.3: Ns, Ns component selectors, then Ss (0 when the scan holds DC terms).
            const size_t ns = segment.empty() ? 0 : byte_at(segment, 0);
            if (segment.size() < 1 + 2 * ns + 3) fail(path, "truncated JPEG scan header");
            const bool dc_scan = byte_at(segment, 1 + 2 * ns) == 0;
            double blocks = 0;
            for (size_t c = 0; c < ns; ++c) blocks += frame.blocks_of(byte_at(segment, 1 + 2 * c));
            const size_t data = skip_entropy_coded(bytes, pos);
            if (dc_scan && 8.0 * double(data) < blocks) {
                fail(path, fmt::format("truncated JPEG: scan {} holds {} bytes of data, its {:.0f} "
                                       "blocks need at least {:.0f}",
                                       scans + 1, data, blocks, std::ceil(blocks / 8)));
            }
            ++scans;
            scan_blocks += blocks;
            if (scans > k_max_jpeg_scans)
                fail(path, fmt::format("JPEG has more than {} scans", k_max_jpeg_scans));
            if (scan_blocks > k_max_jpeg_scan_blocks) {
                fail(path, fmt::format("JPEG's {} scans walk more than {:.0f} blocks of its {}x{} "
                                       "image (a scan bomb)",
                                       scans, k_max_jpeg_scan_blocks, frame.width, frame.height));
            }
        }
    }
    if (have_frame && scans == 0)
        fail(path, "truncated JPEG: headers but no scan data (no SOS segment)");
}

// --- PNG (ISO/IEC 15948) -----------------------------------------------------------------------

std::optional<std::string> png_without_empty_data_chunks(std::string_view bytes) {
    constexpr size_t k_signature = 8, k_chunk_overhead = 12;  // length, type, CRC
    std::optional<std::string> kept;
    size_t copied = 0;  // bytes[0, copied) are in `kept` (or need not be)
    for (size_t pos = k_signature; pos + k_chunk_overhead <= bytes.size();) {
        const size_t length = size_t{byte_at(bytes, pos)} << 24 |
                              size_t{byte_at(bytes, pos + 1)} << 16 |
                              size_t{byte_at(bytes, pos + 2)} << 8 | byte_at(bytes, pos + 3);
        const std::string_view type = bytes.substr(pos + 4, 4);
        if (length == 0 && type == "IDAT") {
            if (!kept) kept.emplace();
            kept->append(bytes.substr(copied, pos - copied));
            copied = pos + k_chunk_overhead;
        }
        if (type == "IEND" || length > bytes.size() - pos - k_chunk_overhead) break;
        pos += k_chunk_overhead + length;
    }
    if (kept) kept->append(bytes.substr(copied));
    return kept;
}

// --- Radiance HDR -------------------------------------------------------------------------------

void check_hdr_data(const std::filesystem::path& path, std::string_view bytes, int width,
                    int height) {
    // The header ends with an empty line, then the resolution line ("-Y H +X W").
    size_t pos = bytes.find("\n\n");
    if (pos == std::string_view::npos) return;  // the decoder reports a malformed header
    pos = bytes.find('\n', pos + 2);
    if (pos == std::string_view::npos) return;
    ++pos;
    const auto truncated = [&](long long row) {
        fail(path, fmt::format("truncated file: the pixel data ends in scanline {} of {}", row + 1,
                               height));
    };
    const auto need_flat = [&](long long pixels, long long row) {
        if (double(bytes.size() - pos) < 4.0 * double(pixels)) truncated(row);
    };
    // stb_image reads scanlines outside [8, 32768) pixels wide as flat RGBE.
    if (width < 8 || width >= 32768) return need_flat(static_cast<long long>(width) * height, 0);
    for (long long row = 0; row < height; ++row) {
        if (pos + 4 > bytes.size()) truncated(row);
        // A run-length scanline starts 2, 2, then its width in 15 bits; anything else makes
        // stb_image read the rest of the image flat from here.
        if (byte_at(bytes, pos) != 2 || byte_at(bytes, pos + 1) != 2 ||
            (byte_at(bytes, pos + 2) & 0x80)) {
            return need_flat((height - row) * static_cast<long long>(width), row);
        }
        pos += 4;
        for (int channel = 0; channel < 4; ++channel) {
            for (int x = 0; x < width;) {
                if (pos >= bytes.size()) truncated(row);
                unsigned count = byte_at(bytes, pos++);
                if (count == 0) return;  // bad RLE data: the decoder says so
                const bool run = count > 128;
                if (run) count -= 128;
                const size_t payload = run ? 1 : count;
                if (pos + payload > bytes.size()) truncated(row);
                pos += payload;
                x += static_cast<int>(count);
            }
        }
    }
}

}  // namespace hikari
