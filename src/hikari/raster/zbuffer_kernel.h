#pragma once
// The Z-buffer (the lecture's Alg 4.2) as kernels, written once for the CPU and the GPU
// (HIKARI_HD): (0) the vertex stage (raster/vertex_pipeline.h), per vertex and per triangle, the
// few triangles that need clipping left to the host; (1) each screen triangle's
// half-space setup (raster/half_space.h, the CPU's own), (2) binning into 16 × 16 pixel tiles,
// each tile's list in ascending triangle order (counts per tile and chunk of triangles, a
// prefix sum, then each chunk fills its places in order, so no atomics decide any order), (3)
// per pixel, the depth test over its tile's list with the CPU's exact edge functions, top-left
// fill rule and depth 1 / Σ b_i inv_w_i, so that ties resolve as on the CPU (the earlier
// triangle stays), then the exact spheres (raster/sphere_raster.h), (4) deferred shading of each
// pixel's visible point by the shared shading code (raster/pixel_surface.h, shading/), with
// shadow-map lookups (raster/shadow_map_lookup.h).
// Run by render_zbuffer_kernels (zbuffer_kernels.h) through core/device_launch.h.

#include <array>
#include <cstddef>
#include <cstdint>

#include "hikari/core/flat_view.h"
#include "hikari/core/host_device.h"
#include "hikari/frame/render_settings.h"
#include "hikari/frame/tiles.h"
#include "hikari/geometry/intersect.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/half_space.h"
#include "hikari/raster/pixel_surface.h"
#include "hikari/raster/screen_triangle.h"
#include "hikari/raster/shadow_map_lookup.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/vertex_transform.h"
#include "hikari/scene/camera.h"
#include "hikari/shading/direct.h"
#include "hikari/shading/lighting_environment.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/material_eval.h"

namespace hikari {

/// (0a) Vertex i through the view (transform_vertex, the CPU vertex stage's own): its clip
/// position, whether it is inside the clip volume, its screen vertex if so.
struct VertexKernel {
    RasterView view;
    const Vec3* positions = nullptr;
    Vec4* clip = nullptr;
    uint8_t* inside = nullptr;
    ScreenVertex* screen = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        transform_vertex(view, positions[i], clip[i], inside[i], screen[i]);
    }
};

/// What the vertex stage does with a triangle (project_to_screen's fates).
enum TriangleFate : uint8_t {
    k_fate_kept,    ///< every corner inside the clip volume: one screen triangle, its corners
    k_fate_clip,    ///< a corner outside: clipped on the host (few, and into pieces)
    k_fate_culled,  ///< a back face, with culling on
};

/// (0b) Triangle t's fate: culled (D = V·N > 0 with culling on, raster/cull.h), kept whole
/// (its corners all inside the clip volume), or to be clipped.
struct TriangleFateKernel {
    RasterView view;
    bool cull = false;
    const Vec3* positions = nullptr;
    const std::array<uint32_t, 3>* indices = nullptr;
    const uint8_t* inside = nullptr;
    uint8_t* fate = nullptr;

    HIKARI_HD void operator()(size_t t) const {
        const std::array<uint32_t, 3>& idx = indices[t];
        if (cull) {
            const Vec3 p1 = positions[idx[0]];
            // RasterView::view_vector: from the eye, or the view direction itself.
            const Vec3 v = view.orthographic ? view.forward : p1 - view.eye;
            if (is_back_face_along(p1, positions[idx[1]], positions[idx[2]], v)) {
                fate[t] = k_fate_culled;
                return;
            }
        }
        fate[t] = inside[idx[0]] && inside[idx[1]] && inside[idx[2]] ? k_fate_kept : k_fate_clip;
    }
};

/// (0c) Triangle t kept whole: its corners' screen vertices at its place `first[t]` of the
/// screen triangles (the pieces of clipped triangles are the host's).
struct TriangleAssembleKernel {
    const std::array<uint32_t, 3>* indices = nullptr;
    const uint8_t* fate = nullptr;
    const uint32_t* first = nullptr;
    const ScreenVertex* screen = nullptr;
    ScreenTriangle* out = nullptr;

