#pragma once
// The shading half of shadow mapping (raster/shadow_map.h): a point is lit when it is no
// farther from the light than the depth the map holds in its direction (Williams 1978), with
// percentage-closer filtering (Reeves, Salesin & Cook 1987). Written once, as templates over the
// map's type, for the CPU's maps (LightShadowMap) and the flat copies the GPU's shading kernel
// reads (FlatShadowMap, raster/zbuffer_kernel.h).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hikari/core/host_device.h"
#include "hikari/core/lanes.h"
#include "hikari/core/mat4.h"
#include "hikari/core/vec.h"
#include "hikari/raster/vertex_transform.h"
#include "hikari/scene/scene.h"
#include "hikari/shading/light_shadow_view.h"

namespace hikari {

/// Bias and normal offset, in texels (lit_in_shadow_map). A point's depth may differ from
/// its texel's centre depth by up to half a texel diagonal times tan θ on a plane, hence the
/// slope term of one texel per unit of tan θ; tan θ is capped where the light grazes.
inline constexpr float k_constant_bias_texels = 1.0f;
inline constexpr float k_normal_offset_texels = 1.0f;
inline constexpr float k_max_slope = 8.0f;
/// Texel radius of percentage-closer filtering: a 5 × 5 texel kernel.
inline constexpr int k_pcf_radius_texels = 2;

/// A receiver point as the map sees it: the lookup point (moved off the surface by the normal
/// offset), its depth, the world size of a texel there, and the depth bias allowed.
struct MapLookup {
    Vec3 q;
    float depth = 0;
    float texel = 0;
    float tan_theta = 0;
    Vec3 across1, across2;  ///< unit directions across the map at q (its texel rows, columns)
};

template <class Map>
HIKARI_HD MapLookup map_lookup(const Map& map, Vec3 p, Vec3 n) {
    MapLookup m;
    const Vec3 to_light = map.directional ? -map.direction : normalize(map.origin - p);
    m.texel = map.directional ? map.texel_size : map.texel_size * length(p - map.origin);
    const float cos_theta = std::clamp(dot(n, to_light), 0.0f, 1.0f);
    const float sin_theta = std::sqrt(1.0f - cos_theta * cos_theta);
    m.tan_theta = std::min(sin_theta / std::max(cos_theta, 1e-6f), float{k_max_slope});
    m.q = p + n * (k_normal_offset_texels * m.texel);
    m.depth = map.directional ? dot(m.q - map.origin, map.direction) : length(m.q - map.origin);
    const Vec3 w = map.directional ? map.direction : normalize(m.q - map.origin);
    const Vec3 up = std::abs(w.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    m.across1 = normalize(cross(up, w));
    m.across2 = cross(w, m.across1);
    return m;
}

/// The face of a cube map that holds direction `d` from the light.
HIKARI_HD inline size_t cube_face(Vec3 d) {
    const Vec3 a(std::abs(d.x), std::abs(d.y), std::abs(d.z));
    if (a.x >= a.y && a.x >= a.z) return d.x < 0.0f ? 1 : 0;
    if (a.y >= a.z) return d.y < 0.0f ? 3 : 2;
    return d.z < 0.0f ? 5 : 4;
}

/// The caster depth the map holds in the direction of world point `x` (seen from the light),
/// or +infinity outside the map.
template <class Map>
HIKARI_HD float caster_depth(const Map& map, Vec3 x) {
    constexpr float k_no_caster = std::numeric_limits<float>::infinity();
    const auto& face = map.faces[map.directional || map.cone ? 0 : cube_face(x - map.origin)];
    if (face.depth.empty()) return k_no_caster;  // a face that sees no caster
    const Vec4 clip = face.view.clip_from_world * Vec4(x, 1.0f);
    if (!(clip.w > 0.0f)) return k_no_caster;
    const Vec3 screen = transform_point(face.view.screen_from_clip, clip.xyz() / clip.w);
    if (!(screen.x >= 0.0f && screen.y >= 0.0f && screen.x < static_cast<float>(map.size) &&
          screen.y < static_cast<float>(map.size)))
        return k_no_caster;  // outside the map: no caster there
    return face.depth[static_cast<size_t>(screen.y) * static_cast<size_t>(map.size) +
                      static_cast<size_t>(screen.x)];
}

/// The lookup point moved (i, j) texels across the map, at the receiver's distance (for a cube
/// map, a texel's angle about the light).
HIKARI_HD inline Vec3 offset_lookup(const MapLookup& m, float i, float j) {
    return m.q + (i * m.texel) * m.across1 + (j * m.texel) * m.across2;
}

/// The fraction of a (2k + 1)² grid of lookups, `stride` texels apart around m, that see no
/// caster nearer than the receiver (percentage-closer filtering: Reeves, Salesin & Cook 1987).
template <class Map>
HIKARI_HD float percentage_closer(const Map& map, const MapLookup& m, int k, float stride) {
    // Neighbouring lookups on a receiver sloped by θ differ in depth by up to tan θ per texel.
    const float bias = m.texel * (k_constant_bias_texels + m.tan_theta * (1.0f + k * stride));
    int lit = 0;
    for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i)
            lit += m.depth <= caster_depth(map, offset_lookup(m, i * stride, j * stride)) + bias
                       ? 1
                       : 0;
    return static_cast<float>(lit) / static_cast<float>((2 * k + 1) * (2 * k + 1));
}

/// lit_in_shadow_map (raster/shadow_map.h) for any map type.
template <class Map>
HIKARI_HD bool lit_in_map(const Map& map, Vec3 p, Vec3 n) {
    const MapLookup m = map_lookup(map, p, n);
    return m.depth <= caster_depth(map, m.q) + m.texel * (k_constant_bias_texels + m.tan_theta);
}

/// The largest blocker search and filter radius of PCSS, as a fraction of the map's side, and
/// the most lookups per side of its filter ((2 · steps + 1)², spread over the radius: wider
/// kernels take lookups more than a texel apart).
inline constexpr float k_pcss_max_radius_fraction = 0.125f;
inline constexpr int k_pcss_max_steps = 6;
/// Lookups per side of the blocker search: (2 · steps + 1)² over the search radius.
inline constexpr int k_pcss_search_steps = 4;

/// pcss_shadow_fraction (raster/shadow_map.h) for any map type.
template <class Map>
HIKARI_HD float pcss_fraction(const Map& map, Vec3 p, Vec3 n, float light_radius) {
    if (map.directional || !(light_radius > 0.0f))
        return percentage_closer(map, map_lookup(map, p, n), k_pcf_radius_texels, 1.0f);
    MapLookup m = map_lookup(map, p, n);
    // Kernels wider than their lookups turn a texel-aligned grid into bands; a grid turned by an
    // angle hashed from the point turns them into fine noise instead (the same for any thread).
    const auto bits = [](float f) { return static_cast<uint32_t>(float_bits(f)); };
    const uint32_t hash =
        (bits(p.x) * 0x9e3779b1u) ^ (bits(p.y) * 0x85ebca77u) ^ (bits(p.z) * 0xc2b2ae3du);
    const float angle =
        static_cast<float>((hash ^ (hash >> 15)) * 0x2c1b3c6du >> 8) * (6.2831853f / 16777216.0f);
    const Vec3 a1 = m.across1, a2 = m.across2;
    m.across1 = std::cos(angle) * a1 + std::sin(angle) * a2;
    m.across2 = std::cos(angle) * a2 - std::sin(angle) * a1;
    // Texels are m.texel wide at the receiver's distance d_r; an occluder at depth d_b hides part
    // of a light of radius R from it when it lies within R (d_r − d_b) / d_b of the receiver's
    // line to the light's centre, measured at the receiver: up to 3R for d_b >= d_r / 4.
    const float max_radius = float{k_pcss_max_radius_fraction} * static_cast<float>(map.size);
    const float search = std::min(3.0f * light_radius / m.texel, max_radius);
    const int k = k_pcss_search_steps;
    const float stride = std::max(search / k, 1.0f);
    const float bias = m.texel * (k_constant_bias_texels + m.tan_theta * (1.0f + k * stride));
    double blocker_sum = 0;
    int blockers = 0;
    for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i) {
            const float d = caster_depth(map, offset_lookup(m, i * stride, j * stride));
            if (d + bias < m.depth) {
                blocker_sum += d;
                ++blockers;
            }
        }
    if (blockers == 0) return 1.0f;
    // Fernando 2005: penumbra width w = R (d_r − d_b) / d_b at the receiver, by similar triangles.
    const float d_blocker = static_cast<float>(blocker_sum / blockers);
    const float penumbra = light_radius * (m.depth - d_blocker) / std::max(d_blocker, 1e-6f);
    const float radius = std::clamp(penumbra / m.texel, 1.0f, max_radius);
    const int steps = std::min(static_cast<int>(std::ceil(radius)), int{k_pcss_max_steps});
    return percentage_closer(map, m, steps, radius / static_cast<float>(steps));
}

/// plane_blocks_light (raster/shadow_map.h) over `count` planes at `planes`.
HIKARI_HD inline bool planes_block_light(const Plane* planes, size_t count,
                                         const LightShadowView& view, Vec3 p) {
    for (size_t i = 0; i < count; ++i) {
        const Plane& plane = planes[i];
        if (!plane.casts_shadow) continue;
        const float side = dot(p - plane.point, plane.normal);
        // A point on the plane (the plane itself, as a receiver) is never behind it.
        if (!(std::abs(side) > 1e-4f * (1.0f + length(p - plane.point)))) continue;
        bool blocked = false;
        if (view.projection == ShadowProjection::parallel)
            blocked = side * dot(-view.direction, plane.normal) < 0.0f;
        else if (view.projection != ShadowProjection::none)
            blocked = side * dot(view.origin - plane.point, plane.normal) < 0.0f;
        if (blocked) return true;
    }
    return false;
}

}  // namespace hikari
