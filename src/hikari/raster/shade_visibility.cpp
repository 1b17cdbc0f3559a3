#include "hikari/raster/shade_visibility.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "hikari/frame/tiles.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/shade_lanes.h"
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
    const SurfacePoint<float> s = pixel_surface_point(p, n, to_eye, tex, vertex_colour);
    const MaterialSample<float> m =
        evaluate_material<float>(ctx.scene.materials.data(), static_cast<int32_t>(material), s);
    const auto lit = [&](size_t l, const LightSample&, const SurfacePoint<float>&, bool) {
        return light_fraction(ctx, l, shadow);
    };
    return direct_lighting<float>(ctx.lighting, s, m, true, lit, RasterExtendedLights{ctx, shadow})
        .colour;
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

/// What every pixel of one source triangle shares: its corners and their attributes, the
/// planes of its perspective-correct weights, its face normal. Pixels of a tile mostly see the
/// triangle their neighbour saw, so the pass keeps the last one.
struct SourceTriangle {
    uint32_t src = k_no_triangle;
    Vec3 p[3], n[3];
    Vec3 c[3] = {Vec3(1.0f), Vec3(1.0f), Vec3(1.0f)};
    BarycentricPlanes planes;
    bool textured = false;
    Vec3 face;  ///< face_normal(p[0], p[1], p[2]), not normalized
    float face_length = 0;

    /// Makes this triangle `src` (nothing to do when it already is).
    void load(const ShadeContext& ctx, uint32_t source) {
        if (source == src) return;
        src = source;
        const auto& idx = ctx.tris.indices[src];
        for (int k = 0; k < 3; ++k) {
            p[k] = ctx.tris.positions[idx[k]];
            n[k] = ctx.tris.normals[idx[k]];
        }
        planes = barycentric_planes(ctx.ps.clip_positions[idx[0]], ctx.ps.clip_positions[idx[1]],
                                    ctx.ps.clip_positions[idx[2]]);
        const Material& material = ctx.scene.materials[ctx.tris.material[src]];
        textured = static_cast<bool>(material.texture);
        const bool coloured = !ctx.tris.colors.empty() && material.vertex_colours;
        for (int k = 0; k < 3; ++k) c[k] = coloured ? ctx.tris.colors[idx[k]] : Vec3(1.0f);
        face = face_normal(p[0], p[1], p[2]);
        face_length = length(face);
    }
};

/// What the centre of pixel (x, y) sees of the source triangle `tri` holds.
PixelSurface surface_at(const ShadeContext& ctx, const SourceTriangle& tri, int x, int y) {
    PixelSurface s;
    s.src = tri.src;
    for (int k = 0; k < 3; ++k) {
        s.p[k] = tri.p[k];
        s.n[k] = tri.n[k];
        s.c[k] = tri.c[k];
    }
    // Perspective-correct weights of the pixel centre on the source triangle.
    const double ndc_x = 2.0 * (x + 0.5) / ctx.width - 1.0;
    const double ndc_y = 1.0 - 2.0 * (y + 0.5) / ctx.height;
    s.b = {1.0f / 3, 1.0f / 3, 1.0f / 3};
    barycentric_weights(tri.planes, ndc_x, ndc_y, s.b);
    s.point = s.b[0] * s.p[0] + s.b[1] * s.p[1] + s.b[2] * s.p[2];
    s.n_interp = s.b[0] * s.n[0] + s.b[1] * s.n[1] + s.b[2] * s.n[2];
    if (tri.textured) {
        // Texture coordinates where a texture will read them.
        if (!ctx.tris.uvs.empty()) {
            const auto& idx = ctx.tris.indices[tri.src];
            const std::array<Vec4, 3> clip{ctx.ps.clip_positions[idx[0]],
                                           ctx.ps.clip_positions[idx[1]],
                                           ctx.ps.clip_positions[idx[2]]};
            s.tex = perspective_uv(
                clip, {ctx.tris.uvs[idx[0]], ctx.tris.uvs[idx[1]], ctx.tris.uvs[idx[2]]}, ndc_x,
                ndc_y, ctx.width, ctx.height);
        }
        s.tex.dp_dx = tangent_plane_step(ctx.frame, s.point, tri.face, x, y, 1, 0);
        s.tex.dp_dy = tangent_plane_step(ctx.frame, s.point, tri.face, x, y, 0, 1);
    }
    s.dir = camera_ray(ctx.frame, x + 0.5f, y + 0.5f).direction;

    // Two-sided, as in the ray tracer: the side the eye sees is the front.
    s.ng = tri.face_length > 0.0f ? tri.face / tri.face_length : -s.dir;
    s.entering = dot(s.ng, s.dir) < 0.0f;
    s.ng_front = s.entering ? s.ng : -s.ng;
    return s;
}

