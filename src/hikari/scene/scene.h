#pragma once
// The scene as plain data: loaders build it, methods only read it (ARCHITECTURE.md, data flow).

#include <array>
#include <cstdint>
#include <vector>

#include "hikari/scene/camera.h"
#include "hikari/scene/light.h"
#include "hikari/scene/material.h"

namespace hikari {

/// Primitive ids number what the scene file lists, in order: a sphere, plane or triangle object
/// is one primitive, a mesh contributes its triangles one after another in file order.
using PrimitiveId = uint32_t;

/// A sphere (ray–sphere: the lecture's A t² + B t + C = 0).
struct Sphere {
    Vec3 center;
    float radius = 1;
    uint32_t material = 0;  ///< index into Scene::materials
    PrimitiveId id = 0;
};

/// An infinite, two-sided plane through `point` with unit `normal`.
struct Plane {
    Vec3 point;
    Vec3 normal{0, 1, 0};
    uint32_t material = 0;
    PrimitiveId id = 0;
};

/// Every triangle of the scene in one flat indexed array, world space.
struct TriangleSet {
    std::vector<Vec3> positions;                   ///< world-space vertex positions
    std::vector<Vec3> normals;                     ///< unit shading normal per vertex
    std::vector<std::array<uint32_t, 3>> indices;  ///< vertex indices per triangle,
                                                   ///< counter-clockwise seen from the front
    std::vector<uint32_t> material;                ///< material index per triangle
    std::vector<PrimitiveId> id;                   ///< primitive id per triangle

    size_t size() const { return indices.size(); }
};

/// A whole scene: camera, lights, materials and geometry.
struct Scene {
    Camera camera;
    Vec3 background{0.0f};  ///< colour of rays that hit nothing
    Vec3 ambient{0.0f};     ///< ambient light intensity Ia
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    TriangleSet triangles;
    uint32_t primitive_count = 0;  ///< number of primitive ids handed out
};

}  // namespace hikari
