#pragma once
// Naming what an explanation talks about: a projected triangle by the scene object it came from.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/raster/vertex_pipeline.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// "sphere (primitive 0)", "plane (primitive 2)", "triangle (primitive 7)" by primitive id.
class PrimitiveNames {
  public:
    explicit PrimitiveNames(const Scene& scene);
    /// "sphere (primitive 0)".
    std::string primitive(PrimitiveId id) const;
    /// Projected triangle `t` of `ps`: "triangle 12 of sphere (primitive 0)".
    std::string screen_triangle(const ProjectedScene& ps, uint32_t t) const;

  private:
    std::vector<std::string_view>
        m_kind;  ///< by primitive id; string literals, so views never dangle
};

/// The view depth a depth key z = −near / w stands for (w, the distance along the view axis), or
/// nothing under a parallel projection, whose key is not a distance.
std::string view_depth_note(const RasterView& view, double z);

}  // namespace hikari