    HIKARI_HD void operator()(size_t t) const {
        if (fate[t] != k_fate_kept) return;
        const std::array<uint32_t, 3>& idx = indices[t];
        out[first[t]] = {{screen[idx[0]], screen[idx[1]], screen[idx[2]]},
                         static_cast<uint32_t>(t)};
    }
};

/// Triangles per binning chunk: one kernel thread counts and fills the bins of a chunk, in
/// triangle order.
inline constexpr size_t k_bin_chunk_triangles = 256;

/// (1) The half-space setup of screen triangle t: setup[t], and drawn[t] = 0 where it covers no
/// pixel centre for sure (setup_half_space's answer).
struct TriangleSetupKernel {
    const ScreenTriangle* triangles = nullptr;
    int width = 0, height = 0;
    HalfSpaceTriangle* setup = nullptr;
    uint8_t* drawn = nullptr;

    HIKARI_HD void operator()(size_t t) const {
        drawn[t] = setup_half_space(triangles[t], width, height, setup[t]) ? 1 : 0;
    }
};

/// The tiles whose pixels a set-up triangle's bounds reach, [tx0, tx1] × [ty0, ty1].
struct TileSpan {
    int tx0, ty0, tx1, ty1;
};
HIKARI_HD inline TileSpan tile_span(const HalfSpaceTriangle& h) {
    return {h.x0 / k_tile_size, h.y0 / k_tile_size, (h.x1 - 1) / k_tile_size,
            (h.y1 - 1) / k_tile_size};
}

/// The drawn triangles of chunk c and the tiles their bounds reach: visit(t, tile) in triangle
/// order, for the two binning passes that count and then fill.
struct BinChunks {
    const HalfSpaceTriangle* setup = nullptr;
    const uint8_t* drawn = nullptr;
    size_t triangles = 0, chunks = 0;
    int tiles_x = 0;

    template <class Visit>
    HIKARI_HD void for_each_reach(size_t c, Visit&& visit) const {
        const size_t end = (c + 1) * k_bin_chunk_triangles < triangles
                               ? (c + 1) * k_bin_chunk_triangles
                               : triangles;
        for (size_t t = c * k_bin_chunk_triangles; t < end; ++t) {
            if (!drawn[t]) continue;
            const TileSpan s = tile_span(setup[t]);
            for (int ty = s.ty0; ty <= s.ty1; ++ty)
                for (int tx = s.tx0; tx <= s.tx1; ++tx)
                    visit(t, static_cast<size_t>(ty) * tiles_x + tx);
        }
    }
};

/// (2a) For chunk c of the triangles: counts[tile · chunks + c] = how many of its triangles
/// reach each tile.
struct BinCountKernel {
    BinChunks bins;
    uint32_t* counts = nullptr;

    HIKARI_HD void operator()(size_t c) const {
        bins.for_each_reach(c, [&](size_t, size_t tile) { ++counts[tile * bins.chunks + c]; });
    }
};

/// (2b) For tile i: its chunks' counts turned into each chunk's first place in the tile's list
/// (an exclusive prefix sum in chunk order), and the tile's total.
struct BinTotalKernel {
    size_t chunks = 0;
    uint32_t* counts = nullptr;
    uint32_t* totals = nullptr;

    HIKARI_HD void operator()(size_t tile) const {
        uint32_t running = 0;
        for (size_t c = 0; c < chunks; ++c) {
            const uint32_t n = counts[tile * chunks + c];
            counts[tile * chunks + c] = running;
            running += n;
        }
        totals[tile] = running;
    }
};

/// (2c) For chunk c: its triangles, in order, into the places of each tile's list that
/// BinTotalKernel gave it; tile i's list is list[tile_begin[i], tile_begin[i + 1]), ascending.
struct BinFillKernel {
    BinChunks bins;
    uint32_t* counts = nullptr;  ///< BinTotalKernel's places, advanced as they fill
    const uint32_t* tile_begin = nullptr;
    uint32_t* list = nullptr;

    HIKARI_HD void operator()(size_t c) const {
        bins.for_each_reach(c, [&](size_t t, size_t tile) {
            list[tile_begin[tile] + counts[tile * bins.chunks + c]++] = static_cast<uint32_t>(t);
        });
    }
};

