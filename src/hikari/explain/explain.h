#pragma once
// `hikari explain`: one step of a hidden-surface algorithm printed as the algorithm saw it, for a
// student to follow with the lecture beside. Each explanation runs the method's own code with an
// observer attached (raster/zbuffer.h zbuffer_visibility_at, raster/scanline.h
// scanline_visibility_at), so what is printed is what the render does.

#include <string>

#include "hikari/integrators/whitted/whitted.h"
#include "hikari/raster/raster_settings.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Alg 4.2 at pixel (x, y): every fragment tested there in drawing order, its depth, the
/// Z-buffer's value before the test and the outcome, then the winner. Throws InputError when
/// the pixel is outside the image.
std::string explain_zbuffer_pixel(const Scene& scene, const RasterSettings& raster, int x, int y);

/// Alg 4.1 at scan line `row`: the edge-table entries that start there, the active edge list
/// with x and depth at y = row + 0.5, the scan segments, and each sample span with its visible
/// segment. Throws InputError when the row is outside the image.
std::string explain_scanline_row(const Scene& scene, const RasterSettings& raster, int row);

/// The depth sort (Newell, Newell & Sancha 1972; Fig 4.6-4.9) on the whole scene: the list by
/// farthest depth, each comparison and which of Newell's tests settled it, the reorderings, the
/// splits and the painting order. Each list (polygons, steps, painting order) is cut after
/// `max_steps` lines (said so).
std::string explain_depth_sort(const Scene& scene, const RasterSettings& raster,
                               size_t max_steps = 2000);

/// Alg 4.3 at pixel (x, y): the ray tree of its centre ray (Whitted): each ray, what it hits,
/// the shadow rays toward the lights and whether they are blocked, the mirror and refracted rays
/// it spawns with their weights, and the colour each ray returns, summed up to the pixel's.
std::string explain_raytrace_pixel(const Scene& scene, const WhittedSettings& whitted, int x,
                                   int y);

/// The assignment (課題) at pixel (x, y) in the lecture's notation, for the ray tree's camera ray
/// `node`: the pixel's screen point, the ray P_E + tÊ, A, B, C and D = B² − 4AC of the sphere it
/// meets, t, P, N, then per point or directional light L, cos α, R = L + 2aN (a = −L·N), cos γ,
/// cosⁿγ, I_d = I₀k_d cos α and I_s = I₀k_s cosⁿγ, their sum with the ambient term, and the 8-bit
/// values the file gets (sRGB, and --encoding linear). Part of explain_raytrace_pixel.
std::string explain_sphere_shading(const Scene& scene, int x, int y, const RayTreeNode& node);

/// The lecture's p_s = V P M p_w for the scene's camera (`--print-matrices`): M the model-view
/// matrix (world to camera coordinates; scene objects are given in world coordinates, so M is the
/// camera's), P the projection, V the viewport, then one vertex of each object (up to a few)
/// carried through them, the division by w between P and V included.
std::string explain_matrices(const Scene& scene, const RasterSettings& raster);

}  // namespace hikari
