// The render session (session/session.h): one load, many renders, each the same image a fresh
// load would give, and what does not depend on the camera built once.
#include "hikari/session/session.h"

#include <gtest/gtest.h>

#include <atomic>
#include <string>

#include "../support/same_bits.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

SceneSource teapot() { return {.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/teapot.json"}; }

RenderRequest small(std::string method) {
    RenderRequest request;
    request.method = std::move(method);
    request.width = 64;
    request.height = 48;
    return request;
}

/// The linear colour of a render, for comparisons.
const auto& colour(const RenderResult& r) { return r.framebuffer.film.linear().pixels; }

/// Whether two images have the same bits, pixel for pixel.
template <class Pixels>
bool same_bits(const Pixels& a, const Pixels& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!testing::same_bits(a[i], b[i])) return false;
    return true;
}

/// `request` rendered by a session made for it alone.
RenderResult fresh_render(const SceneSource& source, const RenderRequest& request) {
    Session session(source);
    return session.render(request);
}

TEST(Session, RendersWhatAFreshLoadRenders) {
    Session session(teapot());
    for (const char* method : {"raytrace", "zbuffer", "scanline", "path"}) {
        RenderRequest request = small(method);
        request.options.samples_per_pixel = 2;
        const RenderResult kept = session.render(request);
        const RenderResult fresh = fresh_render(teapot(), request);
        EXPECT_TRUE(same_bits(colour(kept), colour(fresh))) << method;
    }
}

TEST(Session, ASecondRenderWithTheCameraMovedKeepsTheBvh) {
    Session session(teapot());
    const RenderResult first = session.render(small("raytrace"));
    EXPECT_EQ(first.stats->bvh_reused.load(), 0u);
    EXPECT_GT(first.stats->bvh_build_us.load(), 0u);
    EXPECT_GE(session.kept_structures(), 1u);

    RenderRequest moved = small("raytrace");
    Camera camera = session.scene().camera;
    camera.eye = camera.eye + Vec3{0.5f, 0.2f, 0.0f};
    moved.camera = camera;
    const RenderResult second = session.render(moved);
    EXPECT_EQ(second.stats->bvh_reused.load(), 1u);
    EXPECT_EQ(second.stats->bvh_build_us.load(), 0u);
    EXPECT_TRUE(same_bits(colour(second), colour(fresh_render(teapot(), moved))));
    EXPECT_FALSE(same_bits(colour(second), colour(first)));
    // The path tracer finds the same BVH.
    EXPECT_EQ(session.render(small("path")).stats->bvh_reused.load(), 1u);
}

TEST(Session, AChangedMaterialKeepsTheBvhAndAChangedObjectDoesNot) {
    Session session(teapot());
    const RenderResult before = session.render(small("raytrace"));
    session.set(parse_scene_override("materials.porcelain.shininess=5"));
    const RenderResult shinier = session.render(small("raytrace"));
    EXPECT_EQ(shinier.stats->bvh_reused.load(), 1u);
    EXPECT_FALSE(same_bits(colour(before), colour(shinier)));
    SceneSource edited = teapot();
    edited.overrides.push_back(parse_scene_override("materials.porcelain.shininess=5"));
    EXPECT_TRUE(same_bits(colour(shinier), colour(fresh_render(edited, small("raytrace")))));

    session.set(parse_scene_override("objects[0].point=[0,-0.1,0]"));
    EXPECT_EQ(session.render(small("raytrace")).stats->bvh_reused.load(), 0u);
}

TEST(Session, AnEditThatFailsLeavesTheSessionAsItWas) {
    Session session(teapot());
    const RenderResult before = session.render(small("zbuffer"));
    EXPECT_THROW(session.set(parse_scene_override("materials.porcelain.shininess=-1")), InputError);
    EXPECT_TRUE(same_bits(colour(before), colour(session.render(small("zbuffer")))));
}

TEST(Session, ImagesDoNotDependOnTheThreadCount) {
    Session session(teapot());
    RenderRequest one = small("zbuffer"), two = small("zbuffer");
    one.threads = 1;
    two.threads = 2;
    EXPECT_TRUE(same_bits(colour(session.render(one)), colour(session.render(two))));
}

TEST(Session, ReportsProgressAndStopsWhenCancelled) {
    Session session(teapot());
    RenderRequest endless = small("path");
    endless.options.samples_per_pixel = k_max_samples_per_pixel;
    const CancelToken token;
    endless.cancel = token;
    std::atomic<int> reports{0};
    endless.progress = [&](const RenderProgress& p) {
        EXPECT_GE(p.fraction, 0.0);
        EXPECT_LE(p.fraction, 1.0);
        ++reports;
        token.cancel();
    };
    EXPECT_THROW(session.render(endless), Interrupted);
    EXPECT_GE(reports.load(), 1);
}

TEST(Session, BadRequestsAreInputErrors) {
    Session session(teapot());
    EXPECT_THROW(session.render(small("raytracer")), InputError);
    RenderRequest term = small("path");
    term.aov = Aov::diffuse;
    EXPECT_THROW(session.render(term), InputError);
    RenderRequest spans = small("zbuffer");
    spans.aov = Aov::spans;
    EXPECT_THROW(session.render(spans), InputError);
    EXPECT_THROW(session.draw(small("zbuffer")), InputError);
    EXPECT_THROW(Session(SceneSource{.file = "no-such-scene.json"}), InputError);
}

TEST(Session, LoadsSceneTextAndDrawsLines) {
    Session session(
        SceneSource{.file = "inline.json", .json_text = R"({"camera": {"width": 32, "height": 24},
                                   "materials": {"m": {"kd": [1, 1, 1]}},
                                   "objects": [{"type": "sphere", "center": [0, 0, -3],
                                                "radius": 1, "material": "m"}]})"});
    EXPECT_EQ(session.scene().spheres.size(), 1u);
    EXPECT_EQ(session.render({}).framebuffer.width(), 32);
    RenderRequest lines;
    lines.method = "wireframe";
    EXPECT_FALSE(session.draw(lines).segments.empty());
    EXPECT_THROW(Session(SceneSource{.file = "bad.json", .json_text = "{"}), InputError);
}

}  // namespace
}  // namespace hikari
