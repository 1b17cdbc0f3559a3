// A render session keeps its shadow maps (raster/shadow_map.h shadow_maps_for_render): a render
// with the camera moved draws none and gives the image a fresh session gives; a light that
// moves has its map drawn again, one that only changes colour keeps it.
#include <gtest/gtest.h>

#include <string>

#include "../raster/raster_test_util.h"
#include "../support/same_bits.h"
#include "hikari/io/scene/scene_overrides.h"
#include "hikari/session/session.h"

namespace hikari {
namespace {

/// A box and a sphere on a floor (a plane and a square of triangles), lit by `light`.
SceneSource scene_lit_by(const std::string& light) {
    SceneSource source;
    source.file = "shadows.json";
    source.json_text = R"({
        "camera": {"eye": [2.5, 3, 5], "look_at": [0, 0.4, 0], "fov_y": 45, "width": 80, "height": 60},
        "ambient": [0.1, 0.1, 0.1],
        "materials": {"m": {"ka": [1, 1, 1], "kd": [0.7, 0.7, 0.7], "ks": [0.2, 0.2, 0.2]}},
        "lights": [)" + light +
                       R"(],
        "objects": [
          {"type": "plane", "point": [0, -0.01, 0], "normal": [0, 1, 0], "material": "m"},
          {"type": "triangle", "vertices": [[-3, 0, -3], [-3, 0, 3], [3, 0, 3]], "material": "m"},
          {"type": "triangle", "vertices": [[-3, 0, -3], [3, 0, 3], [3, 0, -3]], "material": "m"},
          {"type": "sphere", "center": [0.8, 0.5, 0.6], "radius": 0.5, "material": "m"},
          )" + testing::box({-1, 0, -0.8f}, {-0.2f, 1.2f, 0}) +
                       "]}";
    return source;
}

const std::string k_point =
    R"({"type": "point", "position": [1, 4, 2], "intensity": [14, 14, 14]})";
const std::string k_spot =
    R"({"type": "spot", "position": [0.5, 4, 1.5], "direction": [-0.1, -1, -0.3],
        "intensity": [16, 16, 16], "inner_angle": 25, "outer_angle": 40})";
const std::string k_directional =
    R"({"type": "directional", "direction": [-0.4, -1, -0.5], "intensity": [0.9, 0.9, 0.9]})";

RenderRequest zbuffer(ShadowMode shadows, Interpolation interp = Interpolation::phong) {
    RenderRequest request;
    request.method = "zbuffer";
    request.options.shadows = shadows;
    request.options.raster.interp = interp;
    request.options.raster.shadow_map_size = 256;
    return request;
}

/// `request` with the scene's camera moved up and to the side.
RenderRequest moved(const Session& session, RenderRequest request) {
    Camera camera = session.scene().camera;
    camera.eye = camera.eye + Vec3{-2.0f, 0.5f, 1.0f};
    request.camera = camera;
    return request;
}

bool same_image(const RenderResult& a, const RenderResult& b) {
    const auto& x = a.framebuffer.film.linear().pixels;
    const auto& y = b.framebuffer.film.linear().pixels;
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
        if (!testing::same_bits(x[i], y[i])) return false;
    return true;
}

TEST(SessionShadowMaps, ACameraMoveDrawsNoMapAndRendersWhatAFreshSessionRenders) {
    for (const std::string& light : {k_point, k_spot, k_directional})
        for (const ShadowMode mode : {ShadowMode::map, ShadowMode::pcf, ShadowMode::pcss}) {
            SCOPED_TRACE(light + " mode " + std::to_string(static_cast<int>(mode)));
            Session session(scene_lit_by(light));
            const RenderResult first = session.render(zbuffer(mode));
            EXPECT_GT(first.stats->shadow_map_faces.load(), 0u);
            EXPECT_EQ(first.stats->shadow_maps_kept.load(), 0u);
            const RenderRequest request = moved(session, zbuffer(mode));
            const RenderResult second = session.render(request);
            EXPECT_EQ(second.stats->shadow_map_faces.load(), 0u);
            EXPECT_EQ(second.stats->shadow_maps_kept.load(), 1u);
            Session fresh(scene_lit_by(light));
            const RenderResult expected = fresh.render(request);
            EXPECT_GT(expected.stats->shadow_map_faces.load(), 0u);
            EXPECT_TRUE(same_image(second, expected));
            EXPECT_FALSE(same_image(second, first));
        }
}

TEST(SessionShadowMaps, TessellatedSpheresThatFollowTheCameraAreDrawnAgain) {
    // Under Gouraud shading the sphere is tessellated by its size on screen: moving the camera
    // closer changes its polygons, so the map of them cannot be kept.
    Session session(scene_lit_by(k_point));
    session.render(zbuffer(ShadowMode::map, Interpolation::gouraud));
    RenderRequest closer = zbuffer(ShadowMode::map, Interpolation::gouraud);
    Camera camera = session.scene().camera;
    camera.eye = camera.look_at + 0.3f * (camera.eye - camera.look_at);
    closer.camera = camera;
    const RenderResult second = session.render(closer);
    EXPECT_GT(second.stats->shadow_map_faces.load(), 0u);
    EXPECT_TRUE(same_image(second, Session(scene_lit_by(k_point)).render(closer)));
}

TEST(SessionShadowMaps, AMovedLightIsDrawnAgainAndAColourChangeIsNot) {
    for (const std::string& light : {k_point, k_spot, k_directional}) {
        SCOPED_TRACE(light);
        Session session(scene_lit_by(light));
        const RenderResult before = session.render(zbuffer(ShadowMode::pcf));
        const std::string edits[] = {light == k_directional ? "lights[0].direction=[0.5,-1,-0.2]"
                                                            : "lights[0].position=[-1.5,3,1]",
                                     light == k_directional ? "lights[0].intensity=[0.5,0.6,0.9]"
                                                            : "lights[0].intensity=[9,10,14]"};
        SceneSource edited = scene_lit_by(light);
        for (const std::string& edit : edits) {
            session.set(parse_scene_override(edit));
            edited.overrides.push_back(parse_scene_override(edit));
            const RenderResult after = session.render(zbuffer(ShadowMode::pcf));
            const bool moved_light = &edit == &edits[0];
            EXPECT_EQ(after.stats->shadow_map_faces.load() > 0, moved_light) << edit;
            EXPECT_EQ(after.stats->shadow_maps_kept.load(), moved_light ? 0u : 1u) << edit;
            EXPECT_FALSE(same_image(after, before)) << edit;
            EXPECT_TRUE(same_image(after, Session(edited).render(zbuffer(ShadowMode::pcf))))
                << edit;
        }
        // The geometry changed: every map is drawn again.
        session.set(parse_scene_override("objects[3].radius=0.6"));
        EXPECT_GT(session.render(zbuffer(ShadowMode::pcf)).stats->shadow_map_faces.load(), 0u);
    }
}

}  // namespace
}  // namespace hikari
