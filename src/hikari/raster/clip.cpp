#include "hikari/raster/clip.h"

#include "hikari/raster/vertex_transform.h"

namespace hikari {

namespace {

/// One Sutherland–Hodgman pass: keeps the part of `in` on the inside of `plane`.
void clip_against(const ClipPolygon& in, int plane, ClipPolygon& out) {
    out.count = 0;
    for (int i = 0; i < in.count; ++i) {
        const Vec4 a = in.v[i];
        const Vec4 b = in.v[(i + 1) % in.count];
        const float da = clip_plane_distance(a, plane), db = clip_plane_distance(b, plane);
        const bool a_in = da >= 0.0f, b_in = db >= 0.0f;
        if (a_in) out.v[out.count++] = a;
        if (a_in != b_in) {
            // Interpolate from the inside end so both triangles sharing the edge agree exactly.
            out.v[out.count++] =
                a_in ? a + (b - a) * (da / (da - db)) : b + (a - b) * (db / (db - da));
        }
        if (out.count >= k_max_clip_vertices) break;  // unreachable for convex input
    }
}

}  // namespace

bool inside_clip_volume(Vec4 p) { return in_clip_volume(p); }

ClipPolygon clip_triangle(Vec4 a, Vec4 b, Vec4 c) {
    ClipPolygon poly;
    poly.v[0] = a;
    poly.v[1] = b;
    poly.v[2] = c;
    poly.count = 3;
    if (inside_clip_volume(a) && inside_clip_volume(b) && inside_clip_volume(c)) return poly;
    ClipPolygon tmp;
    for (int plane = 0; plane < 5 && poly.count > 0; ++plane) {
        clip_against(poly, plane, tmp);
        poly = tmp;
    }
    if (poly.count < 3) poly.count = 0;
    return poly;
}

}  // namespace hikari
