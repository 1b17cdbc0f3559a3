#pragma once
// A scene where a render's kernels read it (issue 46), shared by the Whitted and the path
// tracing kernels: on the CPU, views of the scene's own arrays and BVHs; on a CUDA device,
// copies in the render's DeviceArena (core/cuda_devices.h).

#include <string>
#include <vector>

#include "hikari/bvh/flat_intersector.h"
#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/cuda_devices.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// `intersector`'s geometry and wide BVHs (all triangles, shadow casters) held in `arena`.
FlatIntersector hold_intersector(const SceneIntersector& intersector, DeviceArena& arena);

/// The materials as the device reads them: the plain fields and checker textures (names, which
/// the kernels never read, cleared so that a bytewise copy holds no host pointer worth
/// following; image textures are refused before).
std::vector<Material> device_materials(const Scene& scene);

/// Why the kernels cannot take `scene`'s lights when they take only point, spot and directional
/// ones (the Whitted and Z-buffer kernels): the first other light, as a refusal; "" when none.
std::string delta_lights_refusal(const Scene& scene);

/// The first material with an image texture, as a refusal ("" when none): their mip pyramids
/// are host vectors, which no kernel reads yet.
std::string image_texture_refusal(const Scene& scene);

}  // namespace hikari
