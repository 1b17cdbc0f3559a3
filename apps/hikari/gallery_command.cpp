#include "gallery_command.h"

#include "cli_options.h"

namespace hikari::cli {

CLI::App* add_gallery_command(CLI::App& app, GalleryOptions& g) {
    CLI::App* gallery = app.add_subcommand(
        "gallery",
        "Render the lecture's figures (Fig 4.1 to 4.43) into a directory with an "
        "index.html contact sheet.");
    gallery->add_option("-o,--output", g.dir, "Directory for the images, scenes and index.html")
        ->capture_default_str();
    gallery->add_option("--model", g.model,
                        "Mesh for Fig 4.1 and the others (OBJ; default: the teapot hikari ships, "
                        "scenes/models/teapot.obj)");
    gallery->add_option("--width", g.width, "Image width in pixels")
        ->check(whole_in(16, 4096))
        ->capture_default_str();
    gallery->add_option("--threads", g.threads, "Render threads (default: all cores)")
        ->check(whole_in(1, 1024));
    gallery
        ->add_option("--lang", g.lang,
                     "Language of the captions: en, or ja (the lecture's own terms)")
        ->check(CLI::IsMember({"en", "ja"}))
        ->capture_default_str();
    gallery
        ->add_option("--only", g.only,
                     "Render only these figures, e.g. --only 4.7,4.9c (labels as captioned)")
        ->delimiter(',');
    return gallery;
}

}  // namespace hikari::cli
