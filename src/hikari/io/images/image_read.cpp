#include "hikari/io/images/image_read.h"

#include <tinyexr.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "hikari/core/color.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_data_checks.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/stb_image_bounded.h"

namespace hikari {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw InputError(printable_text(path.string() + ": " + reason));
}

/// Refuses sizes that are not positive or exceed the limits, before anything is allocated;
/// `decoder_bytes_per_pixel` is what the decoder holds besides the image's RGB floats.
void check_size(const std::filesystem::path& path, long long width, long long height,
                double decoder_bytes_per_pixel = 16) {
    if (width <= 0 || height <= 0) {
        fail(path, "invalid image size " + std::to_string(width) + "x" + std::to_string(height));
    }
    if (width > k_max_image_side || height > k_max_image_side ||
        static_cast<unsigned long long>(width) * static_cast<unsigned long long>(height) >
            k_max_image_pixels) {
        fail(path, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                       " exceeds the limit (65536 per side, 2^28 pixels)");
    }
    // The image's RGB floats (12 bytes a pixel) and the decoder's own buffers (by default 16
    // bytes a pixel: tinyexr's float RGBA planes).
    check_memory_need(
        (12.0 + decoder_bytes_per_pixel) * static_cast<double>(width) * static_cast<double>(height),
        fmt::format("{}: decoding a {}x{} image", path.string(), width, height));
}

/// Linear values of the 256 8-bit sRGB codes, so decoding is a table look-up per sample.
const std::array<float, 256>& srgb8_to_linear_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
        return t;
    }();
    return table;
}

// --- PNG / JPEG / HDR through stb_image --------------------------------------------------------

/// The file's bytes as stb_image takes them, with the image's size from its header.
struct StbInput {
    const unsigned char* data;
    int size;
    int width, height;
};

/// Reads the header (PNG: IHDR; JPEG: SOF; HDR: resolution line).
StbInput stb_input(const std::filesystem::path& path, const std::string& bytes) {
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) fail(path, "file too large");
    StbInput in{reinterpret_cast<const unsigned char*>(bytes.data()),
                static_cast<int>(bytes.size()), 0, 0};
    int channels = 0;
    if (!stb::info(in.data, in.size, &in.width, &in.height, &channels)) {
        fail(path, std::string("cannot decode image: ") + stb::failure_reason());
    }
    return in;
}

/// Refuses, before decoding, a size beyond the limits or the memory budget: besides our floats,
/// stb_image holds 16 bytes a pixel at once (PNG: the inflated rows, its output and the RGB
/// copy), 24 for 16-bit samples.
void check_stb_size(const std::filesystem::path& path, const StbInput& in) {
    check_size(path, in.width, in.height, stb::is_16_bit(in.data, in.size) ? 24 : 16);
}

/// The largest single allocation stb_image needs for a `width` × `height` image: 16 bytes a
/// pixel covers PNG's inflated rows (at most 8 bytes a pixel, 16-bit RGBA, doubled as its
/// inflater grows), a JPEG's coefficients and planes padded to whole MCUs (up to 32 pixels
/// each way), and HDR's floats. A PNG whose data inflates past it is a decompression bomb.
size_t stb_allocation_cap(int width, int height) {
    return 16 * (static_cast<size_t>(width) + 32) * (static_cast<size_t>(height) + 32) +
           (size_t{1} << 20);
}

