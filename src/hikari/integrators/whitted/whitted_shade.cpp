#include "hikari/integrators/whitted/whitted_shade.h"

#include <algorithm>
#include <variant>

#include "hikari/integrators/whitted/whitted_shade_kernel.h"
#include "hikari/shading/phong.h"

namespace hikari {

namespace detail {

void shade_lanes_portable(const ShadeScene& scene, int spawn, int count, BlockLanes& lanes) {
    shade_kernel(scene, spawn, count, lanes);
}

}  // namespace detail

LaneShader::LaneShader(const Scene& scene, SimdLevel level) : m_level(level) {
    m_supported = scene.lights.size() <= k_max_block_lights;
    // One column per material parameter; at least one entry, so lanes without a hit can read
    // material 0.
    const size_t count = std::max<size_t>(scene.materials.size(), 1);
    enum FloatColumn {
        ka = 0,
        kd = 3,
        ks = 6,
        reflectivity = 9,
        transparency,
        ior,
        inverse_size,
        offset,
        color_a = offset + 3,
        color_b = color_a + 3,
        float_columns = color_b + 3
    };
    m_floats.assign(static_cast<size_t>(float_columns) * count, 0.0f);
    m_ints.assign(2 * count, 0);
    const auto column = [&](int c) { return m_floats.data() + static_cast<size_t>(c) * count; };
    for (size_t i = 0; i < count; ++i) {
        const Material m = i < scene.materials.size() ? scene.materials[i] : Material{};
        for (int a = 0; a < 3; ++a) {
            column(ka + a)[i] = m.ka[a];
            column(kd + a)[i] = m.kd[a];
            column(ks + a)[i] = m.ks[a];
        }
        column(reflectivity)[i] = m.reflectivity;
        column(transparency)[i] = m.transparency;
        column(ior)[i] = m.ior;
        m_ints[i] = phong_integer_exponent(m.shininess);
        if (m.texture) {
            m_ints[count + i] = 1;
            column(inverse_size)[i] = 1.0f / m.texture->size;
            for (int a = 0; a < 3; ++a) {
                column(offset + a)[i] = m.texture->offset[a];
                column(color_a + a)[i] = m.texture->color_a[a];
                column(color_b + a)[i] = m.texture->color_b[a];
            }
        }
    }
    detail::ShadeMaterials& t = m_scene.materials;
    for (int a = 0; a < 3; ++a) {
        t.ka[a] = column(ka + a);
        t.kd[a] = column(kd + a);
        t.ks[a] = column(ks + a);
        t.offset[a] = column(offset + a);
        t.color_a[a] = column(color_a + a);
        t.color_b[a] = column(color_b + a);
    }
    t.reflectivity = column(reflectivity);
    t.transparency = column(transparency);
    t.ior = column(ior);
    t.inverse_size = column(inverse_size);
    t.exponent = m_ints.data();
    t.textured = m_ints.data() + count;

    for (const Light& light : scene.lights) {
        detail::ShadeLight l{};
        if (const auto* point = std::get_if<PointLight>(&light)) {
            l.inverse_square = point->inverse_square ? 1 : 0;
            for (int a = 0; a < 3; ++a) {
                l.position[a] = point->position[a];
                l.intensity[a] = point->intensity[a];
            }
        } else {
            const auto& directional = std::get<DirectionalLight>(light);
            l.directional = 1;
            for (int a = 0; a < 3; ++a) {
                l.to_light[a] = -directional.direction[a];
                l.intensity[a] = directional.intensity[a];
            }
        }
        m_lights.push_back(l);
    }
    m_scene.lights = m_lights.data();
    m_scene.light_count = static_cast<int32_t>(m_lights.size());
    m_scene.gradient = scene.sky.gradient ? 1 : 0;
    for (int a = 0; a < 3; ++a) {
        m_scene.ambient[a] = scene.ambient[a];
        m_scene.horizon[a] = scene.sky.horizon[a];
        m_scene.zenith[a] = scene.sky.zenith[a];
        m_scene.background[a] = scene.background[a];
    }
}

void LaneShader::shade(detail::BlockLanes& lanes, int count, bool spawn) const {
    simd_pick(m_level, detail::shade_lanes_portable, detail::shade_lanes_avx2,
              detail::shade_lanes_avx512)(m_scene, spawn ? 1 : 0, count, lanes);
}

}  // namespace hikari
