// Each figure of `hikari gallery` shows what its caption claims (ARCHITECTURE.md principle 6):
// the naive and correct depth sorts differ where the caption says, the shading terms add up,
// depth cueing darkens the far, the walls carry no speckles, and the commands under the
// figures run as printed from a gallery moved elsewhere.

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../io/temp_dir.h"
#include "hikari/core/image.h"
#include "hikari/io/images/image_read.h"
#include "run_hikari.h"

namespace {

namespace fs = std::filesystem;
using hikari::Image;
using hikari::read_image;
using hikari::Vec3;
using hikari::testing::run_hikari;
using hikari::testing::run_shell;

/// Renders the figures `only` names into `dir` (English captions, 200 pixels wide).
void make_gallery(const fs::path& dir, const std::string& only, const std::string& lang = "en") {
    const auto r = run_hikari("gallery --width 200 --threads 2 --lang " + lang + " --only " + "'" +
                              only + "' -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
}

float max_channel_difference(Vec3 a, Vec3 b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

/// Blue (the bar, the big triangle) or orange (the U, the small triangle) in an 8-bit figure.
bool bluish(Vec3 c) { return c.z > c.x + 0.2f; }
bool orangish(Vec3 c) { return c.x > c.z + 0.2f; }

/// Pixels where `naive` shows orange and `right` shows blue, counted in columns [x0, x1).
size_t orange_over_blue(const Image& naive, const Image& right, int x0, int x1) {
    size_t n = 0;
    for (int y = 0; y < naive.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const size_t i = static_cast<size_t>(y) * naive.width + x;
            n += orangish(naive.pixels[i]) && bluish(right.pixels[i]);
        }
    return n;
}

TEST(GalleryFigures, Fig47CentroidOrderPaintsTheFarTriangleOverTheNear) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.7");
    const Image naive = read_image(dir / "depth-sort-centroid-naive.png");
    const Image right = read_image(dir / "depth-sort-centroid.png");
    // Where the blue triangle's near end hides the orange one, the naive sort shows orange.
    EXPECT_GT(orange_over_blue(naive, right, 0, naive.width), 200u);
    EXPECT_EQ(orange_over_blue(right, naive, 0, naive.width), 0u);
}

TEST(GalleryFigures, Fig49cConcavePolygonHidesTheBarBehindItsRightArm) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.9c");
    const Image naive = read_image(dir / "depth-sort-concave-naive.png");
    const Image right = read_image(dir / "depth-sort-concave.png");
    const int half = naive.width / 2;
    // The right arm: the naive sort paints the U over the bar there; the left arm: both agree.
    EXPECT_GT(orange_over_blue(naive, right, half, naive.width), 100u);
    EXPECT_EQ(orange_over_blue(naive, right, 0, half), 0u);
    EXPECT_EQ(orange_over_blue(right, naive, 0, naive.width), 0u);
}

TEST(GalleryFigures, Fig44CullingAloneDrawsHiddenEdges) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.4");
    const Image culled = read_image(dir / "fig4-4-cull-only.png");
    const Image hidden = read_image(dir / "fig4-4-hidden-line.png");
    size_t extra_ink = 0, missing_ink = 0;
    for (size_t i = 0; i < culled.pixels.size(); ++i) {
        const bool a = culled.pixels[i].x < 0.5f, b = hidden.pixels[i].x < 0.5f;
        extra_ink += a && !b;
        missing_ink += b && !a;
    }
    EXPECT_GT(extra_ink, 60u);  // the hidden face's edges
    EXPECT_LT(missing_ink, extra_ink / 4);
}

TEST(GalleryFigures, Fig41bFarIsDarkNearIsUnchanged) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.1b");
    const std::string scenes = (dir / "scenes/").string();
    for (const std::string& render : {"model.json -o " + (dir / "plain.pfm").string(),
                                      "model.json --aov depth -o " + (dir / "depth.pfm").string(),
                                      "model-depth-cue.json -o " + (dir / "cued.pfm").string()}) {
        const auto r = run_hikari("render " + scenes + render + " -m zbuffer --width 200 -q");
        ASSERT_EQ(r.status, 0) << r.output;
    }
    const Image plain = read_image(dir / "plain.pfm"), depth = read_image(dir / "depth.pfm"),
                cue = read_image(dir / "cued.pfm");
    size_t far = 0, near = 0;
    for (size_t i = 0; i < plain.pixels.size(); ++i) {
        const float d = depth.pixels[i].x;
        if (d > 6.5f) {  // beyond `far` (and a blur radius): black
            ++far;
            EXPECT_LT(cue.pixels[i].x + cue.pixels[i].y + cue.pixels[i].z, 0.05f) << i;
        } else if (d < 2.5f && d > 0) {
            ++near;
        }
    }
    EXPECT_GT(far, 500u);
    EXPECT_GT(near, 0u);
}