/// The RGB samples `decode` returns (null when it failed) of a `w` × `h` image, each turned
/// into linear light by `to_linear`, decoded under the allocation cap for the header's size.
template <class Decode, class ToLinear>
Image image_from_stb(const std::filesystem::path& path, const StbInput& in, Decode decode,
                     ToLinear to_linear) {
    int w = 0, h = 0, channels = 0;
    const stb::AllocationCap cap(stb_allocation_cap(in.width, in.height));
    using Sample = std::remove_pointer_t<decltype(decode(in.data, in.size, &w, &h, &channels, 3))>;
    std::unique_ptr<Sample, void (*)(void*)> pixels(decode(in.data, in.size, &w, &h, &channels, 3),
                                                    &stb::image_free);
    if (!pixels && cap.exceeded()) {
        fail(path, fmt::format("cannot decode image: its data needs more than the {} its {}x{} "
                               "size allows (a decompression bomb?)",
                               memory_size_text(double(stb_allocation_cap(in.width, in.height))),
                               in.width, in.height));
    }
    if (!pixels) fail(path, std::string("cannot decode image: ") + stb::failure_reason());
    // Size the image from what the decoder returns, not from the header: the two can disagree
    // on malformed files (found by fuzz/image_fuzz.cpp).
    check_size(path, w, h);
    Image image(w, h);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const Sample* p = pixels.get() + 3 * i;
        image.pixels[i] = {to_linear(p[0]), to_linear(p[1]), to_linear(p[2])};
    }
    return image;
}

Image read_stb(const std::filesystem::path& path, const std::string& file_bytes) {
    // Only PNG and JPEG go to stb_image: it also sniffs other formats, and its 16-bit PNM path
    // writes past its buffer (found by fuzz/image_fuzz.cpp).
    const bool png = file_bytes.starts_with("\x89PNG\r\n\x1a\n");
    const bool jpeg = file_bytes.starts_with("\xFF\xD8\xFF");
    const std::optional<std::string> cleaned =
        png ? png_without_empty_data_chunks(file_bytes) : std::nullopt;
    const std::string& bytes = cleaned ? *cleaned : file_bytes;
    if (!png && !jpeg) fail(path, "not a PNG or JPEG file (wrong signature)");
    // Before stb_image reads a byte: its header pass builds the Huffman tables too. Truncation
    // is said first, whatever the size.
    if (jpeg) check_jpeg_data(path, bytes);
    const StbInput in = stb_input(path, bytes);
    check_stb_size(path, in);
    if (stb::is_16_bit(in.data, in.size)) {
        return image_from_stb(path, in, stb::load_16,
                              [](unsigned short c) { return srgb_to_linear(c / 65535.0f); });
    }
    const auto& lut = srgb8_to_linear_table();
    return image_from_stb(path, in, stb::load_8, [&](unsigned char c) { return lut[c]; });
}

/// A Radiance RGBE (.hdr) file through stb_image, which decodes it to linear floats.
Image read_hdr(const std::filesystem::path& path, const std::string& bytes) {
    if (!bytes.starts_with("#?RADIANCE") && !bytes.starts_with("#?RGBE"))
        fail(path, "not a Radiance HDR file (wrong signature)");
    const StbInput in = stb_input(path, bytes);
    check_hdr_data(path, bytes, in.width, in.height);
    check_stb_size(path, in);
    return image_from_stb(path, in, stb::load_float, [](float c) { return c; });
}

// --- Netpbm and PFM headers --------------------------------------------------------------------

/// Reads the whitespace-separated tokens of a Netpbm/PFM header ('#' starts a comment to the end
/// of the line, as in Netpbm), then hands over the byte offset where binary data begins.
class HeaderReader {
  public:
    HeaderReader(const std::filesystem::path& path, std::string_view bytes)
        : m_path(path), m_bytes(bytes) {}

    /// The next token; fails (naming `what`) at the end of the file.
    std::string_view token(const char* what) {
        skip_space_and_comments();
        const size_t begin = m_pos;
        while (m_pos < m_bytes.size() && !is_space(m_bytes[m_pos])) ++m_pos;
        if (begin == m_pos) fail(m_path, std::string("truncated header: missing ") + what);
        return m_bytes.substr(begin, m_pos - begin);
    }

