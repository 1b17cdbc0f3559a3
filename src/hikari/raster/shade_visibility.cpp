#include "hikari/raster/shade_visibility.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "hikari/frame/tiles.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/shadow_map.h"
#include "hikari/raster/shadow_volume.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/tessellate.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_eval.h"
#include "hikari/shading/soft_shadows/occluders.h"
#include "hikari/shading/spherical_harmonics.h"

namespace hikari {

namespace {

struct ShadeContext {
    const Scene& scene;
    const ProjectedScene& ps;
    const TriangleSet& tris;
    Interpolation interp;
    CameraFrame frame;
    int width, height;
    LightingEnvironment lighting;
    ShadowMode shadows;                                  ///< how lights are blocked
    const ShadowMaps* shadow_maps;                       ///< the maps, for map, pcf and pcss
    const std::vector<std::vector<uint8_t>>* in_volume;  ///< per light and pixel, for volume
    const OccluderSet* occluders;                        ///< the casters, for analytic
    /// Per light: an environment light's irradiance (raster lights it unshadowed).
    const std::vector<std::optional<IrradianceSh>>* environment_sh;
    int light_samples;                              ///< specular samples per area light
    bool has_area_lights = false;                   ///< camera rays may see a light's face
    const EnvironmentLight* environment = nullptr;  ///< what pixels without a surface show
    /// The camera rays the Z-buffer drew exact spheres with (ps.scene.spheres); visibility
    /// values from ps.triangles.size() on name those spheres.
    PixelRays sphere_rays;
};

/// The exact sphere that visibility value `t` names, or null for a screen triangle.
const Sphere* sphere_named(const ShadeContext& ctx, uint32_t t) {
    const size_t first = ctx.ps.triangles.size();
    return t >= first && t - first < ctx.ps.scene.spheres.size() ? &ctx.ps.scene.spheres[t - first]
                                                                 : nullptr;
}

/// What the centre of pixel (x, y) sees of an exact sphere: the ray tracer's hit
/// (SceneIntersector::describe_hit), its normal (p − c) / r turned toward the eye.
struct SpherePixel {
    Ray ray;
    Vec3 point;
    Vec3 normal_front;
};

SpherePixel sphere_pixel(const ShadeContext& ctx, const Sphere& s, int x, int y) {
    SpherePixel out;
    float t = pixel_sphere_hit(ctx.sphere_rays, s, x, y, out.ray);
    // The Z-buffer drew the sphere here, so the ray meets it; should rounding say otherwise,
    // the ray's closest approach to the centre stands in.
    if (!(t == t)) t = std::max(0.0f, dot(s.center - out.ray.origin, out.ray.direction));
    out.point = out.ray.at(t);
    const Vec3 n = (out.point - s.center) / s.radius;
    out.normal_front = dot(n, out.ray.direction) < 0.0f ? n : -n;
    return out;
}

/// Where a pixel's shadows are decided: its visible point, face normal toward the eye, and
/// index. Every light's visibility is asked there, also when the colour is computed elsewhere
/// (at the vertices for Gouraud, the centroid for flat shading), as a GPU decides shadows per
/// fragment.
struct ShadowQuery {
    Vec3 point;
    Vec3 ng;
    size_t pixel;
};

/// The source triangle a pixel centre sees, and the centre's point on it.
struct PixelSurface {
    uint32_t src;            ///< index into ctx.tris
    Vec3 p[3];               ///< the corners, world space
    Vec3 n[3];               ///< the corners' normals
    std::array<float, 3> b;  ///< perspective-correct weights of the pixel centre
    Vec3 point;              ///< b-weighted corners
    Vec3 n_interp;           ///< b-weighted normals, not normalized
    Vec3 dir;                ///< the camera ray through the pixel centre
    Vec3 ng;                 ///< unit face normal (−dir for a degenerate triangle)
    bool entering;           ///< the ray meets the side `ng` points to
    Vec3 ng_front;           ///< `ng` turned toward the eye
    PixelUv tex;             ///< texture coordinates and their pixel derivatives
    /// The corners' vertex colours (white where the scene has none), for materials with
    /// vertex_colours.
    Vec3 c[3] = {Vec3(1.0f), Vec3(1.0f), Vec3(1.0f)};
};

/// How much of light `l` reaches the pixel's point (0 to 1), by its shadow map (filtered for
/// pcf and pcss) or stencil (planes, which no finite map or mesh volume holds, answered
/// exactly), or, for analytic shadows, by the casters themselves: the visible fraction of an
/// area light's diffuse light, a segment test toward a point or directional light. Area lights
/// are seen by maps and volumes from their centre.
float light_fraction(const ShadeContext& ctx, size_t l, const ShadowQuery& q) {
    if (ctx.shadows == ShadowMode::none) return 1.0f;
    const Light& light = ctx.scene.lights[l];
    if (ctx.shadows == ShadowMode::analytic) {
        if (const auto* area = light_as<AreaLight>(light)) {
            const float open =
                visible_light(*area, q.point, q.ng, q.ng, nullptr).cosine_solid_angle;
            if (!(open > 0.0f)) return 1.0f;
            const VisibleLight seen = visible_light(*area, q.point, q.ng, q.ng, ctx.occluders);
            return seen.cosine_solid_angle / open;
        }
        if (plane_blocks_light(ctx.scene, shadow_view(light), q.point)) return 0.0f;
        const LightSample toward = sample_light(light, q.point);
        const Vec3 ng = dot(q.ng, toward.to_light) < 0.0f ? -q.ng : q.ng;
        const Vec3 from = offset_ray_origin(q.point, ng);
        return ctx.occluders->blocks_segment(from, toward.to_light, toward.distance) ? 0.0f : 1.0f;
    }
    const LightShadowView view = shadow_view(light);
    if (plane_blocks_light(ctx.scene, view, q.point)) return 0.0f;
    if (ctx.shadows == ShadowMode::volume) return (*ctx.in_volume)[l][q.pixel] == 0 ? 1.0f : 0.0f;
    const auto& map = ctx.shadow_maps->lights[l];
    if (!map) return 1.0f;
    // The normal offset moves the lookup off the surface on the light's side.
    const Vec3 to_light = sample_light(light, q.point).to_light;
    const Vec3 n = dot(q.ng, to_light) < 0.0f ? -q.ng : q.ng;
    switch (ctx.shadows) {
        case ShadowMode::pcf:
            return pcf_shadow_fraction(*map, q.point, n);
        case ShadowMode::pcss:
            return pcss_shadow_fraction(*map, q.point, n, view.radius);
        default:
            return lit_in_shadow_map(*map, q.point, n) ? 1.0f : 0.0f;
    }
}

/// Area and environment lights in the rasterizer: an area light's diffuse term in closed form
/// over the whole light and its specular term sampled over it, both times the pixel's
/// light_fraction; an environment light's irradiance from its spherical harmonics, times kd
/// (unshadowed, no highlight).
struct RasterExtendedLights {
    const ShadeContext& ctx;
    const ShadowQuery& query;

