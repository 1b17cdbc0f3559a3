// A session's scene written back out with another camera (session/scene_document.h): the file
// renders exactly what the session renders with that camera, wherever the scene lies.
#include "hikari/session/scene_document.h"

#include <gtest/gtest.h>

#include <string>

namespace hikari {
namespace {

RenderRequest zbuffer_view(const Camera& camera) {
    RenderRequest request;
    request.method = "zbuffer";
    request.camera = camera;
    request.film = FilmFormat::srgb8;
    return request;
}

/// Whether the scene file of `session` with `camera` renders what the session does.
void expect_same_view(Session& session, const Camera& camera) {
    const nlohmann::json doc = scene_document(session.source(), camera);
    Session copy(SceneSource{.file = "view.json", .json_text = doc.dump(), .base_dir = "/"});
    const RenderResult a = session.render(zbuffer_view(camera));
    const RenderResult b = copy.render(zbuffer_view(camera));
    EXPECT_EQ(a.framebuffer.film.srgb8().bytes, b.framebuffer.film.srgb8().bytes) << doc.dump();
}

TEST(SceneDocument, AViewOfASceneFileWithOverridesRendersAsTheSession) {
    SceneSource source{.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/teapot.json"};
    source.overrides.push_back({"camera.fov_y=30", "camera.fov_y", 30});
    source.crease_angle = 10.0f;
    Session session(source);
    Camera camera = session.scene().camera;
    camera.eye = {1.7f, 0.9f, -2.3f};
    camera.width = 64;
    camera.height = 40;
    expect_same_view(session, camera);
}

TEST(SceneDocument, AViewOfASceneFarFromTheOriginRendersAsTheSession) {
    const std::string far = R"({
      "camera": {"eye": [1000000.3, 2, 1000004], "look_at": [1000000.3, 0.5, 1000000],
                 "width": 48, "height": 32},
      "lights": [{"type": "point", "position": [1000002, 5, 1000003], "intensity": [20, 20, 20]}],
      "objects": [{"type": "sphere", "center": [1000000.3, 0.5, 1000000], "radius": 0.5},
                  {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]})";
    Session session(SceneSource{.file = "far.json", .json_text = far});
    Camera camera = session.scene().camera;
    camera.eye = camera.eye + Vec3{0.4f, 0.3f, 0.0f};
    expect_same_view(session, camera);
}

TEST(SceneDocument, AModelFileBecomesTheDocumentItIsShownBy) {
    Session session(
        SceneSource{.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/models/vertex-colours.obj",
                    .ground = true});
    Camera camera = session.scene().camera;
    camera.fov_y_degrees = 25.0f;
    camera.width = 40;
    camera.height = 40;
    expect_same_view(session, camera);
    const nlohmann::json doc = scene_document(session.source(), camera);
    EXPECT_EQ(doc["camera"]["fov_y"], 25.0);
}

}  // namespace
}  // namespace hikari
