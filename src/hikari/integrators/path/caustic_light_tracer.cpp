#include "hikari/integrators/path/caustic_light_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hikari/core/color.h"
#include "hikari/core/parallel.h"
#include "hikari/core/sobol.h"
#include "hikari/frame/tile_share.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/path/path_estimator.h"
#include "hikari/shading/bsdf/lambert.h"

namespace hikari {

namespace {

constexpr float k_pi = std::numbers::pi_v<float>;
/// Fixed-point units per unit of summed radiance (about 1.5e-5 resolution; sums up to 1.4e14).
constexpr double k_fixed_scale = 65536.0;
/// The light paths' own sequence seed (the camera paths hash their pixel index).
constexpr uint32_t k_light_path_seed = 0x4c696768U;

/// |a·b|.
float abs_dot(Vec3 a, Vec3 b) { return std::abs(dot(a, b)); }

/// The frame at `hit` for a path arriving along `direction` (the path tracer's convention:
/// normals turned toward where the path came from; path_estimator.h).
ScatterFrame frame_at(const SurfaceHit& hit, Vec3 direction) {
    return scatter_frame_at(hit, direction, dot(hit.geometric_normal, direction) < 0.0f);
}

/// Whether some material reflects or refracts by a delta lobe.
bool has_delta_lobe(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return m.reflectivity > 0.0f || m.transparency > 0.0f;
    });
}

}  // namespace

MaterialSample<float> material_at_hit(const Scene& scene, const SceneIntersector& intersector,
                                      const SurfaceHit& hit, const ScatterFrame& at) {
    SurfacePoint<float> point{hit.position, at.normal, at.geometric_normal, at.to_eye};
    const Material& m = scene.materials[hit.material];
    if (m.texture || m.ambient_texture) {
        const SurfaceUv uv = intersector.surface_uv(hit);
        point.u = uv.uv.x, point.v = uv.uv.y;
    }
    if (m.vertex_colours) point.vertex_colour = intersector.surface_colour(hit);
    return evaluate_material<float>(scene.materials.data(), static_cast<int32_t>(hit.material),
                                    point);
}

bool traces_caustics_from_lights(const Scene& scene) {
    if (scene.camera.projection != Projection::perspective || !has_delta_lobe(scene)) return false;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i)
        if (max_component(scene.materials[scene.triangles.material[i]].emission) > 0.0f)
            return true;
    return false;
}

CausticLightTracer::CausticLightTracer(const Scene& scene, const SceneIntersector& intersector,
                                       const std::vector<float>& scale, const PixelFilter& filter,
                                       int max_depth)
    : m_scene(scene),
      m_intersector(intersector),
      m_scale(scale),
      m_filter(filter),
      m_max_depth(max_depth),
      m_frame(make_camera_frame(scene.camera)),
      m_fixed(3 * static_cast<size_t>(scene.camera.width) * scene.camera.height) {
    const float pixel = 2.0f * m_frame.tan_half_fov_y / static_cast<float>(scene.camera.height);
    m_pixel_area = pixel * pixel;
    // The filter's normalization: the camera's samples are drawn with density f / ∫f.
    double integral = 0.0;
    constexpr int k_steps = 4096;
    const float w = filter.width();
    for (int i = 0; i < k_steps; ++i)
        integral += filter.weight_1d(-0.5f * w + w * (static_cast<float>(i) + 0.5f) / k_steps);
    integral *= w / k_steps;
    m_filter_volume = static_cast<float>(integral * integral);
    double total = 0.0;
    const TriangleSet& tris = scene.triangles;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        const Vec3 emission = scene.materials[tris.material[i]].emission;
        if (max_component(emission) <= 0.0f) continue;
        const auto& [a, b, c] = tris.indices[i];
        const float area = 0.5f * length(cross(tris.positions[b] - tris.positions[a],
                                               tris.positions[c] - tris.positions[a]));
        const double power = k_pi * luminance(emission) * area;
        if (!(power > 0.0) || !std::isfinite(power)) continue;
        total += power;
        m_triangles.push_back(i);
        m_cdf.push_back(total);
    }
}

Vec3 CausticLightTracer::sum(size_t i) const {
    const auto channel = [&](size_t c) {
        return static_cast<float>(static_cast<double>(m_fixed[3 * i + c].load()) / k_fixed_scale);
    };
    return {channel(0), channel(1), channel(2)};
}

/// Light paths per run handed to one process of a shared image.
constexpr uint64_t k_paths_per_share = 4096;