    template <class Visible>
    Vec3 operator()(size_t l, const Light& light, const SurfacePoint<float>& s,
                    const MaterialSample<float>& m, bool specular, Visible&, int32_t&) const {
        if (const auto* area = light_as<AreaLight>(light)) {
            const float fraction = light_fraction(ctx, l, query);
            if (!(fraction > 0.0f)) return Vec3(0.0f);
            const VisibleLight whole =
                visible_light(*area, s.position, s.normal, s.normal, nullptr);
            return fraction *
                   area_light_reflection(*area, whole, l, s, m, specular, ctx.light_samples);
        }
        const std::optional<IrradianceSh>& sh = (*ctx.environment_sh)[l];
        return sh ? m.kd * sh->irradiance(s.normal) : Vec3(0.0f);
    }
};

/// The material at `p` (its texture applied) lit by every light that reaches the pixel of
/// `shadow`.
Vec3 shade_point(const ShadeContext& ctx, uint32_t material, Vec3 p, Vec3 n, Vec3 to_eye,
                 const PixelUv& tex, Vec3 vertex_colour, const ShadowQuery& shadow) {
    SurfacePoint<float> s;
    s.position = p;
    s.normal = n;
    s.geometric_normal = n;
    s.to_eye = to_eye;
    s.u = tex.uv.x, s.v = tex.uv.y;
    s.du_dx = tex.du_dx, s.dv_dx = tex.dv_dx, s.du_dy = tex.du_dy, s.dv_dy = tex.dv_dy;
    s.dp_dx = tex.dp_dx, s.dp_dy = tex.dp_dy;
    s.vertex_colour = vertex_colour;
    const MaterialSample<float> m =
        evaluate_material<float>(ctx.scene.materials.data(), static_cast<int32_t>(material), s);
    const auto lit = [&](size_t l, const LightSample&, const SurfacePoint<float>&, bool) {
        return light_fraction(ctx, l, shadow);
    };
    return direct_lighting<float>(ctx.lighting, s, m, true, lit, RasterExtendedLights{ctx, shadow})
        .colour;
}

/// `n` turned to the side of `ng_front` (the face normal facing the viewer), as the ray tracer
/// does: a normal interpolated to face away falls back to the face normal.
Vec3 facing(Vec3 n, bool entering, Vec3 ng_front, Vec3 view_dir) {
    const float len2 = dot(n, n);
    if (!(len2 > 0.0f)) return ng_front;
    n = (entering ? n : -n) / std::sqrt(len2);
    return dot(n, view_dir) > 0.0f ? ng_front : n;
}

/// Where the camera ray of pixel (x + dx, y + dy) meets the plane through `p` with normal `n`,
/// less p: the point's step per pixel on the surface (0 where that ray runs along the plane).
Vec3 tangent_plane_step(const ShadeContext& ctx, Vec3 p, Vec3 n, int x, int y, int dx, int dy) {
    const Ray r = camera_ray(ctx.frame, x + dx + 0.5f, y + dy + 0.5f);
    const float denominator = dot(n, r.direction);
    if (denominator == 0.0f) return Vec3(0.0f);
    const Vec3 step = r.at(dot(p - r.origin, n) / denominator) - p;
    return std::isfinite(step.x + step.y + step.z) ? step : Vec3(0.0f);
}

/// --stats: the shadow pass's time, and the maps' faces and texels or the volumes' stencils.
/// (The maps count what they draw themselves: shadow_maps_for_render.)
void report_shadow_pass(const std::vector<std::vector<uint8_t>>& in_volume,
                        std::chrono::steady_clock::time_point start, RenderStats& stats) {
    const auto elapsed = std::chrono::steady_clock::now() - start;
    stats.shadow_pass_us += std::chrono::duration_cast<std::chrono::microseconds>(elapsed).count();
    for (const std::vector<uint8_t>& stencil : in_volume)
        if (!stencil.empty()) ++stats.shadow_volume_stencils;
}

/// What the centre of pixel (x, y) sees of source triangle `src`.
PixelSurface surface_at(const ShadeContext& ctx, uint32_t src, int x, int y) {
    PixelSurface s;
    s.src = src;
    const auto& idx = ctx.tris.indices[src];
    for (int k = 0; k < 3; ++k) {
        s.p[k] = ctx.tris.positions[idx[k]];
        s.n[k] = ctx.tris.normals[idx[k]];
    }
    // Perspective-correct weights of the pixel centre on the source triangle.
    const double ndc_x = 2.0 * (x + 0.5) / ctx.width - 1.0;
    const double ndc_y = 1.0 - 2.0 * (y + 0.5) / ctx.height;
    s.b = {1.0f / 3, 1.0f / 3, 1.0f / 3};
    perspective_barycentrics(ctx.ps.clip_positions[idx[0]], ctx.ps.clip_positions[idx[1]],
                             ctx.ps.clip_positions[idx[2]], ndc_x, ndc_y, s.b);
    s.point = s.b[0] * s.p[0] + s.b[1] * s.p[1] + s.b[2] * s.p[2];
    s.n_interp = s.b[0] * s.n[0] + s.b[1] * s.n[1] + s.b[2] * s.n[2];
    // Texture coordinates where a texture will read them.
    if (!ctx.tris.uvs.empty() && ctx.scene.materials[ctx.tris.material[src]].texture) {
        const std::array<Vec4, 3> clip{ctx.ps.clip_positions[idx[0]], ctx.ps.clip_positions[idx[1]],
                                       ctx.ps.clip_positions[idx[2]]};
        s.tex =
            perspective_uv(clip, {ctx.tris.uvs[idx[0]], ctx.tris.uvs[idx[1]], ctx.tris.uvs[idx[2]]},
                           ndc_x, ndc_y, ctx.width, ctx.height);
    }
    if (ctx.scene.materials[ctx.tris.material[src]].texture) {
        const Vec3 n = face_normal(s.p[0], s.p[1], s.p[2]);
        s.tex.dp_dx = tangent_plane_step(ctx, s.point, n, x, y, 1, 0);
        s.tex.dp_dy = tangent_plane_step(ctx, s.point, n, x, y, 0, 1);
    }
    if (!ctx.tris.colors.empty() && ctx.scene.materials[ctx.tris.material[src]].vertex_colours)
        for (int k = 0; k < 3; ++k) s.c[k] = ctx.tris.colors[idx[k]];
    s.dir = camera_ray(ctx.frame, x + 0.5f, y + 0.5f).direction;

    // Two-sided, as in the ray tracer: the side the eye sees is the front.
    s.ng = face_normal(s.p[0], s.p[1], s.p[2]);
    const float ng_len = length(s.ng);
    s.ng = ng_len > 0.0f ? s.ng / ng_len : -s.dir;
    s.entering = dot(s.ng, s.dir) < 0.0f;
    s.ng_front = s.entering ? s.ng : -s.ng;
    return s;
}

/// The colour of `s`, seen at `pixel`, interpolated as ctx.interp says. Textures are looked up
/// at the pixel in every mode (flat and Gouraud light the corners but texture the pixel, as
/// texture modulation over Gouraud shading does), so they stay sharp; so are shadows.
Vec3 shade_surface(const ShadeContext& ctx, const PixelSurface& s, size_t pixel) {
    const uint32_t m = ctx.tris.material[s.src];
    const ShadowQuery shadow{s.point, s.ng_front, pixel};
    switch (ctx.interp) {
        case Interpolation::flat: {  // one colour per polygon, at its centroid
            const Vec3 c = (s.p[0] + s.p[1] + s.p[2]) / 3.0f;
            return shade_point(ctx, m, c, s.ng_front, toward_viewer(ctx.frame, c), s.tex,
                               (s.c[0] + s.c[1] + s.c[2]) / 3.0f, shadow);
        }
        case Interpolation::gouraud: {  // shade the vertices, blend the colours
            Vec3 colour(0.0f);
            for (int k = 0; k < 3; ++k) {
                const Vec3 to_eye = toward_viewer(ctx.frame, s.p[k]);
                const Vec3 nk = facing(s.n[k], s.entering, s.ng_front, -to_eye);
                colour += s.b[k] * shade_point(ctx, m, s.p[k], nk, to_eye, s.tex, s.c[k], shadow);
            }
            return colour;
        }
        case Interpolation::phong:  // interpolate the normal, shade the pixel
            return shade_point(ctx, m, s.point, facing(s.n_interp, s.entering, s.ng_front, s.dir),
                               -s.dir, s.tex, s.b[0] * s.c[0] + s.b[1] * s.c[1] + s.b[2] * s.c[2],
                               shadow);
    }
    return Vec3(0.0f);
}

/// What a pixel that sees no triangle shows: the environment map along its camera ray when the
/// scene has an environment light, else the background colour.
Vec3 background_at(const ShadeContext& ctx, int x, int y) {
    if (!ctx.environment) return ctx.scene.background;
    return ctx.environment->radiance_from(camera_ray(ctx.frame, x + 0.5f, y + 0.5f).direction);
}

/// The radiance of an area light's face that pixel (x, y)'s camera ray meets before eye
/// distance `depth`, if one does (the ray tracer's camera rays see the lights the same way).
std::optional<Vec3> light_face_at(const ShadeContext& ctx, int x, int y, float depth) {
    const Ray ray = camera_ray(ctx.frame, x + 0.5f, y + 0.5f);
    return light_face_seen(ctx.scene.lights, ray.origin, ray.direction, depth);
}

/// Texture coordinates of sphere `s` at `p` (normal `n`) seen by pixel (x, y), as the ray tracer
/// maps them (geometry/surface_uv.h), and how they move per pixel step: the neighbouring pixels'
/// rays meet the tangent plane at p, and the surface gradients turn those steps into uv.
PixelUv sphere_pixel_uv(const ShadeContext& ctx, const Sphere& s, Vec3 p, Vec3 n, int x, int y) {
    const SurfaceUv su = sphere_uv(s, p);
    PixelUv out;
    out.uv = su.uv;
    const auto step = [&](int dx, int dy) {
        const Ray r = ctx.sphere_rays.at(x + dx, y + dy);
        const float denominator = dot(n, r.direction);
        return denominator == 0.0f ? Vec3(0.0f) : r.at(dot(p - r.origin, n) / denominator) - p;
    };
    const Vec3 along_x = step(1, 0), along_y = step(0, 1);
    out.dp_dx = along_x, out.dp_dy = along_y;
    out.du_dx = dot(su.du_dp, along_x), out.dv_dx = dot(su.dv_dp, along_x);
    out.du_dy = dot(su.du_dp, along_y), out.dv_dy = dot(su.dv_dp, along_y);
    return out;
}

/// Colour and AOVs of a pixel that sees exact sphere `s`: shaded per pixel (it has no polygons
/// to be flat or Gouraud shaded) by the code that shades triangles.
void shade_sphere_pixel(const ShadeContext& ctx, const Sphere& s, int x, int y, size_t pixel,
                        Framebuffer& fb) {
    const SpherePixel sp = sphere_pixel(ctx, s, x, y);
    const float eye_distance = camera_distance(ctx.frame, sp.point);
    const std::optional<Vec3> light =
        ctx.has_area_lights ? light_face_at(ctx, x, y, eye_distance) : std::nullopt;
    if (light) {
        fb.set_color(pixel, *light);
    } else {
        const PixelUv tex = ctx.scene.materials[s.material].texture
                                ? sphere_pixel_uv(ctx, s, sp.point, sp.normal_front, x, y)
                                : PixelUv{};
        const ShadowQuery shadow{sp.point, sp.normal_front, pixel};
        fb.set_color(pixel, shade_point(ctx, s.material, sp.point, sp.normal_front,
                                        -sp.ray.direction, tex, Vec3(1.0f), shadow));
    }
    fb.depth[pixel] = eye_distance;
    fb.id[pixel] = s.id + 1;
    fb.normal[pixel] = sp.normal_front;
}

/// Colour and AOVs of every pixel of `tile`.
void shade_tile(const ShadeContext& ctx, const VisibilityBuffer& vis, const Tile& tile,
                Framebuffer& fb) {
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const size_t pixel = static_cast<size_t>(y) * ctx.width + x;
            const uint32_t t = vis.triangle[pixel];
            if (t == k_no_triangle) {
                const std::optional<Vec3> light =
                    ctx.has_area_lights ? light_face_at(ctx, x, y, k_infinity) : std::nullopt;
                fb.set_color(pixel, light ? *light : background_at(ctx, x, y));
                continue;
            }
            if (const Sphere* sphere = sphere_named(ctx, t)) {
                shade_sphere_pixel(ctx, *sphere, x, y, pixel, fb);
                continue;
            }
            const PixelSurface s = surface_at(ctx, ctx.ps.triangles[t].source, x, y);
            const float eye_distance = camera_distance(ctx.frame, s.point);
            const std::optional<Vec3> light =
                ctx.has_area_lights ? light_face_at(ctx, x, y, eye_distance) : std::nullopt;
            fb.set_color(pixel, light ? *light : shade_surface(ctx, s, pixel));
            fb.depth[pixel] = eye_distance;
            fb.id[pixel] = ctx.tris.id[s.src] + 1;
            const float nl = length(s.n_interp);
            const Vec3 sn = nl > 0.0f ? s.n_interp / nl : s.ng;
            fb.normal[pixel] = dot(sn, s.dir) < 0.0f ? sn : -sn;
        }
}

}  // namespace

