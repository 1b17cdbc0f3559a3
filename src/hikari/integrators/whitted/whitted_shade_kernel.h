#pragma once
// The lane loops of the Whitted shading step (whitted_shade.h), written once and compiled by
// whitted_shade.cpp (baseline x86-64), whitted_shade_avx2.cpp and whitted_shade_avx512.cpp
// (after their `#pragma GCC target`), which the compiler vectorises. Each loop body repeats the
// scalar code's arithmetic in its order, with branches turned into selects; only float
// arithmetic and builtins appear, in functions of internal linkage (see primary_hits_kernel.h).

#include <cstdint>

#include "hikari/integrators/whitted/primary_hits_kernel.h"
#include "hikari/integrators/whitted/whitted_shade.h"

namespace hikari::detail {
namespace {

/// Parity of floor(v), as CheckerTexture::floor_int(v) & 1: floats of 2^31 or more in
/// magnitude are multiples of 256, so even.
[[maybe_unused]] inline int32_t floor_parity_lane(float v) {
    const bool small = __builtin_fabsf(v) < 2147483648.0f;
    const float w = small ? v : 0.0f;
    const auto truncated = static_cast<int32_t>(w);
    const int32_t floor = truncated - (w < static_cast<float>(truncated) ? 1 : 0);
    return floor & 1;
}

/// out[i] = value in the lanes of a chunk whose material is m; for the chunk's first material
/// in every lane (the later ones overwrite theirs), which saves reading `out`.
template <class T>
void broadcast_lanes(const int32_t* __restrict material, int32_t m, bool first, T value,
                     T* __restrict out) {
    if (first) {
        for (int i = 0; i < k_lane_chunk; ++i) out[i] = value;
    } else {
        for (int i = 0; i < k_lane_chunk; ++i) out[i] = material[i] == m ? value : out[i];
    }
}

/// sample_light for every lane: the unit direction toward the light and I0 after falloff (a
/// template per kind of light, as GCC does not vectorise selects on a loop-invariant flag).
template <bool Directional, bool InverseSquare>
void sample_light_lanes(const ShadeLight& light, LaneChunk& lanes) {
    const float* __restrict px = lanes.position[0];
    const float* __restrict py = lanes.position[1];
    const float* __restrict pz = lanes.position[2];
    auto* __restrict lx = lanes.to_light[0];
    auto* __restrict ly = lanes.to_light[1];
    auto* __restrict lz = lanes.to_light[2];
    auto* __restrict ir = lanes.irradiance[0];
    auto* __restrict ig = lanes.irradiance[1];
    auto* __restrict ib = lanes.irradiance[2];
    const float cx = light.position[0], cy = light.position[1], cz = light.position[2];
    const float tx = light.to_light[0], ty = light.to_light[1], tz = light.to_light[2];
    const float i0r = light.intensity[0], i0g = light.intensity[1], i0b = light.intensity[2];
    for (int i = 0; i < k_lane_chunk; ++i) {
        if constexpr (Directional) {
            lx[i] = tx, ly[i] = ty, lz[i] = tz;
            ir[i] = i0r, ig[i] = i0g, ib[i] = i0b;
        } else {
            const float vx = cx - px[i], vy = cy - py[i], vz = cz - pz[i];
            const float d2 = vx * vx + vy * vy + vz * vz;
            const float inverse_distance = 1.0f / __builtin_sqrtf(d2);
            lx[i] = vx * inverse_distance, ly[i] = vy * inverse_distance;
            lz[i] = vz * inverse_distance;
            if constexpr (InverseSquare) {
                const float inverse_d2 = 1.0f / d2;
                ir[i] = i0r * inverse_d2, ig[i] = i0g * inverse_d2, ib[i] = i0b * inverse_d2;
            } else {
                ir[i] = i0r, ig[i] = i0g, ib[i] = i0b;
            }
        }
    }
}

/// The specular factor's parts for every lane toward the light in to_light: cos γ = R·V with
/// R = reflect(-L, N) and V = -direction, and phong_power(cos γ, exponent) by repeated squaring
/// (the exponent's bits in the scalar order; always all k_exponent_bits steps, as a constant
/// count keeps the lane in registers and the steps past the top bit leave the power as it is).
inline void phong_highlight_lanes(LaneChunk& lanes) {
    const float* __restrict dx = lanes.direction[0];
    const float* __restrict dy = lanes.direction[1];
    const float* __restrict dz = lanes.direction[2];
    const float* __restrict nx = lanes.normal[0];
    const float* __restrict ny = lanes.normal[1];
    const float* __restrict nz = lanes.normal[2];
    const float* __restrict lx = lanes.to_light[0];
    const float* __restrict ly = lanes.to_light[1];
    const float* __restrict lz = lanes.to_light[2];
    const int32_t* __restrict exponent = lanes.exponent;
    float* __restrict cos_gamma = lanes.cos_gamma;
    float* __restrict power = lanes.power;
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float a = 2.0f * -(-lx[i] * nx[i] + -ly[i] * ny[i] + -lz[i] * nz[i]);
        const float rx = -lx[i] + nx[i] * a, ry = -ly[i] + ny[i] * a, rz = -lz[i] + nz[i] * a;
        cos_gamma[i] = rx * -dx[i] + ry * -dy[i] + rz * -dz[i];
    }
    for (int i = 0; i < k_lane_chunk; ++i) {
        const int32_t e = exponent[i];
        float p = 1.0f, squared = cos_gamma[i];
        for (int b = 0; b < k_exponent_bits; ++b) {
            p = (e >> b) & 1 ? p * squared : p;
            squared = squared * squared;
        }
        power[i] = p;
    }
}

/// One chunk of lanes (the struct's constant offsets and constant trip counts are what lets g++
/// vectorise every arithmetic loop below).
inline void shade_chunk(const ShadeScene& scene, int spawn, LaneChunk& lanes) {
    // Every lane array through a restrict pointer: they never overlap, and g++ needs telling.
    const ShadeMaterials mt = scene.materials;
    auto* __restrict dx = lanes.direction[0];
    auto* __restrict dy = lanes.direction[1];
    auto* __restrict dz = lanes.direction[2];
    auto* __restrict px = lanes.position[0];
    auto* __restrict py = lanes.position[1];
    auto* __restrict pz = lanes.position[2];
    auto* __restrict nx = lanes.normal[0];
    auto* __restrict ny = lanes.normal[1];
    auto* __restrict nz = lanes.normal[2];
    auto* __restrict fx = lanes.facing_normal[0];
    auto* __restrict fy = lanes.facing_normal[1];
    auto* __restrict fz = lanes.facing_normal[2];
    auto* __restrict red = lanes.colour[0];
    auto* __restrict green = lanes.colour[1];
    auto* __restrict blue = lanes.colour[2];
    auto* __restrict kd_r = lanes.kd[0];
    auto* __restrict kd_g = lanes.kd[1];
    auto* __restrict kd_b = lanes.kd[2];
    auto* __restrict material = lanes.material;
    auto* __restrict active = lanes.active;
    auto* __restrict entering = lanes.entering;
    auto* __restrict power = lanes.power;
    auto* __restrict cos_gamma = lanes.cos_gamma;
    auto* __restrict shadow_rays = lanes.shadow_rays;
    auto* __restrict lit_bits = lanes.lit;

    int32_t filler = 0;
    for (int i = k_lane_chunk - 1; i >= 0; --i) filler = active[i] ? material[i] : filler;
    // 1. shade(): normals turned toward the ray.
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float gx = lanes.geometric_normal[0][i], gy = lanes.geometric_normal[1][i],
                    gz = lanes.geometric_normal[2][i];
        const float sx = lanes.shading_normal[0][i], sy = lanes.shading_normal[1][i],
                    sz = lanes.shading_normal[2][i];
        const bool enter = gx * dx[i] + gy * dy[i] + gz * dz[i] < 0.0f;
        const float ax = enter ? gx : -gx, ay = enter ? gy : -gy, az = enter ? gz : -gz;
        const float bx = enter ? sx : -sx, by = enter ? sy : -sy, bz = enter ? sz : -sz;
        const bool turned_away = bx * dx[i] + by * dy[i] + bz * dz[i] > 0.0f;
        nx[i] = turned_away ? ax : bx, ny[i] = turned_away ? ay : by, nz[i] = turned_away ? az : bz;
        fx[i] = ax, fy[i] = ay, fz[i] = az;
        entering[i] = enter ? 1 : 0;
        shadow_rays[i] = 0;
        // Lanes without a hit read the first hit's material: one material fewer to broadcast in
        // chunks that are partly sky.
        material[i] = active[i] ? material[i] : filler;
    }
    // The lanes' material parameters: for each material present in the chunk (usually one or
    // two), its values broadcast into the lanes that hold it. GCC vectorises selects like these
    // but not table lookups (it emulates gathers one lane at a time, which stalls the vector
    // loads that read the result).
    auto* __restrict ks_r = lanes.ks[0];
    auto* __restrict ks_g = lanes.ks[1];
    auto* __restrict ks_b = lanes.ks[2];
    auto* __restrict exponent = lanes.exponent;
    int32_t present[k_lane_chunk];
    const int32_t present_count = distinct_values(material, present);
    for (int32_t k = 0; k < present_count; ++k) {
        const int32_t m = present[k];
        for (int c = 0; c < 3; ++c) {
            broadcast_lanes(material, m, k == 0, mt.ka[c][m], lanes.ka[c]);
            broadcast_lanes(material, m, k == 0, mt.kd[c][m], lanes.kd[c]);
            broadcast_lanes(material, m, k == 0, mt.ks[c][m], lanes.ks[c]);
            broadcast_lanes(material, m, k == 0, mt.offset[c][m], lanes.offset[c]);
            broadcast_lanes(material, m, k == 0, mt.color_a[c][m], lanes.color_a[c]);
            broadcast_lanes(material, m, k == 0, mt.color_b[c][m], lanes.color_b[c]);
        }
        broadcast_lanes(material, m, k == 0, mt.inverse_size[m], lanes.inverse_size);
        broadcast_lanes(material, m, k == 0, mt.reflectivity[m], lanes.reflectivity);
        broadcast_lanes(material, m, k == 0, mt.transparency[m], lanes.transparency);
        broadcast_lanes(material, m, k == 0, mt.ior[m], lanes.ior);
        broadcast_lanes(material, m, k == 0, mt.textured[m], lanes.textured);
        broadcast_lanes(material, m, k == 0, mt.exponent[m], exponent);
    }
    // textured(): ka and kd at the point (CheckerTexture::at: q = (p + offset) / size, then the
    // parity of the floors' sum); shade_ambient().
    const float ambient_r = scene.ambient[0], ambient_g = scene.ambient[1],
                ambient_b = scene.ambient[2];
    auto* __restrict scalar_specular = lanes.scalar_specular;
    const float* __restrict check_a_r = lanes.color_a[0];
    const float* __restrict check_a_g = lanes.color_a[1];
    const float* __restrict check_a_b = lanes.color_a[2];
    const float* __restrict check_b_r = lanes.color_b[0];
    const float* __restrict check_b_g = lanes.color_b[1];
    const float* __restrict check_b_b = lanes.color_b[2];
    const auto* __restrict inverse_sizes = lanes.inverse_size;
    const float* __restrict ka_in_r = lanes.ka[0];
    const float* __restrict ka_in_g = lanes.ka[1];
    const float* __restrict ka_in_b = lanes.ka[2];
    const float* __restrict offset_x = lanes.offset[0];
    const float* __restrict offset_y = lanes.offset[1];
    const float* __restrict offset_z = lanes.offset[2];
    const auto* __restrict textured_flags = lanes.textured;
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float inverse_size = inverse_sizes[i];
        const float qx = (px[i] + offset_x[i]) * inverse_size;
        const float qy = (py[i] + offset_y[i]) * inverse_size;
        const float qz = (pz[i] + offset_z[i]) * inverse_size;
        const bool odd =
            (floor_parity_lane(qx) ^ floor_parity_lane(qy) ^ floor_parity_lane(qz)) != 0;
        const bool textured = textured_flags[i] != 0;
        const float tr = odd ? check_b_r[i] : check_a_r[i];
        const float tg = odd ? check_b_g[i] : check_a_g[i];
        const float tb = odd ? check_b_b[i] : check_a_b[i];
        const float ka_r = textured ? ka_in_r[i] * tr : ka_in_r[i];
        const float ka_g = textured ? ka_in_g[i] * tg : ka_in_g[i];
        const float ka_b = textured ? ka_in_b[i] * tb : ka_in_b[i];
        kd_r[i] = textured ? kd_r[i] * tr : kd_r[i];
        kd_g[i] = textured ? kd_g[i] * tg : kd_g[i];
        kd_b[i] = textured ? kd_b[i] * tb : kd_b[i];
        red[i] = ka_r * ambient_r;
        green[i] = ka_g * ambient_g;
        blue[i] = ka_b * ambient_b;
        scalar_specular[i] = active[i] && exponent[i] < 0 ? 1 : 0;
    }

    // What the chunk's materials need at all: a chunk of matte, opaque surfaces (most of them)
    // skips the highlight and the secondary rays. Skipping the highlight changes no bit: with
    // ks = 0 the term ks * specular is +0 whatever the specular factor (>= 0) is.
    int32_t any_specular = 0, any_secondary = 0, any_transparent = 0;
    for (int i = 0; i < k_lane_chunk; ++i) {
        const bool shiny = (ks_r[i] != 0.0f) | (ks_g[i] != 0.0f) | (ks_b[i] != 0.0f);
        const bool transparent = lanes.transparency[i] > 0.0f;
        const bool reflective = lanes.reflectivity[i] > 0.0f;
        any_specular |= active[i] & (shiny ? 1 : 0);
        any_transparent |= active[i] & (transparent ? 1 : 0);
        any_secondary |= active[i] & (transparent | reflective ? 1 : 0);
    }

    // 2. shade_local(): each light that faces the point and whose shadow ray was found unblocked
    // adds shade_direct(), lights in the scalar order.
    auto* __restrict lx = lanes.to_light[0];
    auto* __restrict ly = lanes.to_light[1];
    auto* __restrict lz = lanes.to_light[2];
    auto* __restrict ir = lanes.irradiance[0];
    auto* __restrict ig = lanes.irradiance[1];
    auto* __restrict ib = lanes.irradiance[2];
    for (int32_t l = 0; l < scene.light_count; ++l) {
        const ShadeLight& light = scene.lights[l];
        if (light.directional)
            sample_light_lanes<true, false>(light, lanes);
        else if (light.inverse_square)
            sample_light_lanes<false, true>(light, lanes);
        else
            sample_light_lanes<false, false>(light, lanes);
        // The highlight's cos γ = R·V with R = reflect(-L, N) and V = -direction.
        if (any_specular == 0) {
            for (int i = 0; i < k_lane_chunk; ++i) cos_gamma[i] = 0.0f, power[i] = 0.0f;
        } else {
            phong_highlight_lanes(lanes);
        }
        const int32_t bit = 1 << l;
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float cos_alpha = nx[i] * lx[i] + ny[i] * ly[i] + nz[i] * lz[i];
            // Bitwise & rather than &&: no branches, so GCC can if-convert the loop.
            const bool facing = (active[i] != 0) & !(cos_alpha <= 0.0f);
            shadow_rays[i] = shadow_rays[i] + (facing ? 1 : 0);
            const bool lit = facing & ((lit_bits[i] & bit) != 0);
            const float specular = cos_gamma[i] > 0.0f ? power[i] : 0.0f;
            const float term_r = ir[i] * (kd_r[i] * cos_alpha + ks_r[i] * specular);
            const float term_g = ig[i] * (kd_g[i] * cos_alpha + ks_g[i] * specular);
            const float term_b = ib[i] * (kd_b[i] * cos_alpha + ks_b[i] * specular);
            red[i] = lit ? red[i] + term_r : red[i];
            green[i] = lit ? green[i] + term_g : green[i];
            blue[i] = lit ? blue[i] + term_b : blue[i];
        }
    }
    if (!spawn || any_secondary == 0) {
        for (int i = 0; i < k_lane_chunk; ++i)
            lanes.mirror_weight[i] = 0.0f, lanes.refract_weight[i] = 0.0f;
        return;
    }

    // 3. shade()'s secondary rays: the mirror ray, the refracted ray (refract(), Snell's law)
    // and POV-Ray's total-internal-reflection rule, each from offset_ray_origin.
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float a = 2.0f * -(dx[i] * nx[i] + dy[i] * ny[i] + dz[i] * nz[i]);
        lanes.mirror_direction[0][i] = dx[i] + nx[i] * a;
        lanes.mirror_direction[1][i] = dy[i] + ny[i] * a;
        lanes.mirror_direction[2][i] = dz[i] + nz[i] * a;
        lanes.mirror_origin[0][i] = offset_origin_lane(px[i], fx[i]);
        lanes.mirror_origin[1][i] = offset_origin_lane(py[i], fy[i]);
        lanes.mirror_origin[2][i] = offset_origin_lane(pz[i], fz[i]);
    }
    if (any_transparent == 0) {
        // No refraction, no total internal reflection: the mirror ray has the reflectivity.
        for (int i = 0; i < k_lane_chunk; ++i) {
            lanes.mirror_weight[i] = active[i] ? lanes.reflectivity[i] : 0.0f;
            lanes.refract_weight[i] = 0.0f;
        }
        return;
    }
    for (int i = 0; i < k_lane_chunk; ++i) {
        const float ior = lanes.ior[i];
        const float eta = entering[i] ? 1.0f / ior : ior;
        const float cos_i = -(dx[i] * nx[i] + dy[i] * ny[i] + dz[i] * nz[i]);
        const float sin2_cos = 1.0f - cos_i * cos_i;
        const float sin2_t = eta * eta * (0.0f < sin2_cos ? sin2_cos : 0.0f);
        const bool total_internal_reflection = sin2_t > 1.0f;
        const float cos_t = __builtin_sqrtf(1.0f - sin2_t);
        const float k = eta * cos_i - cos_t;
        const float tx = dx[i] * eta + nx[i] * k, ty = dy[i] * eta + ny[i] * k,
                    tz = dz[i] * eta + nz[i] * k;
        const float inverse_length = 1.0f / __builtin_sqrtf(tx * tx + ty * ty + tz * tz);
        lanes.refract_direction[0][i] = tx * inverse_length;
        lanes.refract_direction[1][i] = ty * inverse_length;
        lanes.refract_direction[2][i] = tz * inverse_length;
        lanes.refract_origin[0][i] = offset_origin_lane(px[i], -fx[i]);
        lanes.refract_origin[1][i] = offset_origin_lane(py[i], -fy[i]);
        lanes.refract_origin[2][i] = offset_origin_lane(pz[i], -fz[i]);

        const float transparency = lanes.transparency[i];
        const bool transparent = active[i] && transparency > 0.0f;
        const float mirror_weight =
            transparent && total_internal_reflection ? transparency : lanes.reflectivity[i];
        lanes.mirror_weight[i] = active[i] ? mirror_weight : 0.0f;
        lanes.refract_weight[i] = transparent && !total_internal_reflection ? transparency : 0.0f;
    }
}

