#pragma once
// A latitude–longitude environment map: the radiance arriving from every direction, stored as an
// image twice as wide as it is high, and the density that importance-samples it.
//
// Orientation (docs/lights.md): +y is up. Row 0 of the image is the zenith, the last row the
// nadir; θ = π·v from the zenith, v = (row + ½) / height at texel centres. The image's middle
// column looks toward −z (the default camera's view), and going right turns toward +x:
// direction = (sin θ sin φ, cos θ, −sin θ cos φ) with φ = 2π·(u − ½). A rotation of a degrees
// turns the whole map about +y, counter-clockwise seen from above (the right-hand rule).

#include <vector>

#include "hikari/core/image.h"
#include "hikari/core/piecewise_constant.h"
#include "hikari/core/vec.h"

namespace hikari {

/// A sampled direction of an environment map and its solid-angle density.
struct EnvironmentDirection {
    Vec3 direction;  ///< unit, toward the sky
    Vec3 radiance;   ///< the texel's radiance there
    float pdf = 0;   ///< per steradian; 0 where the map has no light to offer
};

class EnvironmentMap {
  public:
    /// `image` (linear RGB, width = 2 · height) rotated by `rotation_degrees` about +y.
    /// Negative or non-finite texels are not checked here (the loader rejects them).
    EnvironmentMap(Image image, float rotation_degrees);

    /// The radiance arriving from unit direction `toward`: the texel it falls in.
    Vec3 radiance_from(Vec3 toward) const;
    /// A direction drawn with density proportional to the texels' luminance · sin θ (the
    /// solid angle a texel covers), from the random pair `xi` in [0, 1)².
    EnvironmentDirection sample(Vec2 xi) const;
    /// The density sample() draws unit direction `toward` with, per steradian.
    float pdf(Vec3 toward) const;

    const Image& image() const { return m_image; }
    /// The map's (u, v) of world direction `toward` and back.
    Vec2 uv_of(Vec3 toward) const;
    Vec3 direction_of(Vec2 uv) const;
    /// The texel that holds map point (u, v).
    Vec3 texel_at(Vec2 uv) const;

  private:
    Image m_image;
    float m_cos_rotation = 1, m_sin_rotation = 0;
    PiecewiseConstant2D m_density;
};

}  // namespace hikari