    /// The next token as a non-negative integer.
    long long integer(const char* what) {
        const std::string_view t = token(what);
        long long value = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec != std::errc() || end != t.data() + t.size() || value < 0) {
            fail(m_path, std::string("invalid ") + what + " " + quote_token(t));
        }
        return value;
    }

    /// The next token as a finite float.
    float real(const char* what) {
        const std::string text(token(what));
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (end != text.c_str() + text.size() || !std::isfinite(value)) {
            fail(m_path, std::string("invalid ") + what + " " + quote_token(text));
        }
        return value;
    }

    /// Bytes after the last token read.
    size_t remaining() const { return m_bytes.size() - m_pos; }

    /// Consumes the single whitespace byte that separates the header from binary data.
    size_t data_offset() {
        if (m_pos >= m_bytes.size() || !is_space(m_bytes[m_pos])) {
            fail(m_path, "truncated file: no pixel data after the header");
        }
        return m_pos + 1;
    }

  private:
    static bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

    void skip_space_and_comments() {
        while (m_pos < m_bytes.size()) {
            if (is_space(m_bytes[m_pos])) {
                ++m_pos;
            } else if (m_bytes[m_pos] == '#') {
                while (m_pos < m_bytes.size() && m_bytes[m_pos] != '\n') ++m_pos;
            } else {
                break;
            }
        }
    }

    const std::filesystem::path& m_path;
    std::string_view m_bytes;
    size_t m_pos = 0;
};

void check_data_size(const std::filesystem::path& path, size_t available, size_t needed) {
    if (available < needed) {
        fail(path, "truncated file: expected " + std::to_string(needed) +
                       " bytes of pixel data, found " + std::to_string(available));
    }
}

// --- PPM ---------------------------------------------------------------------------------------

/// Netpbm PPM (netpbm.sourceforge.net/doc/ppm.html): P6 binary (1 byte per sample when
/// maxval < 256, else 2 bytes big-endian) or P3 ASCII; samples are sRGB-encoded, top row first.
Image read_ppm(const std::filesystem::path& path, std::string_view bytes) {
    HeaderReader header(path, bytes);
    const std::string_view magic = header.token("magic number");
    if (magic != "P6" && magic != "P3") {
        fail(path, "not a PPM file (expected magic P6 or P3, found " + quote_token(magic) + ")");
    }
    const long long w = header.integer("width");
    const long long h = header.integer("height");
    check_size(path, w, h);
    const long long maxval = header.integer("maxval");
    if (maxval < 1 || maxval > 65535) fail(path, "invalid maxval " + std::to_string(maxval));

    // The pixel data must be there before the image is allocated: a 19-byte header may claim
    // 2^28 pixels.
    const size_t samples = static_cast<size_t>(w) * static_cast<size_t>(h) * 3;
    if (magic == "P3" && header.remaining() < 2 * samples) {  // a digit and a space each
        fail(path, "truncated file: " + std::to_string(samples) + " ASCII samples need at least " +
                       std::to_string(2 * samples) + " bytes, found " +
                       std::to_string(header.remaining()));
    }
    const size_t width_bytes = maxval < 256 ? 1 : 2;
    if (magic == "P6")
        check_data_size(path, bytes.size() - header.data_offset(), samples * width_bytes);
    Image image(static_cast<int>(w), static_cast<int>(h));
    const auto to_linear = [&](long long v) {
        if (v > maxval) fail(path, "sample value " + std::to_string(v) + " exceeds maxval");
        return srgb_to_linear(static_cast<float>(v) / static_cast<float>(maxval));
    };
    auto store = [&](size_t s, float v) { image.pixels[s / 3][static_cast<int>(s % 3)] = v; };
    if (magic == "P3") {
        for (size_t s = 0; s < samples; ++s) {
            store(s, to_linear(header.integer("sample value")));
        }
        return image;
    }
    const size_t offset = header.data_offset();
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data() + offset);
    for (size_t s = 0; s < samples; ++s) {
        const long long v =
            width_bytes == 1 ? data[s] : (unsigned{data[2 * s]} << 8) | data[2 * s + 1];
        store(s, to_linear(v));
    }
    return image;
}

// --- PFM ---------------------------------------------------------------------------------------