/// The sky's colour (Sky::colour) in the lanes without a hit.
inline void sky_chunk(const ShadeScene& scene, LaneChunk& lanes) {
    const float* __restrict up = lanes.direction[1];
    const int32_t* __restrict active = lanes.active;
    const bool gradient = scene.gradient != 0;
    for (int c = 0; c < 3; ++c) {
        float* __restrict colour = lanes.colour[c];
        const float horizon = scene.horizon[c], zenith = scene.zenith[c];
        const float background = scene.background[c];
        for (int i = 0; i < k_lane_chunk; ++i) {
            const float t = up[i] < 0.0f ? 0.0f : (up[i] > 1.0f ? 1.0f : up[i]);
            const float sky = gradient ? horizon * (1.0f - t) + zenith * t : background;
            colour[i] = active[i] ? colour[i] : sky;
        }
    }
}

/// Every chunk that holds one of the first `count` lanes: shading where a lane has a hit, the
/// sky's colour where not, and every lane's count of shadow rays, scalar flag and children
/// (zero where no hit).
[[maybe_unused]] void shade_kernel(const ShadeScene& scene, int spawn, int count,
                                   BlockLanes& lanes) {
    for (int c = 0; c * k_lane_chunk < count; ++c) {
        LaneChunk& chunk = lanes.chunks[c];
        if (any_active(chunk)) {
            shade_chunk(scene, spawn, chunk);
        } else {
            for (int i = 0; i < k_lane_chunk; ++i) {
                chunk.shadow_rays[i] = 0, chunk.scalar_specular[i] = 0;
                chunk.mirror_weight[i] = 0.0f, chunk.refract_weight[i] = 0.0f;
            }
        }
        for (int i = 0; i < k_lane_chunk; ++i)
            chunk.children[i] =
                (chunk.mirror_weight[i] > 0.0f ? 1 : 0) + (chunk.refract_weight[i] > 0.0f ? 1 : 0);
        sky_chunk(scene, chunk);
    }
}

}  // namespace
}  // namespace hikari::detail
