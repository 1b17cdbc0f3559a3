#include "hikari/io/images/image_format.h"

#include <cctype>
#include <string>

namespace hikari {

std::optional<ImageFormat> image_format_from_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    if (ext == ".ppm") return ImageFormat::Ppm;
    if (ext == ".pfm") return ImageFormat::Pfm;
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".hdr") return ImageFormat::Hdr;
    if (ext == ".xlsx") return ImageFormat::Xlsx;
    return std::nullopt;
}

bool is_low_dynamic_range(ImageFormat format) {
    return format == ImageFormat::Png || format == ImageFormat::Jpeg ||
           format == ImageFormat::Ppm || format == ImageFormat::Xlsx;
}

}  // namespace hikari