/// (3) Alg 4.2 at pixel i: Z = ∞, then every triangle of the pixel's tile in order, a fragment
/// where the pixel centre is inside under the top-left rule, written when z < Z. The edge
/// functions are evaluated exactly (64-bit integers, as for_each_covered_pixel steps them), the
/// weights and depth rounded as interpolated_depth rounds them, so `depth` and `nearest` (the
/// screen triangle seen, k_no_triangle for none) are the CPU Z-buffer's, bit for bit.
struct ZBufferPixelKernel {
    const HalfSpaceTriangle* setup = nullptr;
    const uint32_t* tile_begin = nullptr;
    const uint32_t* list = nullptr;
    int width = 0, tiles_x = 0;
    float* depth = nullptr;       ///< may be null
    uint32_t* nearest = nullptr;  ///< may be null
    /// Exact spheres (raster/sphere_raster.h: SphereRaster's arrays), drawn after the
    /// triangles as draw_spheres_in_tile draws them: none when `sphere_count` is 0.
    const Sphere* spheres = nullptr;
    size_t sphere_count = 0;
    const PixelRect* sphere_bounds = nullptr;
    const uint32_t* sphere_tile_begin = nullptr;  ///< per tile of the image, as tile_begin
    const uint32_t* tile_spheres = nullptr;
    CameraFrame frame;  ///< the camera's rays (PixelRays::at of camera_pixel_rays)
    Vec2 sample_offset;
    Mat4 clip_from_world;
    bool orthographic = false;
    uint32_t first_sphere_id = 0;

    /// draw_spheres_in_tile at pixel (x, y): the nearest sphere its ray meets, in index order (a
    /// later one only when strictly nearer), replaces (z, seen) when its depth key is smaller.
    HIKARI_HD void draw_spheres(size_t tile, int x, int y, float& z_min, uint32_t& seen) const {
        const uint32_t begin = sphere_tile_begin[tile], end = sphere_tile_begin[tile + 1];
        bool any = false;
        for (uint32_t k = begin; k < end && !any; ++k) {
            const PixelRect& r = sphere_bounds[tile_spheres[k]];
            any = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
        }
        if (!any) return;
        const Ray ray = camera_ray(frame, static_cast<float>(x) + 0.5f + sample_offset.x,
                                   static_cast<float>(y) + 0.5f + sample_offset.y);
        Interval range;
        int hit = -1;
        for (uint32_t k = begin; k < end; ++k) {
            const uint32_t j = tile_spheres[k];
            const PixelRect& r = sphere_bounds[j];
            if (!(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1)) continue;
            const float t = intersect_sphere(ray, spheres[j].center, spheres[j].radius, range);
            if (t == t) range.max = t, hit = static_cast<int>(j);
        }
        if (hit < 0) return;
        // The depth key the triangles carry (ScreenVertex::inv_w inverted).
        const Vec4 clip = clip_from_world * Vec4(ray.at(range.max), 1.0f);
        const float z = orthographic ? 1.0f / (1.5f - 0.5f * clip.z / clip.w) : clip.w;
        // Alg 4.2's depth test, as for a triangle drawn after all the others.
        if (z < z_min) {
            z_min = z;
            seen = first_sphere_id + static_cast<uint32_t>(hit);
        }
    }

    HIKARI_HD void operator()(size_t i) const {
        const int x = static_cast<int>(i % static_cast<size_t>(width));
        const int y = static_cast<int>(i / static_cast<size_t>(width));
        const size_t tile = static_cast<size_t>(y / k_tile_size) * tiles_x + x / k_tile_size;
        const int64_t px = int64_t{x} * k_subpixel_one + k_subpixel_one / 2;
        const int64_t py = int64_t{y} * k_subpixel_one + k_subpixel_one / 2;
        float z_min = k_infinity;
        uint32_t seen = k_no_triangle;
        for (uint32_t k = tile_begin[tile]; k < tile_begin[tile + 1]; ++k) {
            const uint32_t t = list[k];
            const HalfSpaceTriangle& h = setup[t];
            if (x < h.x0 || x >= h.x1 || y < h.y0 || y >= h.y1) continue;
            int64_t e[3];
            for (int j = 0; j < 3; ++j) {
                const int a = (j + 1) % 3, b = (j + 2) % 3;
                const int64_t dx = h.x[b] - h.x[a], dy = h.y[b] - h.y[a];
                // E(p) = dx (p.y − a.y) − dy (p.x − a.x), positive inside.
                e[j] = dx * (py - h.y[a]) - dy * (px - h.x[a]) + h.bias[j];
            }
            if ((e[0] | e[1] | e[2]) < 0) continue;
            const float inv_area = 1.0f / static_cast<float>(h.area());
            const float z = interpolated_depth(h, static_cast<float>(e[0] - h.bias[0]) * inv_area,
                                               static_cast<float>(e[1] - h.bias[1]) * inv_area,
                                               static_cast<float>(e[2] - h.bias[2]) * inv_area);
            // Alg 4.2's depth test; on equal depth the earlier triangle stays.
            if (z < z_min) {
                z_min = z;
                seen = t;
            }
        }
        if (sphere_count > 0) draw_spheres(tile, x, y, z_min, seen);
        if (depth) depth[i] = z_min;
        if (nearest) nearest[i] = seen;
    }
};

