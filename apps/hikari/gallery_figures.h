#pragma once
// The figures of `hikari gallery`: what each reproduces of the lecture, its caption in English
// and Japanese, how it is rendered and what is measured for its caption.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gallery_scenes.h"

namespace hikari::gallery {

/// A caption in English and in the lecture's Japanese.
struct Text {
    std::string en;
    std::string ja;
    const std::string& in(bool japanese) const { return japanese && !ja.empty() ? ja : en; }
};

struct Gallery;

/// One picture of the gallery: the lecture's figure it reproduces and how.
struct Figure {
    Text section;                   ///< the lecture's section (the contact sheet's headings)
    std::string figure;             ///< "Fig 4.1a", "Alg 4.1", ... (never repeated in `title`)
    Text title;                     ///< what it shows
    std::string image;              ///< file name in the gallery directory
    std::string scene;              ///< file name in the gallery's scenes/
    std::vector<std::string> args;  ///< `hikari render` options besides scene and output
    Text note;                      ///< measured facts for the caption (filled while rendering)
    double seconds = 0;             ///< time of the runs that made it
    /// The commands that make it, run from the gallery directory (filled while rendering).
    std::vector<std::string> commands;
    /// Renders the figure when it is more than one plain render (default: one render).
    std::function<void(const Gallery&, Figure&)> make;
    /// A false-colour figure's key (`--aov overdraw`, `paint-order`): the colour ramp from
    /// frame/aov_picture.h's ramp_colour, `low` at its dark blue end and `high` at its white
    /// end (filled while rendering); empty `high`: no legend.
    Text legend_low, legend_high;
    /// Why the picture could not be made here and how to get what it needs (filled while
    /// rendering: the turntable without ffmpeg); the contact sheet shows it in the picture's
    /// place. Empty: the picture was made.
    Text missing;
    bool wide = false;  ///< as wide as the page allows: several pictures side by side
};

/// The gallery being made: where it goes, how to render, the figures and the files they use.
struct Gallery {
    std::filesystem::path dir;  ///< absolute
    std::string program;        ///< this executable, absolute
    int width = 480;
    int threads = 0;
    bool japanese = false;
    std::vector<Figure> figures;
    std::map<std::string, Json> scene_files;   ///< scenes/NAME → the scene
    std::map<std::string, std::string> files;  ///< scenes/NAME → other text (OBJ models)

    std::filesystem::path scenes() const { return dir / "scenes"; }
    /// Buffers measured for captions; removed when the gallery is done.
    std::filesystem::path data() const { return dir / "data"; }

    void write_text(const std::string& name, const std::string& text) const;
    void write_scene(const std::string& name, const Json& scene) const;
    /// Runs `hikari render scenes/SCENE ARGS -o OUTPUT -q` in the gallery directory (OUTPUT
    /// relative to it), its stderr into `log` when given; returns the seconds it took. A failed
    /// render is an error.
    double render(const std::string& scene, const std::vector<std::string>& args,
                  const std::string& output, const std::string& log = {}) const;
    /// Adds a figure rendered by `hikari render scenes/SCENE ARGS -o IMAGE`.
    Figure& add(Text section, std::string figure, Text title, std::string image, std::string scene,
                std::vector<std::string> args);
};

/// "hikari render scenes/SCENE ARGS -o OUTPUT", as printed under a figure.
std::string command_line(const std::string& scene, const std::vector<std::string>& args,
                         const std::string& output);

/// The figures, in the lecture's order, and the scenes and models they use.
void plan(Gallery& g, const PlacedModel& model);

/// Renders figure `f` into the gallery and fills its commands, time and measured note.
void render_figure(const Gallery& g, Figure& f);

}  // namespace hikari::gallery