TEST(GalleryFigures, Fig424bShadowsOnlyIsFlatColourWithCastShadows) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.24");
    const Image shadows = read_image(dir / "fig4-24-shadows.png");
    // The same scene without shadows: every surface in its one flat colour (no shading).
    const auto flat =
        run_hikari("render " + (dir / "scenes/model-shadows-only.json").string() +
                   " -m raytrace --shadows none -q -o " + (dir / "flat.png").string());
    ASSERT_EQ(flat.status, 0) << flat.output;
    const Image colour = read_image(dir / "flat.png");
    const Vec3 model_colour(0.85f, 0.55f, 0.35f);  // the model's kd (gallery_scenes.cpp)
    size_t model = 0, model_flat = 0;
    for (const Vec3& c : colour.pixels) {
        if (!(c.x > c.z + 0.15f)) continue;
        ++model;
        model_flat += max_channel_difference(c, model_colour) < 0.02f;
    }
    EXPECT_GT(model, colour.pixels.size() / 50);
    EXPECT_GT(model_flat, model * 95 / 100);
    size_t shadowed = 0, coloured = 0, unchanged = 0;
    for (size_t i = 0; i < shadows.pixels.size(); ++i) {
        const Vec3 s = shadows.pixels[i], c = colour.pixels[i];
        shadowed += s.x + s.y + s.z < 0.6f * (c.x + c.y + c.z);
        unchanged += max_channel_difference(s, c) < 0.01f;
        coloured += s.x > s.z + 0.15f;  // the model's orange, not white on white
    }
    const size_t n = shadows.pixels.size();
    EXPECT_GT(shadowed, n / 200);
    EXPECT_GT(unchanged, n / 2);
    EXPECT_GT(coloured, n / 50);
}

TEST(GalleryFigures, Fig429TermsFromOneSceneSumToTheColour) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.29");
    const std::string scene = (dir / "scenes/model.json").string();
    Image sum;
    for (const char* aov : {"color", "ambient", "diffuse", "specular"}) {
        const fs::path out = dir / (std::string(aov) + ".pfm");
        ASSERT_EQ(run_hikari("render " + scene + " -m raytrace --shadows none --width 120 -q " +
                             "--aov " + aov + " -o " + out.string())
                      .status,
                  0);
        const Image term = read_image(out);
        if (sum.pixels.empty()) {
            sum = term;
            continue;
        }
        for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] -= term.pixels[i];
    }
    for (const Vec3& d : sum.pixels) ASSERT_LT(max_channel_difference(d, Vec3(0.0f)), 1e-4f);
    // Every figure of Fig 4.29 renders scenes/model.json: one scene.
    const std::string index = hikari::testing::read_text(dir / "index.html");
    const std::regex model_scene("render scenes/model\\.json");
    EXPECT_EQ(std::distance(std::sregex_iterator(index.begin(), index.end(), model_scene),
                            std::sregex_iterator()),
              4);
}

TEST(GalleryFigures, Fig443WallLiesMidCellOfItsSolidChecker) {
    // On a cell boundary of the solid checker (z a multiple of its size), rounding of each
    // refracted ray's hit picks either cell's colour: wrong-colour speckles on the ball's rim.
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.43");
    for (const char* ior : {"1", "1.33", "1.5", "2.4"}) {
        const std::string text =
            hikari::testing::read_text(dir / (std::string("scenes/refraction-") + ior + ".json"));
        const auto scene = nlohmann::json::parse(text);
        const float size = scene["materials"]["wall"]["texture"]["size"].get<float>();
        const float z = scene["objects"][1]["point"][2].get<float>();
        const float cells = z / size;
        EXPECT_NEAR(cells - std::floor(cells), 0.5f, 0.1f) << ior;
    }
}

