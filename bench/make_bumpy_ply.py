#!/usr/bin/env python3
"""Writes a bumpy sphere as a binary little-endian PLY (float x y z, uchar/int faces), for timing
the loaders on a large mesh: `make_bumpy_ply.py OUT [--rings 500 --segments 1000]` gives
2 × rings × segments triangles (1,000,000 by default)."""
import argparse

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--rings", type=int, default=500)
ap.add_argument("--segments", type=int, default=1000)
args = ap.parse_args()
R, S = args.rings, args.segments
theta = np.linspace(0.0, np.pi, R + 1)[:, None]
phi = np.linspace(0.0, 2.0 * np.pi, S, endpoint=False)[None, :]
r = 1.0 + 0.05 * np.sin(7 * theta) * np.cos(11 * phi) + 0.02 * np.sin(23 * phi + 5 * theta)
pos = np.stack([r * np.sin(theta) * np.cos(phi), r * np.cos(theta), r * np.sin(theta) * np.sin(phi)],
               axis=-1).astype("<f4").reshape(-1, 3)
i = np.arange(R)[:, None]
j = np.arange(S)[None, :]
a = i * S + j
b = i * S + (j + 1) % S
c = a + S
d = b + S
tris = np.concatenate([np.stack([a, c, b], -1).reshape(-1, 3), np.stack([b, c, d], -1).reshape(-1, 3)])
faces = np.zeros(len(tris), dtype=[("n", "u1"), ("v", "<i4", 3)])
faces["n"] = 3
faces["v"] = tris
with open(args.out, "wb") as f:
    f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(pos)}\n"
             "property float x\nproperty float y\nproperty float z\n"
             f"element face {len(tris)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
    f.write(pos.tobytes())
    f.write(faces.tobytes())
