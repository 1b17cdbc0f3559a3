#include "hikari/io/image_write.h"

#include <tinyexr.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/io/atomic_file.h"
#include "hikari/io/image_format.h"
#include "hikari/io/png_write.h"
#include "hikari/io/xlsx_write.h"

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

/// The 8-bit formats.
Bytes encode(const std::filesystem::path& path, const Srgb8Image& image, ImageFormat format) {
    switch (format) {
        case ImageFormat::Png:
            return encode_png(image);
        case ImageFormat::Ppm:
            return encode_ppm(image);
        case ImageFormat::Xlsx:
            return encode_xlsx(path, image);
        default:
            break;
    }
    throw InputError("cannot write " + path.string() +
                     ": an 8-bit sRGB image can only be written as .png or .ppm");
}

Bytes encode(const std::filesystem::path& path, const Image& image, ImageFormat format) {
    switch (format) {
        case ImageFormat::Png:
        case ImageFormat::Ppm:
        case ImageFormat::Xlsx:
            return encode(path, encode_srgb8(image), format);
        case ImageFormat::Pfm:
            return encode_pfm(image);
        case ImageFormat::Exr:
            return encode_exr(path, image);
        case ImageFormat::Jpeg:
        case ImageFormat::Hdr:
            break;
    }
    throw InputError("cannot write " + path.string() + ": unsupported image format");
}

/// write_image's checks, then the file; `pixels`: how many pixels the image holds.
template <class AnyImage>
void write_any_image(const std::filesystem::path& path, const AnyImage& image, size_t pixels) {
    if (!is_supported_image_extension(path)) {
        throw InputError("cannot write " + path.string() + ": unknown image extension '" +
                         path.extension().string() +
                         "' (supported: " + k_writable_image_extensions + ")");
    }
    if (image.width <= 0 || image.height <= 0 ||
        pixels != static_cast<size_t>(image.width) * static_cast<size_t>(image.height)) {
        throw InputError("cannot write " + path.string() + ": the image is empty or malformed");
    }
    const Bytes bytes = encode(path, image, *image_format_from_extension(path));
    write_file_atomically(path, bytes);
}

}  // namespace

bool is_supported_image_extension(const std::filesystem::path& path) {
    const auto format = image_format_from_extension(path);
    return format && *format != ImageFormat::Jpeg && *format != ImageFormat::Hdr;
}

void write_image(const std::filesystem::path& path, const Image& image) {
    write_any_image(path, image, image.pixels.size());
}

void write_image(const std::filesystem::path& path, const Srgb8Image& image) {
    const bool whole_pixels = image.bytes.size() % 3 == 0;
    write_any_image(path, image, whole_pixels ? image.bytes.size() / 3 : 0);
}

}  // namespace hikari
