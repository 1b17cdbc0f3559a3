// Image textures from files: scene JSON and MTL references, decoding, and the errors a bad
// texture gives.
#include "hikari/io/images/texture_files.h"

#include <gtest/gtest.h>

#include <variant>

#include "../../support/input_error.h"
#include "../temp_dir.h"
#include "hikari/core/error.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/models/obj_loader.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

using testing::input_error_of;
using testing::TempDir;
using testing::write_text;

/// A scene whose one material "m" has `texture` (JSON) on a sphere.
std::string scene_with_texture(const std::string& texture) {
    return R"({"materials": {"m": {"kd": [1, 1, 1], "texture": )" + texture +
           R"(}}, "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "m"}]})";
}

Scene parse_in(const TempDir& dir, const std::string& json) {
    std::vector<std::string> warnings;
    return parse_scene(json, "s.json", dir.path(), warnings);
}

const ImageTexture& image_texture_of(const Scene& scene) {
    return std::get<ImageTexture>(*scene.materials.at(0).texture);
}

TEST(TextureFiles, EightBitTexturesAreSrgbDecodedToLinear) {
    TempDir dir;
    Image image(1, 1, Vec3(0.2158605f));  // sRGB 128
    write_image(dir / "grey.png", image);
    TextureFiles files;
    const auto pyramid = files.pyramid(dir / "grey.png");
    EXPECT_NEAR(pyramid->levels[0].at(0, 0).x, 0.2158605f, 1e-6f);
    // The same file twice is read once.
    EXPECT_EQ(files.pyramid(dir / "." / "grey.png"), pyramid);
}

TEST(TextureFiles, ReadsRadianceHdr) {
    TempDir dir;
    // Two flat (not run-length encoded) RGBE pixels: (1, 0.5, 0.25) and (4, 4, 4).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
    hdr += std::string{char(128), char(64), char(32), char(129)};
    hdr += std::string{char(128), char(128), char(128), char(131)};
    write_text(dir / "sky.hdr", hdr);
    const Image image = read_image(dir / "sky.hdr");
    ASSERT_EQ(image.width, 2);
    EXPECT_FLOAT_EQ(image.at(0, 0).x, 1.0f);
    EXPECT_FLOAT_EQ(image.at(0, 0).y, 0.5f);
    EXPECT_FLOAT_EQ(image.at(0, 0).z, 0.25f);
    EXPECT_FLOAT_EQ(image.at(1, 0).y, 4.0f);
}

TEST(TextureFiles, SceneImageTextureDefaultsToRepeatTrilinear) {
    TempDir dir;
    write_image(dir / "t.png", Image(4, 2, Vec3(1.0f)));
    const Scene scene = parse_in(dir, scene_with_texture(R"({"type": "image", "file": "t.png"})"));
    const ImageTexture& t = image_texture_of(scene);
    EXPECT_EQ(t.wrap, TextureWrap::repeat);
    EXPECT_EQ(t.filter, TextureFilter::trilinear);
    EXPECT_EQ(t.pyramid->levels.size(), 3u);
    const Scene clamped = parse_in(
        dir, scene_with_texture(
                 R"({"type": "image", "file": "t.png", "wrap": "clamp", "filter": "nearest"})"));
    EXPECT_EQ(image_texture_of(clamped).wrap, TextureWrap::clamp);
    EXPECT_EQ(image_texture_of(clamped).filter, TextureFilter::nearest);
}

TEST(TextureFiles, BadSceneTexturesNameTheFileAndTheJsonPath) {
    TempDir dir;
    write_text(dir / "empty.png", "");
    write_text(dir / "text.png", "this is not a picture");
    write_text(dir / "notes.txt", "hello");
    const std::string missing = input_error_of(
        [&] { parse_in(dir, scene_with_texture(R"({"type": "image", "file": "wood.png"})")); });
    EXPECT_NE(missing.find("materials.m.texture.file"), std::string::npos) << missing;
    EXPECT_NE(missing.find("wood.png"), std::string::npos) << missing;
    for (const char* file : {"empty.png", "text.png", "notes.txt"}) {
        const std::string e = input_error_of([&] {
            parse_in(dir, scene_with_texture(std::string(R"({"type": "image", "file": ")") + file +
                                             "\"}"));
        });
        EXPECT_NE(e.find("materials.m.texture.file"), std::string::npos) << e;
        EXPECT_NE(e.find(file), std::string::npos) << e;
    }
    write_image(dir / "t.png", Image(1, 1));
    const std::string wrap = input_error_of([&] {
        parse_in(dir,
                 scene_with_texture(R"({"type": "image", "file": "t.png", "wrap": "mirror"})"));
    });
    EXPECT_NE(wrap.find("materials.m.texture.wrap"), std::string::npos) << wrap;
    const std::string filter = input_error_of([&] {
        parse_in(dir,
                 scene_with_texture(R"({"type": "image", "file": "t.png", "filter": "cubic"})"));
    });
    EXPECT_NE(filter.find("materials.m.texture.filter"), std::string::npos) << filter;
}

constexpr const char* k_textured_quad_obj =
    "mtllib sub/quad.mtl\nusemtl wood\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3 4/4\n";

TEST(TextureFiles, MtlMapKdIsRelativeToTheMtlFile) {
    TempDir dir;
    std::filesystem::create_directories(dir / "sub/maps");
    write_text(dir / "quad.obj", k_textured_quad_obj);
    write_text(dir / "sub/quad.mtl",
               "newmtl wood\nKa 1 1 1\nKd 1 1 1\nmap_Kd maps/wood.png\nmap_Ka maps\\dark.png\n");
    write_image(dir / "sub/maps/wood.png", Image(2, 2, Vec3(0.5f)));
    write_image(dir / "sub/maps/dark.png", Image(1, 1, Vec3(0.0f)));
    const MeshData mesh = load_obj(dir / "quad.obj");
    ASSERT_EQ(mesh.materials.size(), 1u);
    ASSERT_TRUE(mesh.materials[0].texture.has_value());
    const auto& kd = std::get<ImageTexture>(*mesh.materials[0].texture);
    EXPECT_EQ(kd.pyramid->levels[0].width, 2);
    ASSERT_TRUE(mesh.materials[0].ambient_texture.has_value());
    EXPECT_EQ(std::get<ImageTexture>(*mesh.materials[0].ambient_texture).file, "maps/dark.png");
}

TEST(TextureFiles, MissingMtlTextureNamesTheMtlLine) {
    TempDir dir;
    std::filesystem::create_directories(dir / "sub");
    write_text(dir / "quad.obj", k_textured_quad_obj);
    write_text(dir / "sub/quad.mtl", "# a comment\nnewmtl wood\nKd 1 1 1\nmap_Kd gone.png\n");
    const std::string e = input_error_of([&] { load_obj(dir / "quad.obj"); });
    EXPECT_NE(e.find("quad.mtl:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("gone.png"), std::string::npos) << e;
}

}  // namespace
}  // namespace hikari
