#include "gallery_figures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "console.h"
#include "data_folder.h"
#include "hikari/core/error.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/io/video/video_pipe.h"

namespace hikari::gallery {

namespace fs = std::filesystem;

namespace {

Json vec(float x, float y, float z) { return {x, y, z}; }

/// A scene hikari ships (scenes/NAME, data_folder.h) to copy into the gallery, or an error naming
/// it.
Json repository_scene(const std::string& name) {
    const fs::path path = cli::data_folder() / "scenes" / name;
    try {
        return Json::parse(read_file_bytes(path));
    } catch (const std::exception& e) {
        throw InputError(fmt::format("gallery: cannot read {}: {}", path.string(), e.what()));
    }
}

/// `scene` (a repository scene) at `width` × `height` pixels.
Json resized(Json scene, int width, int height) {
    scene["camera"]["width"] = width;
    scene["camera"]["height"] = height;
    return scene;
}

// ---- Measurements for captions -------------------------------------------------------------

/// One plain render: `hikari render scenes/SCENE ARGS -o IMAGE`.
void render_plain(const Gallery& g, Figure& f) {
    f.seconds = g.render(f.scene, f.args, f.image);
    f.commands = {command_line(f.scene, f.args, f.image)};
}

/// The text of a render's `--stats` log, or "" when there is none.
std::string read_log(const fs::path& log) {
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The first number after `before` in `text` (a --stats line), or NaN.
double stat_after(const std::string& text, const std::string& pattern) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(pattern))) return std::nan("");
    return std::stod(m[1].str());
}

/// How many pixels of two images of one size differ in any channel.
size_t differing_pixels(const fs::path& a, const fs::path& b) {
    const Image x = read_image(a), y = read_image(b);
    size_t n = 0;
    for (size_t i = 0; i < x.pixels.size(); ++i) n += x.pixels[i] != y.pixels[i];
    return n;
}

/// The fraction of pixels where two renders' id buffers (PFM) agree.
double id_agreement(const fs::path& a, const fs::path& b) {
    const Image x = read_image(a), y = read_image(b);
    size_t same = 0;
    for (size_t i = 0; i < x.pixels.size(); ++i) same += x.pixels[i].x == y.pixels[i].x;
    return static_cast<double>(same) / static_cast<double>(x.pixels.size());
}

/// Fig 4.3: a render with --stats, its culled-triangle count and render time in the note.
void render_culling(const Gallery& g, Figure& f) {
    const fs::path log = g.data() / (f.image + ".log");
    std::vector<std::string> args = f.args;
    args.push_back("--stats");
    f.seconds = g.render(f.scene, args, f.image, log.string());
    f.commands = {command_line(f.scene, args, f.image)};
    const std::string stats = read_log(log);
    const double in = stat_after(stats, R"(([0-9]+) triangles in)");
    const double culled = stat_after(stats, R"(([0-9]+) culled)");
    const double ms = stat_after(stats, R"(render ([0-9.]+) ms)");
    f.note = {fmt::format("--stats: {:.0f} of {:.0f} triangles culled; render {:.1f} ms (one run)",
                          culled, in, ms),
              fmt::format("--stats：{:.0f} 枚中 {:.0f} 枚をカリング、描画 {:.1f} ms（1回の計測）",
                          in, culled, ms)};
    if (f.image != "fig4-3-cull-none.png") return;
    const size_t differ = differing_pixels(g.dir / "fig4-3-cull-back.png", g.dir / f.image);
    f.note.en += fmt::format(
        ". {} pixels differ from culling on: there the nearest surface is a back face (the "
        "model's inside, seen through an opening; --aov culled marks them). The times are single "
        "runs, not a benchmark: which is faster here is within their run-to-run spread.",
        differ);
    f.note.ja += fmt::format(
        "。カリングありと異なる画素は {} 個：最も手前の面が裏向きの面（開口部から見えるモデル"
        "の内側。--aov culled で表示）の所だけ。時間は1回ずつの計測で、ベンチマークではない。",
        differ);
}

