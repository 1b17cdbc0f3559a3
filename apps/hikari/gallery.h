#pragma once
// `hikari gallery`: the lecture's figures reproduced by the methods it describes, each a real
// render by `hikari render` with the command line shown under it, gathered in one HTML page.

#include <string>
#include <vector>

namespace hikari {

/// The options of `hikari gallery`.
struct GalleryOptions {
    std::string dir = "gallery";  ///< where the images, scenes and index.html go
    std::string model;            ///< the model of Fig 4.1 and the others; default: the teapot
    int width = 480;              ///< image width in pixels (heights follow each scene)
    int threads = 0;              ///< render threads (0: all cores)
    std::string lang = "en";      ///< the captions' language: "en" or "ja" (the lecture's terms)
    /// Render only these figures ("4.7", "4.9c", "Alg 4.1", "lights", ...; a figure matches
    /// its label with or without "Fig "/"Alg "); empty: all.
    std::vector<std::string> only;
};

/// Renders every figure into o.dir by running `program render ...` (this executable) for each,
/// writes the scenes it renders (and copies of the models they load) into o.dir/scenes/ and the
/// contact sheet o.dir/index.html; every command under a figure runs as printed from o.dir.
/// Throws InputError for a directory that cannot be written, a model that does not load, a
/// figure name in o.only that names no figure, or a render that fails. Returns the exit status.
int run_gallery(const GalleryOptions& o, const std::string& program);

}  // namespace hikari
