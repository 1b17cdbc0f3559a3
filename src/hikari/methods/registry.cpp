#include "hikari/methods/registry.h"

#include <array>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/depth_sort.h"
#include "hikari/raster/scanline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {

namespace {

constexpr std::array k_methods = {
    Method{"raytrace",
           "Whitted ray tracing (Alg 4.3): nearest hit, shadow rays, reflection, refraction",
           &render_whitted},
    Method{"zbuffer", "Z-buffer (Alg 4.2): rasterize every triangle, keep the nearest per pixel",
           &render_zbuffer},
    Method{"scanline",
           "scanline (Alg 4.1): edge table, active edges, nearest segment per sample span",
           &render_scanline},
    Method{"depthsort",
           "depth sort (Newell et al. 1972): sort, overlap tests, reorder, split cycles",
           &render_depth_sort},
    Method{"depthsort-naive",
           "painter's algorithm by centroid depth (Fig 4.7): fails on overlap cycles",
           &render_depth_sort_naive},
};

}  // namespace

std::span<const Method> methods() { return k_methods; }

const Method* find_method(std::string_view name) {
    for (const Method& m : k_methods)
        if (m.name == name) return &m;
    return nullptr;
}

}  // namespace hikari
