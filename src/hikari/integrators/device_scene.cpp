#include "hikari/integrators/device_scene.h"

#include <optional>
#include <span>
#include <variant>

#include <fmt/format.h>

#include "hikari/shading/lights.h"

namespace hikari {

namespace {

/// A wide BVH's arrays held in `arena`.
FlatBvh hold_bvh(const WideBvh& tree, DeviceArena& arena) {
    FlatBvh flat;
    flat.nodes = arena.hold(std::span<const WideBvhNode>(tree.nodes.data(), tree.nodes.size()));
    flat.triangle_data =
        arena.hold(std::span<const float>(tree.triangle_data.data(), tree.triangle_data.size()));
    flat.triangle_ids =
        arena.hold(std::span<const uint32_t>(tree.triangle_ids.data(), tree.triangle_ids.size()));
    flat.root = tree.root;
    return flat;
}

}  // namespace

FlatIntersector hold_intersector(const SceneIntersector& intersector, DeviceArena& arena) {
    FlatIntersector out;
    const FlatGeometry g = intersector.geometry();
    out.geometry.spheres = arena.hold(std::span(g.spheres.data, g.spheres.count));
    out.geometry.planes = arena.hold(std::span(g.planes.data, g.planes.count));
    out.geometry.positions = arena.hold(std::span(g.positions.data, g.positions.count));
    out.geometry.normals = arena.hold(std::span(g.normals.data, g.normals.count));
    out.geometry.indices = arena.hold(std::span(g.indices.data, g.indices.count));
    out.geometry.material = arena.hold(std::span(g.material.data, g.material.count));
    out.geometry.id = arena.hold(std::span(g.id.data, g.id.count));
    out.geometry.uvs = arena.hold(std::span(g.uvs.data, g.uvs.count));
    out.geometry.colors = arena.hold(std::span(g.colors.data, g.colors.count));
    out.triangles = hold_bvh(intersector.bvh(), arena);
    out.shadow_triangles = hold_bvh(intersector.shadow_bvh(), arena);
    return out;
}

std::vector<Material> device_materials(const Scene& scene) {
    std::vector<Material> out = scene.materials;
    for (Material& m : out) m.name.clear();
    return out;
}

std::string delta_lights_refusal(const Scene& scene) {
    for (const Light& light : scene.lights)
        if (!is_delta_light(light))
            return fmt::format(
                "{} lights are not in the kernels yet (point, spot and directional lights are)",
                light_kind_name(light));
    return {};
}

std::string image_texture_refusal(const Scene& scene) {
    for (const Material& m : scene.materials)
        for (const std::optional<Texture>* t : {&m.texture, &m.ambient_texture})
            if (*t && std::holds_alternative<ImageTexture>(**t))
                return fmt::format(
                    "material \"{}\": image textures are not in the kernels yet (checker "
                    "textures are)",
                    m.name);
    return {};
}

}  // namespace hikari
