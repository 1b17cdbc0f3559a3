#include "hikari/io/images/image_write.h"

#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/png_write.h"
#include "hikari/io/images/xlsx_write.h"

namespace hikari {

namespace {

using Bytes = std::vector<uint8_t>;

void append(Bytes& out, const std::string& text) {
    out.insert(out.end(), text.begin(), text.end());
}

/// Netpbm P6 (netpbm.sourceforge.net/doc/ppm.html): maxval 255, one byte per sample, top row first.
Bytes encode_ppm(const Srgb8Image& image) {
    Bytes out;
    append(out,
           "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n");
    out.insert(out.end(), image.bytes.begin(), image.bytes.end());
    return out;
}

/// The same with maxval 65535: two bytes per sample, most significant first (Netpbm's rule).
Bytes encode_ppm(const Srgb16Image& image) {
    Bytes out;
    append(out,
           "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n65535\n");
    out.insert(out.end(), image.bytes.begin(), image.bytes.end());
    return out;
}

/// stb_image_write's output callback: appends to the Bytes that `context` points to.
void append_to_bytes(void* context, void* data, int size) {
    const auto* first = static_cast<const uint8_t*>(data);
    static_cast<Bytes*>(context)->insert(static_cast<Bytes*>(context)->end(), first, first + size);
}

/// Baseline JPEG through stb_image_write at quality 95 (of 100): little visible loss, for
/// renders with smooth gradients, at a fraction of PNG's size.
Bytes encode_jpeg(const std::filesystem::path& path, const Srgb8Image& image) {
    constexpr int k_quality = 95;
    Bytes out;
    if (!stbi_write_jpg_to_func(append_to_bytes, &out, image.width, image.height, 3,
                                image.bytes.data(), k_quality))
        throw InputError("cannot write " + path.string() + ": JPEG encoding failed");
    return out;
}

/// Radiance RGBE (Ward, "Real Pixels", Graphics Gems II, 1991) through stb_image_write, which
/// run-length encodes the rows. RGBE holds no sign and no NaN (0 instead), and its exponent
/// byte tops out near 2^127 (larger values are stored as 1e38).
Bytes encode_hdr(const std::filesystem::path& path, const Image& image) {
    std::vector<float> rgb(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = image.pixels[i][c];
            rgb[3 * i + c] = v > 0.0f ? std::min(v, 1e38f) : 0.0f;  // NaN fails v > 0
        }
    Bytes out;
    if (!stbi_write_hdr_to_func(append_to_bytes, &out, image.width, image.height, 3, rgb.data()))
        throw InputError("cannot write " + path.string() + ": HDR encoding failed");
    return out;
}

void append_float_le(Bytes& out, float v) {
    const auto bits = std::bit_cast<uint32_t>(v);
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(bits >> shift));
}

/// PFM (Debevec, www.pauldebevec.com/Research/HDR/PFM/): "PF", size, then a scale whose sign
/// gives the byte order (negative = little-endian), then rows from the BOTTOM of the image up.
Bytes encode_pfm(const Image& image) {
    Bytes out;
    append(out,
           "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n");
    out.reserve(out.size() + image.pixels.size() * 12);
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const Vec3 p = image.at(x, y);
            append_float_le(out, p.x);
            append_float_le(out, p.y);
            append_float_le(out, p.z);
        }
    }
    return out;
}

/// OpenEXR through tinyexr's full API. Channels go in B, G, R order: OpenEXR lists channels
/// sorted by name, and "most of EXR viewers expect this channel order" (tinyexr README, SaveEXR).
Bytes encode_exr(const std::filesystem::path& path, const Image& image) {
    const size_t n = image.pixels.size();
    std::vector<float> planes[3];  // B, G, R
    for (auto& plane : planes) plane.resize(n);
    for (size_t i = 0; i < n; ++i) {
        if (i % (1 << 20) == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        planes[0][i] = image.pixels[i].z;
        planes[1][i] = image.pixels[i].y;
        planes[2][i] = image.pixels[i].x;
    }
    unsigned char* plane_ptrs[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                    reinterpret_cast<unsigned char*>(planes[1].data()),
                                    reinterpret_cast<unsigned char*>(planes[2].data())};

    EXRImage exr_image;
    InitEXRImage(&exr_image);
    exr_image.num_channels = 3;
    exr_image.images = plane_ptrs;
    exr_image.width = image.width;
    exr_image.height = image.height;

    EXRHeader header;
    InitEXRHeader(&header);
    EXRChannelInfo channels[3] = {};
    std::strcpy(channels[0].name, "B");
    std::strcpy(channels[1].name, "G");
    std::strcpy(channels[2].name, "R");
    int pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT,
                          TINYEXR_PIXELTYPE_FLOAT};
    int requested_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT,
                              TINYEXR_PIXELTYPE_FLOAT};
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixel_types;
    header.requested_pixel_types = requested_types;
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

    unsigned char* memory = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&exr_image, &header, &memory, &err);
    if (size == 0 || memory == nullptr) {
        const std::string reason = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        std::free(memory);
        throw InputError("cannot write " + path.string() + ": EXR encoding failed: " + reason);
    }
    Bytes out(memory, memory + size);
    std::free(memory);  // tinyexr allocates the buffer with malloc
    return out;
}

