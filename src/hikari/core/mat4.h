#pragma once
// 4x4 homogeneous matrices: the lecture's p_s = V P M p_w. Names read right to left, so
// `view_from_world * p` takes a world-space point into view space.

#include <array>

#include "hikari/core/vec.h"

namespace hikari {

/// A row-major 4x4 matrix acting on column vectors: p' = M p.
struct Mat4 {
    std::array<std::array<float, 4>, 4> m{};

    /// The identity matrix.
    static constexpr Mat4 identity() {
        Mat4 r;
        for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0f;
        return r;
    }
    /// A matrix from 16 numbers in row-major order.
    static constexpr Mat4 from_rows(const std::array<float, 16>& v) {
        Mat4 r;
        for (int i = 0; i < 16; ++i) r.m[i / 4][i % 4] = v[i];
        return r;
    }

    constexpr float operator()(int row, int col) const { return m[row][col]; }
    constexpr float& operator()(int row, int col) { return m[row][col]; }
    bool operator==(const Mat4&) const = default;
};

Mat4 operator*(const Mat4& a, const Mat4& b);
/// Inline, as transform_point: the vertex stage runs them once per vertex and frame (on the
/// GPU too: raster/vertex_transform.h).
HIKARI_HD inline Vec4 operator*(const Mat4& a, Vec4 v) {
    auto row = [&](int i) {
        return a.m[i][0] * v.x + a.m[i][1] * v.y + a.m[i][2] * v.z + a.m[i][3] * v.w;
    };
    return {row(0), row(1), row(2), row(3)};
}

Mat4 transpose(const Mat4& a);
/// The inverse by cofactors, computed in double. Returns false when `a` is singular (zero or
/// non-finite determinant, or an inverse that does not fit in floats); `out` is then left
/// unchanged. Nearly singular matrices are judged by their use: see flattens_space().
bool invert(const Mat4& a, Mat4& out);

/// Whether the linear part of `a` (its upper-left 3 × 3) squashes space flat: its determinant is
/// below 10⁻⁹ times the cube of its largest entry. Scale-free (a model in millimetres passes) and
/// blind to the translation, so a model placed far from the origin is not judged singular.
bool flattens_space(const Mat4& a);
/// Determinant (in double, rounded to float).
float determinant(const Mat4& a);

/// Maps a point (w = 1), dividing by the resulting w when it is not 1.
HIKARI_HD inline Vec3 transform_point(const Mat4& a, Vec3 p) {
    const Vec4 h = a * Vec4(p, 1.0f);
    return h.w == 1.0f ? h.xyz() : h.xyz() / h.w;
}
/// Maps a direction (w = 0): translation does not apply.
Vec3 transform_direction(const Mat4& a, Vec3 d);
/// Maps a surface normal by the inverse transpose, given here as `normal_matrix`
/// = transpose(inverse(a)); the result is not normalized.
Vec3 transform_normal(const Mat4& normal_matrix, Vec3 n);

Mat4 translate(Vec3 t);
Mat4 scale(Vec3 s);
/// Rotation by `degrees` about `axis` (need not be unit), counter-clockwise when the axis
/// points at the viewer (right-handed).
Mat4 rotate(Vec3 axis, float degrees);
/// view_from_world for a camera at `eye` looking at `target`; the camera looks down its
/// -z axis with +y up (OpenGL convention). `up` must not be parallel to the view direction.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);
/// clip_from_view: OpenGL-style perspective projection with vertical field of view `fov_y_degrees`;
/// view-space z = -near maps to NDC z = -1 and z = -far to +1.
Mat4 perspective(float fov_y_degrees, float aspect, float near, float far);
/// clip_from_view of a parallel projection (glOrtho): the view-space box [left, right] ×
/// [bottom, top] × [−far, −near] to the NDC cube [−1, 1]³, w = 1.
Mat4 orthographic(float left, float right, float bottom, float top, float near, float far);
/// screen_from_ndc: NDC x, y in [-1, 1] to pixel coordinates with y = 0 at the top row and
/// pixel centres at half-integers; z in [-1, 1] to [0, 1].
Mat4 viewport(int width, int height);

}  // namespace hikari
