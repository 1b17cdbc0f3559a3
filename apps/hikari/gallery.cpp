#include "gallery.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "console.h"
#include "data_folder.h"
#include "gallery_figures.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/frame/aov_picture.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "signals.h"

extern char** environ;

namespace hikari::gallery {

namespace fs = std::filesystem;

void Gallery::write_text(const std::string& name, const std::string& text) const {
    write_file_atomically(scenes() / name,
                          {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

void Gallery::write_scene(const std::string& name, const Json& scene) const {
    write_text(name, scene.dump(2) + "\n");
}

namespace {

/// The exit status of child `pid`, waited for. A signal interrupts waitpid (EINTR): that is no
/// status, so the wait goes on; the first SIGINT or SIGTERM is passed on to the child, which
/// stops its render, removes its temporaries and exits.
int wait_for_child(pid_t pid) {
    bool passed_on = false;
    int status = 0;
    while (waitpid(pid, &status, 0) == -1) {
        if (errno != EINTR)
            throw InputError(fmt::format("gallery: lost the render process {}", pid));
        if (cancel_requested() && !passed_on) {
            kill(pid, cli::first_signal());
            passed_on = true;
        }
    }
    return status;
}

}  // namespace

double Gallery::render(const std::string& scene, const std::vector<std::string>& args,
                       const std::string& output, const std::string& log) const {
    std::vector<std::string> argv = {program, "render", "scenes/" + scene};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"-o", output, "-q"});
    if (threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(threads)});
    std::vector<char*> raw;
    raw.reserve(argv.size() + 1);
    for (std::string& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    // Run in the gallery directory, so that the command is the one printed under the figure.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
    if (!log.empty())
        posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
    const auto start = std::chrono::steady_clock::now();
    throw_if_cancelled();  // after a signal, no render starts
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, raw.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw InputError(fmt::format("gallery: cannot run {}", program));
    cli::set_child_process(pid);
    const int status = wait_for_child(pid);
    cli::set_child_process(0);
    throw_if_cancelled();  // the child was stopped: what it wrote is not a figure
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw InputError(fmt::format("gallery: rendering {} failed (hikari render scenes/{} ...)",
                                     output, scene));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Figure& Gallery::add(Text section, std::string figure, Text title, std::string image,
                     std::string scene, std::vector<std::string> args) {
    Figure f;
    f.section = std::move(section);
    f.figure = std::move(figure);
    f.title = std::move(title);
    f.image = std::move(image);
    f.scene = std::move(scene);
    f.args = std::move(args);
    figures.push_back(std::move(f));
    return figures.back();
}

std::string command_line(const std::string& scene, const std::vector<std::string>& args,
                         const std::string& output) {
    std::string line = "hikari render scenes/" + scene;
    for (const std::string& a : args) line += " " + a;
    return line + " -o " + output;
}

namespace {

std::string html_escape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

/// The figure's label in the caption's language: "Fig 4.7" → "図4.7", "Alg 4.1" →
/// "アルゴリズム4.1".
std::string label(const std::string& figure, bool japanese) {
    if (!japanese) return figure;
    if (figure.rfind("Fig ", 0) == 0) return "図" + figure.substr(4);
    if (figure.rfind("Alg ", 0) == 0) return "アルゴリズム" + figure.substr(4);
    return figure;
}

/// A false-colour figure's key: ramp_colour (frame/aov_picture.h) as a CSS gradient, its two
/// ends labelled; empty for other figures.
std::string legend_html(const Figure& f, bool japanese) {
    if (f.legend_high.en.empty()) return "";
    std::string stops;
    for (int k = 0; k <= 10; ++k) {
        const Vec3 c = ramp_colour(static_cast<float>(k) / 10.0f);  // display values
        stops += fmt::format(", rgb({:.0f},{:.0f},{:.0f})", 255 * c.x, 255 * c.y, 255 * c.z);
    }
    return fmt::format(
        "<div class=\"legend\" role=\"img\" aria-label=\"{0} to {1}\"><div "
        "style=\"background: linear-gradient(to right{2})\"></div><span>{0}</span><span>{1}</span>"
        "</div>",
        html_escape(f.legend_low.in(japanese)), html_escape(f.legend_high.in(japanese)), stops);
}

/// A figure's picture, linked full size (a GIF loops by itself; a video plays muted, looping);
/// or, where it could not be made, the note that says why, in its place.
std::string picture_html(const Figure& f, bool japanese) {
    if (!f.missing.en.empty())
        return "<p class=\"missing\">" + html_escape(f.missing.in(japanese)) + "</p>";
    const std::string alt = html_escape(label(f.figure, japanese) + ": " + f.title.in(japanese));
    const std::string ext = fs::path(f.image).extension().string();
    if (ext == ".mp4" || ext == ".webm")
        return fmt::format(
            "<video src=\"{0}\" autoplay loop muted playsinline aria-label=\"{1}\"></video>",
            html_escape(f.image), alt);
    return fmt::format("<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a>", html_escape(f.image),
                       alt);
}

/// The time the figure's runs took; nothing for a figure that was not made.
std::string run_time_html(const Figure& f, bool japanese) {
    if (!f.missing.en.empty()) return "";
    return "<br>" +
           fmt::format(fmt::runtime(japanese ? "実行時間 {:.2f} 秒（読み込み・描画・書き出し）"
                                             : "{:.2f} s run (load, render, write)"),
                       f.seconds);
}

/// One figure of the contact sheet: the image, its caption, the commands that make it.
std::string figure_html(const Figure& f, bool japanese) {
    std::string commands;
    for (const std::string& c : f.commands) commands += "<br><code>" + html_escape(c) + "</code>";
    const std::string& note = f.note.in(japanese);
    const std::string& caption = f.title.in(japanese);
    return fmt::format(
        "<figure{7}>{0}{6}<figcaption><b>{1}</b>: {2}{3}{4}{5}</figcaption></figure>\n",
        picture_html(f, japanese), html_escape(label(f.figure, japanese)), html_escape(caption),
        note.empty() ? "" : "<br><i>" + html_escape(note) + "</i>", commands,
        run_time_html(f, japanese), legend_html(f, japanese), f.wide ? " class=\"wide\"" : "");
}

constexpr const char* k_style = R"(<style>
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
h2 { border-bottom: 1px solid #ccc; margin-top: 1.5em; }
.grid { display: flex; flex-wrap: wrap; gap: 14px; }
figure { margin: 0; width: 260px; background: #fff; padding: 6px; border: 1px solid #ddd; }
figure img, figure video { width: 100%; image-rendering: auto; }
figure.wide { width: auto; max-width: 100%; }
figure.wide img, figure.wide video { width: auto; max-width: 100%; }
.missing { border: 1px dashed #b44; padding: 1em; color: #822; font-size: 13px; }
figcaption { font-size: 12px; }
code { font-size: 11px; word-break: break-all; color: #444; }
.legend { font-size: 11px; display: flex; flex-wrap: wrap; justify-content: space-between; }
.legend div { width: 100%; height: 10px; border: 1px solid #999; }
</style></head><body>
)";

/// The contact sheet: the figures grouped by section, each image linked full size.
std::string index_html(const Gallery& g, const std::string& model) {
    const bool ja = g.japanese;
    std::string html = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\"><title>hikari "
        "gallery</title>\n{}",
        ja ? "ja" : "en", k_style);
    html += ja ? "<h1>hikari: 講義の図</h1>\n" : "<h1>hikari: the lecture's figures</h1>\n";
    html += fmt::format(
        fmt::runtime(
            ja ? "<p>どの画像も、名前の付いた手法による実際のレンダリング結果です（<code>hikari "
                 "gallery</code>、モデル "
                 "<code>{}</code>）。画像の下のコマンドをこのフォルダで実行す"
                 "ると、同じ画像が作られます。画像をクリックすると原寸で表示します。</p>\n"
               : "<p>Every picture is a render by the method it names, made by <code>hikari "
                 "gallery</code> on the model <code>{}</code>. Run the commands under a picture in "
                 "this folder to make it again. Click a picture for full size.</p>\n"),
        html_escape(model));
    std::string section;
    for (const Figure& f : g.figures) {
        if (f.section.en != section) {
            if (!section.empty()) html += "</div>\n";
            section = f.section.en;
            html += "<h2>" + html_escape(f.section.in(ja)) + "</h2>\n<div class=\"grid\">\n";
        }
        html += figure_html(f, ja);
    }
    if (!section.empty()) html += "</div>\n";
    return html + "</body></html>\n";
}

/// Whether figure label `figure` is what `wanted` names ("4.7" or "Fig 4.7").
bool names(const std::string& wanted, const std::string& figure) {
    return wanted == figure || "Fig " + wanted == figure || "Alg " + wanted == figure;
}

/// Keeps the figures `only` names (all when empty); a name that matches none is an error.
void select_figures(Gallery& g, const std::vector<std::string>& only) {
    if (only.empty()) return;
    for (const std::string& w : only)
        if (std::none_of(g.figures.begin(), g.figures.end(),
                         [&](const Figure& f) { return names(w, f.figure); }))
            throw InputError(fmt::format("gallery: no figure is called '{}'", w));
    std::erase_if(g.figures, [&](const Figure& f) {
        return std::none_of(only.begin(), only.end(),
                            [&](const std::string& w) { return names(w, f.figure); });
    });
}

/// Copies the model (and an OBJ's material libraries beside it) into the gallery's scenes/, so
/// the gallery renders wherever it is moved; returns the copy's name.
std::string copy_model(const fs::path& model, const fs::path& scenes) {
    const std::string name = model.filename().string();
    fs::copy_file(model, scenes / name, fs::copy_options::overwrite_existing);
    if (model.extension() != ".obj") return name;
    const std::string text = read_file_bytes(model);
    static const std::regex mtllib(R"(^mtllib[ \t]+(\S+))", std::regex::multiline);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), mtllib);
         it != std::sregex_iterator(); ++it) {
        const fs::path mtl = model.parent_path() / (*it)[1].str();
        if (fs::is_regular_file(mtl) && mtl.filename() == fs::path((*it)[1].str()))
            fs::copy_file(mtl, scenes / mtl.filename(), fs::copy_options::overwrite_existing);
    }
    return name;
}

/// Prints "gallery i/n: figure" on stderr: on one rewritten line at a terminal, else a line
/// each (no control codes in a log).
void progress(size_t i, size_t n, const Figure& f) {
    static const bool terminal = ::isatty(2) != 0;
    if (terminal)
        cli::print_err("\rhikari: gallery {}/{}: {} {}\x1b[K", i + 1, n, f.figure, f.image);
    else
        cli::print_err("hikari: gallery {}/{}: {} {}\n", i + 1, n, f.figure, f.image);
}

/// Renders every figure; the buffers measured for their captions (g.data()) are removed when
/// they are done, and also when a render fails or a signal stops the gallery.
void render_figures(Gallery& g) {
    struct RemoveData {
        fs::path dir;
        ~RemoveData() {
            std::error_code ec;
            fs::remove_all(dir, ec);
        }
    } remove_data{g.data()};
    for (size_t i = 0; i < g.figures.size(); ++i) {
        progress(i, g.figures.size(), g.figures[i]);
        render_figure(g, g.figures[i]);
    }
}

}  // namespace

}  // namespace hikari::gallery

namespace hikari {

int run_gallery(const GalleryOptions& o, const std::string& program) {
    namespace fs = std::filesystem;
    using namespace gallery;
    Gallery g;
    g.dir = fs::absolute(o.dir);
    g.program = fs::absolute(program).string();
    g.width = o.width;
    g.threads = o.threads;
    g.japanese = o.lang == "ja";
    const fs::path model = o.model.empty() ? cli::data_folder() / "scenes" / "models" / "teapot.obj"
                                           : fs::path(o.model);
    // A model that does not load: nothing made.
    const PlacedModel placed = place_model(model, model.filename().string());
    plan(g, placed);
    select_figures(g, o.only);
    std::error_code ec;
    fs::create_directories(g.scenes(), ec);
    if (!ec) fs::create_directories(g.data(), ec);
    if (ec || ::access(g.dir.c_str(), W_OK) != 0)
        throw InputError(fmt::format("gallery: cannot write into {}{}", g.dir.string(),
                                     ec ? ": " + ec.message() : ""));
    copy_model(model, g.scenes());
    for (const auto& [name, text] : g.files) g.write_text(name, text);
    for (const auto& [name, scene] : g.scene_files) g.write_scene(name, scene);
    render_figures(g);
    const std::string html = index_html(g, model.filename().string());
    write_file_atomically(g.dir / "index.html",
                          {reinterpret_cast<const uint8_t*>(html.data()), html.size()});
    cli::print_err("{}hikari: gallery: {} figures in {}\n", ::isatty(2) ? "\r\x1b[K" : "",
                   g.figures.size(), (g.dir / "index.html").string());
    return 0;
}

}  // namespace hikari
