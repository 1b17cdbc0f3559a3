#pragma once
// A tangent frame around a unit normal, for turning directions sampled about +z into world
// space (Duff et al. 2017, "Building an Orthonormal Basis, Revisited": no branch on the normal
// but its sign, no division near zero).

#include <cmath>

#include "hikari/core/host_device.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Unit vectors t, b, n with t × b = n.
struct OrthonormalBasis {
    Vec3 t, b, n;

    HIKARI_HD explicit OrthonormalBasis(Vec3 normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float c = n.x * n.y * a;
        t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
        b = {c, sign + n.y * n.y * a, -n.y};
    }
    /// Local (x, y, z) to world x·t + y·b + z·n.
    HIKARI_HD Vec3 to_world(Vec3 local) const { return local.x * t + local.y * b + local.z * n; }
};

}  // namespace hikari