/// The same for source triangle `src`.
PixelSurface surface_at(const ShadeContext& ctx, uint32_t src, int x, int y) {
    SourceTriangle tri;
    tri.load(ctx, src);
    return surface_at(ctx, tri, x, y);
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

/// The colour (returned) and AOVs of a pixel that sees exact sphere `s`: shaded per pixel (it has
/// no polygons to be flat or Gouraud shaded) by the code that shades triangles.
Vec3 shade_sphere_pixel(const ShadeContext& ctx, const Sphere& s, int x, int y, size_t pixel,
                        Framebuffer& fb) {
    const SpherePixel sp = sphere_pixel(ctx, s, x, y);
    const float eye_distance = camera_distance(ctx.frame, sp.point);
    const std::optional<Vec3> light =
        ctx.has_area_lights ? light_face_at(ctx, x, y, eye_distance) : std::nullopt;
    Vec3 colour;
    if (light) {
        colour = *light;
    } else {
        const PixelUv tex = ctx.scene.materials[s.material].texture
                                ? sphere_pixel_uv(ctx, s, sp.point, sp.normal_front, x, y)
                                : PixelUv{};
        const ShadowQuery shadow{sp.point, sp.normal_front, pixel};
        colour = shade_point(ctx, s.material, sp.point, sp.normal_front, -sp.ray.direction, tex,
                             Vec3(1.0f), shadow);
    }
    if (!fb.depth.empty()) {
        fb.depth[pixel] = eye_distance;
        fb.id[pixel] = s.id + 1;
        fb.normal[pixel] = sp.normal_front;
    }
    return colour;
}

}  // namespace

void add_vertex_stage_stats(const ProjectedScene& ps, RenderStats& stats) {
    stats.raster_triangles += ps.counts.triangles_in;
    stats.raster_culled += ps.counts.culled;
    stats.raster_clipped_away += ps.counts.clipped_away;
    stats.raster_cut += ps.counts.cut;
    stats.raster_screen_triangles += ps.triangles.size();
}