void CausticLightTracer::trace(uint64_t first, uint64_t count, uint64_t& rays,
                               const TileShare* share) {
    if (m_triangles.empty()) return;
    std::atomic<uint64_t> traced{0};
    hikari::parallel_for(tbb::blocked_range<uint64_t>(first, first + count, 4096),
                         [&](const tbb::blocked_range<uint64_t>& range) {
                             uint64_t own = 0;
                             for (uint64_t i = range.begin(); i != range.end(); ++i)
                                 if (!share || share->owns_block(i / k_paths_per_share))
                                     trace_path(i, own);
                             traced += own;
                         });
    rays += traced.load();
}

void CausticLightTracer::sum_over_parts(const TileShare& share) {
    std::vector<int64_t> sums(m_fixed.size());
    for (size_t i = 0; i < sums.size(); ++i) sums[i] = m_fixed[i].load();
    share.sum_over_parts(sums);
    for (size_t i = 0; i < sums.size(); ++i) m_fixed[i] = sums[i];
}

void CausticLightTracer::trace_path(uint64_t index, uint64_t& rays) {
    SobolSampler sampler(hash_u32(k_light_path_seed ^ static_cast<uint32_t>(index >> 32)),
                         static_cast<uint32_t>(index));
    // Emission: a triangle chosen by power, a point uniform on it, a direction by the cosine
    // about its front: β = L_e cos θ / (p_choice / area · cos θ / π) = L_e π area / p_choice.
    const float u_choice = sampler.next_1d();
    const Vec2 u_point = sampler.next_2d(), u_direction = sampler.next_2d();
    const double target = static_cast<double>(u_choice) * m_cdf.back();
    const size_t chosen = std::min<size_t>(
        static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin()),
        m_cdf.size() - 1);
    const double choice = (m_cdf[chosen] - (chosen > 0 ? m_cdf[chosen - 1] : 0.0)) / m_cdf.back();
    const TriangleSet& tris = m_scene.triangles;
    const uint32_t triangle = m_triangles[chosen];
    const auto& [a, b, c] = tris.indices[triangle];
    const Vec3 corner = tris.positions[a], e1 = tris.positions[b] - corner,
               e2 = tris.positions[c] - corner;
    const Vec3 n = cross(e1, e2);
    const float area = 0.5f * length(n);
    if (!(area > 0.0f)) return;
    const Vec3 front = n / (2.0f * area);
    const float su = std::sqrt(u_point.x);
    const Vec3 origin = corner + (su * (1.0f - u_point.y)) * e1 + (su * u_point.y) * e2;
    Vec3 beta = m_scene.materials[tris.material[triangle]].emission *
                static_cast<float>(k_pi * area / choice);
    Ray ray{offset_ray_origin(origin, front), cosine_hemisphere_direction(front, u_direction)};
    Vec3 walk(1.0f);  // β relative to the light's, for Russian roulette
    for (int vertex = 1; vertex <= m_max_depth; ++vertex) {
        SurfaceHit hit;
        ++rays;
        if (!m_intersector.closest(ray, {0.0f, k_infinity}, hit)) return;
        const float u_lobe = sampler.next_1d();
        const Vec2 u_next = sampler.next_2d();
        const float u_roulette = sampler.next_1d();
        const ScatterFrame at = frame_at(hit, ray.direction);
        const Scattering bsdf(material_at_hit(m_scene, m_intersector, hit, at),
                              m_scale[hit.material]);
        if (bsdf.black()) return;
        // The vertex next to the light is the path tracer's unless it is a mirror or glass
        // bounce; every later one is joined to the eye by its smooth lobes.
        if (vertex > 1 && bsdf.smooth()) connect_to_eye(hit.position, at, bsdf, beta, rays);
        if (vertex == m_max_depth) return;
        const ScatterSample next = bsdf.sample(at, u_lobe, u_next);
        if (vertex == 1 && !next.delta) return;
        if (!(max_component(next.weight) > 0.0f)) return;
        // Light carries importance the other way: shading normals need Veach's adjoint factor
        // |ω_o·n_s| |ω_i·n_g| / (|ω_o·n_g| |ω_i·n_s|) (Veach 1997, §5.3; 1 on flat surfaces).
        const float cos_in_s = abs_dot(next.direction, at.normal);
        const float adjoint = cos_in_s > 0.0f
                                  ? abs_dot(at.to_eye, at.normal) *
                                        abs_dot(next.direction, at.geometric_normal) /
                                        (abs_dot(at.to_eye, at.geometric_normal) * cos_in_s)
                                  : 1.0f;
        beta = beta * next.weight * adjoint;
        walk = walk * next.weight * adjoint;
        if (vertex >= k_roulette_after) {  // as the camera paths (path_estimator.h)
            const float q = std::min(1.0f, max_component(walk));
            if (!(u_roulette < q)) return;
            beta = beta / q;
            walk = walk / q;
        }
        const Vec3 side = dot(next.direction, at.geometric_normal) > 0.0f ? at.geometric_normal
                                                                          : -at.geometric_normal;
        ray = {offset_ray_origin(hit.position, side), next.direction};
    }
}