/// Fig 4.14: the depth picture itself (near white, far black), the range measured for the note.
void render_depth(const Gallery& g, Figure& f) {
    render_plain(g, f);
    const std::string pfm = "data/depth.pfm";
    g.render(f.scene, f.args, pfm);
    const Image depth = read_image(g.dir / pfm);
    float lo = std::numeric_limits<float>::infinity(), hi = 0;
    for (const Vec3& d : depth.pixels)
        if (std::isfinite(d.x) && d.x > 0) lo = std::min(lo, d.x), hi = std::max(hi, d.x);
    f.note = {fmt::format("white = {:.2f}, black = {:.2f} units from the eye", lo, hi),
              fmt::format("白 = 視点から {:.2f}、黒 = {:.2f}", lo, hi)};
}

/// Alg 4.2: the picture, and the agreement of the scanline and Z-buffer id buffers.
void render_zbuffer(const Gallery& g, Figure& f) {
    render_plain(g, f);
    g.render(f.scene, {"-m", "zbuffer", "--aov", "id"}, "data/zbuffer-id.pfm");
    g.render(f.scene, {"-m", "scanline", "--aov", "id"}, "data/scanline-id.pfm");
    const double agree =
        100.0 * id_agreement(g.data() / "zbuffer-id.pfm", g.data() / "scanline-id.pfm");
    f.note = {
        fmt::format("id buffers of scanline and zbuffer agree on {:.3f}% of pixels", agree),
        fmt::format("スキャンライン法とZバッファ法のID バッファは {:.3f}% の画素で一致", agree)};
}

