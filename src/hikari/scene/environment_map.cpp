#include "hikari/scene/environment_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "hikari/core/color.h"
#include "hikari/core/memory_budget.h"

namespace hikari {

namespace {
constexpr float k_pi = std::numbers::pi_v<float>;
}  // namespace

EnvironmentMap::EnvironmentMap(Image image, float rotation_degrees) : m_image(std::move(image)) {
    const float radians = rotation_degrees * k_pi / 180.0f;
    m_cos_rotation = std::cos(radians);
    m_sin_rotation = std::sin(radians);
    // Each texel's weight: its luminance times sin θ at its centre, the solid angle it covers
    // (Pharr, Jakob & Humphreys, "Physically Based Rendering", §12.6: infinite area lights).
    const int w = m_image.width, h = m_image.height;
    // The weights and the sampling tables built from them: some 12 bytes a texel.
    check_memory_need(12.0 * w * h, fmt::format("a {}x{} environment map's sampling tables", w, h));
    std::vector<float> weights(static_cast<size_t>(w) * static_cast<size_t>(h));
    for (int y = 0; y < h; ++y) {
        const float sin_theta =
            std::sin(k_pi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
        for (int x = 0; x < w; ++x)
            weights[static_cast<size_t>(y) * w + x] = luminance(m_image.at(x, y)) * sin_theta;
    }
    m_density = PiecewiseConstant2D(weights, w, h);
}

Vec2 EnvironmentMap::uv_of(Vec3 toward) const {
    // Undo the rotation: the map's own direction of world direction `toward`.
    const float x = m_cos_rotation * toward.x - m_sin_rotation * toward.z;
    const float z = m_sin_rotation * toward.x + m_cos_rotation * toward.z;
    const float phi = std::atan2(x, -z);  // 0 toward −z, π/2 toward +x
    // atan2, not acos: exact near the poles, where cos θ rounds to ±1.
    const float theta = std::atan2(std::sqrt(x * x + z * z), toward.y);
    float u = 0.5f + phi / (2.0f * k_pi);
    u -= std::floor(u);
    return {u, theta / k_pi};
}

Vec3 EnvironmentMap::direction_of(Vec2 uv) const {
    const float phi = 2.0f * k_pi * (uv.x - 0.5f), theta = k_pi * uv.y;
    const float s = std::sin(theta);
    const float x = s * std::sin(phi), z = -s * std::cos(phi);
    // The map's rotation, about +y: x' = c x + s z, z' = −s x + c z (inverse of uv_of's).
    return {m_cos_rotation * x + m_sin_rotation * z, std::cos(theta),
            -m_sin_rotation * x + m_cos_rotation * z};
}

Vec3 EnvironmentMap::radiance_from(Vec3 toward) const { return texel_at(uv_of(toward)); }

Vec3 EnvironmentMap::texel_at(Vec2 uv) const {
    const int x = std::clamp(static_cast<int>(uv.x * static_cast<float>(m_image.width)), 0,
                             m_image.width - 1);
    const int y = std::clamp(static_cast<int>(uv.y * static_cast<float>(m_image.height)), 0,
                             m_image.height - 1);
    return m_image.at(x, y);
}

EnvironmentDirection EnvironmentMap::sample(Vec2 xi) const {
    float pdf_uv = 0;
    const Vec2 uv = m_density.sample(xi, pdf_uv);
    const float sin_theta = std::sin(k_pi * uv.y);
    if (!(pdf_uv > 0.0f) || !(sin_theta > 0.0f)) return {direction_of(uv), Vec3(0.0f), 0.0f};
    // dω = sin θ dθ dφ = 2π² sin θ du dv.
    return {direction_of(uv), texel_at(uv), pdf_uv / (2.0f * k_pi * k_pi * sin_theta)};
}

float EnvironmentMap::pdf(Vec3 toward) const {
    const Vec2 uv = uv_of(toward);
    const float sin_theta = std::sin(k_pi * uv.y);
    if (!(sin_theta > 0.0f)) return 0.0f;
    return m_density.pdf(uv) / (2.0f * k_pi * k_pi * sin_theta);
}

}  // namespace hikari