void report_raster_stats(const ProjectedScene& ps, const VisibilityBuffer& vis,
                         RenderStats& stats) {
    stats.raster_triangles += ps.counts.triangles_in;
    stats.raster_culled += ps.counts.culled;
    stats.raster_clipped_away += ps.counts.clipped_away;
    stats.raster_cut += ps.counts.cut;
    stats.raster_screen_triangles += ps.triangles.size();
    stats.raster_covered_pixels += static_cast<uint64_t>(std::count_if(
        vis.triangle.begin(), vis.triangle.end(), [](uint32_t t) { return t != k_no_triangle; }));
}

namespace {

/// The eye distance of every pixel's visible point, infinity where nothing is seen.
std::vector<float> visible_depth(const ShadeContext& ctx, const VisibilityBuffer& vis) {
    std::vector<float> depth(vis.triangle.size(), k_infinity);
    for_each_tile(vis.width, vis.height, nullptr, [&](const Tile& tile) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const size_t pixel = static_cast<size_t>(y) * ctx.width + x;
                const uint32_t t = vis.triangle[pixel];
                if (t == k_no_triangle) continue;
                if (const Sphere* sphere = sphere_named(ctx, t)) {
                    depth[pixel] =
                        camera_distance(ctx.frame, sphere_pixel(ctx, *sphere, x, y).point);
                    continue;
                }
                const PixelSurface s = surface_at(ctx, ctx.ps.triangles[t].source, x, y);
                depth[pixel] = camera_distance(ctx.frame, s.point);
            }
    });
    return depth;
}

}  // namespace

