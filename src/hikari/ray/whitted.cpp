#include "hikari/ray/whitted.h"

#include <cmath>
#include <optional>

#include "hikari/core/rng.h"
#include "hikari/ray/primary_hits.h"
#include "hikari/ray/ray_offset.h"
#include "hikari/ray/scene_intersector.h"
#include "hikari/render/tiles.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/refraction.h"

namespace hikari {

namespace {

/// What every ray of a render reads, plus the ray count of the tile being rendered (each tile
/// works on its own copy, so counting needs no atomics per ray).
struct TraceContext {
    const Scene& scene;
    const SceneIntersector& intersector;
    int max_depth;
    uint64_t rays = 0;
};

/// The local (direct) illumination of a hit: ambient, then each light that a shadow ray
/// finds unblocked. `lit`, when given, holds the shadow rays' answers already (bit l: light l
/// unblocked), found in bulk for camera-ray hits by ray/primary_hits.h.
Vec3 shade_local(TraceContext& ctx, const Material& m, Vec3 p, Vec3 n, Vec3 ng, Vec3 to_eye,
                 const uint8_t* lit) {
    Vec3 colour = shade_ambient(m, ctx.scene.ambient);
    const Vec3 shadow_origin = offset_ray_origin(p, ng);
    for (size_t l = 0; l < ctx.scene.lights.size(); ++l) {
        const LightSample ls = sample_light(ctx.scene.lights[l], p);
        if (dot(n, ls.to_light) <= 0.0f) continue;
        ++ctx.rays;
        const bool blocked =
            lit ? (*lit & (1u << l)) == 0
                : ctx.intersector.occluded({shadow_origin, ls.to_light}, {0.0f, ls.distance});
        if (blocked) continue;
        colour += shade_direct(m, n, ls.to_light, to_eye, ls.irradiance);
    }
    return colour;
}

/// The material at a textured point: ka and kd scaled by the texture's colour there. A copy
/// without the name (an empty string allocates nothing).
Material textured(const Material& m, Vec3 p) {
    Material out;
    const Vec3 c = m.texture->at(p);
    out.ka = m.ka * c;
    out.kd = m.kd * c;
    out.ks = m.ks;
    out.shininess = m.shininess;
    out.reflectivity = m.reflectivity;
    out.transparency = m.transparency;
    out.ior = m.ior;
    return out;
}

Vec3 trace(TraceContext& ctx, const Ray& ray, int segment, SurfaceHit* first_hit = nullptr);

/// What a ray that hits nothing sees.
Vec3 sky(const TraceContext& ctx, const Ray& ray) {
    return ctx.scene.sky.colour(ray.direction, ctx.scene.background);
}

/// Colour seen along `ray` (segment number `segment` of its path, primary = 1) whose nearest
/// hit is `hit`: local illumination, then the mirror and refracted rays. `lit` as for
/// shade_local.
Vec3 shade(TraceContext& ctx, const Ray& ray, const SurfaceHit& hit, int segment,
           const uint8_t* lit = nullptr) {
    // Face the normals toward the incoming ray: planes and triangles are two-sided, and a ray
    // inside a sphere sees its inner side.
    const bool entering = dot(hit.geometric_normal, ray.direction) < 0.0f;
    const Vec3 ng = entering ? hit.geometric_normal : -hit.geometric_normal;
    Vec3 n = entering ? hit.shading_normal : -hit.shading_normal;
    if (dot(n, ray.direction) > 0.0f) n = ng;  // interpolated normal turned away: use the true one

    const Material& material = ctx.scene.materials[hit.material];
    Material local;
    const Material* textured_material = &material;
    if (material.texture) textured_material = &(local = textured(material, hit.position));
    const Material& m = *textured_material;
    Vec3 colour = shade_local(ctx, m, hit.position, n, ng, -ray.direction, lit);
    if (segment >= ctx.max_depth) return colour;

    const Vec3 mirror = reflect(ray.direction, n);
    std::optional<Vec3> refracted;
    if (m.transparency > 0.0f)
        refracted = refract(ray.direction, n, entering ? 1.0f / m.ior : m.ior);
    // On total internal reflection the mirror ray takes the transmitted weight and the
    // reflectivity term is dropped (POV-Ray's rule), so the mirror ray is traced once.
    const bool total_internal = m.transparency > 0.0f && !refracted;
    const float mirror_weight = total_internal ? m.transparency : m.reflectivity;
    if (mirror_weight > 0.0f)
        colour +=
            mirror_weight * trace(ctx, {offset_ray_origin(hit.position, ng), mirror}, segment + 1);
    if (refracted)
        colour += m.transparency *
                  trace(ctx, {offset_ray_origin(hit.position, -ng), *refracted}, segment + 1);
    return colour;
}

/// Colour seen along `ray`, which is segment number `segment` of its path (primary = 1).
/// Returns the primary hit through `first_hit` when asked (for the AOVs).
Vec3 trace(TraceContext& ctx, const Ray& ray, int segment, SurfaceHit* first_hit) {
    ++ctx.rays;
    SurfaceHit hit;
    if (!ctx.intersector.closest(ray, {0.0f, k_infinity}, hit)) return sky(ctx, ray);
    if (first_hit) *first_hit = hit;
    return shade(ctx, ray, hit, segment);
}

/// Strata for `n` jittered samples: the most square grid cols × rows = n.
void strata(int n, int& cols, int& rows) {
    cols = static_cast<int>(std::sqrt(static_cast<double>(n)));
    while (n % cols != 0) --cols;
    rows = n / cols;
}

}  // namespace

Framebuffer render_whitted(const Scene& scene, const RenderSettings& settings) {
    const Camera& cam = scene.camera;
    Framebuffer fb(cam.width, cam.height, scene.background, settings.aov_buffers);
    const SceneIntersector intersector(scene);
    const TraceContext shared{scene, intersector, settings.max_depth};
    if (RenderControl* control = settings.control) {
        const WideBvh& bvh = intersector.bvh();
        control->bvh_triangles = bvh.triangle_count();
        control->bvh_nodes = bvh.nodes.size();
        control->bvh_bytes = bvh.memory_bytes();
        control->bvh_build_us = static_cast<uint64_t>(intersector.build_ms() * 1000.0);
    }
    const CameraFrame frame = make_camera_frame(cam);
    const int spp = settings.samples_per_pixel;
    int cols = 1, rows = 1;
    strata(spp, cols, rows);

    // One ray per pixel: the tile's camera rays and their nearest hits are found together
    // (ray/primary_hits.h, SIMD), then each pixel is shaded from its hit as trace() would.
    const PrimaryHitTracer primary(intersector, scene, frame);
    const auto store_aovs = [&](size_t i, const Ray& centre, const SurfaceHit& first) {
        if (!settings.aov_buffers || !(first.t < k_infinity)) return;
        fb.depth[i] = first.t;
        fb.id[i] = first.id + 1;
        fb.normal[i] = dot(first.shading_normal, centre.direction) < 0.0f ? first.shading_normal
                                                                          : -first.shading_normal;
    };
    static_assert(k_tile_size <= k_primary_block);

    for_each_tile(cam.width, cam.height, settings.control, [&](const Tile& tile) {
        TraceContext ctx = shared;
        if (spp == 1 && settings.primary_blocks) {
            PrimaryBlock block;
            primary.trace(tile.x0, tile.y0, tile.x1 - tile.x0, tile.y1 - tile.y0, block);
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const size_t i = static_cast<size_t>(y) * cam.width + x;
                    const int k = (y - tile.y0) * k_primary_block + (x - tile.x0);
                    const Ray& ray = block.rays[k];
                    ++ctx.rays;
                    if (!block.found[k]) {
                        fb.color.pixels[i] = sky(ctx, ray);
                        continue;
                    }
                    fb.color.pixels[i] = shade(ctx, ray, block.hits[k], 1,
                                               block.shadows_known ? &block.lit[k] : nullptr);
                    store_aovs(i, ray, block.hits[k]);
                }
            if (settings.control) settings.control->rays_traced += ctx.rays;
            return;
        }
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const size_t i = static_cast<size_t>(y) * cam.width + x;
                const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
                SurfaceHit first;
                first.t = k_infinity;
                const Ray centre = camera_ray(frame, fx + 0.5f, fy + 0.5f);
                Vec3 sum(0.0f);
                if (spp == 1) {
                    sum = trace(ctx, centre, 1, &first);
                } else {
                    // The AOVs describe the pixel centre; colour averages jittered samples, one
                    // in each stratum, from a stream seeded by the pixel alone.
                    intersector.closest(centre, {0.0f, k_infinity}, first);
                    ++ctx.rays;
                    Pcg32 rng(i, 0x68696b617269ULL);
                    for (int s = 0; s < spp; ++s) {
                        const int column = s % cols, row = s / cols;
                        const float sx = (static_cast<float>(column) + rng.next_float()) / cols;
                        const float sy = (static_cast<float>(row) + rng.next_float()) / rows;
                        sum += trace(ctx, camera_ray(frame, fx + sx, fy + sy), 1);
                    }
                    sum = sum / static_cast<float>(spp);
                }
                fb.color.pixels[i] = sum;
                store_aovs(i, centre, first);
            }
        if (settings.control) settings.control->rays_traced += ctx.rays;
    });
    return fb;
}

}  // namespace hikari