/// Fig 4.29d: the colour, and how closely the three term AOVs add up to it (float files).
void render_term_sum(const Gallery& g, Figure& f) {
    render_plain(g, f);
    Image sum = read_image((g.render(f.scene, f.args, "data/color.pfm"), g.data() / "color.pfm"));
    for (const char* term : {"ambient", "diffuse", "specular"}) {
        std::vector<std::string> args = f.args;
        args.insert(args.end(), {"--aov", term});
        const std::string out = fmt::format("data/{}.pfm", term);
        g.render(f.scene, args, out);
        const Image t = read_image(g.dir / out);
        for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] -= t.pixels[i];
    }
    float worst = 0;
    for (const Vec3& d : sum.pixels)
        worst = std::max({worst, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    f.note = {fmt::format("(a) + (b) + (c) = (d): largest difference {:.1e} in .pfm files", worst),
              fmt::format("(a) + (b) + (c) = (d)：.pfm での最大の差 {:.1e}", worst)};
}

/// The largest value of a raw AOV buffer (a .pfm of counts or paint positions).
float largest_value(const fs::path& pfm) {
    float most = 0.0f;
    for (const Vec3& v : read_image(pfm).pixels) most = std::max(most, v.x);
    return most;
}

/// A false-colour figure (--aov overdraw, paint-order): the picture, and its legend's ends from
/// the same render's raw values (.pfm: the counts themselves).
void render_with_legend(const Gallery& g, Figure& f, Text low, Text high_format) {
    render_plain(g, f);
    const std::string pfm = "data/" + fs::path(f.image).stem().string() + ".pfm";
    g.render(f.scene, f.args, pfm);
    const float most = largest_value(g.dir / pfm);
    f.legend_low = std::move(low);
    f.legend_high = {fmt::format(fmt::runtime(high_format.en), most),
                     fmt::format(fmt::runtime(high_format.ja), most)};
}

/// The turntable: a video made by ffmpeg; without it, the figure says what to install instead.
void render_turntable(const Gallery& g, Figure& f) {
    f.commands = {command_line(f.scene, f.args, f.image)};
    // Its stderr in a log: the warning that --line-color is no option of zbuffer and raytrace;
    // shown when the render fails, since it says why.
    if (find_ffmpeg()) {
        const fs::path log = g.data() / "turntable.log";
        try {
            f.seconds = g.render(f.scene, f.args, f.image, log.string());
        } catch (const InputError&) {
            cli::print_err("{}", read_log(log));
            throw;
        }
        return;
    }
    f.missing = {
        "Not made here: this animation is a GIF encoded by the ffmpeg program, which is not "
        "installed. Install it (Debian, Ubuntu: sudo apt-get install ffmpeg), then run hikari "
        "gallery again, or only the command below in this folder.",
        "ここでは作成していません：このアニメーションは ffmpeg プログラムで GIF "
        "に変換しますが、ffmpeg がインストールされていません。インストールして（Debian、"
        "Ubuntu：sudo apt-get install ffmpeg）から、hikari gallery をもう一度実行するか、"
        "このフォルダで下のコマンドだけを実行してください。"};
}

// ---- The figures, section by section ---------------------------------------------------------

const Text k_fig41 = {"Fig 4.1: what rendering draws", "図4.1: 3次元モデルの写実的表現"};

void plan_fig41(Gallery& g, const Json& m) {
    g.scene_files["model-depth-cue.json"] = depth_cued(m, 2.5f, 6.0f);
    g.scene_files["model-textured.json"] = textured(m);
    const std::vector<std::string> lines = {"--line-color", "0.1,0.12,0.2"};
    g.add(k_fig41, "Fig 4.1a", {"wireframe: every edge of every face", "ワイヤフレーム"},
          "fig4-1a-wireframe.png", "model.json", {"-m", "wireframe", lines[0], lines[1]});
    g.add(k_fig41, "Fig 4.1b",
          {"depth cueing: near bright and sharp, far dark and blurred (from 2.5 to 6 units the "
           "colour fades to black and blurs up to 4 pixels)",
           "デプスキューイング（近：明るい、鮮明　遠：暗い、ぼやけ。視点から 2.5〜6 の間で黒へ"
           "近づき、最大 4 画素ぼける）"},
          "fig4-1b-depth-cue.png", "model-depth-cue.json", {"-m", "zbuffer"});
    g.add(k_fig41, "Fig 4.1c", {"hidden-line removal", "隠線消去（見えない線の消去）"},
          "fig4-1c-hidden-line.png", "model.json", {"-m", "hiddenline", lines[0], lines[1]});
    g.add(k_fig41, "Fig 4.1d",
          {"shading (ambient + Lambert + Phong)", "陰影の付加（環境光＋拡散反射＋鏡面反射）"},
          "fig4-1d-shading.png", "model.json", {"-m", "zbuffer", "--shadows", "none"});
    g.add(k_fig41, "Fig 4.1e", {"shadows (shadow mapping)", "影付け（シャドウマッピング）"},
          "fig4-1e-shadows.png", "model.json", {"-m", "zbuffer", "--shadows", "map"});
    g.add(k_fig41, "Fig 4.1f",
          {"texture mapping (a checker texture)", "模様の付加（テクスチャマッピング、市松模様）"},
          "fig4-1f-texture.png", "model-textured.json", {"-m", "zbuffer"});
}

void plan_culling(Gallery& g) {
    const Text s43 = {"Fig 4.3, 4.4: back-face culling (D = V·N) and its limit",
                      "図4.3, 4.4: バックフェースカリング（D = V·N）とその限界"};
    const std::vector<std::pair<std::string, Text>> culling = {
        {"back",
         {"culling on: triangles facing away from the eye are dropped before rasterizing",
          "カリングあり：視点に背を向けた三角形をラスタ化の前に捨てる"}},
        {"none",
         {"culling off: every triangle is rasterized; the Z-buffer hides the back faces anyway",
          "カリングなし：全三角形をラスタ化（裏向きの面はZバッファが隠す）"}}};
    for (const auto& [mode, title] : culling)
        g.add(s43, "Fig 4.3", title, "fig4-3-cull-" + mode + ".png", "model.json",
              {"-m", "zbuffer", "--cull", mode, "--shadows", "none"})
            .make = render_culling;
    g.files["u-block.obj"] = concave_block_obj();
    g.scene_files["u-block.json"] = concave_block_scene("u-block.obj", g.width);
    const std::vector<std::string> ink = {"--line-color", "0.1,0.12,0.2"};
    g.add(s43, "Fig 4.4",
          {"a concave polyhedron (a U-shaped block), shaded", "凹多面体（U字形のブロック）"},
          "fig4-4-shaded.png", "u-block.json", {"-m", "zbuffer", "--shadows", "none"});
    g.add(s43, "Fig 4.4",
          {"back-face culling alone (wireframe --cull back): the edges of every front face are "
           "drawn, also where the U's right arm hides the left arm's inner face",
           "バックフェースカリングだけ：表向きの面の辺がすべて描かれ、右腕に隠れる左腕の内側の面"
           "の辺まで見えてしまう"},
          "fig4-4-cull-only.png", "u-block.json",
          {"-m", "wireframe", "--cull", "back", ink[0], ink[1]});
    g.add(s43, "Fig 4.4", {"hidden-line removal: only what is seen", "隠線消去：見える線だけ"},
          "fig4-4-hidden-line.png", "u-block.json", {"-m", "hiddenline", ink[0], ink[1]});
}

void plan_depth_sort(Gallery& g) {
    const Text s = {"Fig 4.7, 4.9: the depth sort and where it fails",
                    "図4.7, 4.9: 奥行きソート法とその限界"};
    const std::vector<std::tuple<std::string, std::string, Text, Text>> sorts = {
        {"Fig 4.7",
         "depth-sort-centroid.json",
         {"depthsort-naive (centroid order): the small orange triangle's centroid is the nearer, "
          "so it is painted last, over the near end of the blue triangle that hides it",
          "重心で順位を決めた奥行きソート（depthsort-naive）：オレンジの三角形の重心の方が近いの"
          "で後に描かれ、それを隠すはずの青い三角形の手前の端を塗りつぶす"},
         {"depthsort (Newell's tests): the blue triangle's near end hides the orange one's top; "
          "the two do not touch",
          "depthsort（Newellらの判定）：青い三角形の手前の端がオレンジの上部を隠す（2枚は交わら"
          "ない）"}},
        {"Fig 4.9a",
         "depth-sort-cyclic.json",
         {"depthsort-naive: three bars in cyclic overlap; any order of whole bars gets one "
          "crossing wrong",
          "三すくみの場合（depthsort-naive）：どの順に描いても1か所の重なりが誤る"},
         {"depthsort: one bar is split, which breaks the cycle",
          "depthsort：1本を分割して循環を断つ"}},
        {"Fig 4.9b",
         "depth-sort-piercing.json",
         {"depthsort-naive: two triangles piercing each other; one is painted whole over the "
          "other",
          "貫通している場合（depthsort-naive）：一方が他方の上に丸ごと描かれる"},
         {"depthsort: split along the line where they meet", "depthsort：交線で分割する"}}};
    for (const auto& [fig, file, naive, right] : sorts) {
        g.scene_files[file] = resized(repository_scene(file), g.width / 2, g.width / 2);
        const std::string stem = fs::path(file).stem().string();
        g.add(s, fig, naive, stem + "-naive.png", file, {"-m", "depthsort-naive"});
        g.add(s, fig, right, stem + ".png", file, {"-m", "depthsort"});
    }
    g.add(s, "Fig 4.9a",
          {"depthsort's paint order (--aov paint-order): the polygon each pixel shows, by when "
           "it was painted; stripes mark pieces of the split bar",
           "depthsort の描画順（--aov paint-order）：各画素に見えるポリゴンを描いた順に色分け"
           "（縞は分割された棒の断片）"},
          "depth-sort-cyclic-paint-order.png", "depth-sort-cyclic.json",
          {"-m", "depthsort", "--aov", "paint-order"})
        .make = [](const Gallery& g, Figure& f) {
        render_with_legend(g, f, {"painted first", "最初に描画"}, {"painted last", "最後に描画"});
    };
    g.files["u-polygon.obj"] = concave_polygon_obj();
    g.scene_files["depth-sort-concave.json"] = concave_polygon_scene("u-polygon.obj", g.width);
    g.add(s, "Fig 4.9c",
          {"depthsort-naive: a concave polygon (a U, ONE polygon) and a blue bar through its "
           "notch. The U's centroid is nearer than the bar, so the whole U is painted after the "
           "bar and hides it behind the right arm too, where the bar lies in front",
           "凹ポリゴンの場合（depthsort-naive）：U字形の1枚のポリゴンと切れ込みを通る青い棒。Uの"
           "重心の方が近いのでU全体が棒の後に描かれ、棒が手前にある右腕の所まで棒を隠す"},
          "depth-sort-concave-naive.png", "depth-sort-concave.json", {"-m", "depthsort-naive"});
    g.add(s, "Fig 4.9c",
          {"depthsort: the bar in front of the right arm, behind the left",
           "depthsort：棒は右腕の手前、左腕の奥"},
          "depth-sort-concave.png", "depth-sort-concave.json", {"-m", "depthsort"});
}

void plan_hidden_surfaces(Gallery& g) {
    const Text s = {"Alg 4.1, 4.2, Fig 4.14: scanline and Z-buffer",
                    "アルゴリズム4.1, 4.2, 図4.14: スキャンライン法とZバッファ法"};
    g.add(s, "Alg 4.1", {"scanline hidden-surface removal", "スキャンライン法による隠面消去"},
          "alg4-1-scanline.png", "model.json", {"-m", "scanline", "--shadows", "none"});
    g.add(s, "Alg 4.2", {"Z-buffer hidden-surface removal", "Zバッファ法による隠面消去"},
          "alg4-2-zbuffer.png", "model.json", {"-m", "zbuffer", "--shadows", "none"})
        .make = render_zbuffer;
    g.add(s, "Alg 4.2",
          {"overdraw: fragments depth-tested per pixel (--aov overdraw)",
           "オーバードロー：画素ごとの奥行き比較の回数（--aov overdraw）"},
          "alg4-2-overdraw.png", "model.json", {"-m", "zbuffer", "--aov", "overdraw"})
        .make = [](const Gallery& g, Figure& f) {
        render_with_legend(g, f, {"1 fragment", "1回"}, {"{:.0f} fragments", "{:.0f}回"});
    };
    g.add(s, "Fig 4.14",
          {"the Z-buffer itself: eye distance per pixel, near white, far black",
           "Zバッファの中身：画素ごとの視点からの距離（近：白、遠：黒）"},
          "fig4-14-depth.png", "model.json", {"-m", "zbuffer", "--aov", "depth"})
        .make = render_depth;
    g.add(s, "Fig 4.14", {"the frame buffer beside it", "同じ視点のフレームバッファ"},
          "fig4-14-frame.png", "model.json", {"-m", "zbuffer", "--shadows", "none"});
}

void plan_shading(Gallery& g) {
    const Text s = {"Fig 4.29, 4.39: the shading model", "図4.29, 4.39: 陰影付けのモデル"};
    const std::vector<std::tuple<std::string, Text>> terms = {
        {"ambient", {"(a) ambient only: ka·Ia (--aov ambient)", "(a) 環境光による反射 ka·Ia"}},
        {"diffuse", {"(b) diffuse only: I·kd·cos α (--aov diffuse)", "(b) 拡散反射光 I·kd·cos α"}},
        {"specular",
         {"(c) specular only: I·ks·cos^n γ (--aov specular)", "(c) 鏡面反射光 I·ks·cos^n γ"}}};
    const std::vector<std::string> base = {"-m", "raytrace", "--shadows", "none"};
    for (const auto& [term, title] : terms) {
        std::vector<std::string> args = base;
        args.insert(args.end(), {"--aov", term});
        g.add(s, "Fig 4.29", title, "fig4-29-" + term + ".png", "model.json", args);
    }
    g.add(s, "Fig 4.29", {"(d) their sum: the colour render", "(d) 3成分の和（通常の描画）"},
          "fig4-29-sum.png", "model.json", base)
        .make = render_term_sum;
    for (const int n : {1, 5, 20, 100}) {
        const std::string file = fmt::format("phong-n{}.json", n);
        g.scene_files[file] = phong_sphere(static_cast<float>(n), g.width);
        g.add(s, "Fig 4.39",
              {fmt::format("Phong exponent n = {}", n), fmt::format("鏡面反射の指数 n = {}", n)},
              fmt::format("fig4-39-n{}.png", n), file, {"-m", "raytrace"});
    }
}

void plan_shadows(Gallery& g, const Json& m, const PlacedModel& model) {
    const Text s = {"Fig 4.24: shading and shadows", "図4.24: シェーディングと影付け"};
    g.files["model-toward-light.obj"] = model.toward_light_obj;
    g.scene_files["model-shadows-only.json"] = shadows_only(m, "model-toward-light.obj");
    g.add(s, "Fig 4.24", {"(a) shading only", "(a) シェーディングのみ"}, "fig4-24-shading.png",
          "model.json", {"-m", "raytrace", "--shadows", "none"});
    g.add(s, "Fig 4.24",
          {"(b) shadows only: every surface in its flat colour, darker where the light is "
           "blocked (no shading: every normal faces the light, so cos α = 1)",
           "(b) 影付けのみ：各面を一様な色で塗り、光がさえぎられる所だけ暗くする（法線をすべて"
           "光源へ向け cos α = 1 とし、陰影を消す）"},
          "fig4-24-shadows.png", "model-shadows-only.json", {"-m", "raytrace"});
    g.add(s, "Fig 4.24", {"(c) both", "(c) シェーディングと影付けの両方"}, "fig4-24-both.png",
          "model.json", {"-m", "raytrace"});
}

void plan_lights(Gallery& g, const Json& m) {
    const Text s = {"Light sources and soft shadows", "光源とソフトシャドウ"};
    const Json area = {{"type", "area"},
                       {"corner", vec(-0.4f, 2.6f, 0.1f)},
                       {"edge1", vec(0.8f, 0, 0)},
                       {"edge2", vec(0, 0, 0.8f)},
                       {"radiance", vec(9, 8.6f, 8.2f)}};
    const std::vector<std::tuple<std::string, Text, Json>> lights = {
        {"point",
         {"point light (1/d²)", "点光源（1/d²）"},
         {{{"type", "point"},
           {"position", vec(0, 2.6f, 0.5f)},
           {"intensity", vec(6.5f, 6.2f, 5.8f)}}}},
        {"spot",
         {"spot light (a cone, smooth edge)", "スポットライト（円錐、なめらかな縁）"},
         {{{"type", "spot"},
           {"position", vec(0.6f, 2.8f, 1.2f)},
           {"direction", vec(-0.2f, -1, -0.35f)},
           {"intensity", vec(9, 8.6f, 8)},
           {"inner_angle", 22},
           {"outer_angle", 34}}}},
        {"directional",
         {"directional light", "平行光源"},
         {{{"type", "directional"},
           {"direction", vec(-0.3f, -1, -0.4f)},
           {"intensity", vec(1, 1, 1)}}}},
        {"area", {"area light (soft shadows)", "面光源（ソフトシャドウ）"}, Json::array({area})},
        {"environment",
         {"environment light (a constant sky)", "環境光源（一様な空）"},
         {{{"type", "environment"}, {"radiance", vec(0.3f, 0.32f, 0.36f)}}}}};
    for (const auto& [kind, title, json] : lights) {
        Json scene = with_lights(m, json);
        scene["ambient"] = vec(0.02f, 0.02f, 0.02f);
        g.scene_files["light-" + kind + ".json"] = scene;
        g.add(s, "lights", title, "light-" + kind + ".png", "light-" + kind + ".json",
              {"-m", "raytrace", "--light-samples", "64"});
    }
    const std::vector<std::pair<std::string, std::string>> modes = {
        {"map", "シャドウマッピング"},
        {"volume", "シャドウボリューム"},
        {"pcf", "シャドウマップのフィルタリング（PCF）"},
        {"pcss", "PCSS（半影の幅を推定）"},
        {"analytic", "面光源の解析的なソフトシャドウ"}};
    for (const auto& [mode, ja] : modes)
        g.add(s, "soft shadows", {"zbuffer --shadows " + mode, "Zバッファ法、" + ja},
              "soft-" + mode + ".png", "light-area.json", {"-m", "zbuffer", "--shadows", mode});
    g.add(s, "soft shadows",
          {"raytrace, 64 samples per area light", "レイトレーシング法、面光源あたり64サンプル"},
          "soft-sampled.png", "light-area.json", {"-m", "raytrace", "--light-samples", "64"});
}

void plan_ray_tracing(Gallery& g) {
    const Text s = {"Fig 4.16, 4.43: ray tracing", "図4.16, 4.43: レイトレーシング法"};
    g.scene_files["whitted.json"] =
        resized(repository_scene("whitted.json"), g.width, g.width * 9 / 16);
    g.add(s, "Fig 4.16",
          {"ray tracing: reflection, refraction, shadows", "レイトレーシング法：反射・屈折・影"},
          "fig4-16-raytrace.png", "whitted.json", {"-m", "raytrace"});
    for (const float ior : {1.0f, 1.33f, 1.5f, 2.4f}) {
        const std::string file = fmt::format("refraction-{}.json", ior);
        g.scene_files[file] = refraction_scene(ior, g.width);
        g.add(s, "Fig 4.43",
              {fmt::format("refraction, index of refraction {}", ior),
               fmt::format("屈折を考慮したレイトレーシング法、屈折率 {}", ior)},
              fmt::format("fig4-43-ior-{}.png", ior), file, {"-m", "raytrace"});
    }
}

void plan_global_illumination(Gallery& g) {
    const Text s = {"Global illumination: light that bounces (path tracing)",
                    "大域照明：反射をくり返す光（パストレーシング）"};
    for (const char* name : {"bench/cornell.json", "cornell-glass.json"})
        g.scene_files[fs::path(name).filename().string()] =
            resized(repository_scene(name), g.width / 2, g.width / 2);
    g.add(s, "GI", {"direct light only (--max-depth 0)", "直接光のみ"}, "gi-direct.png",
          "cornell.json", {"-m", "path", "--max-depth", "0"});
    g.add(s, "GI", {"with inter-reflection: 8 bounces", "相互反射（間接光）あり：8回反射"},
          "gi-path.png", "cornell.json", {"-m", "path"});
    g.add(s, "GI",
          {"glass and mirror: caustics (light focused by the glass ball, thrown by the mirror "
           "ball) traced from the light, 64 samples per pixel",
           "ガラスと鏡：コースティクス（ガラス球が集め、鏡の球が投げる光）を光源から追跡、"
           "1画素64サンプル"},
          "gi-glass.png", "cornell-glass.json", {"-m", "path"});
}

void plan_assignment(Gallery& g) {
    const Text s = {"The assignment: ray trace a sphere", "課題：球をレイトレーシングで描く"};
    const std::vector<std::tuple<std::string, Text>> stages = {
        {"assignment-1-hit-miss.json",
         {"stage 1: hit or miss (the sphere's colour wherever the ray hits it)",
          "段階1：交差判定（光線が球に当たる所を球の色で塗る）"}},
        {"assignment-2-diffuse.json",
         {"stage 2: + Lambert diffuse reflection, I_d = I0 kd cos α",
          "段階2：＋拡散反射 I_d = I0 kd cos α"}},
        {"assignment-3-specular.json",
         {"stage 3: + Phong specular reflection, I_s = I0 ks cos^n γ",
          "段階3：＋鏡面反射 I_s = I0 ks cos^n γ"}}};
    for (const auto& [stage, title] : stages) {
        g.scene_files[stage] = resized(repository_scene(stage), g.width / 2, g.width / 2);
        g.add(s, "assignment", title, fs::path(stage).stem().string() + ".png", stage,
              {"-m", "raytrace"});
    }
}

/// The frames of the turntable: a turn in 15° steps, shown at 12 per second (2 s a turn).
constexpr int k_turntable_frames = 24;
constexpr int k_turntable_fps = 12;

void plan_turntable(Gallery& g, const Json& m) {
    const Text s = {"Animation: one turn, four methods", "アニメーション：1回転を4つの手法で"};
    g.scene_files["model-turntable.json"] = closer(m, 0.7f);
    // Four panels, each half a figure wide; even sizes, which every video codec takes.
    const int width = std::max(16, g.width / 4 * 2);
    const int height = width * 3 / 4 / 2 * 2;
    g.add(s, "turntable",
          {fmt::format(
               "the camera turning once around the model ({} frames, {}° apart, looping at {} "
               "frames per second), every frame drawn from the same scene and camera by four "
               "methods, left to right: wireframe (every edge of every face), hiddenline (only "
               "the edges that are seen), zbuffer (Z-buffer, Phong shading, shadow maps) and "
               "raytrace (a ray per pixel, shadow rays)",
               k_turntable_frames, 360 / k_turntable_frames, k_turntable_fps),
           fmt::format("モデルのまわりを1周するカメラ（{} コマ、{}° ずつ、毎秒 {} "
                       "コマでくり返し）。同じシーンと視点の各コマを4つの手法で描く。左から"
                       "ワイヤフレーム（wireframe：全ての面の全ての辺）、隠線消去（hiddenline："
                       "見える辺だけ）、Zバッファ法（zbuffer：フォンの反射モデル、シャドウ"
                       "マッピング）、レイトレーシング法（raytrace：画素ごとに光線、影は"
                       "シャドウレイ）",
                       k_turntable_frames, 360 / k_turntable_frames, k_turntable_fps)},
          "turntable.gif", "model-turntable.json",
          {"-m", "wireframe,hiddenline,zbuffer,raytrace", "--line-color", "0.1,0.12,0.2",
           "--side-by-side", "--turntable", std::to_string(k_turntable_frames), "--fps",
           std::to_string(k_turntable_fps), "--width", std::to_string(width), "--height",
           std::to_string(height)});
    g.figures.back().make = render_turntable;
    g.figures.back().wide = true;
}

}  // namespace

void plan(Gallery& g, const PlacedModel& model) {
    const Json m = model_scene(model, g.width);
    g.scene_files["model.json"] = m;
    plan_fig41(g, m);
    plan_culling(g);
    plan_depth_sort(g);
    plan_hidden_surfaces(g);
    plan_shading(g);
    plan_shadows(g, m, model);
    plan_lights(g, m);
    plan_ray_tracing(g);
    plan_global_illumination(g);
    plan_assignment(g);
    plan_turntable(g, m);
}

void render_figure(const Gallery& g, Figure& f) {
    if (f.make)
        f.make(g, f);
    else
        render_plain(g, f);
}

}  // namespace hikari::gallery
