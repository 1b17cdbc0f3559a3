#include "compare.h"

#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/frame/image_compare.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "output_paths.h"

namespace hikari::cli {

namespace {

/// Whether `path` is a format that stores 8-bit sRGB values.
bool is_eight_bit_image(const std::filesystem::path& path) {
    const std::optional<ImageFormat> format = image_format_from_extension(path);
    return format == ImageFormat::Png || format == ImageFormat::Jpeg || format == ImageFormat::Ppm;
}

/// The figures of `d` on stdout: the PSNR alone with --psnr, else three lines.
void print_difference(const ImageDifference& d, bool psnr_only) {
    if (psnr_only) {
        print_out("{:.3f}\n", d.psnr_db);
        return;
    }
    print_out("PSNR {:.3f} dB (sRGB values, RGB channels)\n", d.psnr_db);
    print_out("max difference {:.4f} ({:.1f}/255) at pixel ({}, {})\n", d.max_difference,
              255.0 * d.max_difference, d.max_x, d.max_y);
    print_out("differing pixels {} of {} ({:.2f} %)\n", d.differing, d.pixels,
              100.0 * static_cast<double>(d.differing) / static_cast<double>(d.pixels));
    if (d.not_a_number_a > 0 || d.not_a_number_b > 0)
        print_out("not-a-number pixels {} in the first image, {} in the second (NaN equals NaN)\n",
                  d.not_a_number_a, d.not_a_number_b);
}

}  // namespace

CLI::App* add_compare_command(CLI::App& app, CompareOptions& c) {
    CLI::App* compare = app.add_subcommand(
        "compare",
        "Compare two images (any format hikari reads): PSNR, largest difference, differing "
        "pixels, and a false-colour difference image.");
    compare->add_option("a", c.a, "First image")->required();
    compare->add_option("b", c.b, "Second image")->required();
    compare->add_option("-o,--output", c.output,
                        "Write where they differ as a false-colour image (black: equal)");
    compare
        ->add_option("--tolerance", c.tolerance,
                     "Pixels differ where a channel's linear values differ by more than this")
        ->check(real_in(0, k_max_real))
        ->capture_default_str();
    compare->add_flag("--psnr", c.psnr_only, "Print the PSNR alone (for scripts)");
    add_max_memory_option(*compare, "images");
    return compare;
}

int run_compare(const CompareOptions& o) {
    if (is_svg_path(o.output))
        throw UsageError(
            fmt::format("{}: compare writes its difference as an image, not as SVG", o.output));
    if (!o.output.empty())
        check_output_path(o.output, std::vector<RenderInput>{{o.a, "the first image"},
                                                             {o.b, "the second image"}});
    const Image a = read_image(o.a);
    // The first image is kept while the second is decoded: both count against --max-memory.
    const MemoryHeld first(static_cast<double>(a.pixels.size() * sizeof(Vec3)));
    const Image b = read_image(o.b);
    if (a.width != b.width || a.height != b.height)
        throw InputError(fmt::format("{} is {}x{} but {} is {}x{}: only images of one size compare",
                                     o.a, a.width, a.height, o.b, b.width, b.height));
    const ImageDifference d =
        compare_images(a, b, is_eight_bit_image(o.a) && is_eight_bit_image(o.b), o.tolerance);
    print_difference(d, o.psnr_only);
    if (!o.output.empty()) {
        write_image(o.output, difference_image(a, b, d.max_difference));
        if (!o.psnr_only)
            print_out(
                "wrote {}: black where equal, blue, red, yellow up to the largest "
                "difference\n",
                o.output);
    }
    return 0;
}

}  // namespace hikari::cli
