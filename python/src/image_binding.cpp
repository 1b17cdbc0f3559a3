// Images between hikari and NumPy, and the image tools of the command line (the colour an 8-bit
// file keeps, writing every output format, comparing two renders).
#include <cstring>
#include <string>

#include <pybind11/stl.h>

#include "bindings.h"
#include "hikari/core/error.h"
#include "hikari/core/srgb8_encoder.h"
#include "hikari/frame/image_compare.h"
#include "hikari/frame/tone_map.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/methods/method_options.h"

namespace hikari::python {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "a Vec3 array is a float array of 3 columns");

/// `values` moved to the heap and handed to NumPy as an array of `shape` whose memory a capsule
/// frees with the array: the render's buffer itself, not a copy.
template <class Vector>
py::array owned_array(Vector&& values, std::vector<py::ssize_t> shape) {
    auto* kept = new Vector(std::move(values));
    const py::capsule free_when_done(kept, [](void* p) { delete static_cast<Vector*>(p); });
    return py::array_t<float>(shape, reinterpret_cast<const float*>(kept->data()), free_when_done);
}

py::array to_srgb8(const py::array& array, float exposure, const std::string& tonemap) {
    const std::optional<ToneMap> op = choice_value<ToneMap>(k_tone_map_choices, tonemap);
    if (!op) throw InputError("tonemap: '" + tonemap + "' is not one of clamp, reinhard, aces");
    Image image = array_image(array);
    expose_and_tone_map(image, exposure, *op);
    const Srgb8Image encoded = encode_srgb8(image);
    py::array_t<uint8_t> out({image.height, image.width, 3});
    std::memcpy(out.mutable_data(), encoded.bytes.data(), encoded.bytes.size());
    return out;
}

void write(const std::string& path, const py::array& array, int bit_depth,
           const std::string& encoding) {
    const std::optional<SampleEncoding> samples =
        choice_value<SampleEncoding>(k_sample_encoding_choices, encoding);
    if (!samples) throw InputError("encoding: '" + encoding + "' is not one of srgb, linear");
    if (!is_supported_image_extension(path))
        throw InputError(path + ": unknown image format (supported: " +
                         std::string(k_writable_image_extensions) + ")");
    if (!supports_bit_depth(path, bit_depth))
        throw InputError(path + ": this format has no " + std::to_string(bit_depth) +
                         "-bit samples (16 bits: .png and .ppm)");
    const Image image = array_image(array);
    py::gil_scoped_release unlocked;
    write_image(path, image, ImageWriteSettings{bit_depth, *samples});
}

py::dict compare(const py::array& a, const py::array& b, double scale) {
    const Image first = array_image(a), second = array_image(b);
    if (first.width != second.width || first.height != second.height)
        throw InputError("compare: the images differ in size");
    const ImageDifference d = compare_images(first, second);
    py::dict out;
    out["psnr"] = d.psnr_db;
    out["max_difference"] = d.max_difference;
    out["max_at"] = py::make_tuple(d.max_x, d.max_y);
    out["differing_pixels"] = d.differing;
    out["pixels"] = d.pixels;
    out["difference"] = image_array(difference_image(first, second, scale));
    return out;
}

}  // namespace

py::array image_array(Image&& image) {
    const py::ssize_t h = image.height, w = image.width;
    return owned_array(std::move(image.pixels), {h, w, 3});
}

py::array framebuffer_array(Framebuffer&& fb, Aov aov) {
    const py::ssize_t h = fb.height(), w = fb.width();
    if (aov == Aov::depth) return owned_array(std::move(fb.depth), {h, w});
    if (aov == Aov::normal) return owned_array(std::move(fb.normal), {h, w, 3});
    if (aov == Aov::id) {
        // Ids as the float files hold them: exact up to 2^24 primitives.
        py::array_t<float> ids({h, w});
        float* out = ids.mutable_data();
        for (size_t i = 0; i < fb.id.size(); ++i) out[i] = static_cast<float>(fb.id[i]);
        return ids;
    }
    return image_array(std::move(fb.film.linear()));
}

Image array_image(const py::array& array) {
    const auto values =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!values) throw py::type_error("expected an array of numbers");
    const bool grey = values.ndim() == 2, rgb = values.ndim() == 3 && values.shape(2) == 3;
    if (!grey && !rgb)
        throw InputError("expected an image array of shape (height, width, 3) or (height, width)");
    if (values.shape(0) < 1 || values.shape(1) < 1 || values.shape(0) > 65536 ||
        values.shape(1) > 65536)
        throw InputError("an image must be 1 to 65536 pixels on each side");
    Image image(static_cast<int>(values.shape(1)), static_cast<int>(values.shape(0)));
    const float* in = values.data();
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = grey ? Vec3(in[i]) : Vec3(in[3 * i], in[3 * i + 1], in[3 * i + 2]);
    return image;
}

void bind_images(py::module_& m) {
    m.def("to_srgb8", &to_srgb8, py::arg("image"), py::arg("exposure") = 0.0f,
          py::arg("tonemap") = "clamp",
          "The 8-bit sRGB values a PNG of `image` (linear RGB) holds: uint8 (H, W, 3), after "
          "exposure (×2^EV) and the tone map (clamp, reinhard, aces).");
    m.def("write", &write, py::arg("path"), py::arg("image"), py::arg("bit_depth") = 8,
          py::arg("encoding") = "srgb",
          "Writes a linear RGB image in the format its extension names, as `hikari render -o` "
          "does (.png .ppm .jpg sRGB, or encoding='linear' for round(255 v) as the lecture's "
          "sample code writes; .pfm .exr .hdr linear; .xlsx a spreadsheet).");
    m.def(
        "read",
        [](const std::string& path) {
            Image image = [&] {
                py::gil_scoped_release unlocked;
                return read_image(path);
            }();
            return image_array(std::move(image));
        },
        py::arg("path"), "Reads an image file into linear RGB, float32 (H, W, 3).");
    m.def("compare", &compare, py::arg("a"), py::arg("b"), py::arg("scale") = 0.1,
          "How two linear images differ, as `hikari compare` reports it: psnr (dB, over sRGB "
          "values), max_difference, max_at, differing_pixels, and a false-colour difference "
          "image.");
}

}  // namespace hikari::python
