#include "gallery.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hikari/core/aabb.h"
#include "hikari/core/error.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/scene/scene_json.h"

extern char** environ;

namespace hikari {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

/// One picture of the gallery: the lecture's figure it reproduces and how.
struct Figure {
    std::string section;            ///< the lecture's section (the contact sheet's headings)
    std::string figure;             ///< "Fig 4.1a", "Alg 4.1", ...
    std::string title;              ///< what it shows
    std::string image;              ///< file name in the gallery directory
    std::string scene;              ///< file name in scenes/
    std::vector<std::string> args;  ///< `hikari render` options besides scene and output
    std::string note;               ///< measured facts for the caption (filled while rendering)
    double seconds = 0;             ///< render time
    std::string command;            ///< the command that reproduces it (filled while rendering)
};

/// The gallery being made: where it goes and how to render.
struct Gallery {
    fs::path dir;
    std::string program;
    int width;
    int threads;
    std::vector<Figure> figures;

    fs::path scenes() const { return dir / "scenes"; }

    /// Writes `scene` as scenes/NAME.
    void write_scene(const std::string& name, const Json& scene) const {
        const std::string text = scene.dump(2) + "\n";
        write_file_atomically(scenes() / name,
                              {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
    }

    /// Runs `hikari render scenes/SCENE ARGS -o OUTPUT -q` in the gallery directory; returns the
    /// seconds it took. A failed render is an error.
    double render(const std::string& scene, const std::vector<std::string>& args,
                  const std::string& output) const {
        std::vector<std::string> argv = {program, "render", (scenes() / scene).string()};
        argv.insert(argv.end(), args.begin(), args.end());
        argv.insert(argv.end(), {"-o", (dir / output).string(), "-q"});
        if (threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(threads)});
        std::vector<char*> raw;
        raw.reserve(argv.size() + 1);
        for (std::string& a : argv) raw.push_back(a.data());
        raw.push_back(nullptr);
        const auto start = std::chrono::steady_clock::now();
        pid_t pid = 0;
        if (posix_spawn(&pid, program.c_str(), nullptr, nullptr, raw.data(), environ) != 0)
            throw InputError(fmt::format("gallery: cannot run {}", program));
        int status = 0;
        waitpid(pid, &status, 0);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            throw InputError(
                fmt::format("gallery: rendering {} failed (hikari render {} ...)", output, scene));
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    void add(std::string section, std::string figure, std::string title, std::string image,
             std::string scene, std::vector<std::string> args) {
        Figure f;
        f.section = std::move(section);
        f.figure = std::move(figure);
        f.title = std::move(title);
        f.image = std::move(image);
        f.scene = std::move(scene);
        f.args = std::move(args);
        figures.push_back(std::move(f));
    }
};

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

/// The model placed on the ground: its bounds, and the mesh object that puts it there (its
/// largest side 1.2 long, standing on y = 0, centred on the y axis).
struct PlacedModel {
    Json object;
    float height = 1;    ///< its height after placing
    float distance = 3;  ///< how far the camera stands from its centre to see all of it
};

PlacedModel place_model(const fs::path& model, const fs::path& scenes) {
    // The mesh loaded as a scene's one object, as every figure will load it.
    const std::string probe =
        Json{{"objects", {{{"type", "mesh"}, {"file", fs::absolute(model).string()}}}}}.dump();
    std::vector<std::string> warnings;
    const Scene scene = parse_scene(probe, model.string(), fs::current_path(), warnings);
    Aabb box;
    for (const Vec3& p : scene.triangles.positions) box.extend(p);
    if (scene.triangles.size() == 0 || box.empty())
        throw InputError(fmt::format("{}: the model has no triangles", model.string()));
    const Vec3 extent = box.extent();
    const float scale = 1.2f / std::max({extent.x, extent.y, extent.z, 1e-12f});
    const Vec3 c = box.center();
    PlacedModel placed;
    // Relative to the scenes that name it, so a gallery moved with its model still renders.
    placed.object = {
        {"type", "mesh"},
        {"file", fs::absolute(model).lexically_relative(fs::absolute(scenes)).string()},
        {"material", "model"},
        {"transform", {{{"translate", {-c.x, -box.min.y, -c.z}}}, {{"scale", scale}}}}};
    placed.height = extent.y * scale;
    // The bounding sphere fills the view (38° high, 4:3): r / sin(19°), with a margin.
    const float radius = 0.5f * length(extent) * scale;
    placed.distance = 1.1f * radius / std::sin(19.0f * 3.14159265f / 180.0f);
    return placed;
}

Json vec(float x, float y, float z) { return {x, y, z}; }

/// A ground of two triangles, 12 × 12 around the origin, material "ground".
Json ground_triangles() {
    return {{{"type", "triangle"},
             {"vertices", {vec(-6, 0, -6), vec(-6, 0, 6), vec(6, 0, 6)}},
             {"material", "ground"}},
            {{"type", "triangle"},
             {"vertices", {vec(-6, 0, -6), vec(6, 0, 6), vec(6, 0, -6)}},
             {"material", "ground"}}};
}

/// The model on the ground under a key point light and a fill directional light.
Json model_scene(const PlacedModel& m, int width) {
    const Vec3 centre(0, 0.5f * m.height, 0);
    Json objects = ground_triangles();
    objects.push_back(m.object);
    return {
        {"description", "hikari gallery: the model on a ground (Fig 4.1 and others)"},
        {"camera",
         {{"eye", vec(centre.x + m.distance * 0.5f, centre.y + m.distance * 0.42f,
                      centre.z + m.distance * 0.76f)},
          {"look_at", vec(centre.x, centre.y, centre.z)},
          {"fov_y", 38},
          {"width", width},
          {"height", width * 3 / 4}}},
        {"background", vec(0.62f, 0.7f, 0.82f)},
        {"ambient", vec(0.15f, 0.15f, 0.16f)},
        {"materials",
         {{"model",
           {{"ka", vec(0.85f, 0.55f, 0.35f)},
            {"kd", vec(0.85f, 0.55f, 0.35f)},
            {"ks", vec(0.4f, 0.4f, 0.4f)},
            {"shininess", 40}}},
          {"ground", {{"ka", vec(0.7f, 0.7f, 0.68f)}, {"kd", vec(0.7f, 0.7f, 0.68f)}}}}},
        {"lights",
         {{{"type", "point"}, {"position", vec(2.2f, 3.5f, 2.5f)}, {"intensity", vec(18, 17, 16)}},
          {{"type", "directional"},
           {"direction", vec(-0.5f, -1, -0.3f)},
           {"intensity", vec(0.25f, 0.27f, 0.32f)}}}},
        {"objects", objects}};
}

/// `scene` with its lights replaced by `lights`.
Json with_lights(Json scene, Json lights) {
    scene["lights"] = std::move(lights);
    return scene;
}

/// The assignment's sphere with Phong exponent `n` (Fig 4.39).
Json phong_sphere(float n, int width) {
    return {
        {"description", fmt::format("Fig 4.39: the Phong highlight with n = {}", n)},
        {"camera",
         {{"eye", vec(0, 0, 0)},
          {"look_at", vec(0, 0, -1)},
          {"fov_y", 40},
          {"width", width / 2},
          {"height", width / 2}}},
        {"background", vec(0.1f, 0.1f, 0.1f)},
        {"ambient", vec(0.1f, 0.1f, 0.1f)},
        {"materials",
         {{"clay",
           {{"ka", vec(0.8f, 0.3f, 0.2f)},
            {"kd", vec(0.8f, 0.3f, 0.2f)},
            {"ks", vec(0.6f, 0.6f, 0.6f)},
            {"shininess", n}}}}},
        {"lights",
         {{{"type", "directional"}, {"direction", vec(1, -1, -1)}, {"intensity", vec(1, 1, 1)}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", vec(0, 0, -3)}, {"radius", 1}, {"material", "clay"}}}}};
}

/// A glass ball with index of refraction `ior` before a checker wall (Fig 4.43).
Json refraction_scene(float ior, int width) {
    return {
        {"description", fmt::format("Fig 4.43: refraction through a ball of ior {}", ior)},
        {"camera",
         {{"eye", vec(0, 1, 4.5f)},
          {"look_at", vec(0, 1, 0)},
          {"fov_y", 40},
          {"width", width / 2},
          {"height", width / 2}}},
        {"background", vec(0.3f, 0.3f, 0.35f)},
        {"ambient", vec(0.3f, 0.3f, 0.3f)},
        {"materials",
         {{"glass",
           {{"ks", vec(0.6f, 0.6f, 0.6f)},
            {"shininess", 200},
            {"transparency", 0.9},
            {"reflectivity", 0.05},
            {"ior", ior}}},
          {"wall",
           {{"ka", vec(1, 1, 1)},
            {"kd", vec(0.8f, 0.8f, 0.8f)},
            {"texture",
             {{"type", "checker"},
              {"size", 0.5},
              {"color_a", vec(0.9f, 0.85f, 0.3f)},
              {"color_b", vec(0.15f, 0.3f, 0.7f)}}}}}}},
        {"lights",
         {{{"type", "point"}, {"position", vec(2, 4, 5)}, {"intensity", vec(30, 30, 30)}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", vec(0, 1, 0)}, {"radius", 0.8}, {"material", "glass"}},
          {{"type", "plane"},
           {"point", vec(0, 0, -2)},
           {"normal", vec(0, 0, 1)},
           {"material", "wall"}}}}};
}

/// Fig 4.9c: a concave (U-shaped) polygon, as the triangles hikari draws, with a bar through
/// its notch: in front of the bar on the left, behind it on the right.
Json concave_scene(int width) {
    const auto z = [](float x) { return -10.0f - 0.6667f * x; };  // the U's tilted plane
    const auto quad = [&](float x0, float x1, float y0, float y1, const char* material) {
        return Json::array(
            {{{"type", "triangle"},
              {"vertices", {vec(x0, y0, z(x0)), vec(x1, y0, z(x1)), vec(x1, y1, z(x1))}},
              {"material", material}},
             {{"type", "triangle"},
              {"vertices", {vec(x0, y0, z(x0)), vec(x1, y1, z(x1)), vec(x0, y1, z(x0))}},
              {"material", material}}});
    };
    Json objects = Json::array();
    for (const Json& q : {quad(-1.5f, -0.7f, -1.5f, 1.5f, "u"),
                          quad(-0.7f, 0.7f, -1.5f, -0.5f, "u"), quad(0.7f, 1.5f, -1.5f, 1.5f, "u")})
        for (const Json& t : q) objects.push_back(t);
    objects.push_back(
        {{"type", "triangle"},
         {"vertices", {vec(-2.5f, 0.2f, -10), vec(2.5f, 0.2f, -10), vec(2.5f, 0.8f, -10)}},
         {"material", "bar"}});
    objects.push_back(
        {{"type", "triangle"},
         {"vertices", {vec(-2.5f, 0.2f, -10), vec(2.5f, 0.8f, -10), vec(-2.5f, 0.8f, -10)}},
         {"material", "bar"}});
    return {{"description",
             "Fig 4.9c: a concave polygon (a U) and a bar through its notch: as one polygon the U "
             "is both in front of and behind the bar"},
            {"camera",
             {{"eye", vec(0, 0, 0)},
              {"look_at", vec(0, 0, -1)},
              {"fov_y", 30},
              {"width", width / 2},
              {"height", width / 2}}},
            {"background", vec(0.95f, 0.95f, 0.92f)},
            {"ambient", vec(0.7f, 0.7f, 0.7f)},
            {"materials",
             {{"u", {{"ka", vec(0.9f, 0.3f, 0.25f)}}}, {"bar", {{"ka", vec(0.2f, 0.45f, 0.9f)}}}}},
            {"lights", Json::array()},
            {"objects", objects}};
}

/// A repository scene (scenes/NAME) copied into the gallery, or an error naming it.
Json repository_scene(const std::string& name) {
    const fs::path path = fs::path(HIKARI_SOURCE_DIR) / "scenes" / name;
    try {
        return Json::parse(read_file_bytes(path));
    } catch (const std::exception& e) {
        throw InputError(fmt::format("gallery: cannot read {}: {}", path.string(), e.what()));
    }
}

/// `image` (a linear PFM of eye distances) as a grey PNG, near white and far black, and the
/// range it spans.
std::pair<float, float> depth_to_grey(const fs::path& pfm, const fs::path& png) {
    Image depth = read_image(pfm);
    float lo = std::numeric_limits<float>::infinity(), hi = 0;
    for (const Vec3& d : depth.pixels)
        if (std::isfinite(d.x) && d.x > 0) lo = std::min(lo, d.x), hi = std::max(hi, d.x);
    for (Vec3& d : depth.pixels) {
        const float t = std::isfinite(d.x) && d.x > 0 && hi > lo ? (hi - d.x) / (hi - lo) : 0.0f;
        d = Vec3(std::pow(0.05f + 0.95f * t, 2.2f));  // grey steps even in the sRGB file
    }
    write_image(png, depth);
    return {lo, hi};
}

/// `scene` with every material's terms other than `keep` ("ka", "kd" or "ks") set to zero.
Json only_term(Json scene, const std::string& keep) {
    for (auto& [name, m] : scene["materials"].items())
        for (const char* term : {"ka", "kd", "ks"})
            if (term != keep) m[term] = vec(0, 0, 0);
    return scene;
}

/// The fraction of pixels where two renders' id buffers (PFM) agree.
double id_agreement(const fs::path& a, const fs::path& b) {
    const Image x = read_image(a), y = read_image(b);
    size_t same = 0;
    for (size_t i = 0; i < x.pixels.size(); ++i) same += x.pixels[i].x == y.pixels[i].x;
    return static_cast<double>(same) / static_cast<double>(x.pixels.size());
}

/// Lit (shadowed) over unlit (--shadows none) colour, per pixel, as grey: the shadows alone.
void shadow_ratio(const fs::path& lit, const fs::path& open, const fs::path& png) {
    Image a = read_image(lit);
    const Image b = read_image(open);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const float denominator = b.pixels[i].x + b.pixels[i].y + b.pixels[i].z;
        const float v =
            denominator > 0 ? (a.pixels[i].x + a.pixels[i].y + a.pixels[i].z) / denominator : 1.0f;
        a.pixels[i] = Vec3(std::clamp(v, 0.0f, 1.0f));
    }
    write_image(png, a);
}

/// The figures, in the lecture's order; scenes written into the gallery as they are named.
void plan(Gallery& g, const PlacedModel& model) {
    const int w = g.width;
    const Json m = model_scene(model, w);
    g.write_scene("model.json", m);
    // Fig 4.1 a–f.
    const std::string s41 = "Fig 4.1: what rendering draws";
    g.add(s41, "Fig 4.1a", "wireframe", "fig4-1a-wireframe.png", "model.json",
          {"-m", "wireframe", "--line-color", "0.1,0.12,0.2"});
    const float near = 2.0f, far = 6.0f;
    g.add(s41, "Fig 4.1b", "depth cueing (near bright and sharp, far dark)",
          "fig4-1b-depth-cue.png", "model.json",
          {"-m", "zbuffer", "--depth-cue", fmt::format("{},{}", near, far)});
    g.add(s41, "Fig 4.1c", "hidden-line removal", "fig4-1c-hidden-line.png", "model.json",
          {"-m", "hiddenline", "--line-color", "0.1,0.12,0.2"});
    g.add(s41, "Fig 4.1d", "shading (ambient + Lambert + Phong)", "fig4-1d-shading.png",
          "model.json", {"-m", "zbuffer", "--shadows", "none"});
    g.add(s41, "Fig 4.1e", "shadows (shadow mapping)", "fig4-1e-shadows.png", "model.json",
          {"-m", "zbuffer", "--shadows", "map"});
    Json textured = m;
    const Json checker = {{"type", "checker"},
                          {"size", 0.25},
                          {"color_a", vec(0.9f, 0.9f, 0.85f)},
                          {"color_b", vec(0.25f, 0.35f, 0.6f)}};
    textured["materials"]["ground"]["texture"] = checker;
    textured["materials"]["model"]["texture"] = checker;
    g.write_scene("model-textured.json", textured);
    g.add(s41, "Fig 4.1f", "texture mapping (a checker texture)", "fig4-1f-texture.png",
          "model-textured.json", {"-m", "zbuffer"});
    // Fig 4.3.
    const std::string s43 = "Fig 4.3: back-face culling (D = V·N)";
    g.add(s43, "Fig 4.3", "culling on: triangles facing away are dropped", "fig4-3-cull-back.png",
          "model.json", {"-m", "zbuffer", "--cull", "back", "--shadows", "none"});
    g.add(s43, "Fig 4.3", "culling off: the same picture, more work", "fig4-3-cull-none.png",
          "model.json", {"-m", "zbuffer", "--cull", "none", "--shadows", "none"});
    // Fig 4.7, 4.9.
    const std::string sds = "Fig 4.7, 4.9: the depth sort and where it fails";
    const std::vector<std::pair<std::string, std::string>> sorts = {
        {"Fig 4.7", "depth-sort-centroid.json"},
        {"Fig 4.9a", "depth-sort-cyclic.json"},
        {"Fig 4.9b", "depth-sort-piercing.json"}};
    for (const auto& [fig, file] : sorts) {
        Json scene = repository_scene(file);
        scene["camera"]["width"] = w / 2;
        scene["camera"]["height"] = w / 2;
        g.write_scene(file, scene);
        const std::string stem = fs::path(file).stem().string();
        g.add(sds, fig, scene["description"].get<std::string>() + " — depthsort-naive",
              stem + "-naive.png", file, {"-m", "depthsort-naive"});
        g.add(sds, fig, "the same scene — depthsort (Newell's tests, splitting)", stem + ".png",
              file, {"-m", "depthsort"});
    }
    g.write_scene("depth-sort-concave.json", concave_scene(w));
    g.add(sds, "Fig 4.9c",
          "a concave polygon (a U, drawn as its triangles) with a bar through its notch, in front "
          "of the U's right arm and behind its left — depthsort-naive paints the bar over both",
          "depth-sort-concave-naive.png", "depth-sort-concave.json", {"-m", "depthsort-naive"});
    g.add(sds, "Fig 4.9c", "the same scene — depthsort", "depth-sort-concave.png",
          "depth-sort-concave.json", {"-m", "depthsort"});
    // Alg 4.1, 4.2, Fig 4.14.
    const std::string szb = "Alg 4.1, 4.2, Fig 4.14: scanline and Z-buffer";
    g.add(szb, "Alg 4.1", "scanline hidden-surface removal", "alg4-1-scanline.png", "model.json",
          {"-m", "scanline", "--shadows", "none"});
    g.add(szb, "Alg 4.2", "Z-buffer hidden-surface removal", "alg4-2-zbuffer.png", "model.json",
          {"-m", "zbuffer", "--shadows", "none"});
    g.add(szb, "Fig 4.14", "the Z-buffer itself: eye distance per pixel, near white, far black",
          "fig4-14-depth.png", "model.json", {"-m", "zbuffer", "--aov", "depth"});
    g.add(szb, "Fig 4.14", "the frame buffer beside it", "fig4-14-frame.png", "model.json",
          {"-m", "zbuffer", "--shadows", "none"});
    // Fig 4.29, 4.39.
    const std::string sph = "Fig 4.29, 4.39: the shading model";
    for (const auto& [term, title] :
         std::vector<std::pair<std::string, std::string>>{{"ka", "ambient only: ka·Ia"},
                                                          {"kd", "diffuse only: I·kd·cos α"},
                                                          {"ks", "specular only: I·ks·cos^n γ"}}) {
        const std::string file = "model-" + term + ".json";
        g.write_scene(file, only_term(m, term));
        g.add(sph, "Fig 4.29", title, "fig4-29-" + term + ".png", file,
              {"-m", "raytrace", "--shadows", "none"});
    }
    g.add(sph, "Fig 4.29", "their sum", "fig4-29-sum.png", "model.json",
          {"-m", "raytrace", "--shadows", "none"});
    for (const int n : {1, 5, 20, 100}) {
        const std::string file = fmt::format("phong-n{}.json", n);
        g.write_scene(file, phong_sphere(static_cast<float>(n), w));
        g.add(sph, "Fig 4.39", fmt::format("Phong exponent n = {}", n),
              fmt::format("fig4-39-n{}.png", n), file, {"-m", "raytrace"});
    }
    // Fig 4.24.
    const std::string ssh = "Fig 4.24: shading and shadows";
    g.add(ssh, "Fig 4.24", "shading only", "fig4-24-shading.png", "model.json",
          {"-m", "raytrace", "--shadows", "none"});
    g.add(ssh, "Fig 4.24", "shadows only: shadowed over unshadowed light (1 = lit)",
          "fig4-24-shadows.png", "model.json", {"-m", "raytrace"});
    g.add(ssh, "Fig 4.24", "both", "fig4-24-both.png", "model.json", {"-m", "raytrace"});
    // The four lights; hard and soft shadows.
    const std::string sli = "Light sources and soft shadows";
    const Json area = {{"type", "area"},
                       {"corner", vec(-0.4f, 2.6f, 0.1f)},
                       {"edge1", vec(0.8f, 0, 0)},
                       {"edge2", vec(0, 0, 0.8f)},
                       {"radiance", vec(9, 8.6f, 8.2f)}};
    const std::vector<std::tuple<std::string, std::string, Json>> lights = {
        {"point",
         "point light (1/d²)",
         {{{"type", "point"},
           {"position", vec(0, 2.6f, 0.5f)},
           {"intensity", vec(6.5f, 6.2f, 5.8f)}}}},
        {"directional",
         "directional light",
         {{{"type", "directional"},
           {"direction", vec(-0.3f, -1, -0.4f)},
           {"intensity", vec(1, 1, 1)}}}},
        {"area", "area light (soft shadows)", Json::array({area})},
        {"environment",
         "environment light (a constant sky)",
         {{{"type", "environment"}, {"radiance", vec(0.3f, 0.32f, 0.36f)}}}}};
    for (const auto& [kind, title, json] : lights) {
        Json scene = with_lights(m, json);
        scene["ambient"] = vec(0.02f, 0.02f, 0.02f);
        g.write_scene("light-" + kind + ".json", scene);
        g.add(sli, "lights", title, "light-" + kind + ".png", "light-" + kind + ".json",
              {"-m", "raytrace", "--light-samples", "64"});
    }
    for (const std::string mode : {"map", "volume", "pcf", "pcss", "analytic"})
        g.add(sli, "soft shadows", "zbuffer --shadows " + mode, "soft-" + mode + ".png",
              "light-area.json", {"-m", "zbuffer", "--shadows", mode});
    g.add(sli, "soft shadows", "raytrace, 64 samples per area light", "soft-sampled.png",
          "light-area.json", {"-m", "raytrace", "--light-samples", "64"});
    // Fig 4.16, 4.43.
    const std::string srt = "Fig 4.16, 4.43: ray tracing";
    Json whitted = repository_scene("whitted.json");
    whitted["camera"]["width"] = w;
    whitted["camera"]["height"] = w * 9 / 16;
    g.write_scene("whitted.json", whitted);
    g.add(srt, "Fig 4.16", "ray tracing: reflection, refraction, shadows", "fig4-16-raytrace.png",
          "whitted.json", {"-m", "raytrace"});
    for (const float ior : {1.0f, 1.33f, 1.5f, 2.4f}) {
        const std::string file = fmt::format("refraction-{}.json", ior);
        g.write_scene(file, refraction_scene(ior, w));
        g.add(srt, "Fig 4.43", fmt::format("refraction, ior {}", ior),
              fmt::format("fig4-43-ior-{}.png", ior), file, {"-m", "raytrace"});
    }
    // Global illumination: the inter-reflection the ambient term stands in for.
    const std::string sgi = "Global illumination: light that bounces (path tracing)";
    for (const char* name : {"bench/cornell.json", "cornell-glass.json"}) {
        Json scene = repository_scene(name);
        scene["camera"]["width"] = w / 2;
        scene["camera"]["height"] = w / 2;
        g.write_scene(fs::path(name).filename().string(), scene);
    }
    g.add(sgi, "GI", "direct light only (--max-depth 0)", "gi-direct.png", "cornell.json",
          {"-m", "path", "--max-depth", "0"});
    g.add(sgi, "GI", "with inter-reflection: 8 bounces", "gi-path.png", "cornell.json",
          {"-m", "path"});
    g.add(sgi, "GI", "glass and mirror: caustics, 256 samples per pixel", "gi-glass.png",
          "cornell-glass.json", {"-m", "path", "--spp", "256"});
    // The assignment.
    const std::string sas = "The assignment: ray trace a sphere";
    for (const char* stage : {"assignment-1-hit-miss.json", "assignment-2-diffuse.json",
                              "assignment-3-specular.json"}) {
        Json scene = repository_scene(stage);
        scene["camera"]["width"] = w / 2;
        scene["camera"]["height"] = w / 2;
        g.write_scene(stage, scene);
        g.add(sas, "assignment", scene["description"].get<std::string>(),
              fs::path(stage).stem().string() + ".png", stage, {"-m", "raytrace"});
    }
}

/// The command that reproduces `f`, run from the gallery directory.
std::string command_line(const Figure& f) {
    std::string line = "hikari render scenes/" + f.scene;
    for (const std::string& a : f.args) line += " " + a;
    return line + " -o " + f.image;
}

/// Renders figure `f`; some figures render extra buffers and measure what their caption says.
void render_figure(const Gallery& g, Figure& f) {
    f.command = command_line(f);
    const fs::path data = g.dir / "data";
    const std::string stem = fs::path(f.image).stem().string();
    if (f.image == "fig4-14-depth.png") {
        f.seconds = g.render(f.scene, f.args, "data/" + stem + ".pfm");
        const auto [lo, hi] = depth_to_grey(data / (stem + ".pfm"), g.dir / f.image);
        f.note = fmt::format("white = {:.2f}, black = {:.2f} units from the eye", lo, hi);
        Figure pfm = f;
        pfm.image = "data/" + stem + ".pfm";
        f.command = command_line(pfm) + " (then grey from near to far)";
        return;
    }
    if (f.image == "fig4-24-shadows.png") {
        f.seconds = g.render(f.scene, f.args, "data/lit.pfm") +
                    g.render(f.scene, {"-m", "raytrace", "--shadows", "none"}, "data/open.pfm");
        shadow_ratio(data / "lit.pfm", data / "open.pfm", g.dir / f.image);
        f.command = "hikari render scenes/" + f.scene +
                    " -m raytrace -o lit.pfm, and --shadows none -o open.pfm; lit / open";
        return;
    }
    f.seconds = g.render(f.scene, f.args, f.image);
    if (f.image == "alg4-2-zbuffer.png") {
        g.render(f.scene, {"-m", "zbuffer", "--aov", "id"}, "data/zbuffer-id.pfm");
        g.render(f.scene, {"-m", "scanline", "--aov", "id"}, "data/scanline-id.pfm");
        f.note =
            fmt::format("id buffers of scanline and zbuffer agree on {:.3f}% of pixels",
                        100.0 * id_agreement(data / "zbuffer-id.pfm", data / "scanline-id.pfm"));
    }
    if (f.image == "fig4-3-cull-back.png") {
        std::vector<std::string> warnings;
        const Scene scene = load_scene_file(g.scenes() / f.scene, warnings);
        size_t away = 0;
        const TriangleSet& t = scene.triangles;
        for (size_t i = 0; i < t.size(); ++i) {
            const Vec3 a = t.positions[t.indices[i][0]], b = t.positions[t.indices[i][1]],
                       c = t.positions[t.indices[i][2]];
            // D = V·N with V from the eye to the triangle: D >= 0 faces away.
            away += dot(a - scene.camera.eye, cross(b - a, c - b)) >= 0.0f;
        }
        f.note = fmt::format("{} of the {} triangles face away from the eye and are culled", away,
                             t.size());
    }
}

/// The contact sheet: the figures grouped by section, each image linked full size.
std::string index_html(const Gallery& g, const std::string& model) {
    std::string html = R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>hikari gallery</title>
<style>
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
h2 { border-bottom: 1px solid #ccc; margin-top: 1.5em; }
.grid { display: flex; flex-wrap: wrap; gap: 14px; }
figure { margin: 0; width: 260px; background: #fff; padding: 6px; border: 1px solid #ddd; }
figure img { width: 100%; image-rendering: auto; }
figcaption { font-size: 12px; }
code { font-size: 11px; word-break: break-all; color: #444; }
</style></head><body>
<h1>hikari: the lecture's figures</h1>
)";
    html += fmt::format(
        "<p>Every picture is a render by the method it names, made by "
        "<code>hikari gallery</code> on the model <code>{}</code>. Run the "
        "command under a picture in this directory to make it again. Click a "
        "picture for full size.</p>\n",
        html_escape(model));
    std::string section;
    for (const Figure& f : g.figures) {
        if (f.section != section) {
            if (!section.empty()) html += "</div>\n";
            section = f.section;
            html += "<h2>" + html_escape(section) + "</h2>\n<div class=\"grid\">\n";
        }
        html += fmt::format(
            "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption><b>{1}</b>: "
            "{2}{3}<br><code>{4}</code><br>{5:.2f} s</figcaption></figure>\n",
            html_escape(f.image), html_escape(f.figure), html_escape(f.title),
            f.note.empty() ? "" : "<br><i>" + html_escape(f.note) + "</i>", html_escape(f.command),
            f.seconds);
    }
    if (!section.empty()) html += "</div>\n";
    return html + "</body></html>\n";
}

}  // namespace

int run_gallery(const GalleryOptions& o, const std::string& program) {
    Gallery g{o.dir, program, o.width, o.threads, {}};
    const fs::path model = o.model.empty()
                               ? fs::path(HIKARI_SOURCE_DIR) / "scenes" / "models" / "teapot.obj"
                               : fs::path(o.model);
    const PlacedModel placed =
        place_model(model, g.scenes());  // a model that does not load: nothing made
    std::error_code ec;
    fs::create_directories(g.dir / "scenes", ec);
    if (!ec) fs::create_directories(g.dir / "data", ec);
    if (ec || ::access(g.dir.c_str(), W_OK) != 0)
        throw InputError(fmt::format("gallery: cannot write into {}{}", g.dir.string(),
                                     ec ? ": " + ec.message() : ""));
    plan(g, placed);
    for (size_t i = 0; i < g.figures.size(); ++i) {
        Figure& f = g.figures[i];
        fmt::print(stderr, "\rhikari: gallery {}/{}: {} {}\x1b[K", i + 1, g.figures.size(),
                   f.figure, f.image);
        render_figure(g, f);
    }
    fs::remove_all(g.dir / "data", ec);  // the buffers measured for captions
    const std::string html = index_html(g, model.filename().string());
    write_file_atomically(g.dir / "index.html",
                          {reinterpret_cast<const uint8_t*>(html.data()), html.size()});
    fmt::print(stderr, "\rhikari: gallery: {} figures in {}\x1b[K\n", g.figures.size(),
               (g.dir / "index.html").string());
    return 0;
}

}  // namespace hikari