/// One face of a shadow map where the kernels read it (ShadowMapFace's fields).
struct FlatShadowFace {
    RasterView view;
    FlatView<float> depth;  ///< empty: the face sees no caster
};

/// A light's shadow map where the kernels read it (LightShadowMap's fields); `present` false
/// where the light has none (nothing casts shadows in its light).
struct FlatShadowMap {
    bool present = false;
    bool directional = false, cone = false;
    Vec3 origin, direction;
    int size = 0;
    float texel_size = 0;
    FlatView<FlatShadowFace> faces;
};

/// Area and environment lights, which the kernels refuse (zbuffer_kernel_refusal): never
/// called; what a missing light gives.
struct NoRasterExtendedLights {
    template <class Visible>
    HIKARI_HD Vec3 operator()(size_t, const Light&, const SurfacePoint<float>&,
                              const MaterialSample<float>&, bool, Visible&, int32_t&) const {
        return Vec3(0.0f);
    }
};

/// (4) The colour and AOVs of pixel i from the triangle or exact sphere the Z-buffer left there:
/// the CPU pass's surface_at and shade_surface (raster/shade_visibility.cpp) with flat, Gouraud
/// or Phong interpolation, delta lights, checker textures and vertex colours, shadows by map, pcf
/// or pcss.
struct ZBufferShadeKernel {
    /* the tessellated scene (RasterScene::triangles) and its clip-space corners */
    FlatView<Vec3> positions, normals, colors;
    FlatView<Vec2> uvs;
    FlatView<std::array<uint32_t, 3>> indices;
    FlatView<uint32_t> material;
    FlatView<PrimitiveId> id;
    FlatView<Vec4> clip_positions;
    const ScreenTriangle* triangles = nullptr;  ///< the screen triangles (their sources)
    size_t triangle_count = 0;  ///< visibility values from here on name exact spheres
    const Sphere* spheres = nullptr;
    Vec2 sample_offset;                 ///< of the spheres' camera rays
    const uint32_t* nearest = nullptr;  ///< ZBufferPixelKernel's
    /* shading */
    const Material* materials = nullptr;
    LightingEnvironment lighting;
    Vec3 background;
    CameraFrame frame;
    int width = 0, height = 0;
    Interpolation interp = Interpolation::phong;
    /* shadows */
    ShadowMode shadows = ShadowMode::none;  ///< none, map, pcf or pcss
    const LightShadowView* light_views = nullptr;
    const FlatShadowMap* maps = nullptr;
    const Plane* planes = nullptr;
    size_t plane_count = 0;
    /* outputs */
    Vec3* colours = nullptr;
    float* depth = nullptr;  ///< AOVs: null without them
    uint32_t* ids = nullptr;
    Vec3* normal = nullptr;

    /// light_fraction (shade_visibility.cpp) for the map modes.
    HIKARI_HD float light_fraction(size_t l, Vec3 point, Vec3 ng) const {
        if (shadows == ShadowMode::none) return 1.0f;
        if (planes_block_light(planes, plane_count, light_views[l], point)) return 0.0f;
        const FlatShadowMap& map = maps[l];
        if (!map.present) return 1.0f;
        // The normal offset moves the lookup off the surface on the light's side.
        const Vec3 to_light = sample_light(lighting.lights[l], point).to_light;
        const Vec3 n = dot(ng, to_light) < 0.0f ? -ng : ng;
        if (shadows == ShadowMode::pcf)
            return percentage_closer(map, map_lookup(map, point, n), k_pcf_radius_texels, 1.0f);
        if (shadows == ShadowMode::pcss) return pcss_fraction(map, point, n, light_views[l].radius);
        return lit_in_map(map, point, n) ? 1.0f : 0.0f;
    }