float load_float(const uint8_t* p, bool little_endian) {
    uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
        const int shift = little_endian ? 8 * i : 8 * (3 - i);
        bits |= uint32_t{p[i]} << shift;
    }
    return std::bit_cast<float>(bits);
}

/// PFM (Debevec, www.pauldebevec.com/Research/HDR/PFM/): "PF" (RGB) or "Pf" (grey), size,
/// scale (negative = little-endian), then float rows from the BOTTOM up. Like pbrt-v3's reader
/// (src/core/imageio.cpp), samples are multiplied by |scale| when it is not 1.
Image read_pfm(const std::filesystem::path& path, std::string_view bytes) {
    HeaderReader header(path, bytes);
    const std::string_view magic = header.token("magic number");
    if (magic != "PF" && magic != "Pf") {
        fail(path, "not a PFM file (expected magic PF or Pf, found " + quote_token(magic) + ")");
    }
    const int channels = magic == "PF" ? 3 : 1;
    const long long w = header.integer("width");
    const long long h = header.integer("height");
    check_size(path, w, h);
    const float scale = header.real("scale");
    if (scale == 0.0f) fail(path, "invalid scale 0 (its sign must give the byte order)");
    const bool little_endian = scale < 0.0f;
    const float factor = std::abs(scale);

    const size_t offset = header.data_offset();
    check_data_size(path, bytes.size() - offset,
                    static_cast<size_t>(w) * static_cast<size_t>(h) * channels * 4);
    Image image(static_cast<int>(w), static_cast<int>(h));
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data() + offset);
    for (int row = 0; row < image.height; ++row) {
        const int y = image.height - 1 - row;  // stored bottom to top
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = data + (static_cast<size_t>(row) * image.width + x) * channels * 4;
            Vec3& out = image.at(x, y);
            for (int c = 0; c < 3; ++c) out[c] = load_float(p + 4 * (c % channels), little_endian);
            if (factor != 1.0f) out *= factor;
        }
    }
    return image;
}

// --- OpenEXR through tinyexr ------------------------------------------------------------------

std::string take_exr_error(const char* err, int code) {
    std::string reason = err ? err : "error code " + std::to_string(code);
    if (err) FreeEXRErrorMessage(err);
    return reason;
}

/// Frees a parsed header and its image on every path out. We use tinyexr's full API rather than
/// LoadEXRFromMemory, which in tinyexr 1.0.1 leaks the header when the pixel data is bad.
struct ExrFile {
    EXRHeader header;
    EXRImage image;
    ExrFile() {
        InitEXRHeader(&header);
        InitEXRImage(&image);
    }
    ~ExrFile() {
        FreeEXRImage(&image);
        FreeEXRHeader(&header);
    }
    ExrFile(const ExrFile&) = delete;
    ExrFile& operator=(const ExrFile&) = delete;
};

/// Sample `i` of channel plane `plane`, stored as `type` (FLOAT or UINT after loading).
float exr_sample(const unsigned char* plane, int type, size_t i) {
    if (type == TINYEXR_PIXELTYPE_UINT)
        return static_cast<float>(reinterpret_cast<const unsigned int*>(plane)[i]);
    return reinterpret_cast<const float*>(plane)[i];
}

/// Index of the channel named `name`, or -1.
int find_channel(const EXRHeader& header, const char* name) {
    for (int c = 0; c < header.num_channels; ++c) {
        if (std::strcmp(header.channels[c].name, name) == 0) return c;
    }
    return -1;
}

/// Which channels become R, G and B: R/G/B by name, else a single (grey) channel three times.
std::array<int, 3> exr_rgb_channels(const std::filesystem::path& path, const EXRHeader& header) {
    const std::array<int, 3> rgb = {find_channel(header, "R"), find_channel(header, "G"),
                                    find_channel(header, "B")};
    if (rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0) return rgb;
    int grey = find_channel(header, "Y");
    if (grey < 0 && header.num_channels == 1) grey = 0;
    if (grey >= 0) return {grey, grey, grey};
    std::string names;
    for (int c = 0; c < header.num_channels; ++c) {
        names += (c ? ", " : "") + std::string(header.channels[c].name);
    }
    fail(path, "OpenEXR file has no R, G, B or single grey channel (channels: " + names + ")");
}