void report_raster_stats(const ProjectedScene& ps, const VisibilityBuffer& vis,
                         RenderStats& stats) {
    add_vertex_stage_stats(ps, stats);
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

bool perspective_barycentrics(Vec4 c0, Vec4 c1, Vec4 c2, double ndc_x, double ndc_y,
                              std::array<float, 3>& weights) {
    return barycentric_weights(barycentric_planes(c0, c1, c2), ndc_x, ndc_y, weights);
}

namespace {

/// A shading pass over one frame: its context and what the context points to (the shadow
/// pass's maps, stencils or occluders, the environment lights' irradiance). Not movable: the
/// context points into it.
struct ShadePass {
    std::vector<std::optional<IrradianceSh>> environment_sh;
    std::shared_ptr<const ShadowMaps> maps;
    std::vector<std::vector<uint8_t>> in_volume;
    std::shared_ptr<const OccluderSet> occluders;
    ShadeContext ctx;
    /// Triangles' pixels are shaded in SIMD lanes (raster/shade_lanes.h): per-pixel (Phong)
    /// interpolation and delta lights only, which is what the lanes evaluate.
    bool lanes = false;
    SimdLevel simd = best_simd_level();  ///< the lanes' kernel
    /// Screen triangle t is source triangle t (nothing culled or clipped: a model in view), so
    /// its 52 bytes need not be read for the index.
    bool same_order = false;

    /// The source triangle of screen triangle `t`.
    uint32_t source_of(uint32_t t) const { return same_order ? t : ctx.ps.triangles[t].source; }

    ShadePass(const Scene& scene, const ProjectedScene& ps, const RasterSettings& raster, int width,
              int height)
        : ctx{scene,
              ps,
              ps.scene.triangles,
              raster.interp,
              make_camera_frame(scene.camera),
              width,
              height,
              {scene.lights.data(), scene.lights.size(), scene.ambient},
              scene.lights.empty() ? ShadowMode::none : raster.shadows,
              nullptr,
              nullptr,
              nullptr,
              nullptr,
              raster.light_samples,
              false,
              nullptr,
              {}} {
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
        simd = raster.simd;
        same_order = ps.triangles.size() == ps.scene.triangles.size() && ps.counts.culled == 0 &&
                     ps.counts.clipped_away == 0 && ps.counts.cut == 0;
        lanes = raster.interp == Interpolation::phong &&
                std::all_of(scene.lights.begin(), scene.lights.end(), is_delta_light);
    }
    ShadePass(const ShadePass&) = delete;
    ShadePass& operator=(const ShadePass&) = delete;

    /// The shadow pass, shared by every visibility method: maps from the lights, or a stencil
    /// per light counted against the depth of each pixel's visible point (`vis` must then be
    /// given).
    void draw_shadows(const RenderSettings& settings, const RasterSettings& raster,
                      const VisibilityBuffer* vis) {
        const Scene& scene = ctx.scene;
        const ProjectedScene& ps = ctx.ps;
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
            const std::vector<float> depth = visible_depth(ctx, *vis);
            // Shadow volumes are built from polygon silhouettes: exact spheres cast theirs
            // through their tessellation.
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
    }
};

/// The AOVs of a pixel that sees triangle point `s`, when the framebuffer keeps them.
void write_surface_aovs(const ShadeContext& ctx, const PixelSurface& s, size_t pixel,
                        Framebuffer& fb) {
    if (fb.depth.empty()) return;
    fb.depth[pixel] = camera_distance(ctx.frame, s.point);
    fb.id[pixel] = ctx.tris.id[s.src] + 1;
    const float nl = length(s.n_interp);
    const Vec3 sn = nl > 0.0f ? s.n_interp / nl : s.ng;
    fb.normal[pixel] = dot(sn, s.dir) < 0.0f ? sn : -sn;
}

/// The visible triangle points of one tile, gathered for the lanes, and where they came from.
struct TileLanes {
    SurfaceLanes lanes;
    std::array<int32_t, SurfaceLanes::k_capacity> x, y;
    std::array<size_t, SurfaceLanes::k_capacity> pixel;
    std::array<float, 3 * SurfaceLanes::k_capacity> shadow_normal;  ///< ShadowQuery::ng
    std::array<int32_t, SurfaceLanes::k_capacity> local;            ///< pixel index inside the tile
    /// The tile's colours, k_tile_size wide, written to the film a row at a time.
    std::array<Vec3, SurfaceLanes::k_capacity> colour;
    int count = 0;
    const ShadeContext* ctx = nullptr;

    /// Lane `count` := the Phong-shaded point of `s` (shade_surface's Interpolation::phong).
    void add(const PixelSurface& s, int px, int py, size_t at, int in_tile) {
        const int k = count++;
        const Vec3 n = facing(s.n_interp, s.entering, s.ng_front, s.dir);
        const Vec3 to_eye = -s.dir;
        for (int a = 0; a < 3; ++a) {
            lanes.position[a][k] = s.point[a];
            lanes.normal[a][k] = n[a];
            lanes.to_eye[a][k] = to_eye[a];
            lanes.dp_dx[a][k] = s.tex.dp_dx[a];
            lanes.dp_dy[a][k] = s.tex.dp_dy[a];
            shadow_normal[3 * k + a] = s.ng_front[a];
        }
        lanes.material[k] = static_cast<int32_t>(ctx->tris.material[s.src]);
        lanes.u[k] = s.tex.uv.x, lanes.v[k] = s.tex.uv.y;
        lanes.du_dx[k] = s.tex.du_dx, lanes.dv_dx[k] = s.tex.dv_dx;
        lanes.du_dy[k] = s.tex.du_dy, lanes.dv_dy[k] = s.tex.dv_dy;
        x[k] = px, y[k] = py, pixel[k] = at, local[k] = in_tile;
    }

    /// Lanes past `count` up to a whole group: copies of lane 0, so that every lane the
    /// kernel reads holds a real point (its texture lookups stay in range).
    void pad() {
        const int end = (count + SurfaceLanes::k_lane_group - 1) / SurfaceLanes::k_lane_group *
                        SurfaceLanes::k_lane_group;
        for (int k = count; k < end; ++k) {
            for (int a = 0; a < 3; ++a) {
                lanes.position[a][k] = lanes.position[a][0];
                lanes.normal[a][k] = lanes.normal[a][0];
                lanes.to_eye[a][k] = lanes.to_eye[a][0];
                lanes.dp_dx[a][k] = lanes.dp_dx[a][0];
                lanes.dp_dy[a][k] = lanes.dp_dy[a][0];
            }
            lanes.material[k] = lanes.material[0];
            lanes.u[k] = lanes.u[0], lanes.v[k] = lanes.v[0];
            lanes.du_dx[k] = lanes.du_dx[0], lanes.dv_dx[k] = lanes.dv_dx[0];
            lanes.du_dy[k] = lanes.du_dy[0], lanes.dv_dy[k] = lanes.dv_dy[0];
        }
    }

    /// LaneLighting::fractions: light_fraction at each asked lane's point.
    static void fractions(const void* self, size_t light, int first, uint32_t asked,
                          float* fraction) {
        const auto& t = *static_cast<const TileLanes*>(self);
        for (; asked; asked &= asked - 1) {
            const int j = std::countr_zero(asked), k = first + j;
            const ShadowQuery q{
                Vec3(t.lanes.position[0][k], t.lanes.position[1][k], t.lanes.position[2][k]),
                Vec3(t.shadow_normal[3 * k], t.shadow_normal[3 * k + 1],
                     t.shadow_normal[3 * k + 2]),
                t.pixel[k]};
            fraction[j] = light_fraction(*t.ctx, light, q);
        }
    }
};

/// Colour and AOVs of every pixel of `tile`, whose visibility values are `seen` (k_tile_size
/// wide from the tile's corner). Triangle pixels are shaded in lanes when the pass allows it,
/// each lane as shade_surface would shade it alone; lanes whose material has no lane form are
/// shaded again one at a time. Returns the pixels that show a triangle or sphere.
size_t shade_tile_seen(const ShadePass& pass, const Tile& tile, const uint32_t* seen,
                       Framebuffer& fb, TileLanes& gathered) {
    const ShadeContext& ctx = pass.ctx;
    gathered.count = 0;
    gathered.ctx = &ctx;
    std::array<Vec3, SurfaceLanes::k_capacity>& colour = gathered.colour;
    SourceTriangle tri;
    size_t covered = 0;
    if (!ctx.has_area_lights && !ctx.environment &&
        std::all_of(seen, seen + SurfaceLanes::k_capacity,
                    [](uint32_t t) { return t == k_no_triangle; })) {
        // Nothing in the tile (a partial tile's values past its edge are k_no_triangle too):
        // the background, a row at a time.
        std::fill(colour.begin(), colour.end(), ctx.scene.background);
        for (int y = tile.y0; y < tile.y1; ++y)
            fb.set_colors(static_cast<size_t>(y) * ctx.width + tile.x0, colour.data(),
                          static_cast<size_t>(tile.x1 - tile.x0));
        return 0;
    }
    // Start loading every triangle the tile sees: they lie far apart in memory.
    const size_t screen_triangles = ctx.ps.triangles.size();
    for (int k = 0, last = -1; k < SurfaceLanes::k_capacity; ++k)
        if (seen[k] != static_cast<uint32_t>(last) && seen[k] < screen_triangles) {
            last = static_cast<int>(seen[k]);
            __builtin_prefetch(&ctx.tris.indices[pass.source_of(seen[k])]);
        }
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const size_t pixel = static_cast<size_t>(y) * ctx.width + x;
            const int local = (y - tile.y0) * k_tile_size + (x - tile.x0);
            const uint32_t t = seen[local];
            if (t == k_no_triangle) {
                const std::optional<Vec3> light =
                    ctx.has_area_lights ? light_face_at(ctx, x, y, k_infinity) : std::nullopt;
                colour[local] = light ? *light : background_at(ctx, x, y);
                continue;
            }
            ++covered;
            if (const Sphere* sphere = sphere_named(ctx, t)) {
                colour[local] = shade_sphere_pixel(ctx, *sphere, x, y, pixel, fb);
                continue;
            }
            tri.load(ctx, pass.source_of(t));
            const PixelSurface s = surface_at(ctx, tri, x, y);
            write_surface_aovs(ctx, s, pixel, fb);
            if (pass.lanes) {
                gathered.add(s, x, y, pixel, local);
                continue;
            }
            const std::optional<Vec3> light =
                ctx.has_area_lights ? light_face_at(ctx, x, y, camera_distance(ctx.frame, s.point))
                                    : std::nullopt;
            colour[local] = light ? *light : shade_surface(ctx, s, pixel);
        }
    if (gathered.count > 0) {
        gathered.pad();
        LaneLighting lighting;
        lighting.lighting = ctx.lighting;
        lighting.materials = ctx.scene.materials.data();
        if (ctx.shadows != ShadowMode::none) {
            lighting.fractions = &TileLanes::fractions;
            lighting.context = &gathered;
        }
        SurfaceLanes& lanes = gathered.lanes;
        shade_surface_lanes(lighting, gathered.count, lanes, pass.simd);
        for (int k = 0; k < gathered.count; ++k) {
            const int local = gathered.local[k];
            if (lanes.scalar_only[k]) {
                const int x = gathered.x[k], y = gathered.y[k];
                tri.load(ctx, pass.source_of(seen[local]));
                colour[local] = shade_surface(ctx, surface_at(ctx, tri, x, y), gathered.pixel[k]);
                continue;
            }
            colour[local] = Vec3(lanes.colour[0][k], lanes.colour[1][k], lanes.colour[2][k]);
        }
    }
    for (int y = tile.y0; y < tile.y1; ++y)
        fb.set_colors(static_cast<size_t>(y) * ctx.width + tile.x0,
                      colour.data() + (y - tile.y0) * k_tile_size,
                      static_cast<size_t>(tile.x1 - tile.x0));
    return covered;
}

/// Each thread's lanes, made once per thread and kept (a tile's gathered points are 50 KB:
/// too much for every tile's stack frame to clear, and no allocation per frame).
TileLanes& thread_tile_lanes() {
    thread_local std::unique_ptr<TileLanes> lanes = std::make_unique<TileLanes>();
    return *lanes;
}

}  // namespace