    /// Material `m` at `point` (its texture at `tex`) lit by every light that reaches it
    /// (shade_visibility.cpp's shade_point); shadows asked at the pixel's `shadow_point` with
    /// `shadow_normal` (ShadowQuery).
    HIKARI_HD Vec3 shade_point(uint32_t m, Vec3 point, Vec3 n, Vec3 to_eye, const PixelUv& tex,
                               Vec3 vertex_colour, Vec3 shadow_point, Vec3 shadow_normal) const {
        const SurfacePoint<float> s = pixel_surface_point(point, n, to_eye, tex, vertex_colour);
        const MaterialSample<float> ms =
            evaluate_material<float>(materials, static_cast<int32_t>(m), s);
        const auto lit = [&](size_t l, const LightSample&, const SurfacePoint<float>&, bool) {
            return light_fraction(l, shadow_point, shadow_normal);
        };
        return direct_lighting<float>(lighting, s, ms, true, lit, NoRasterExtendedLights{}).colour;
    }

    /// The ray of pixel (x + dx, y + dy), as the Z-buffer drew the spheres with it.
    HIKARI_HD Ray sphere_ray(int x, int y) const {
        return camera_ray(frame, static_cast<float>(x) + 0.5f + sample_offset.x,
                          static_cast<float>(y) + 0.5f + sample_offset.y);
    }

    /// A pixel that sees exact sphere `s` (shade_visibility.cpp's shade_sphere_pixel): the ray
    /// tracer's hit, shaded per pixel.
    HIKARI_HD void shade_sphere(size_t i, int x, int y, const Sphere& sphere) const {
        const Ray ray = sphere_ray(x, y);
        float t = intersect_sphere(ray, sphere.center, sphere.radius, Interval{});
        // The Z-buffer drew the sphere here, so the ray meets it; should rounding say otherwise,
        // the ray's closest approach to the centre stands in.
        if (!(t == t)) t = std::max(0.0f, dot(sphere.center - ray.origin, ray.direction));
        const Vec3 point = ray.at(t);
        const Vec3 n = (point - sphere.center) / sphere.radius;
        const Vec3 normal_front = dot(n, ray.direction) < 0.0f ? n : -n;
        PixelUv tex;
        if (materials[sphere.material].texture) {  // sphere_pixel_uv
            const SurfaceUv su = sphere_uv(sphere, point);
            tex.uv = su.uv;
            const auto step = [&](int dx, int dy) {
                const Ray r = sphere_ray(x + dx, y + dy);
                const float denominator = dot(normal_front, r.direction);
                return denominator == 0.0f
                           ? Vec3(0.0f)
                           : r.at(dot(point - r.origin, normal_front) / denominator) - point;
            };
            const Vec3 along_x = step(1, 0), along_y = step(0, 1);
            tex.dp_dx = along_x, tex.dp_dy = along_y;
            tex.du_dx = dot(su.du_dp, along_x), tex.dv_dx = dot(su.dv_dp, along_x);
            tex.du_dy = dot(su.du_dp, along_y), tex.dv_dy = dot(su.dv_dp, along_y);
        }
        colours[i] = shade_point(sphere.material, point, normal_front, -ray.direction, tex,
                                 Vec3(1.0f), point, normal_front);
        if (depth) {
            depth[i] = camera_distance(frame, point);
            ids[i] = sphere.id + 1;
            normal[i] = normal_front;
        }
    }