namespace {

/// The vectors k_i = col_j × col_k of the columns (x, y, w) of the three clip-space corners:
/// Cramer's rule gives the point projecting to q = (ndc_x, ndc_y, 1) the weights λ_i ∝ q · k_i.
std::array<std::array<double, 3>, 3> barycentric_planes(Vec4 c0, Vec4 c1, Vec4 c2) {
    const double col[3][3] = {{c0.x, c0.y, c0.w}, {c1.x, c1.y, c1.w}, {c2.x, c2.y, c2.w}};
    std::array<std::array<double, 3>, 3> k{};
    for (int i = 0; i < 3; ++i) {
        const double* a = col[(i + 1) % 3];
        const double* b = col[(i + 2) % 3];
        k[i] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    return k;
}

double dot3(const std::array<double, 3>& a, const double (&q)[3]) {
    return a[0] * q[0] + a[1] * q[1] + a[2] * q[2];
}

}  // namespace

bool perspective_barycentrics(Vec4 c0, Vec4 c1, Vec4 c2, double ndc_x, double ndc_y,
                              std::array<float, 3>& weights) {
    const auto k = barycentric_planes(c0, c1, c2);
    const double q[3] = {ndc_x, ndc_y, 1.0};
    double l[3], sum = 0;
    for (int i = 0; i < 3; ++i) {
        l[i] = dot3(k[i], q);
        sum += l[i];
    }
    if (!(std::abs(sum) > 0.0) || !std::isfinite(sum)) return false;
    for (int i = 0; i < 3; ++i) weights[i] = static_cast<float>(l[i] / sum);
    return true;
}

PixelUv perspective_uv(const std::array<Vec4, 3>& clip, const std::array<Vec2, 3>& uv, double ndc_x,
                       double ndc_y, int width, int height) {
    const auto k = barycentric_planes(clip[0], clip[1], clip[2]);
    const double q[3] = {ndc_x, ndc_y, 1.0};
    std::array<double, 3> big_k{}, big_u{}, big_v{};
    for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a) {
            big_k[a] += k[i][a];
            big_u[a] += uv[i].x * k[i][a];
            big_v[a] += uv[i].y * k[i][a];
        }
    const double sum = dot3(big_k, q);
    PixelUv out;
    if (!(std::abs(sum) > 0.0) || !std::isfinite(sum)) return out;
    const double u = dot3(big_u, q) / sum, v = dot3(big_v, q) / sum;
    const double per_x = 2.0 / width / sum, per_y = -2.0 / height / sum;
    out.uv = {static_cast<float>(u), static_cast<float>(v)};
    out.du_dx = static_cast<float>((big_u[0] - u * big_k[0]) * per_x);
    out.dv_dx = static_cast<float>((big_v[0] - v * big_k[0]) * per_x);
    out.du_dy = static_cast<float>((big_u[1] - u * big_k[1]) * per_y);
    out.dv_dy = static_cast<float>((big_v[1] - v * big_k[1]) * per_y);
    return out;
}