/// Copies channel `plane_of[c]` of a scanline image or of every tile into `out`.
void copy_exr_pixels(const EXRHeader& header, const EXRImage& exr,
                     const std::array<int, 3>& plane_of, Image& out) {
    auto copy_block = [&](unsigned char** planes, int block_w, int block_h, int x0, int y0) {
        for (int j = 0; j < block_h; ++j) {
            for (int i = 0; i < block_w; ++i) {
                const int x = x0 + i, y = y0 + j;
                if (x >= out.width || y >= out.height) continue;  // edge tiles are padded
                const size_t src = static_cast<size_t>(j) * block_w + i;
                for (int c = 0; c < 3; ++c) {
                    out.at(x, y)[c] = exr_sample(planes[plane_of[c]],
                                                 header.requested_pixel_types[plane_of[c]], src);
                }
            }
        }
    };
    if (!header.tiled) {
        copy_block(exr.images, out.width, out.height, 0, 0);
        return;
    }
    // Tiles of the first level only (tinyexr README, "Load tiled EXR").
    for (int t = 0; t < exr.num_tiles; ++t) {
        const EXRTile& tile = exr.tiles[t];
        copy_block(tile.images, header.tile_size_x, header.tile_size_y,
                   tile.offset_x * header.tile_size_x, tile.offset_y * header.tile_size_y);
    }
}

/// tinyexr 1.0.1 asserts (aborts) on some malformed header attributes instead of returning an
/// error (found by fuzz/image_fuzz.cpp): a "tiles" attribute not 9 bytes long, or a "type" that
/// is unknown or contradicts the tiled flag. Walk the attribute list first and refuse those.
void check_exr_attributes(const std::filesystem::path& path, std::string_view bytes, bool tiled) {
    size_t pos = 8;  // magic number and version field
    auto c_string = [&]() -> std::string_view {
        const size_t end = bytes.find('\0', pos);
        if (end == std::string_view::npos) fail(path, "truncated OpenEXR header");
        const std::string_view s = bytes.substr(pos, end - pos);
        pos = end + 1;
        return s;
    };
    for (;;) {
        const std::string_view name = c_string();
        if (name.empty()) return;  // end of the header
        c_string();                // attribute type
        if (pos + 4 > bytes.size()) fail(path, "truncated OpenEXR header");
        uint32_t size = 0;
        for (int k = 3; k >= 0; --k) size = size << 8 | static_cast<unsigned char>(bytes[pos + k]);
        pos += 4;
        if (size > bytes.size() - pos) fail(path, "truncated OpenEXR header");
        const std::string_view value = bytes.substr(pos, size);
        pos += size;
        if (name == "tiles" && size != 9) fail(path, "malformed OpenEXR \"tiles\" attribute");
        if (name == "type" && !(value == (tiled ? "tiledimage" : "scanlineimage")))
            fail(path, "unsupported OpenEXR image type (only flat scanline or tiled images)");
    }
}

/// Refuses an OpenEXR file too short for the table of chunk offsets its header implies (one
/// 8-byte offset a chunk after the header, OpenEXR "File Layout"), before tinyexr allocates the
/// image: a 300-byte file cannot hold a 60000-line picture.
void check_exr_offset_table(const std::filesystem::path& path, const EXRHeader& header,
                            long long width, long long height, size_t file_bytes) {
    double chunks = 0;
    if (header.tiled) {
        const double tx = std::max(1, header.tile_size_x), ty = std::max(1, header.tile_size_y);
        chunks = std::ceil(double(width) / tx) * std::ceil(double(height) / ty);
    } else {
        // Scanlines a chunk holds, by compression (tinyexr's, as in OpenEXR).
        const int lines = header.compression_type == TINYEXR_COMPRESSIONTYPE_ZIP   ? 16
                          : header.compression_type == TINYEXR_COMPRESSIONTYPE_PIZ ? 32
                          : header.compression_type == TINYEXR_COMPRESSIONTYPE_ZFP ? 16
                                                                                   : 1;
        chunks = std::ceil(double(height) / lines);
    }
    const double needed = double(header.header_len) + 8.0 * chunks;
    if (double(file_bytes) < needed) {
        fail(path, fmt::format("truncated file: its {}x{} image needs {:.0f} chunk offsets, the "
                               "file ends first ({} bytes)",
                               width, height, chunks, file_bytes));
    }
}