TEST(GalleryFigures, Fig43CaptionsCountCulledTrianglesAndChangedPixels) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.3");
    const std::string index = hikari::testing::read_text(dir / "index.html");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(index, m, std::regex("([0-9]+) of ([0-9]+) triangles culled")));
    EXPECT_GT(std::stoi(m[1].str()), 0);
    ASSERT_TRUE(std::regex_search(index, m, std::regex("([0-9]+) pixels differ from culling on")));
    const Image a = read_image(dir / "fig4-3-cull-back.png"),
                b = read_image(dir / "fig4-3-cull-none.png");
    size_t differ = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(std::to_string(differ), m[1].str());
}

TEST(GalleryFigures, CaptionsInJapaneseUseTheLecturesTermsAndNeverRepeatTheirNumber) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "4.1a,4.1b,4.1c,4.1d,4.1e,4.1f,4.7,Alg 4.1,Alg 4.2,4.24", "ja");
    const std::string index = hikari::testing::read_text(dir / "index.html");
    for (const char* term :
         {"ワイヤフレーム", "デプスキューイング", "隠線消去", "陰影の付加", "影付け", "模様の付加",
          "奥行きソート法", "スキャンライン法", "Zバッファ法", "シャドウマッピング", "図4.7"})
        EXPECT_NE(index.find(term), std::string::npos) << term;
    EXPECT_FALSE(std::regex_search(index, std::regex("<b>([^<]+)</b>: \\1")));
    EXPECT_FALSE(std::regex_search(index, std::regex("Fig [0-9.a-z]+: Fig")));
}

TEST(GalleryFigures, CommandsRunAsPrintedFromAMovedGallery) {
    const hikari::testing::TempDir dir;
    make_gallery(dir.path() / "made", "4.9c,4.24,4.1a");  // 2 + 3 + 1 commands
    fs::rename(dir / "made", dir / "moved");  // nothing may point back into the first folder
    const std::string index = hikari::testing::read_text(dir / "moved/index.html");
    const std::regex code("<code>hikari (render [^<]+)</code>");
    size_t ran = 0;
    for (auto it = std::sregex_iterator(index.begin(), index.end(), code);
         it != std::sregex_iterator(); ++it, ++ran) {
        const std::string command = "cd '" + (dir / "moved").string() + "' && " + HIKARI_CLI_PATH +
                                    " " + (*it)[1].str() + " -q";
        const int status = std::system(command.c_str());
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    }
    EXPECT_GE(ran, 6u);
}

/// PSNR in dB of `a` against `b` (linear colour, clamped to [0, 1]; same size).
double psnr(const Image& a, const Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d =
                std::clamp(a.pixels[i][c], 0.0f, 1.0f) - std::clamp(b.pixels[i][c], 0.0f, 1.0f);
            sum += d * d;
        }
    return 10.0 * std::log10(1.0 / (sum / (3.0 * static_cast<double>(a.pixels.size()))));
}

TEST(GalleryFigures, AnalyticSoftShadowOfTheTeapotBeatsSampling) {
    // The gallery's area-light scene: the teapot's many small triangles between the floor and
    // the light (more than k_max_cut_occluders in the spout's penumbra).
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "soft shadows");
    const auto render = [&](const std::string& args, const std::string& out) {
        const auto r =
            run_hikari("render " + (dir / "scenes/light-area.json").string() +
                       " --width 160 --threads 2 -q " + args + " -o " + (dir / out).string());
        EXPECT_EQ(r.status, 0) << r.output;
        return read_image(dir / out);
    };
    // Highlights are sampled in every mode: 64 light samples each, so only the shadow differs.
    const Image reference = render("-m raytrace --light-samples 1024", "reference.pfm");
    const Image sampled = render("-m raytrace --light-samples 64", "sampled.pfm");
    const Image analytic =
        render("-m raytrace --light-samples 64 --shadows analytic", "analytic.pfm");
    const Image raster = render("-m zbuffer --light-samples 64 --shadows analytic", "raster.pfm");
    const double sampled_db = psnr(sampled, reference), analytic_db = psnr(analytic, reference);
    EXPECT_GT(analytic_db, sampled_db)
        << "ray tracing: analytic " << analytic_db << " dB, 64 samples " << sampled_db << " dB";
    // The raster pipeline computes the same visible light: it agrees with the ray tracer's
    // analytic shadow better than 64 samples agree with the converged one.
    const double raster_db = psnr(raster, analytic);
    EXPECT_GT(raster_db, sampled_db) << "zbuffer vs raytrace analytic " << raster_db << " dB";
}

