#pragma once
// `hikari gallery` on the command line (the gallery itself: gallery.h).

#include <CLI/CLI.hpp>

#include "gallery.h"

namespace hikari::cli {

/// `hikari gallery` and its options.
CLI::App* add_gallery_command(CLI::App& app, GalleryOptions& g);

}  // namespace hikari::cli
