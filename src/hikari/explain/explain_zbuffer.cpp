#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/explain/explain.h"
#include "hikari/explain/primitive_names.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {

namespace {

std::string depth_text(float z) { return std::isinf(z) ? "∞" : fmt::format("{:.6f}", z); }

/// The exact spheres' fragments at pixel (x, y), drawn after the triangles as the render draws
/// them (raster/sphere_raster.h): each sphere the pixel's ray meets gives the depth key of its
/// nearer root, tested against Z(i,j) in sphere order. Returns the lines; `seen` becomes the
/// visible sphere's name when one wins, `stored` the final Z(i,j).
std::string sphere_fragments(const ProjectedScene& ps, const Camera& camera,
                             const PrimitiveNames& names, int x, int y, float& stored,
                             std::string& seen, size_t& number) {
    std::string out;
    const PixelRays rays = camera_pixel_rays(camera, ps.view);
    for (const Sphere& sphere : ps.scene.spheres) {
        Ray ray;
        const float t = pixel_sphere_hit(rays, sphere, x, y, ray);
        if (!(t == t)) continue;
        // The depth key the triangles carry: clip w, or 1 / (1.5 − 0.5 z_ndc) in a parallel view.
        const Vec4 clip = ps.view.clip_from_world * Vec4(ray.at(t), 1.0f);
        const float z = ps.view.orthographic ? 1.0f / (1.5f - 0.5f * clip.z / clip.w) : clip.w;
        const bool won = z < stored;
        out += fmt::format(
            "  {:>3}. exact {}: the ray meets it at t = {:.6f} (nearer root of A t² + B t + C = "
            "0): "
            "z = {}, Z(i,j) was {} -> {}\n",
            ++number, names.primitive(sphere.id), t, depth_text(z), depth_text(stored),
            won ? "nearer: written, Z(i,j) := z" : "not nearer: discarded");
        if (won) stored = z, seen = "exact " + names.primitive(sphere.id);
    }
    return out;
}

}  // namespace

std::string explain_zbuffer_pixel(const Scene& scene, const RasterSettings& raster, int x, int y) {
    if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height)
        throw InputError(fmt::format("--pixel {},{} is outside the {}x{} image", x, y,
                                     scene.camera.width, scene.camera.height));
    // The render's geometry: per-pixel (Phong) shading draws spheres exactly, flat and Gouraud
    // shading their polygons (raster/zbuffer.cpp render_zbuffer).
    const SphereGeometry geometry =
        raster.interp == Interpolation::phong ? SphereGeometry::exact : SphereGeometry::tessellated;
    const ProjectedScene ps = project_scene(scene, raster, geometry);
    std::vector<ZBufferFragment> fragments;
    const VisibilityBuffer vis = zbuffer_visibility_at(ps.triangles, scene.camera.width,
                                                       scene.camera.height, x, y, fragments);
    const PrimitiveNames names(scene);
    const size_t exact = ps.scene.spheres.size();
    std::string out = fmt::format(
        "Z-buffer (Alg 4.2) at pixel ({}, {}), centre ({}.5, {}.5)\n"
        "Z(i,j) starts at ∞; each triangle covering the centre gives a fragment of depth\n"
        "z = 1/(1/w interpolated){}; a fragment nearer than Z(i,j) (z < Z) is written.\n",
        x, y, x, y,
        ps.view.orthographic ? " (a parallel view: a monotone key, not a distance)"
                             : " (w: the depth along the view axis)");
    if (exact > 0)
        out += fmt::format(
            "{} drawn exactly, after the triangles: a sphere's depth at the pixel is the nearer "
            "root of the ray-sphere equation, not a polygon's.\n",
            exact == 1 ? "The sphere is" : fmt::format("The {} spheres are", exact));
    if (ps.triangles.empty())
        out += "No triangles; the fragments of the exact spheres its ray meets:\n";
    else
        out += fmt::format(
            "{} of {} projected triangles cover this pixel centre{}, in drawing "
            "order:\n",
            fragments.size(), ps.triangles.size(),
            exact > 0 ? " (then the exact spheres its ray meets)" : "");
    float stored = k_infinity;
    std::string seen;
    for (size_t k = 0; k < fragments.size(); ++k) {
        const ZBufferFragment& f = fragments[k];
        out += fmt::format("  {:>3}. {}: z = {}, Z(i,j) was {} -> {}\n", k + 1,
                           names.screen_triangle(ps, f.triangle), depth_text(f.depth),
                           depth_text(f.stored),
                           f.won ? "nearer: written, Z(i,j) := z" : "not nearer: discarded");
        if (f.won) stored = f.depth;
    }
    const uint32_t triangle = vis.triangle[static_cast<size_t>(y) * vis.width + x];
    if (triangle != k_no_triangle) seen = names.screen_triangle(ps, triangle);
    size_t number = fragments.size();
    out += sphere_fragments(ps, scene.camera, names, x, y, stored, seen, number);
    if (seen.empty())
        out += "Result: no fragment; the pixel shows the background.\n";
    else
        out += fmt::format("Result: {} is visible; the shading pass colours the pixel from it.\n",
                           seen);
    return out;
}

}  // namespace hikari
