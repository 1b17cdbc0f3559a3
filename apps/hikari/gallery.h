#pragma once
// `hikari gallery`: the lecture's figures reproduced by the methods it describes, each a real
// render by `hikari render` with the command line shown under it, gathered in one HTML page.

#include <string>

namespace hikari {

/// The options of `hikari gallery`.
struct GalleryOptions {
    std::string dir = "gallery";  ///< where the images, scenes and index.html go
    std::string model;            ///< the model of Fig 4.1 and the others; default: the teapot
    int width = 480;              ///< image width in pixels (heights follow each scene)
    int threads = 0;              ///< render threads (0: all cores)
};

/// Renders every figure into o.dir by running `program render ...` (this executable) for each,
/// writes the scenes it renders into o.dir/scenes/ and the contact sheet o.dir/index.html.
/// Throws InputError for a directory that cannot be written, a model that does not load or a
/// render that fails. Returns the exit status (0).
int run_gallery(const GalleryOptions& o, const std::string& program);

}  // namespace hikari
