#pragma once
// The test oracle for the Whitted ray tracer: Whitted's algorithm as it is usually written, one
// ray at a time, recursing at every mirror and glass surface, with the lecture's shading model
// spelled out term by term. The product's tracer (integrators/whitted/) traces blocks of rays
// level by level and shades them in SIMD lanes; the tests require its images to be
// bit-identical to this one's.

#include <optional>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/subpixel.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/refraction.h"
#include "hikari/shading/texture.h"

namespace hikari::testing {

class RecursiveWhitted {
  public:
    RecursiveWhitted(const Scene& scene, int max_depth)
        : m_scene(scene), m_intersector(scene), m_max_depth(max_depth) {}

    /// The colour seen along `ray`, segment `segment` of its path (primary = 1).
    Vec3 trace(const Ray& ray, int segment) const {
        SurfaceHit hit;
        if (!m_intersector.closest(ray, {0.0f, k_infinity}, hit))
            return m_scene.sky.colour(ray.direction, m_scene.background);
        return shade(ray, hit, segment);
    }

    const SceneIntersector& intersector() const { return m_intersector; }

  private:
    /// Local illumination, then the mirror and refracted rays (Fig 4.43).
    Vec3 shade(const Ray& ray, const SurfaceHit& hit, int segment) const {
        const bool entering = dot(hit.geometric_normal, ray.direction) < 0.0f;
        const Vec3 ng = entering ? hit.geometric_normal : -hit.geometric_normal;
        Vec3 n = entering ? hit.shading_normal : -hit.shading_normal;
        if (dot(n, ray.direction) > 0.0f) n = ng;
        const Material& m = m_scene.materials[hit.material];
        Vec3 colour = local(m, hit.position, n, ng, -ray.direction);
        if (segment >= m_max_depth) return colour;
        const Vec3 reflected = reflect(ray.direction, n);
        const Vec3 mirror = reflected * (1.0f / std::sqrt(dot(reflected, reflected)));
        std::optional<Vec3> refracted;
        if (m.transparency > 0.0f)
            refracted = refract(ray.direction, n, entering ? 1.0f / m.ior : m.ior);
        const bool total_internal = m.transparency > 0.0f && !refracted;
        const float mirror_weight = total_internal ? m.transparency : m.reflectivity;
        if (mirror_weight > 0.0f)
            colour +=
                mirror_weight * trace({offset_ray_origin(hit.position, ng), mirror}, segment + 1);
        if (refracted)
            colour += m.transparency *
                      trace({offset_ray_origin(hit.position, -ng), *refracted}, segment + 1);
        return colour;
    }

    /// ka Ia + Σ over the lights a shadow ray reaches of I (kd cos α + ks cos^n γ), with ka and
    /// kd scaled by the texture.
    Vec3 local(const Material& m, Vec3 p, Vec3 n, Vec3 ng, Vec3 to_eye) const {
        Vec3 ka = m.ka, kd = m.kd;
        if (m.texture) {
            SurfacePoint<float> point;
            point.position = p;
            const Vec3 c = texture_colour<float>(*m.texture, point);
            ka = ka * c, kd = kd * c;
        }
        Vec3 colour = ka * m_scene.ambient;
        const Vec3 origin = offset_ray_origin(p, ng);
        for (const Light& light : m_scene.lights) {
            const LightSample ls = sample_light<float>(light, p);
            const float cos_alpha = dot(n, ls.to_light);
            if (cos_alpha <= 0.0f) continue;
            if (m_intersector.occluded({origin, ls.to_light}, {0.0f, ls.distance})) continue;
            const Vec3 r = reflect(-ls.to_light, n);
            const float cos_gamma = dot(r, to_eye);
            const float specular = phong_power(cos_gamma > 0.0f ? cos_gamma : 0.0f, m.shininess);
            colour += ls.irradiance * (kd * cos_alpha + m.ks * specular);
        }
        return colour;
    }

    const Scene& m_scene;
    SceneIntersector m_intersector;
    int m_max_depth;
};

/// The whole image as render_whitted makes it (linear colour and AOVs), by the recursive oracle.
inline Framebuffer render_whitted_recursive(const Scene& scene, const WhittedSettings& whitted = {},
                                            bool aov_buffers = true) {
    const Camera& cam = scene.camera;
    Framebuffer fb(Film(cam), cam.width, cam.height, aov_buffers);
    const RecursiveWhitted tracer(scene, whitted.max_depth);
    const CameraFrame frame = make_camera_frame(cam);
    const int spp = whitted.samples_per_pixel;
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const size_t i = static_cast<size_t>(y) * cam.width + x;
            const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
            const Ray centre = camera_ray(frame, fx + 0.5f, fy + 0.5f);
            Vec3 sum(0.0f);
            if (spp == 1) {
                sum = tracer.trace(centre, 1);
            } else {
                // The same points in every pixel (frame/subpixel.h).
                for (int s = 0; s < spp; ++s) {
                    const Vec2 offset = subpixel_sample(s, spp);
                    sum += tracer.trace(camera_ray(frame, fx + offset.x, fy + offset.y), 1);
                }
                sum = sum / static_cast<float>(spp);
            }
            fb.set_color(i, sum);
            SurfaceHit first;
            if (!aov_buffers || !tracer.intersector().closest(centre, {0.0f, k_infinity}, first))
                continue;
            fb.depth[i] = first.t;
            fb.id[i] = first.id + 1;
            fb.normal[i] = dot(first.shading_normal, centre.direction) < 0.0f
                               ? first.shading_normal
                               : -first.shading_normal;
        }
    return fb;
}

}  // namespace hikari::testing
