#include <fmt/format.h>

#include "hikari/explain/explain.h"
#include "hikari/raster/tessellate.h"
#include "hikari/raster/vertex_pipeline.h"

namespace hikari {

namespace {

/// At most this many objects get a vertex carried through the matrices.
constexpr size_t k_max_objects_shown = 8;

std::string matrix_text(std::string_view name, std::string_view meaning, const Mat4& m) {
    std::string out = fmt::format("{} ({}):\n", name, meaning);
    for (const auto& row : m.m)
        out += fmt::format("  [{:12.5f} {:12.5f} {:12.5f} {:12.5f}]\n", row[0], row[1], row[2],
                           row[3]);
    return out;
}

std::string vertex_text(const RasterView& view, std::string_view what, Vec3 p) {
    const Vec4 camera = view.view_from_world * Vec4(p, 1.0f);
    const Vec4 clip = view.clip_from_view * camera;
    std::string out =
        fmt::format("{}:\n  p_w        = ({:.4f}, {:.4f}, {:.4f}, 1)\n", what, p.x, p.y, p.z);
    out += fmt::format("  M p_w      = ({:.4f}, {:.4f}, {:.4f}, {:.4f})  camera coordinates\n",
                       camera.x, camera.y, camera.z, camera.w);
    out += fmt::format("  P M p_w    = ({:.4f}, {:.4f}, {:.4f}, {:.4f})  clip coordinates\n",
                       clip.x, clip.y, clip.z, clip.w);
    if (!(clip.w > 0.0f) || clip.z < -clip.w) {
        out += "  behind the near plane: clipped before the division by w\n";
        return out;
    }
    const Vec3 ndc = clip.xyz() / clip.w;
    const Vec3 screen = transform_point(view.screen_from_clip, ndc);
    out += fmt::format("  / w        = ({:.4f}, {:.4f}, {:.4f})  normalized device coordinates\n",
                       ndc.x, ndc.y, ndc.z);
    out += fmt::format("  p_s = V ·  = ({:.2f}, {:.2f})  pixels (depth key {:.6f})\n", screen.x,
                       screen.y, view.depth_key(p, 1.0f / clip.w));
    return out;
}

}  // namespace

std::string explain_matrices(const Scene& scene, const RasterSettings& raster) {
    const RasterScene rs = tessellate_scene(scene);
    const RasterView view = make_raster_view(scene.camera, rs, raster.sample_offset);
    std::string out = fmt::format(
        "p_s = V P M p_w (Fig 4.2): world coordinates p_w to screen coordinates p_s, {}x{} "
        "pixels, {} projection\n",
        scene.camera.width, scene.camera.height,
        view.orthographic ? "orthographic (parallel)" : "perspective");
    out += matrix_text("M", "model-view: world to camera coordinates, the camera looking down -z",
                       view.view_from_world);
    out += matrix_text(
        "P",
        view.orthographic
            ? fmt::format("orthographic projection, near {:.4g}, far {:.4g}", 0.0f, view.far_plane)
            : fmt::format("perspective projection, fov_y {:.4g} deg, near {:.4g}, far {:.4g}",
                          scene.camera.fov_y_degrees, view.near_plane, view.far_plane),
        view.clip_from_view);
    out += matrix_text("V", "viewport: after the division by w, NDC [-1, 1] to pixels, y down",
                       view.screen_from_clip);
    size_t shown = 0;
    for (const Sphere& s : scene.spheres) {
        if (shown++ == k_max_objects_shown) break;
        out += vertex_text(view, fmt::format("sphere (primitive {}), its top point", s.id),
                           s.center + Vec3(0.0f, s.radius, 0.0f));
    }
    for (const Plane& p : scene.planes) {
        if (shown++ >= k_max_objects_shown) break;
        out += vertex_text(view, fmt::format("plane (primitive {}), its point", p.id), p.point);
    }
    const TriangleSet& t = scene.triangles;
    PrimitiveId previous = UINT32_MAX;
    for (size_t i = 0; i < t.size() && shown < k_max_objects_shown; ++i) {
        // One vertex per run of consecutive ids that starts a new object is not known after
        // loading; the first triangle and each one after a sphere or plane id gap stand in.
        if (previous != UINT32_MAX && t.id[i] == previous + 1) {
            previous = t.id[i];
            continue;
        }
        previous = t.id[i];
        ++shown;
        out += vertex_text(view, fmt::format("triangle (primitive {}), its first corner", t.id[i]),
                           t.positions[t.indices[i][0]]);
    }
    return out;
}

}  // namespace hikari