Image read_exr(const std::filesystem::path& path, const std::string& bytes) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    EXRVersion version;
    int code = ParseEXRVersionFromMemory(&version, data, bytes.size());
    if (code != TINYEXR_SUCCESS) fail(path, "not an OpenEXR file (bad magic number or version)");
    if (version.multipart || version.non_image) {
        fail(path, "multi-part and deep OpenEXR files are not supported");
    }
    check_exr_attributes(path, bytes, version.tiled != 0);
    ExrFile exr;
    const char* err = nullptr;
    code = ParseEXRHeaderFromMemory(&exr.header, &version, data, bytes.size(), &err);
    if (code != TINYEXR_SUCCESS) fail(path, "invalid OpenEXR header: " + take_exr_error(err, code));
    // Size check before tinyexr allocates the pixels.
    const EXRBox2i& window = exr.header.data_window;
    const long long width = static_cast<long long>(window.max_x) - window.min_x + 1;
    const long long height = static_cast<long long>(window.max_y) - window.min_y + 1;
    if (width > 0 && height > 0)
        check_exr_offset_table(path, exr.header, width, height, bytes.size());
    check_size(path, width, height);
    const std::array<int, 3> plane_of = exr_rgb_channels(path, exr.header);
    for (int c = 0; c < exr.header.num_channels; ++c) {
        if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
            exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }
    code = LoadEXRImageFromMemory(&exr.image, &exr.header, data, bytes.size(), &err);
    if (code != TINYEXR_SUCCESS) {
        // tinyexr 1.0.1 has already freed the image's buffers but left the pointers dangling.
        InitEXRImage(&exr.image);
        fail(path, "cannot decode OpenEXR image: " + take_exr_error(err, code));
    }
    check_size(path, exr.image.width, exr.image.height);
    if (!exr.header.tiled ? exr.image.images == nullptr : exr.image.tiles == nullptr) {
        fail(path, "cannot decode OpenEXR image: no pixel data");
    }
    Image image(exr.image.width, exr.image.height);
    copy_exr_pixels(exr.header, exr.image, plane_of, image);
    return image;
}

}  // namespace

Image decode_png_or_jpeg(const std::filesystem::path& name, const std::string& bytes) {
    if (bytes.empty()) fail(name, "the image is empty");
    return read_stb(name, bytes);
}

Image read_image(const std::filesystem::path& path) {
    const auto format = image_format_from_extension(path);
    if (!format) {
        fail(path, "unknown image extension '" + path.extension().string() +
                       "' (supported: .png, .jpg, .jpeg, .ppm, .pfm, .exr, .hdr)");
    }
    const std::string bytes = read_file_bytes(path, InputKind::image);
    if (bytes.empty()) fail(path, "the file is empty");
    switch (*format) {
        case ImageFormat::Png:
        case ImageFormat::Jpeg:
            return read_stb(path, bytes);
        case ImageFormat::Ppm:
            return read_ppm(path, bytes);
        case ImageFormat::Pfm:
            return read_pfm(path, bytes);
        case ImageFormat::Exr:
            return read_exr(path, bytes);
        case ImageFormat::Hdr:
            return read_hdr(path, bytes);
        case ImageFormat::Xlsx:
            break;
    }
    fail(path, "unsupported image format");
}

}  // namespace hikari
