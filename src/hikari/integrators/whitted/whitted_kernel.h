#pragma once
// Whitted ray tracing as one kernel body per pixel (the lecture's Alg 4.3 with shadow rays,
// mirror reflection and refraction), written once for the CPU and the GPU (HIKARI_HD): the
// intersection is bvh/flat_intersector.h, the shading whitted_surface.h's, the same source the
// CPU's SIMD ray tracer (whitted.cpp) runs in its lanes. Run by render_whitted_kernels
// (whitted_kernels.h) through core/device_launch.h.

#include <cstddef>
#include <cstdint>

#include "hikari/bvh/flat_intersector.h"
#include "hikari/core/cuda_devices.h"
#include "hikari/core/flat_view.h"
#include "hikari/core/host_device.h"
#include "hikari/integrators/whitted/ray_cone.h"
#include "hikari/integrators/whitted/whitted_scene.h"
#include "hikari/integrators/whitted/whitted_surface.h"
#include "hikari/scene/camera.h"

namespace hikari {

/// Rays a pixel's ray tree holds at once: a depth-first walk pushes at most two children per
/// node it pops, so --max-depth D needs D + 1 (D ≤ 64, the option's bound).
inline constexpr int k_whitted_kernel_stack = 66;

/// The curvature of the surface `hit` is on, positive where it bulges toward its geometric
/// normal: a sphere's 1 / radius, a triangle's from its vertex normals (ray cones), a plane's 0.
HIKARI_HD inline float surface_curvature_of(const FlatGeometry& g, const SurfaceHit& hit) {
    if (hit.kind == HitKind::sphere) return 1.0f / g.spheres[hit.index].radius;
    if (hit.kind != HitKind::triangle) return 0.0f;
    const std::array<uint32_t, 3>& c = g.indices[hit.index];
    const Vec3 p0 = g.positions[c[0]], p1 = g.positions[c[1]], p2 = g.positions[c[2]];
    // Vertex normals may point either way of the lecture's N: measure along N.
    const float side = dot(cross(p1 - p0, p2 - p1), g.normals[c[0]]) < 0.0f ? -1.0f : 1.0f;
    return side *
           triangle_curvature({p0, p1, p2}, {g.normals[c[0]], g.normals[c[1]], g.normals[c[2]]});
}

/// Area and environment lights, which the kernels do not integrate: render_whitted_kernels
/// refuses scenes that have them, so this is never called; it gives what a missing light gives.
struct NoExtendedLights {
    template <class Visible>
    HIKARI_HD Vec3 operator()(size_t, const Light&, const SurfacePoint<float>&,
                              const MaterialSample<float>&, bool, Visible&, int32_t&) const {
        return Vec3(0.0f);
    }
};

/// The shadow test of the kernels: a shadow ray from offset_ray_origin(position, geometric
/// normal) toward the light, as whitted.cpp's ShadowRays casts it.
struct FlatShadowRays {
    const FlatIntersector* scene;
    HIKARI_HD bool operator()(size_t, const LightSample& light, const SurfacePoint<float>& s,
                              bool) const {
        const Ray shadow{offset_ray_origin(s.position, s.geometric_normal), light.to_light};
        return !scene->occluded(shadow, {0.0f, light.distance});
    }
};

/// One pixel of a Whitted render: `samples` camera rays through it (pixel-relative points; one
/// at (0.5, 0.5) for the centre), each traced to `max_depth` ray segments, their colours
/// averaged into colours[i]; the centre ray's first hit into first_hits[i] when that is set
/// (HitKind::none where it sees the sky). Rays carry their cones where `textured` (some
/// material has a texture, filtered over the pixel's footprint as whitted.cpp filters it).
struct WhittedPixelKernel {
    FlatIntersector scene;
    WhittedScene shading;  ///< its pointers: lights, materials and sky where the device reads
    CameraFrame frame;
    CameraCones camera_cones;
    bool textured = false;
    FlatView<Vec2> samples;
    int max_depth = 5;
    Vec3* colours = nullptr;
    SurfaceHit* first_hits = nullptr;

