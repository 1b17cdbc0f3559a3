#include <functional>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/explain/explain.h"
#include "hikari/explain/primitive_names.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

std::string vec_text(Vec3 v, int digits = 4) {
    return fmt::format("({:.{}f}, {:.{}f}, {:.{}f})", v.x, digits, v.y, digits, v.z, digits);
}

std::string_view kind_text(RayTreeNode::Kind k) {
    switch (k) {
        case RayTreeNode::Kind::camera:
            return "camera ray";
        case RayTreeNode::Kind::mirror:
            return "mirror ray";
        case RayTreeNode::Kind::refracted:
            return "refracted ray";
    }
    return "";
}

/// About how many bytes the listing of `tree` takes: each node's lines, indented two spaces a
/// level, at most some 120 characters besides. A deep tree between mirrors and glass lists a
/// hundred thousand rays (40 MB at --max-depth 30), which must count against the limit too.
double listing_bytes(const Scene& scene, const std::vector<RayTreeNode>& tree) {
    size_t sampled_lights = 0;
    for (const Light& light : scene.lights) sampled_lights += is_delta_light(light) ? 0 : 1;
    constexpr double k_line_bytes = 120;
    double bytes = 0;
    for (const RayTreeNode& node : tree) {
        const double lines = 4.0 + static_cast<double>(node.shadow_rays.size() + sampled_lights);
        bytes += lines * (k_line_bytes + 2.0 * node.depth);
    }
    return bytes;
}

}  // namespace

std::string explain_raytrace_pixel(const Scene& scene, const WhittedSettings& whitted, int x,
                                   int y) {
    if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height)
        throw InputError(fmt::format("--pixel {},{} is outside the {}x{} image", x, y,
                                     scene.camera.width, scene.camera.height));
    const std::vector<RayTreeNode> tree = whitted_ray_tree(scene, whitted, x, y);
    const PrimitiveNames names(scene);
    // The listing, and its copy where a front end takes it (a Python string).
    const double listing = listing_bytes(scene, tree);
    check_memory_need(2 * listing, fmt::format("listing the ray tree of pixel ({}, {}) ({} rays "
                                               "to --max-depth {})",
                                               x, y, tree.size(), whitted.max_depth));
    std::string out;
    out.reserve(static_cast<size_t>(listing));
    out += fmt::format(
        "Ray tracing (Alg 4.3, Whitted 1980) at pixel ({}, {}): the ray tree of its centre ray, "
        "at most {} ray segments\n"
        "Each ray returns local + reflectivity × (mirror ray) + transparency × (refracted ray);\n"
        "local = ambient + every light its shadow ray reaches (Fig 4.29).\n\n",
        x, y, whitted.max_depth);
    std::vector<std::vector<int>> children(tree.size());
    for (size_t n = 1; n < tree.size(); ++n)
        if (tree[n].parent >= 0) children[static_cast<size_t>(tree[n].parent)].push_back(int(n));
    std::function<void(int)> print = [&](int n) {
        const RayTreeNode& node = tree[static_cast<size_t>(n)];
        const std::string indent(2 * static_cast<size_t>(node.depth), ' ');
        out += fmt::format("{}#{} {}", indent, n, kind_text(node.kind));
        if (node.kind != RayTreeNode::Kind::camera)
            out += fmt::format(" of #{} (weight {:.4g})", node.parent, node.weight);
        out += fmt::format(": from {} along {}\n", vec_text(node.ray.origin),
                           vec_text(node.ray.direction));
        if (!node.hit) {
            out += fmt::format("{}   misses everything: sees {}\n", indent, vec_text(node.local));
        } else {
            const Material& m = scene.materials[node.surface.material];
            out += fmt::format("{}   hits {} at t = {:.5g}, point {}, material '{}'\n", indent,
                               names.primitive(node.surface.id), node.surface.t,
                               vec_text(node.surface.position), m.name);
            for (const ShadowRayRecord& r : node.shadow_rays)
                out +=
                    fmt::format("{}   shadow ray to light {} ({}): {}\n", indent, r.light,
                                light_kind_name(scene.lights[r.light]),
                                !r.facing ? "not cast, the surface faces away"
                                          : (r.blocked ? "blocked: in shadow" : "reaches it: lit"));
            for (uint32_t l = 0; l < scene.lights.size(); ++l)
                if (!is_delta_light(scene.lights[l]))
                    out += fmt::format(
                        "{}   light {} ({}): sampled by --light-samples {} shadow "
                        "rays\n",
                        indent, l, light_kind_name(scene.lights[l]), whitted.light_samples);
            out += fmt::format("{}   local colour {}\n", indent, vec_text(node.local));
        }
        for (const int c : children[static_cast<size_t>(n)]) print(c);
        out += fmt::format("{}   #{} returns {}\n", indent, n, vec_text(node.total));
    };
    if (!tree.empty()) print(0);
    out += fmt::format("\nPixel colour (linear RGB): {}\n",
                       tree.empty() ? "none" : vec_text(tree.front().total));
    if (!tree.empty()) out += explain_sphere_shading(scene, x, y, tree.front());
    return out;
}

}  // namespace hikari