    HIKARI_HD void operator()(size_t i) const {
        const uint32_t t = nearest[i];
        if (t == k_no_triangle) {
            colours[i] = background;
            return;
        }
        const int x = static_cast<int>(i % static_cast<size_t>(width));
        const int y = static_cast<int>(i / static_cast<size_t>(width));
        if (t >= triangle_count) {
            shade_sphere(i, x, y, spheres[t - triangle_count]);
            return;
        }
        /* the source triangle (shade_visibility.cpp's SourceTriangle::load) */
        const uint32_t src = triangles[t].source;
        const std::array<uint32_t, 3>& idx = indices[src];
        Vec3 p[3], n[3], c[3];
        const Material& m = materials[material[src]];
        const bool coloured = !colors.empty() && m.vertex_colours;
        for (int k = 0; k < 3; ++k) {
            p[k] = positions[idx[k]];
            n[k] = normals[idx[k]];
            c[k] = coloured ? colors[idx[k]] : Vec3(1.0f);
        }
        const BarycentricPlanes planes_b = barycentric_planes(
            clip_positions[idx[0]], clip_positions[idx[1]], clip_positions[idx[2]]);
        const Vec3 face = face_normal(p[0], p[1], p[2]);
        const float face_length = length(face);
        /* the pixel centre on it (surface_at) */
        const double ndc_x = 2.0 * (x + 0.5) / width - 1.0;
        const double ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
        std::array<float, 3> b = {1.0f / 3, 1.0f / 3, 1.0f / 3};
        barycentric_weights(planes_b, ndc_x, ndc_y, b);
        const Vec3 point = b[0] * p[0] + b[1] * p[1] + b[2] * p[2];
        const Vec3 n_interp = b[0] * n[0] + b[1] * n[1] + b[2] * n[2];
        PixelUv tex;
        if (m.texture) {
            if (!uvs.empty())
                tex = perspective_uv(
                    {clip_positions[idx[0]], clip_positions[idx[1]], clip_positions[idx[2]]},
                    {uvs[idx[0]], uvs[idx[1]], uvs[idx[2]]}, ndc_x, ndc_y, width, height);
            tex.dp_dx = tangent_plane_step(frame, point, face, x, y, 1, 0);
            tex.dp_dy = tangent_plane_step(frame, point, face, x, y, 0, 1);
        }
        const Vec3 dir = camera_ray(frame, x + 0.5f, y + 0.5f).direction;
        // Two-sided, as in the ray tracer: the side the eye sees is the front.
        const Vec3 ng = face_length > 0.0f ? face / face_length : -dir;
        const bool entering = dot(ng, dir) < 0.0f;
        const Vec3 ng_front = entering ? ng : -ng;
        /* the colour, interpolated as `interp` says (shade_surface) */
        const uint32_t m_index = material[src];
        switch (interp) {
            case Interpolation::flat: {  // one colour per polygon, at its centroid
                const Vec3 centre = (p[0] + p[1] + p[2]) / 3.0f;
                colours[i] = shade_point(m_index, centre, ng_front, toward_viewer(frame, centre),
                                         tex, (c[0] + c[1] + c[2]) / 3.0f, point, ng_front);
                break;
            }
            case Interpolation::gouraud: {  // shade the vertices, blend the colours
                Vec3 colour(0.0f);
                for (int k = 0; k < 3; ++k) {
                    const Vec3 to_eye = toward_viewer(frame, p[k]);
                    const Vec3 nk = facing(n[k], entering, ng_front, -to_eye);
                    colour +=
                        b[k] * shade_point(m_index, p[k], nk, to_eye, tex, c[k], point, ng_front);
                }
                colours[i] = colour;
                break;
            }
            case Interpolation::phong:  // interpolate the normal, shade the pixel
                colours[i] =
                    shade_point(m_index, point, facing(n_interp, entering, ng_front, dir), -dir,
                                tex, b[0] * c[0] + b[1] * c[1] + b[2] * c[2], point, ng_front);
                break;
        }
        /* the AOVs (write_surface_aovs) */
        if (depth) {
            depth[i] = camera_distance(frame, point);
            ids[i] = id[src] + 1;
            const float nl = length(n_interp);
            const Vec3 sn = nl > 0.0f ? n_interp / nl : ng;
            normal[i] = dot(sn, dir) < 0.0f ? sn : -sn;
        }
    }
};

/// Each kernel for every index in [0, count) on `device` (core/device_launch.h); their own
/// file, which nvcc compiles when HIKARI_CUDA is on.
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const VertexKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleFateKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleAssembleKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const TriangleSetupKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinCountKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinTotalKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const BinFillKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const ZBufferPixelKernel& k);
void launch_zbuffer_kernel(ExecutionDevice device, size_t count, const ZBufferShadeKernel& k);

}  // namespace hikari