/// One linear value as an integer sample of `max_code` steps: round(max_code · clamp(v, 0, 1)),
/// NaN as 0 (`!(v > 0)` holds for it).
uint32_t linear_code(float v, float max_code) {
    if (!(v > 0.0f)) return 0;
    return static_cast<uint32_t>(std::lround(std::min(v, 1.0f) * max_code));
}

/// `image` as 16-bit linear samples, big-endian like encode_srgb16's.
Srgb16Image encode_linear16(const Image& image) {
    Srgb16Image out{image.width, image.height, {}};
    out.bytes.resize(image.pixels.size() * 6);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const uint32_t code = linear_code(image.pixels[i][c], 65535.0f);
            out.bytes[6 * i + 2 * c] = static_cast<uint8_t>(code >> 8);
            out.bytes[6 * i + 2 * c + 1] = static_cast<uint8_t>(code);
        }
    return out;
}

/// The 8-bit formats.
Bytes encode(const std::filesystem::path& path, const Srgb8Image& image, ImageFormat format) {
    switch (format) {
        case ImageFormat::Png:
            return encode_png(image);
        case ImageFormat::Ppm:
            return encode_ppm(image);
        case ImageFormat::Jpeg:
            return encode_jpeg(path, image);
        case ImageFormat::Xlsx:
            return encode_xlsx(path, image);
        default:
            break;
    }
    throw InputError("cannot write " + path.string() +
                     ": an 8-bit sRGB image can only be written as .png, .ppm, .jpg or .xlsx");
}

Bytes encode(const std::filesystem::path& path, const Image& image, ImageFormat format,
             const ImageWriteSettings& settings) {
    const bool linear = settings.encoding == SampleEncoding::linear;
    if (settings.bit_depth == 16) {
        // supports_bit_depth has let only PNG and PPM through.
        const Srgb16Image samples = linear ? encode_linear16(image) : encode_srgb16(image);
        return format == ImageFormat::Png ? encode_png(samples) : encode_ppm(samples);
    }
    switch (format) {
        case ImageFormat::Png:
        case ImageFormat::Ppm:
        case ImageFormat::Jpeg:
        case ImageFormat::Xlsx:
            return encode(path, linear ? encode_linear8(image) : encode_srgb8(image), format);
        case ImageFormat::Pfm:
            return encode_pfm(image);
        case ImageFormat::Exr:
            return encode_exr(path, image);
        case ImageFormat::Hdr:
            return encode_hdr(path, image);
    }
    throw InputError("cannot write " + path.string() + ": unsupported image format");
}

/// write_image's checks, then the bytes; `pixels`: how many pixels the image holds.
template <class AnyImage>
Bytes encode_any_image(const std::filesystem::path& path, const AnyImage& image, size_t pixels,
                       const ImageWriteSettings& settings) {
    if (!is_supported_image_extension(path)) {
        throw InputError("cannot write " + path.string() + ": unknown image extension '" +
                         path.extension().string() +
                         "' (supported: " + k_writable_image_extensions + ")");
    }
    if (image.width <= 0 || image.height <= 0 ||
        pixels != static_cast<size_t>(image.width) * static_cast<size_t>(image.height)) {
        throw InputError("cannot write " + path.string() + ": the image is empty or malformed");
    }
    if (!supports_bit_depth(path, settings.bit_depth)) {
        throw InputError("cannot write " + path.string() + ": " +
                         std::to_string(settings.bit_depth) +
                         "-bit samples are not possible (8 bits, or 16 for .png and .ppm)");
    }
    throw_if_cancelled();  // SIGINT / SIGTERM: nothing to encode for a stopped render
    const ImageFormat format = *image_format_from_extension(path);
    if constexpr (std::is_same_v<AnyImage, Image>)
        return encode(path, image, format, settings);
    else
        return encode(path, image, format);
}

}  // namespace

Srgb8Image encode_linear8(const Image& image) {
    Srgb8Image out(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out.bytes[3 * i + static_cast<size_t>(c)] =
                static_cast<uint8_t>(linear_code(image.pixels[i][c], 255.0f));
    return out;
}

bool is_supported_image_extension(const std::filesystem::path& path) {
    return image_format_from_extension(path).has_value();
}

bool supports_bit_depth(const std::filesystem::path& path, int bit_depth) {
    if (bit_depth == 8) return true;
    const auto format = image_format_from_extension(path);
    return bit_depth == 16 && (format == ImageFormat::Png || format == ImageFormat::Ppm);
}

std::vector<uint8_t> encode_image(const std::filesystem::path& path, const Image& image,
                                  const ImageWriteSettings& settings) {
    return encode_any_image(path, image, image.pixels.size(), settings);
}

std::vector<uint8_t> encode_image(const std::filesystem::path& path, const Srgb8Image& image) {
    const bool whole_pixels = image.bytes.size() % 3 == 0;
    return encode_any_image(path, image, whole_pixels ? image.bytes.size() / 3 : 0,
                            ImageWriteSettings{});
}

void write_image(const std::filesystem::path& path, const Image& image,
                 const ImageWriteSettings& settings) {
    write_file_atomically(path, encode_image(path, image, settings));
}

void write_image(const std::filesystem::path& path, const Srgb8Image& image) {
    write_file_atomically(path, encode_image(path, image));
}

}  // namespace hikari
