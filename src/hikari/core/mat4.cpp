#include "hikari/core/mat4.h"

#include <cmath>
#include <numbers>

namespace hikari {

Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            float s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

namespace {

using Mat4d = std::array<std::array<double, 4>, 4>;

Mat4d to_double(const Mat4& a) {
    Mat4d d;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) d[i][j] = a.m[i][j];
    return d;
}

// 3x3 minor of `a` without row `r` and column `c`.
double minor3(const Mat4d& a, int r, int c) {
    double s[3][3];
    for (int i = 0, si = 0; i < 4; ++i) {
        if (i == r) continue;
        for (int j = 0, sj = 0; j < 4; ++j) {
            if (j == c) continue;
            s[si][sj++] = a[i][j];
        }
        ++si;
    }
    return s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) -
           s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
           s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
}

double cofactor(const Mat4d& a, int r, int c) {
    return ((r + c) % 2 == 0 ? 1.0 : -1.0) * minor3(a, r, c);
}

double determinant_d(const Mat4d& a) {
    double det = 0;
    for (int j = 0; j < 4; ++j) det += a[0][j] * cofactor(a, 0, j);
    return det;
}

}  // namespace

float determinant(const Mat4& a) { return static_cast<float>(determinant_d(to_double(a))); }

bool invert(const Mat4& a, Mat4& out) {
    const Mat4d d = to_double(a);
    const double det = determinant_d(d);
    if (!std::isfinite(det) || det == 0.0) return false;
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {  // inverse = adjugate / det, adjugate = cofactor transpose
            r.m[i][j] = static_cast<float>(cofactor(d, j, i) / det);
            if (!std::isfinite(r.m[i][j])) return false;
        }
    out = r;
    return true;
}

bool flattens_space(const Mat4& a) {
    const Mat4d d = to_double(a);
    double largest = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(d[i][j]));
    const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                       d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                       d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
    return !std::isfinite(det) || largest == 0 ||
           std::abs(det) <= 1e-9 * largest * largest * largest;
}

Vec3 transform_direction(const Mat4& a, Vec3 d) { return (a * Vec4(d, 0.0f)).xyz(); }

Vec3 transform_normal(const Mat4& normal_matrix, Vec3 n) {
    return (normal_matrix * Vec4(n, 0.0f)).xyz();
}

Mat4 translate(Vec3 t) {
    Mat4 r = Mat4::identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Mat4 scale(Vec3 s) {
    Mat4 r = Mat4::identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Mat4 rotate(Vec3 axis, float degrees) {
    // Rodrigues' rotation formula as a matrix: R = cI + s[a]x + (1-c) a a^T.
    const Vec3 a = normalize(axis);
    const double theta = degrees * std::numbers::pi / 180.0;
    const float c = static_cast<float>(std::cos(theta));
    const float s = static_cast<float>(std::sin(theta));
    const float t = 1.0f - c;
    // clang-format off
    return Mat4::from_rows({
        t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y, 0,
        t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x, 0,
        t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c, 0,
        0, 0, 0, 1,
    });
    // clang-format on
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
    const Vec3 w = normalize(eye - target);  // camera looks down -w
    const Vec3 u = normalize(cross(up, w));
    const Vec3 v = cross(w, u);
    // clang-format off
    return Mat4::from_rows({
        u.x, u.y, u.z, -dot(u, eye),
        v.x, v.y, v.z, -dot(v, eye),
        w.x, w.y, w.z, -dot(w, eye),
        0, 0, 0, 1,
    });
    // clang-format on
}

Mat4 perspective(float fov_y_degrees, float aspect, float near, float far) {
    const double f = 1.0 / std::tan(fov_y_degrees * std::numbers::pi / 360.0);
    const float fx = static_cast<float>(f / aspect);
    const float fy = static_cast<float>(f);
    const float a = (far + near) / (near - far);
    const float b = 2.0f * far * near / (near - far);
    // clang-format off
    return Mat4::from_rows({
        fx, 0, 0, 0,
        0, fy, 0, 0,
        0, 0, a, b,
        0, 0, -1, 0,
    });
    // clang-format on
}

Mat4 orthographic(float left, float right, float bottom, float top, float near, float far) {
    const float sx = 2.0f / (right - left), sy = 2.0f / (top - bottom), sz = -2.0f / (far - near);
    // clang-format off
    return Mat4::from_rows({
        sx, 0, 0, -(right + left) / (right - left),
        0, sy, 0, -(top + bottom) / (top - bottom),
        0, 0, sz, -(far + near) / (far - near),
        0, 0, 0, 1,
    });
    // clang-format on
}

Mat4 viewport(int width, int height) {
    const float hw = 0.5f * static_cast<float>(width);
    const float hh = 0.5f * static_cast<float>(height);
    // clang-format off
    return Mat4::from_rows({
        hw, 0, 0, hw,
        0, -hh, 0, hh,
        0, 0, 0.5f, 0.5f,
        0, 0, 0, 1,
    });
    // clang-format on
}

}  // namespace hikari