/// The mean difference of two 8-bit pictures of one size, per channel in [0, 1] (display values).
double mean_difference(const Image& a, const Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        sum += max_channel_difference(a.pixels[i], b.pixels[i]);
    return sum / static_cast<double>(a.pixels.size());
}

TEST(GalleryFigures, TurntableIsALoopingGifOfTheFourMethodsSideBySide) {
    if (run_shell("command -v ffmpeg && command -v ffprobe").status != 0)
        GTEST_SKIP() << "ffmpeg and ffprobe are not installed (apt-get install ffmpeg)";
    const hikari::testing::TempDir dir;
    make_gallery(dir.path(), "turntable");
    const fs::path gif = dir / "turntable.gif";
    // 24 frames of four 100 × 74 panels (half a 200-pixel figure; even), 2 pixels apart, under a
    // 12-pixel label strip (the labels at the font's size: doubled, "hiddenline" is too wide).
    const auto probe = run_shell(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=nb_read_frames,width,height -of csv=p=0 " +
        gif.string());
    EXPECT_EQ(probe.output, "406,86,24\n");
    // It loops for ever: the NETSCAPE2.0 block with a loop count of 0.
    const std::string bytes = hikari::testing::read_text(gif);
    EXPECT_NE(bytes.find(std::string("NETSCAPE2.0\x03\x01\x00\x00", 16)), std::string::npos);
    const std::string index = hikari::testing::read_text(dir / "index.html");
    EXPECT_NE(index.find("<img src=\"turntable.gif\""), std::string::npos);
    for (const char* method : {"wireframe (", "hiddenline (", "zbuffer (", "raytrace ("})
        EXPECT_NE(index.find(method), std::string::npos) << method;
    // Frame 6 of the GIF is frame 6 of the printed command written as a PNG, up to the GIF's
    // palette and dithering; and the camera turned since frame 0.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(
        index, m, std::regex("hikari render scenes/([^ ]+) ([^<]+) -o turntable\\.gif")));
    const auto png =
        run_hikari("render " + (dir / "scenes" / m[1].str()).string() + " " + m[2].str() +
                   " --threads 2 -q --frames 0-6 -o " + (dir / "f_%d.png").string());
    ASSERT_EQ(png.status, 0) << png.output;
    const auto extract =
        run_shell("ffmpeg -v error -i " + gif.string() + " -vf 'select=eq(n\\,6)' -frames:v 1 " +
                  (dir / "gif6.png").string());
    ASSERT_EQ(extract.status, 0) << extract.output;
    const Image from_gif = read_image(dir / "gif6.png");
    const Image frame6 = read_image(dir / "f_6.png"), frame0 = read_image(dir / "f_0.png");
    ASSERT_EQ(from_gif.width, frame6.width);
    EXPECT_LT(mean_difference(from_gif, frame6), 0.01);
    EXPECT_GT(mean_difference(frame0, frame6), 0.03);
    fs::remove(dir / "gif6.png");
    for (int k = 0; k <= 6; ++k) fs::remove(dir / ("f_" + std::to_string(k) + ".png"));
    for (const auto& e : fs::directory_iterator(dir.path()))  // no temporaries left
        EXPECT_TRUE(e.path().filename() == "turntable.gif" || e.path().filename() == "index.html" ||
                    e.path().filename() == "scenes")
            << e.path();
}

TEST(GalleryFigures, TurntableWithoutFfmpegSaysHowToGetIt) {
    const hikari::testing::TempDir dir;
    fs::create_directories(dir / "empty");
    const auto r =
        run_shell("PATH=" + (dir / "empty").string() + " " + HIKARI_CLI_PATH +
                  " gallery --width 200 --threads 2 --only turntable -o " + (dir / "g").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string index = hikari::testing::read_text(dir / "g/index.html");
    EXPECT_NE(index.find("class=\"missing\""), std::string::npos);
    EXPECT_NE(index.find("sudo apt-get install ffmpeg"), std::string::npos);
    EXPECT_EQ(index.find("<img"), std::string::npos);              // no broken picture
    EXPECT_NE(index.find("-o turntable.gif"), std::string::npos);  // the command to make it
    EXPECT_FALSE(fs::exists(dir / "g/turntable.gif"));
}

}  // namespace
