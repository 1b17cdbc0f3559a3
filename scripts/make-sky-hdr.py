#!/usr/bin/env python3
"""Writes scenes/sky.hdr: a small synthetic latitude-longitude sky (Radiance RGBE) for the
environment-light example: a blue sky brightening toward the horizon, a dim ground below, and
a small sun. Run from the repository root; needs only the Python standard library."""
import math
import struct

W, H = 256, 128
SUN = (math.radians(35.0), math.radians(60.0))  # elevation, azimuth (from -z toward +x)


def rgbe(r, g, b):
    v = max(r, g, b)
    if v < 1e-32:
        return b"\0\0\0\0"
    m, e = math.frexp(v)
    scale = m * 256.0 / v
    return bytes((int(r * scale), int(g * scale), int(b * scale), e + 128))


def radiance(theta, phi):
    elevation = math.pi / 2 - theta
    d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
    se, sa = SUN
    s = (math.cos(se) * math.sin(sa), math.sin(se), -math.cos(se) * math.cos(sa))
    cos_sun = sum(a * b for a, b in zip(d, s))
    if elevation < 0:
        return (0.12, 0.1, 0.08)
    t = elevation / (math.pi / 2)
    sky = (0.55 + (0.15 - 0.55) * t, 0.7 + (0.3 - 0.7) * t, 0.95 + (0.8 - 0.95) * t)
    if cos_sun > math.cos(math.radians(3.0)):
        return (160.0, 150.0, 130.0)
    glow = 2.0 * max(0.0, cos_sun) ** 64
    return tuple(c + glow for c in sky)


with open("scenes/sky.hdr", "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
    for y in range(H):
        theta = math.pi * (y + 0.5) / H
        for x in range(W):
            phi = 2 * math.pi * ((x + 0.5) / W - 0.5)
            f.write(rgbe(*radiance(theta, phi)))
