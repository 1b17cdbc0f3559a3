#pragma once
// Options shared by every rendering method, and the channel through which a render reports
// progress and learns that it should stop.

#include <atomic>
#include <cstdint>

namespace hikari {

/// Progress and cancellation of one render, shared between the render and its caller.
struct RenderControl {
    std::atomic<uint64_t> work_done{0};   ///< units (tiles, primitives) finished so far
    std::atomic<uint64_t> work_total{0};  ///< units in all, set by the method when it starts
    std::atomic<bool> cancel{false};      ///< set by the caller (e.g. on SIGINT) to stop early
    // Statistics the ray-tracing methods report (`hikari render --stats`).
    std::atomic<uint64_t> rays_traced{0};    ///< camera, secondary and shadow rays
    std::atomic<uint64_t> bvh_triangles{0};  ///< triangles in the BVH
    std::atomic<uint64_t> bvh_nodes{0};      ///< wide BVH nodes
    std::atomic<uint64_t> bvh_bytes{0};      ///< BVH nodes + triangle data + ids
    std::atomic<uint64_t> bvh_build_us{0};   ///< BVH build wall time, microseconds
};

/// How the raster methods interpolate shading across a triangle (the lecture's flat, Gouraud and
/// Phong shading).
enum class Interpolation {
    flat,     ///< one face normal per triangle
    gouraud,  ///< shade at the vertices, interpolate the colours
    phong,    ///< interpolate the normal, shade every pixel
};

/// Settings of a render; the scene says what, these say how.
struct RenderSettings {
    int samples_per_pixel = 1;  ///< 1: one ray through each pixel centre; more: stratified jitter
    int max_depth = 5;          ///< ray segments per path, the primary ray included
    Interpolation interp = Interpolation::phong;  ///< raster methods' shading interpolation
    bool cull_back_faces = false;      ///< raster methods drop triangles facing away (Fig 4.3)
    RenderControl* control = nullptr;  ///< optional progress / cancellation
    /// Fill the framebuffer's depth, id and normal buffers too. False: colour only (ray tracing
    /// then neither allocates nor writes them; raster methods, which need depth, keep them).
    bool aov_buffers = true;
    /// The caller needs the colour only as 8-bit sRGB (a PNG or PPM file): a method may then fill
    /// Framebuffer::srgb8 instead of `color`, a quarter of the fresh memory (on a virtual machine
    /// the page faults of a full-HD float image cost more than encoding it). The Whitted ray
    /// tracer does so when aov_buffers is false; the other methods ignore it.
    bool srgb8_output = false;
    /// Ray tracing with one sample per pixel finds the camera rays' hits a tile at a time, in
    /// SIMD (integrators/whitted/primary_hits.h). False: one camera ray at a time through trace(),
    /// the reference the tests compare with (the images are bit-identical).
    bool primary_blocks = true;
};

}  // namespace hikari
