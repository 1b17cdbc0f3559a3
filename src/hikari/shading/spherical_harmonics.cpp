#include "hikari/shading/spherical_harmonics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hikari {

namespace {
constexpr float k_pi = std::numbers::pi_v<float>;
/// Â_l per coefficient: the clamped cosine's own harmonic coefficients (R&H 2001, eq. 8).
constexpr std::array<float, 9> k_cosine_lobe = {k_pi,         2 * k_pi / 3, 2 * k_pi / 3,
                                                2 * k_pi / 3, k_pi / 4,     k_pi / 4,
                                                k_pi / 4,     k_pi / 4,     k_pi / 4};
}  // namespace

std::array<float, 9> sh_basis(Vec3 d) {
    return {0.282095f,
            0.488603f * d.y,
            0.488603f * d.z,
            0.488603f * d.x,
            1.092548f * d.x * d.y,
            1.092548f * d.y * d.z,
            0.315392f * (3.0f * d.z * d.z - 1.0f),
            1.092548f * d.x * d.z,
            0.546274f * (d.x * d.x - d.y * d.y)};
}

Vec3 IrradianceSh::irradiance(Vec3 n) const {
    const std::array<float, 9> y = sh_basis(n);
    Vec3 e(0.0f);
    for (size_t i = 0; i < 9; ++i) e += (k_cosine_lobe[i] * y[i]) * coefficients[i];
    return {std::max(e.x, 0.0f), std::max(e.y, 0.0f), std::max(e.z, 0.0f)};
}

IrradianceSh project_environment(const EnvironmentLight& light) {
    IrradianceSh sh;
    if (!light.map) {
        // ∫ L Y_00 dω = L · 0.282095 · 4π; the other bands of a constant vanish.
        sh.coefficients[0] = light.radiance * (0.282095f * 4.0f * k_pi);
        return sh;
    }
    const Image& image = light.map->image();
    const int w = image.width, h = image.height;
    std::array<double, 27> sum{};
    for (int y = 0; y < h; ++y) {
        const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(h);
        // The texel's solid angle: (2π / w) · (π / h) · sin θ.
        const double d_omega = (2.0 * k_pi / w) * (k_pi / h) * std::sin(k_pi * v);
        for (int x = 0; x < w; ++x) {
            const Vec2 uv{(static_cast<float>(x) + 0.5f) / static_cast<float>(w), v};
            const std::array<float, 9> basis = sh_basis(light.map->direction_of(uv));
            const Vec3 radiance = image.at(x, y);
            for (size_t i = 0; i < 9; ++i)
                for (int c = 0; c < 3; ++c) sum[3 * i + c] += radiance[c] * basis[i] * d_omega;
        }
    }
    for (size_t i = 0; i < 9; ++i)
        sh.coefficients[i] = light.radiance * Vec3(static_cast<float>(sum[3 * i]),
                                                   static_cast<float>(sum[3 * i + 1]),
                                                   static_cast<float>(sum[3 * i + 2]));
    return sh;
}

}  // namespace hikari
