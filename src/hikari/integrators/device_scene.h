#pragma once
// A scene where a render's kernels read it (issue 46), shared by the Whitted and the path
// tracing kernels: on the CPU, views of the scene's own arrays and BVHs; on a CUDA device,
// copies in the render's DeviceArena (core/cuda_devices.h).

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

}  // namespace hikari