    HIKARI_HD void operator()(size_t i) const {
        const int x = static_cast<int>(i % static_cast<size_t>(frame.width));
        const int y = static_cast<int>(i / static_cast<size_t>(frame.width));
        const bool centre_only = samples.size() == 1;
        Vec3 sum(0.0f);
        for (size_t s = 0; s < samples.size(); ++s) {
            const Ray ray = camera_ray(frame, static_cast<float>(x) + samples[s].x,
                                       static_cast<float>(y) + samples[s].y);
            sum += trace(ray, centre_only ? first_hits + (first_hits ? i : 0) : nullptr);
        }
        colours[i] = centre_only ? sum : sum / static_cast<float>(samples.size());
        if (first_hits && !centre_only) {
            // The AOVs describe the pixel centre, whichever points were sampled.
            const Ray centre =
                camera_ray(frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            SurfaceHit& hit = first_hits[i];
            if (!scene.closest(centre, {0.0f, k_infinity}, hit)) hit.kind = HitKind::none;
        }
    }

    /// A ray of the tree still to trace.
    struct Pending {
        Ray ray;
        RayCone cone;  ///< its footprint (where `textured`)
        float weight;  ///< the product of the weights from the camera ray down to it
        int segment;   ///< ray segments up to and including this one
    };

    /// The colour `camera` sees: Σ over the ray tree's nodes of (product of the weights down to
    /// the node) × (its local colour), Whitted's recursion colour = local + mirror_weight ×
    /// mirror colour + refract_weight × refracted colour, unrolled onto a stack. Its first hit
    /// into `first` when that is set.
    HIKARI_HD Vec3 trace(const Ray& camera, SurfaceHit* first) const {
        Pending stack[k_whitted_kernel_stack];
        int top = 0;
        stack[top++] = {camera, textured ? camera_cones(camera.direction) : RayCone{}, 1.0f, 1};
        Vec3 colour(0.0f);
        while (top > 0) {
            const Pending p = stack[--top];
            /* nearest hit, or the sky */
            SurfaceHit hit;
            const bool found = scene.closest(p.ray, {0.0f, k_infinity}, hit);
            if (first && p.segment == 1) {
                *first = hit;
                if (!found) first->kind = HitKind::none;
            }
            if (!found) {
                colour += p.weight * shading.sky->colour(p.ray.direction, shading.background);
                continue;
            }
            /* local illumination: ambient + each light its shadow ray reaches (Fig 4.29) */
            const WhittedShading<float> shaded = shade(p, hit);
            colour += p.weight * shaded.direct.colour;
            if (p.segment >= max_depth) continue;
            /* the mirror and refracted rays (Fig 4.43), each with its weight and cone */
            const SecondaryRays<float> next =
                whitted_secondary_rays<float>(shaded, p.ray.direction, true);
            if (next.refract_weight > 0.0f)
                stack[top++] = {{next.refract_origin, next.refract_direction},
                                child_cone(p, hit, &next.refract_direction),
                                p.weight * next.refract_weight,
                                p.segment + 1};
            if (next.mirror_weight > 0.0f)
                stack[top++] = {{next.mirror_origin, next.mirror_direction},
                                child_cone(p, hit, nullptr),
                                p.weight * next.mirror_weight,
                                p.segment + 1};
        }
        return colour;
    }

    /// The local illumination of `hit`, seen by the pending ray `p`: whitted.cpp's shade_hit,
    /// the texture's footprint from the ray's cone.
    HIKARI_HD WhittedShading<float> shade(const Pending& p, const SurfaceHit& hit) const {
        const Vec3 d = p.ray.direction;
        WhittedHit<float> h{d, hit.position, hit.geometric_normal, hit.shading_normal,
                            static_cast<int32_t>(hit.material)};
        const Material& m = shading.materials[hit.material];
        if (m.texture) {
            const SurfaceUv uv = surface_uv_of(scene.geometry, hit);
            const UvFootprint f =
                cone_footprint(p.cone.width_at(hit.t), d, hit.geometric_normal, uv);
            h.u = uv.uv.x, h.v = uv.uv.y;
            h.du_dx = f.du_dx, h.dv_dx = f.dv_dx, h.du_dy = f.du_dy, h.dv_dy = f.dv_dy;
            h.dp_dx = f.dp_dx, h.dp_dy = f.dp_dy;
        }
        if (m.vertex_colours) h.vertex_colour = surface_colour_of(scene.geometry, hit);
        const FlatShadowRays visible{&scene};
        return shade_whitted_hit<float>(shading, h, true, visible, NoExtendedLights{});
    }

    /// The cone of a mirror ray (`refracted` null) or of the refracted ray along *refracted,
    /// spawned at `hit` by `p`: whitted.cpp's spawn_cones (Akenine-Möller et al. 2019).
    HIKARI_HD RayCone child_cone(const Pending& p, const SurfaceHit& hit,
                                 const Vec3* refracted) const {
        if (!textured) return {};
        const float width = p.cone.width_at(hit.t);
        const Vec3 d = p.ray.direction;
        const bool entering = dot(hit.geometric_normal, d) < 0.0f;
        const float curvature =
            (entering ? 1.0f : -1.0f) * surface_curvature_of(scene.geometry, hit);
        if (!refracted) return reflected_cone(p.cone, width, curvature);
        const float ior = shading.materials[hit.material].ior;
        return refracted_cone(p.cone, width, curvature, entering ? 1.0f / ior : ior,
                              std::abs(dot(d, hit.shading_normal)),
                              std::abs(dot(*refracted, hit.shading_normal)));
    }
};

}  // namespace hikari

namespace hikari {

/// kernel(i) for every pixel i in [0, pixels) on `device` (core/device_launch.h); its own file,
/// which nvcc compiles when HIKARI_CUDA is on.
void launch_whitted_kernel(ExecutionDevice device, size_t pixels, const WhittedPixelKernel& kernel);

}  // namespace hikari