Framebuffer shade_visibility(const Scene& scene, const ProjectedScene& ps,
                             const VisibilityBuffer& vis, Film film, const RenderSettings& settings,
                             const RasterSettings& raster) {
    Framebuffer fb(std::move(film), vis.width, vis.height, settings.aov_buffers);
    ShadePass pass(scene, ps, raster, vis.width, vis.height);
    pass.draw_shadows(settings, raster, &vis);
    for_each_tile(vis.width, vis.height, settings.control, [&](const Tile& tile) {
        // The tile's values, k_tile_size wide, as a per-tile visibility method leaves them.
        std::array<uint32_t, k_tile_size * k_tile_size> seen;
        seen.fill(k_no_triangle);
        for (int y = tile.y0; y < tile.y1; ++y)
            std::copy_n(vis.triangle.data() + static_cast<size_t>(y) * vis.width + tile.x0,
                        tile.x1 - tile.x0, seen.data() + (y - tile.y0) * k_tile_size);
        shade_tile_seen(pass, tile, seen.data(), fb, thread_tile_lanes());
    });
    return fb;
}

Framebuffer shade_tiles(const Scene& scene, const ProjectedScene& ps, Film film,
                        const RenderSettings& settings, const RasterSettings& raster,
                        const TileVisibility& visible) {
    const int width = scene.camera.width, height = scene.camera.height;
    Framebuffer fb(std::move(film), width, height, settings.aov_buffers);
    ShadePass pass(scene, ps, raster, width, height);
    pass.draw_shadows(settings, raster, nullptr);
    std::atomic<uint64_t> covered{0};
    for_each_tile(width, height, settings.control, [&](const Tile& tile) {
        std::array<uint32_t, k_tile_size * k_tile_size> seen;
        visible(tile, seen.data());
        covered.fetch_add(shade_tile_seen(pass, tile, seen.data(), fb, thread_tile_lanes()),
                          std::memory_order_relaxed);
    });
    if (settings.stats) settings.stats->raster_covered_pixels += covered.load();
    return fb;
}

}  // namespace hikari