Framebuffer shade_visibility(const Scene& scene, const ProjectedScene& ps,
                             const VisibilityBuffer& vis, Film film, const RenderSettings& settings,
                             const RasterSettings& raster) {
    Framebuffer fb(std::move(film), vis.width, vis.height, true);
    ShadeContext ctx{scene,
                     ps,
                     ps.scene.triangles,
                     raster.interp,
                     make_camera_frame(scene.camera),
                     vis.width,
                     vis.height,
                     {scene.lights.data(), scene.lights.size(), scene.ambient},
                     scene.lights.empty() ? ShadowMode::none : raster.shadows,
                     nullptr,
                     nullptr,
                     nullptr,
                     nullptr,
                     raster.light_samples};
    std::vector<std::optional<IrradianceSh>> environment_sh;
    for (const Light& light : scene.lights) {
        const auto* env = light_as<EnvironmentLight>(light);
        environment_sh.push_back(env ? std::optional(project_environment(*env)) : std::nullopt);
    }
    ctx.environment_sh = &environment_sh;
    ctx.sphere_rays = camera_pixel_rays(scene.camera, ps.view);
    if (scene.show_background) {
        ctx.environment = find_environment(scene.lights);
        ctx.has_area_lights = has_area_light(scene.lights);
    }
    // The shadow pass, shared by every visibility method: maps from the lights, or a stencil
    // per light counted against the depth of each pixel's visible point.
    std::shared_ptr<const ShadowMaps> maps;
    std::vector<std::vector<uint8_t>> in_volume;
    std::shared_ptr<const OccluderSet> occluders;
    const auto shadow_pass_start = std::chrono::steady_clock::now();
    if (ctx.shadows == ShadowMode::analytic) {
        occluders = shadow_occluders(scene, settings.cache);
        ctx.occluders = occluders.get();
    } else if (ctx.shadows == ShadowMode::map || ctx.shadows == ShadowMode::pcf ||
               ctx.shadows == ShadowMode::pcss) {
        // Kept by a session, or shared by supersampling's passes (raster/shadow_map.h).
        maps = shadow_maps_for_render(scene, ps.scene, raster.shadow_map_size, settings.cache,
                                      raster.shared_shadow_maps.get(), settings.stats);
        ctx.shadow_maps = maps.get();
    } else if (ctx.shadows == ShadowMode::volume) {
        const std::vector<float> depth = visible_depth(ctx, vis);
        // Shadow volumes are built from polygon silhouettes: exact spheres cast theirs through
        // their tessellation.
        std::optional<RasterScene> tessellated;
        if (!ps.scene.spheres.empty()) tessellated.emplace(tessellate_scene(scene));
        const RasterScene& volume_scene = tessellated ? *tessellated : ps.scene;
        const std::vector<uint8_t> casters = shadow_casting_triangles(scene, volume_scene);
        for (const Light& light : scene.lights) {
            if (shadow_view(light).projection == ShadowProjection::none) {
                in_volume.emplace_back();  // lit unshadowed: never asked
                continue;
            }
            const std::vector<VolumePolygon> volume =
                shadow_volume_polygons(volume_scene.triangles, casters, light);
            in_volume.push_back(stencil_shadow_mask(volume, ps.view, ctx.frame, depth));
        }
        ctx.in_volume = &in_volume;
    }
    if (settings.stats && ctx.shadows != ShadowMode::none)
        report_shadow_pass(in_volume, shadow_pass_start, *settings.stats);
    for_each_tile(vis.width, vis.height, settings.control,
                  [&](const Tile& tile) { shade_tile(ctx, vis, tile, fb); });
    return fb;
}

}  // namespace hikari