void CausticLightTracer::connect_to_eye(Vec3 x, const ScatterFrame& at, const Scattering& bsdf,
                                        Vec3 beta, uint64_t& rays) {
    const Vec3 v = x - m_frame.eye;
    const float depth = dot(v, m_frame.forward);
    if (!(depth > 0.0f)) return;
    const float r2 = dot(v, v), r = std::sqrt(r2);
    const Vec3 to_eye = -v / r;
    if (!(dot(to_eye, at.geometric_normal) > 0.0f)) return;
    // Where the eye sees x: camera_ray inverted.
    const float plane_x = dot(v, m_frame.right) / depth, plane_y = dot(v, m_frame.up) / depth;
    const Vec2 image{
        (plane_x / (m_frame.tan_half_fov_y * m_frame.aspect) + 1.0f) * 0.5f *
            static_cast<float>(m_frame.width),
        (1.0f - plane_y / m_frame.tan_half_fov_y) * 0.5f * static_cast<float>(m_frame.height)};
    const float margin = 0.5f * m_filter.width();
    if (!(image.x > -margin && image.y > -margin && image.x < m_frame.width + margin &&
          image.y < m_frame.height + margin))
        return;
    float pdf = 0.0f;
    const Vec3 f = bsdf.evaluate(at, to_eye, pdf);
    if (!(max_component(f) > 0.0f)) return;
    ++rays;
    if (m_intersector.occluded({offset_ray_origin(x, at.geometric_normal), to_eye},
                               {0.0f, r * (1.0f - 1e-4f)}))
        return;
    // The pixel measures ∫ L du over its square (image-plane units): du = dω / (A_pixel cos³θ)
    // and dω = |ω·n_g| dA / r², so a point of the surface adds
    // β f |ω_o·n_s| |ω·n_g| / |ω_o·n_g| / (A_pixel cos³θ r²) (pbrt-v3's t = 1 connection).
    const float cos_camera = depth / r;
    const float shading = abs_dot(at.to_eye, at.normal) * dot(to_eye, at.geometric_normal) /
                          std::max(abs_dot(at.to_eye, at.geometric_normal), 1e-6f);
    const float importance = 1.0f / (m_pixel_area * cos_camera * cos_camera * cos_camera * r2);
    splat(image, beta * f * (shading * importance));
}

void CausticLightTracer::splat(Vec2 image_point, Vec3 value) {
    if (!is_finite(value)) return;
    const float half = 0.5f * m_filter.width();
    const int x0 = std::max(0, static_cast<int>(std::floor(image_point.x - half - 0.5f)));
    const int y0 = std::max(0, static_cast<int>(std::floor(image_point.y - half - 0.5f)));
    const int x1 = std::min(m_frame.width - 1, static_cast<int>(image_point.x + half + 0.5f));
    const int y1 = std::min(m_frame.height - 1, static_cast<int>(image_point.y + half + 0.5f));
    for (int py = y0; py <= y1; ++py)
        for (int px = x0; px <= x1; ++px) {
            // A camera sample for pixel (px, py) lands at offset d from its centre with density
            // f(d) / ∫f: the point counts toward that pixel with the same weight.
            const float wx = m_filter.weight_1d(image_point.x - (static_cast<float>(px) + 0.5f));
            const float wy = m_filter.weight_1d(image_point.y - (static_cast<float>(py) + 0.5f));
            const float w = wx * wy / m_filter_volume;
            if (!(w > 0.0f)) continue;
            const size_t i = static_cast<size_t>(py) * m_frame.width + px;
            for (int ch = 0; ch < 3; ++ch) {
                const double fixed = std::round(static_cast<double>(value[ch] * w) * k_fixed_scale);
                if (fixed < 9.0e18) m_fixed[3 * i + ch].fetch_add(static_cast<int64_t>(fixed));
            }
        }
}

}  // namespace hikari
